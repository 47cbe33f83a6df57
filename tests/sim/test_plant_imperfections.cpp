// The plant-only imperfections (plant_imperfections.hpp) against the physics they stand for:
// crossfall and side force against the body's lateral equation, plant scales against the
// understeer gradient, the actuator scales against the low-pass's step response, and the late
// pose against the trace's own poses.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "smoothsteer/path/path.hpp"
#include "smoothsteer/sim/simulation.hpp"
#include "smoothsteer/vehicle/double_track.hpp"
#include "support/sim_test_support.hpp"

namespace smoothsteer {
namespace {

//! Soft tires (B = 0.1): the tire forces lag the lateral velocity by m v / (Cf + Cr) = 7 s at
//! 10 m/s, so that over 0.2 s the body's lateral equation is nearly the external force alone.
VehicleParameters soft_tired_car() {
  VehicleParameters car;
  car.front_tire.stiffness_factor_b = 0.1;
  car.rear_tire.stiffness_factor_b = 0.1;
  car.double_track = DoubleTrackParameters{};
  return car;
}

SimulationResult drive_straight(const VehicleModel& plant, const SimulationParameters& sim,
                                double angle = 0.0, double speed_mps = 10.0) {
  const Path path = Path::straight_line({0, 0}, 0.0, 2000.0);
  testing::ConstantSteering controller(angle);
  return simulate(path, plant, ActuatorParameters{}, SpeedProfile{speed_mps, speed_mps, 0.0, 0.0},
                  sim, {{0, 0}, 0.0}, controller);
}

TEST(Crossfall, PushesTheCarDownTheSlopeWithGSinPhi) {
  const VehicleParameters car = soft_tired_car();
  const DynamicSingleTrack single(car);
  const DoubleTrack double_track(car);
  for (const VehicleModel* plant : {static_cast<const VehicleModel*>(&single),
                                    static_cast<const VehicleModel*>(&double_track)}) {
    SimulationParameters sim;
    sim.duration_s = 0.2;
    EXPECT_EQ(drive_straight(*plant, sim).trace.back().lateral_velocity_mps, 0.0);
    sim.crossfall = 0.05;  // the road falls to the right: the car is pushed toward -y
    const SimulationResult result = drive_straight(*plant, sim);
    const double expected = -car.gravity_mps2 * std::sin(std::atan(0.05)) * 0.2;
    EXPECT_NEAR(result.trace.back().lateral_velocity_mps, expected, 0.03 * std::abs(expected))
        << plant->name();
    EXPECT_LT(result.trace.back().rear_axle.position.y, 0.0) << plant->name();
  }
}

TEST(SideForce, IsTheCrossfallOfTheSameForceAndStepsInAtItsStart) {
  const VehicleParameters car = soft_tired_car();
  const DynamicSingleTrack plant(car);
  SimulationParameters sim;
  sim.duration_s = 1.0;
  sim.crossfall = 0.05;
  const SimulationResult crossfall = drive_straight(plant, sim);
  sim.crossfall = 0.0;
  sim.side_force.force_n = car.mass_kg * crossfall_lateral_acceleration(0.05, car.gravity_mps2);
  const SimulationResult wind = drive_straight(plant, sim);
  ASSERT_EQ(crossfall.trace.size(), wind.trace.size());
  for (std::size_t k = 0; k < wind.trace.size(); ++k) {
    EXPECT_NEAR(wind.trace[k].lateral_velocity_mps, crossfall.trace[k].lateral_velocity_mps, 1e-9);
  }
  // A gust from 0.5 s on: nothing before, the force's acceleration after; a yaw moment M turns
  // the body with M / Iz.
  sim.side_force = {2000.0, 3000.0, 0.5};
  const SimulationResult gust = drive_straight(plant, sim);
  for (const TraceSample& sample : gust.trace) {
    if (sample.time_s <= 0.5) {
      EXPECT_EQ(sample.lateral_velocity_mps, 0.0) << sample.time_s;
      EXPECT_EQ(sample.yaw_rate_radps, 0.0) << sample.time_s;
    }
  }
  const TraceSample& at = gust.trace[30];  // 0.1 s after the step
  ASSERT_NEAR(at.time_s, 0.6, 1e-12);
  const double yaw_rate = 3000.0 / car.yaw_inertia_kgm2 * 0.1;
  EXPECT_NEAR(at.yaw_rate_radps, yaw_rate, 0.03 * yaw_rate);
  EXPECT_GT(at.lateral_velocity_mps, 0.0);
}

TEST(Crossfall, TheKinematicPlantRefusesForcesOnTheBody) {
  const KinematicVehicleModel plant{VehicleParameters{}};
  SimulationParameters sim;
  sim.duration_s = 0.1;
  sim.crossfall = 0.02;
  EXPECT_THROW(drive_straight(plant, sim), std::invalid_argument);
  sim.crossfall = 0.0;
  sim.side_force.force_n = 100.0;
  EXPECT_THROW(drive_straight(plant, sim), std::invalid_argument);
  sim.side_force.force_n = 0.0;
  sim.plant_scales.mass = 1.3;
  EXPECT_THROW(drive_straight(plant, sim), std::invalid_argument);
}

//! Steady yaw rate of the linear single-track model, r = v delta / (L + K v^2).
double steady_yaw_rate(const VehicleParameters& car, double speed_mps, double delta) {
  return speed_mps * delta /
         (car.wheelbase_m() + car.understeer_gradient() * speed_mps * speed_mps);
}

TEST(PlantScales, ChangeTheSteadyYawRateAsTheUndersteerGradientSays) {
  // Stiffer rear tires: an understeering car (the defaults' per-load stiffnesses are equal,
  // which makes K = 0, so that no mass would change the steady yaw rate).
  VehicleParameters told;
  told.front_tire.stiffness_factor_b = 11.0;
  ASSERT_GT(told.understeer_gradient(), 1e-3);
  const DynamicSingleTrack plant(told);
  constexpr double speed = 15.0, delta = 0.005;  // a_y 0.4 m/s^2: the tires' linear range
  struct Case {
    const char* what;
    PlantScales scales;
  };
  const Case cases[] = {
      {"nominal", {}},
      {"mass 1.3", {1.3, 1.0, 1.0, 1.0, 0.0}},
      {"cornering stiffness 0.75", {1.0, 1.0, 0.75, 1.0, 0.0}},
      {"CG 10 % forward", {1.0, 1.0, 1.0, 1.0, 0.1}},
      {"friction 0.6 (the slope stays)", {1.0, 1.0, 1.0, 0.6, 0.0}},
      {"yaw inertia 1.5 (no steady effect)", {1.0, 1.5, 1.0, 1.0, 0.0}},
  };
  const double nominal = steady_yaw_rate(told, speed, delta);
  for (const Case& c : cases) {
    const VehicleParameters truth = scaled_plant_vehicle(told, c.scales);
    SimulationParameters sim;
    sim.duration_s = 8.0;
    sim.plant_scales = c.scales;
    const SimulationResult result = drive_straight(plant, sim, delta, speed);
    const double expected = steady_yaw_rate(truth, speed, delta);
    EXPECT_NEAR(result.trace.back().yaw_rate_radps, expected, 0.005 * expected) << c.what;
    // The plant, not the given model, was scaled: the given model keeps its parameters.
    EXPECT_EQ(plant.parameters().mass_kg, told.mass_kg);
    if (std::string(c.what).rfind("mass", 0) == 0) {
      EXPECT_NEAR(truth.understeer_gradient(), 1.3 * told.understeer_gradient(), 1e-12);
      EXPECT_LT(expected, nominal * 0.98) << "an understeering car turns less when loaded";
    }
  }
}

TEST(PlantScales, RefuseACentreOfGravityBeyondAnAxle) {
  VehicleParameters car;
  car.cg_to_front_axle_m = 0.5;
  car.cg_to_rear_axle_m = 2.0;  // lf / L = 0.2
  try {
    (void)scaled_plant_vehicle(car, {1.0, 1.0, 1.0, 1.0, 0.25});
    FAIL() << "expected a refusal";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("plant_scales.cg_position = 0.25"), std::string::npos)
        << error.what();
  }
}

//! delta_actual of the third-order low-pass after a step of `size` at `start` [s].
double low_pass_step(const ActuatorParameters& a, double size, double start, double t) {
  if (t <= start) return 0.0;
  const double pt = a.pole_radps() * (t - start);
  return size * (1.0 - std::exp(-pt) * (1.0 + pt + 0.5 * pt * pt));
}

TEST(PlantActuatorScales, DelayAndSlowTheSimulatedActuatorOnly) {
  const DynamicSingleTrack plant{VehicleParameters{}};
  ActuatorParameters told;
  told.dead_time_s = 0.04;
  told.bandwidth_hz = 8.0;
  constexpr double step = 0.004;  // below the rate limit all along
  for (const PlantActuatorScales scales : {PlantActuatorScales{}, PlantActuatorScales{1.5, 0.5}}) {
    SimulationParameters sim;
    sim.duration_s = 0.4;
    sim.plant_actuator_scales = scales;
    const Path path = Path::straight_line({0, 0}, 0.0, 500.0);
    testing::ConstantSteering controller(step);
    const SimulationResult result = simulate(path, plant, told, SpeedProfile{10.0, 10.0, 0.0, 0.0},
                                             sim, {{0, 0}, 0.0}, controller);
    ActuatorParameters truth = told;
    truth.dead_time_s *= scales.dead_time;
    truth.bandwidth_hz *= scales.bandwidth;
    for (const TraceSample& sample : result.trace) {
      EXPECT_NEAR(sample.steering_actual_rad,
                  low_pass_step(truth, step, truth.dead_time_s, sample.time_s), 1e-7)
          << "t = " << sample.time_s << ", dead time x" << scales.dead_time;
    }
  }
}

//! Holds a steering angle and keeps every pose it is given.
class PoseRecorder final : public SteeringController {
 public:
  Status compute_command(const ControllerInput& input, ControllerOutput& output) noexcept override {
    output = ControllerOutput{};
    output.steering_angle_rad = 0.05;
    poses.push_back({input.rear_axle_position, input.heading_rad});
    return Status::ok;
  }
  Status reset(double) noexcept override {
    poses.clear();
    return Status::ok;
  }
  const char* name() const noexcept override { return "pose_recorder"; }
  std::vector<Pose2> poses;
};

TEST(PoseLatency, DeliversExactlyThePoseOfLatencyAgo) {
  const DynamicSingleTrack plant{VehicleParameters{}};
  const Path path = Path::straight_line({0, 0}, 0.0, 500.0);
  const Pose2 start{{1.0, 2.0}, 0.3};
  constexpr double speed = 12.0;
  SimulationParameters sim;
  sim.duration_s = 3.0;
  sim.pose_latency_s = 0.06;  // three control periods
  PoseRecorder recorder;
  const SimulationResult result =
      simulate(path, plant, ActuatorParameters{}, SpeedProfile{speed, speed, 0.0, 0.0}, sim, start,
               recorder);
  ASSERT_EQ(recorder.poses.size(), result.trace.size());
  for (std::size_t k = 3; k < result.trace.size(); ++k) {
    const Pose2& truth = result.trace[k - 3].rear_axle;
    EXPECT_EQ(recorder.poses[k].position.x, truth.position.x) << k;
    EXPECT_EQ(recorder.poses[k].position.y, truth.position.y) << k;
    EXPECT_EQ(recorder.poses[k].heading_rad, truth.heading_rad) << k;
  }
  // Before t = 0 the car drove straight at the start speed.
  for (std::size_t k = 0; k < 3; ++k) {
    const double back = (3.0 - static_cast<double>(k)) * sim.control_period_s * speed;
    EXPECT_NEAR(recorder.poses[k].position.x, start.position.x - back * std::cos(0.3), 1e-12);
    EXPECT_NEAR(recorder.poses[k].position.y, start.position.y - back * std::sin(0.3), 1e-12);
  }
  // Half a period more: halfway between two recorded poses.
  sim.pose_latency_s = 0.07;
  const SimulationResult later =
      simulate(path, plant, ActuatorParameters{}, SpeedProfile{speed, speed, 0.0, 0.0}, sim, start,
               recorder);
  for (std::size_t k = 4; k < later.trace.size(); ++k) {
    const Pose2& a = later.trace[k - 4].rear_axle;
    const Pose2& b = later.trace[k - 3].rear_axle;
    EXPECT_NEAR(recorder.poses[k].position.x, 0.5 * (a.position.x + b.position.x), 1e-9) << k;
    EXPECT_NEAR(recorder.poses[k].heading_rad, 0.5 * (a.heading_rad + b.heading_rad), 1e-12) << k;
  }
}

TEST(PoseLatency, ALowPoseRateHoldsTheLatePose) {
  const DynamicSingleTrack plant{VehicleParameters{}};
  const Path path = Path::straight_line({0, 0}, 0.0, 500.0);
  SimulationParameters sim;
  sim.duration_s = 2.0;
  sim.pose_latency_s = 0.04;
  sim.pose_rate_hz = 10.0;  // every fifth control step
  PoseRecorder recorder;
  const SimulationResult result = simulate(path, plant, ActuatorParameters{},
                                           SpeedProfile{10, 10, 0, 0}, sim, {{0, 0}, 0}, recorder);
  for (std::size_t k = 0; k < result.trace.size(); ++k) {
    const double t = result.trace[k].time_s;
    // The latest pose sampled at a multiple of 0.1 s that is at least the latency old.
    const long sampled = static_cast<long>(std::floor((t - 0.04) * 10.0 + 1e-9) * 5.0 + 0.5);
    if (sampled < 0) continue;
    EXPECT_EQ(recorder.poses[k].position.y,
              result.trace[static_cast<std::size_t>(sampled)].rear_axle.position.y)
        << "t = " << t;
  }
}

TEST(SensorImperfections, TheObserverReadsTheOffsetAngleAndTheBiasedGyro) {
  const VehicleParameters car;
  const DynamicSingleTrack plant(car);
  const Path path = Path::straight_line({0, 0}, 0.0, 2000.0);
  struct Observed {
    double slip, yaw_rate, steering_offset;
  };
  auto observed = [&](double angle_offset, double gyro_bias, double max_offset = 0.02) {
    SimulationParameters sim;
    sim.duration_s = 3.0;
    sim.side_slip.source = SideSlipSource::observer;
    sim.side_slip.max_steering_offset_rad = max_offset;
    sim.steering_angle_sensor_offset_rad = angle_offset;
    sim.gyro_bias_radps = gyro_bias;
    // The observer's own estimate: the course error estimator would take a biased slip back
    // from the pose (CourseError tests).
    sim.side_slip.estimate_course_error = false;
    testing::ConstantSteering controller(0.0);
    SteeringSystem system(controller,
                          steering_system_parameters(sim.side_slip, car, ActuatorParameters{}));
    const SimulationResult result = simulate(path, plant, ActuatorParameters{},
                                             SpeedProfile{15, 15, 0, 0}, sim, {{0, 0}, 0}, system);
    EXPECT_EQ(result.trace.back().yaw_rate_radps, 0.0);  // the car itself drives straight
    return Observed{result.trace.back().rear_side_slip_input_rad,
                    system.observer()->yaw_rate_radps(), system.observer()->steering_offset_rad()};
  };
  const Observed clean = observed(0.0, 0.0);
  EXPECT_EQ(clean.slip, 0.0);
  EXPECT_EQ(clean.yaw_rate, 0.0);
  EXPECT_EQ(clean.steering_offset, 0.0);
  // Told the wheels are steered 0.01 rad while the car drives straight, the observer learns a
  // steering offset of -0.01 rad and keeps the rear slip at 0; without the offset state it
  // believes a rear slip of several mrad.
  const Observed offset = observed(0.01, 0.0);
  EXPECT_NEAR(offset.steering_offset, -0.01, 5e-4);
  EXPECT_LT(std::abs(offset.slip), 2e-4);
  EXPECT_GT(std::abs(observed(0.01, 0.0, 0.0).slip), 1e-3);
  EXPECT_GT(observed(0.0, 0.01).yaw_rate, 0.002);  // it follows the gyro's bias in part
}

TEST(ImperfectionValidation, EveryOutOfRangeValueIsRefusedNamingItsField) {
  struct Bad {
    const char* field;
    void (*set)(SimulationParameters&);
  };
  const Bad cases[] = {
      {"plant_scales.mass", [](SimulationParameters& p) { p.plant_scales.mass = 2.5; }},
      {"plant_scales.yaw_inertia",
       [](SimulationParameters& p) { p.plant_scales.yaw_inertia = 0.4; }},
      {"plant_scales.cornering_stiffness",
       [](SimulationParameters& p) { p.plant_scales.cornering_stiffness = NAN; }},
      {"plant_scales.friction", [](SimulationParameters& p) { p.plant_scales.friction = 0.05; }},
      {"plant_scales.cg_position",
       [](SimulationParameters& p) { p.plant_scales.cg_position = 0.3; }},
      {"plant_actuator_scales.dead_time",
       [](SimulationParameters& p) { p.plant_actuator_scales.dead_time = 1.6; }},
      {"plant_actuator_scales.bandwidth",
       [](SimulationParameters& p) { p.plant_actuator_scales.bandwidth = 0.4; }},
      {"crossfall", [](SimulationParameters& p) { p.crossfall = -0.11; }},
      {"side_force.force_n", [](SimulationParameters& p) { p.side_force.force_n = 2e5; }},
      {"side_force.yaw_moment_nm",
       [](SimulationParameters& p) { p.side_force.yaw_moment_nm = INFINITY; }},
      {"side_force.start_s", [](SimulationParameters& p) { p.side_force.start_s = -1.0; }},
      {"pose_latency_s", [](SimulationParameters& p) { p.pose_latency_s = 0.51; }},
      {"pose_rate_hz", [](SimulationParameters& p) { p.pose_rate_hz = 51.0; }},
      {"pose_rate_hz", [](SimulationParameters& p) { p.pose_rate_hz = 0.5; }},
      {"steering_angle_sensor_offset_rad",
       [](SimulationParameters& p) { p.steering_angle_sensor_offset_rad = 0.2; }},
      {"gyro_bias_radps", [](SimulationParameters& p) { p.gyro_bias_radps = -0.6; }},
  };
  EXPECT_EQ(SimulationParameters{}.validation_error(), "");
  for (const Bad& bad : cases) {
    SimulationParameters p;
    bad.set(p);
    const std::string error = p.validation_error();
    EXPECT_NE(error.find(std::string("SimulationParameters: ") + bad.field + " = "),
              std::string::npos)
        << error;
    EXPECT_NE(error.find("must be in ["), std::string::npos) << error;
  }
  SimulationParameters at_the_limits;
  at_the_limits.pose_rate_hz = 50.0;
  at_the_limits.pose_latency_s = 0.5;
  at_the_limits.crossfall = 0.1;
  EXPECT_EQ(at_the_limits.validation_error(), "");
}

}  // namespace
}  // namespace smoothsteer
