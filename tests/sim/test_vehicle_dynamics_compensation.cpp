// Vehicle-dynamics compensation (docs/vehicle_dynamics.md): the side-slip observer converges on
// the kinetic model, actuator inversion followed by the actuator reproduces the chain's angle,
// the friction guard holds, and every new parameter is named when it is wrong.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/controller/steering_certificate.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/sim/simulation.hpp"
#include "smoothsteer/vehicle/side_slip_observer.hpp"
#include "support/property.hpp"
#include "support/sim_test_support.hpp"

namespace smoothsteer {
namespace {

using testing::case_seed;
using testing::noisy_slip_sensors;
using testing::property_cases;
using testing::Random;
using testing::seed_message;
using testing::vehicle_rk4_step;

// Random manoeuvres of the kinetic (Pacejka) model: a steady turn at the start that the observer
// does not know, then sums of sines of the steering with lateral accelerations up to 5 m/s^2,
// noisy gyro and accelerometer. After 1.5 s the rear-axle slip estimate is within 15 % of the
// manoeuvre's largest slip plus 4 mrad, and its RMS error within 5 % plus 1 mrad, with either tire
// model.
TEST(SideSlipObserver, ConvergesOnRandomManoeuvresOfTheKineticModel) {
  const VehicleParameters car;
  const DynamicSingleTrack model(car);
  const int cases = property_cases(40);
  for (int c = 0; c < cases; ++c) {
    const std::uint64_t seed = case_seed(c);
    Random random(seed);
    const double speed = random.uniform(6.0, 25.0);
    // Steering amplitude for a_y <= 5 m/s^2 and at most 0.1 rad (the small-angle assumption).
    const double amplitude =
        std::min(0.1, 5.0 / (speed * speed) * car.wheelbase_m()) * random.uniform(0.3, 1.0);
    double frequency[3], phase[3], weight[3];
    for (int i = 0; i < 3; ++i) {
      frequency[i] = random.uniform(0.1, 1.2);
      phase[i] = random.uniform(0.0, 2.0 * pi);
      weight[i] = random.uniform(0.2, 1.0) / 3.0;
    }
    auto steering = [&](double t) {
      double delta = 0.0;
      for (int i = 0; i < 3; ++i)
        delta += weight[i] * std::sin(2 * pi * frequency[i] * t + phase[i]);
      return amplitude * delta;
    };
    // Settle a steady turn with the initial steering (unknown to the observer).
    VehicleState x{0.0, 0.0, 0.0, speed, 0.0, 0.0};
    for (int k = 0; k < 3000; ++k) x = vehicle_rk4_step(model, x, steering(0.0), 1e-3);
    // Both tire models on the same measurements: in this linear range they must both hold.
    const ObserverTireModel models[2] = {ObserverTireModel::linear,
                                         ObserverTireModel::magic_formula};
    SideSlipObserver observers[2] = {
        SideSlipObserver(SideSlipObserverParameters::from_vehicle(car, 1.0, 1.0, models[0])),
        SideSlipObserver(SideSlipObserverParameters::from_vehicle(car, 1.0, 1.0, models[1]))};
    double largest = 0.0, worst[2] = {0.0, 0.0}, sum_squares[2] = {0.0, 0.0};
    int counted = 0;
    const double period = 0.02;
    for (int k = 0; k <= 500; ++k) {
      const double t = k * period;
      const double delta = steering(t);
      const SideSlipMeasurement m = noisy_slip_sensors(model, x, delta, random.engine());
      const double truth = rear_axle_side_slip_angle(x, car);
      largest = std::max(largest, std::abs(truth));
      for (int i = 0; i < 2; ++i) {
        ASSERT_EQ(observers[i].update(m, period), Status::ok) << seed_message(seed);
        if (t >= 1.5) {
          const double error = std::abs(observers[i].rear_axle_side_slip_rad() - truth);
          worst[i] = std::max(worst[i], error);
          sum_squares[i] += error * error;
        }
      }
      if (t >= 1.5) ++counted;
      for (int j = 0; j < 20; ++j)
        x = vehicle_rk4_step(model, x, delta, 1e-3);  // held over the period
    }
    for (int i = 0; i < 2; ++i) {
      const char* name = i == 0 ? "linear" : "magic_formula";
      const double rms = std::sqrt(sum_squares[i] / counted);
      EXPECT_LE(worst[i], 0.15 * largest + 0.004)
          << name << ": v " << speed << " amplitude " << amplitude << " largest slip " << largest
          << "; " << seed_message(seed);
      EXPECT_LE(rms, 0.05 * largest + 0.001)
          << name << ": v " << speed << " amplitude " << amplitude << "; " << seed_message(seed);
    }
  }
}

// A NaN gyro or accelerometer sample is a dropped sample: the filter predicts that channel and
// counts it (sensor_fault_gate.hpp). What it cannot do without (speed, steering angle, period)
// is refused, and then nothing changes.
TEST(SideSlipObserver, DropsNonFiniteSamplesAndRefusesNonFiniteInputs) {
  SideSlipObserver observer(SideSlipObserverParameters::from_vehicle(VehicleParameters{}));
  SideSlipMeasurement m{15.0, 0.1, 1.5, 0.02};
  ASSERT_EQ(observer.update(m, 0.02), Status::ok);
  m.lateral_acceleration_mps2 = std::nan("");
  EXPECT_EQ(observer.update(m, 0.02), Status::ok);
  EXPECT_EQ(observer.health().lateral_acceleration_dropped, 1u);
  EXPECT_EQ(observer.health().last_period, fault_lateral_acceleration_dropped);
  EXPECT_TRUE(std::isfinite(observer.rear_axle_side_slip_rad()));
  m.lateral_acceleration_mps2 = 1.5;
  const double before = observer.rear_axle_side_slip_rad();
  EXPECT_EQ(observer.update(m, 0.0), Status::invalid_input);
  m.speed_mps = std::nan("");
  EXPECT_EQ(observer.update(m, 0.02), Status::invalid_input);
  m.speed_mps = 15.0;
  m.steering_angle_rad = std::nan("");
  EXPECT_EQ(observer.update(m, 0.02), Status::invalid_input);
  EXPECT_EQ(observer.rear_axle_side_slip_rad(), before);
}

// Inversion: a controller with actuator_time_constant_s = T commands delta + 3 T delta' for the
// three-lag actuator (1 + T s)^3. Replayed on the same poses, the actuator's output then follows
// the uninverted controller's angle (what the chain asks for) within the truncation error
// 3 T^2 max |delta''| + 1 mrad, and about 3 times closer than without (worst and RMS).
TEST(ActuatorInversion, TheActuatorReproducesTheChainAngle) {
  const VehicleParameters car;
  auto path = std::make_shared<const Path>(
      PathBuilder({0, 0}, 0.0).line(20).arc(25, pi / 2).arc(25, -pi / 2).line(40).build());
  ControllerParameters p = ControllerParameters::paper_c1(car.wheelbase_m(), 0.8, 0.12, 0.3);
  ActuatorParameters a;
  a.bandwidth_hz = 3.0;  // T = 0.027 s: a slow actuator, the inversion's use case
  a.dead_time_s = 0.0;
  a.max_rate_radps = 10.0;
  const double lag = 1.0 / a.pole_radps();
  ControllerParameters inverted = p;
  inverted.actuator_inversion.time_constant_s = lag;
  inverted.actuator_inversion.enabled = lag > 0.0;
  // Poses of a closed loop of the plain controller on the kinematic model.
  LeadWheelController plain(p, path);
  KinematicVehicleModel model(car);
  SimulationParameters sim;
  sim.duration_s = 12.0;
  ActuatorParameters ideal;
  ideal.ideal = true;
  ideal.dead_time_s = 0.0;
  const SimulationResult run =
      simulate(*path, model, ideal, SpeedProfile{8.0, 8.0}, sim, {{0.0, 0.3}, 0.0}, plain);
  ASSERT_EQ(run.status, Status::ok);
  LeadWheelController reference(p, path), with(inverted, path);
  SteeringActuator with_inversion(a, sim.substep_s), without_inversion(a, sim.substep_s);
  with_inversion.reset(0.0);
  without_inversion.reset(0.0);
  double error_with = 0.0, error_without = 0.0, squares_with = 0.0, squares_without = 0.0;
  double largest_acceleration = 0.0;
  int counted = 0;
  double previous_reference = 0.0;
  for (const TraceSample& sample : run.trace) {
    ControllerInput input{sample.rear_axle.position, sample.rear_axle.heading_rad, sample.speed_mps,
                          0.0, sim.control_period_s};
    ControllerOutput out_reference, out_with;
    ASSERT_EQ(reference.update(input, out_reference), Status::ok);
    ASSERT_EQ(with.update(input, out_with), Status::ok);
    EXPECT_EQ(out_with.derivatives_available, 1);
    largest_acceleration =
        std::max(largest_acceleration, std::abs(out_reference.steering_acceleration_radps2));
    if (sample.time_s > 1.0) {
      // The actuator's output now against the chain's angle half a period ago (the hold).
      const double target = 0.5 * (out_reference.steering_angle_rad + previous_reference);
      error_with = std::max(error_with, std::abs(with_inversion.angle() - target));
      error_without = std::max(error_without, std::abs(without_inversion.angle() - target));
      squares_with += std::pow(with_inversion.angle() - target, 2);
      squares_without += std::pow(without_inversion.angle() - target, 2);
      ++counted;
    }
    previous_reference = out_reference.steering_angle_rad;
    for (int j = 0; j < 20; ++j) {
      with_inversion.step(out_with.steering_angle_rad);
      without_inversion.step(out_reference.steering_angle_rad);
    }
  }
  const double rms_with = std::sqrt(squares_with / counted);
  const double rms_without = std::sqrt(squares_without / counted);
  // n = 2 drops the a2 = 3 T^2 term: the residual is about a2 max |delta''| (+1 mrad for the
  // hold and the a3 term).
  const double tolerance = 3.0 * lag * lag * largest_acceleration + 0.001;
  EXPECT_LT(error_with, tolerance) << "largest delta'' " << largest_acceleration;
  EXPECT_LT(error_with, 0.35 * error_without)
      << "with " << error_with << " without " << error_without;
  EXPECT_LT(rms_with, 0.3 * rms_without) << "rms with " << rms_with << " without " << rms_without;
}

// Friction guard: on circles that ask 1.2-2.5 times the allowed lateral acceleration, the rear
// axle's curvature of the command, tan(delta) / L, never asks more than a_max / v^2 (1 %).
TEST(FrictionGuard, TheCommandNeverAsksMoreThanTheLimit) {
  const VehicleParameters car;
  const int cases = property_cases(30);
  for (int c = 0; c < cases; ++c) {
    const std::uint64_t seed = case_seed(c);
    Random random(seed);
    const double limit = random.uniform(2.0, 8.0);
    const double radius = random.uniform(15.0, 80.0);
    const double speed = std::sqrt(random.uniform(1.2, 2.5) * limit * radius);
    auto path = std::make_shared<const Path>(
        PathBuilder({0, 0}, 0.0).line(10).arc(radius, random.coin() ? pi : -pi).build());
    ControllerParameters p = ControllerParameters::paper_c1(car.wheelbase_m(), 0.8, 0.2, 0.3);
    p.feedforward.share = 0.6;
    p.friction_guard = {.enabled = std::isfinite(limit), .max_lateral_acceleration_mps2 = limit};
    LeadWheelController controller(p, path);
    KinematicVehicleModel model(car);
    SimulationParameters sim;
    sim.duration_s = pi * radius / speed;
    ActuatorParameters ideal;
    ideal.ideal = true;
    ideal.dead_time_s = 0.0;
    const SimulationResult run = simulate(*path, model, ideal, SpeedProfile{speed, speed}, sim,
                                          {{0.0, 0.0}, 0.0}, controller);
    ASSERT_EQ(run.status, Status::ok) << seed_message(seed);
    double worst = 0.0;
    for (const TraceSample& s : run.trace) {
      worst = std::max(
          worst, speed * speed * std::tan(std::abs(s.steering_command_rad)) / car.wheelbase_m());
    }
    EXPECT_LE(worst, 1.01 * limit)
        << "a_max " << limit << " R " << radius << " v " << speed << "; " << seed_message(seed);
    EXPECT_GE(worst, 0.9 * limit) << "the guard should let the car use its tires; "
                                  << seed_message(seed);
  }
}

TEST(VehicleDynamicsValidation, EveryNewParameterIsNamed) {
  auto controller_error = [](auto change) {
    ControllerParameters p;
    change(p);
    return p.validation_error();
  };
  EXPECT_NE(controller_error([](ControllerParameters& p) {
              p.single_track.preview_time_s = -1;
            }).find("preview_time_s"),
            std::string::npos);
  EXPECT_NE(controller_error([](ControllerParameters& p) {
              p.single_track.rear_slip_gradient_s2pm = 1;
            }).find("rear_slip_gradient_s2pm"),
            std::string::npos);
  EXPECT_NE(controller_error([](ControllerParameters& p) {
              p.single_track.front_slip_gradient_s2pm = -0.01;
            }).find("front_slip_gradient_s2pm"),
            std::string::npos);
  EXPECT_NE(controller_error([](ControllerParameters& p) {
              p.friction_guard.max_lateral_acceleration_mps2 = 0;
            }).find("max_lateral_acceleration_mps2"),
            std::string::npos);
  EXPECT_NE(controller_error([](ControllerParameters& p) {
              p.actuator_inversion.time_constant_s = 1;
            }).find("actuator_time_constant_s"),
            std::string::npos);
  EXPECT_NE(controller_error([](ControllerParameters& p) {
              p.actuator_inversion.lag_count = 4;
            }).find("actuator_lag_count"),
            std::string::npos);
  SideSlipObserverParameters observer;
  observer.rear_cornering_stiffness_npr = std::nan("");
  EXPECT_NE(observer.validation_error().find("rear_cornering_stiffness_npr"), std::string::npos);
  EXPECT_THROW(SideSlipObserver{observer}, std::invalid_argument);
  observer = {};
  observer.min_speed_mps = 0.0;
  EXPECT_NE(observer.validation_error().find("min_speed_mps"), std::string::npos);
  SimulationParameters sim;
  sim.side_slip.mass_scale = 9.0;
  EXPECT_NE(sim.validation_error().find("side_slip.mass_scale"), std::string::npos);
  sim = {};
  sim.side_slip.source = static_cast<SideSlipSource>(7);
  EXPECT_NE(sim.validation_error().find("side_slip.source"), std::string::npos);
  sim = {};
  sim.side_slip.lateral_acceleration_noise_std_mps2 = -1.0;
  EXPECT_NE(sim.validation_error().find("side_slip.lateral_acceleration_noise_std_mps2"),
            std::string::npos);
  // A slip input the controller cannot use is refused, not steered on.
  auto path = std::make_shared<const Path>(Path::straight_line({0, 0}, 0.0));
  LeadWheelController controller(ControllerParameters{}, path);
  ControllerInput input{{0, 0}, 0.0, 10.0, 0.0, 0.02};
  input.rear_axle_side_slip_rad = 0.6;
  ControllerOutput output;
  EXPECT_EQ(controller.update(input, output), Status::invalid_input);
  input.rear_axle_side_slip_rad = std::nan("");
  EXPECT_EQ(controller.update(input, output), Status::invalid_input);
}

}  // namespace
}  // namespace smoothsteer

namespace smoothsteer {
namespace {

// A constant curvature disturbance on the PLANT's rear axle (not injected into
// the controller's model). disturbance_estimation_length_m estimates it to within 3 %, and the
// feedforward absorbs it: the steady rear-axle offset shrinks by at least a quarter (typically
// 30-60 %). It does not vanish (docs/feedforward.md, "disturbances on the vehicle", says why this
// is still open).
TEST(PlantDisturbance, EstimationFindsTheDisturbanceAndRemovesTheOffset) {
  const VehicleParameters car;
  const int cases = testing::property_cases(20);
  for (int c = 0; c < cases; ++c) {
    const std::uint64_t seed = testing::case_seed(c);
    testing::Random random(seed);
    const bool circle = random.coin();
    const double radius = random.uniform(40.0, 100.0);
    auto path = std::make_shared<const Path>(
        circle ? PathBuilder({0, 0}, 0.0).line(5.0).arc(radius, 1.5 * pi).build()
               : PathBuilder({0, 0}, 0.0).line(400.0).build());
    // n = 2 (the paper's C^1 controller) or n = 3 (its chain with one more lag, lambda_1 from
    // eq. cornering_constr), where the defaults left 32 and 53 cm at 0.9 k_rob kbar.
    ControllerParameters p = ControllerParameters::paper_c1(car.wheelbase_m(), 1.0, 0.1, 0.3);
    if (random.coin()) {
      p.chain.order = 3;
      p.chain.wheelbases_m[1] = 0.8;
      p.chain.wheelbases_m[2] = 0.6;
      p.chain.wheelbases_m[0] = cornering_front_wheelbase(car.wheelbase_m(), 0.8 * 0.8 + 0.6 * 0.6);
    }
    p.feedforward.share = 0.6;
    p.feedforward.curvature_rate = 0.01;
    p.feedforward.cornering_target = CorneringTarget::rear_axle;
    const double disturbance =
        (random.coin() ? 1.0 : -1.0) * random.uniform(0.2, 0.9) * p.switching_curvature_bound();
    const double speed = random.uniform(3.0, 8.0);
    struct Outcome {
      double offset, estimate;
    };
    auto run_with = [&](double estimation_length) {
      ControllerParameters q = p;
      q.disturbance_estimation = {.enabled = estimation_length > 0.0,
                                  .length_m = estimation_length};
      LeadWheelController controller(q, path);
      KinematicVehicleModel model(car);
      SimulationParameters sim;
      sim.duration_s = 150.0 / speed;
      sim.plant_curvature_disturbance = disturbance;
      ActuatorParameters ideal;
      ideal.ideal = true;
      ideal.dead_time_s = 0.0;
      const SimulationResult run = simulate(*path, model, ideal, SpeedProfile{speed, speed}, sim,
                                            {{0.0, 0.0}, 0.0}, controller);
      EXPECT_EQ(run.status, Status::ok) << testing::seed_message(seed);
      EXPECT_EQ(run.stop_reason, "duration") << testing::seed_message(seed);
      return Outcome{std::abs(run.trace.back().lateral_error_m), controller.disturbance_estimate()};
    };
    const Outcome without = run_with(0.0);
    const Outcome with = run_with(5.0);
    const std::string inputs = "kappa_d " + std::to_string(disturbance) + " n " +
                               std::to_string(p.chain.order) + (circle ? " circle R " : " line ") +
                               std::to_string(radius) + " v " + std::to_string(speed) + "; " +
                               testing::seed_message(seed);
    EXPECT_NEAR(with.estimate, disturbance, 0.03 * std::abs(disturbance)) << inputs;
    // The target's heading carries the chain's steady cross-track angle kappa_d l
    // (lead_wheel_target.cpp, target_curve): the offset goes, not only a part of it
    // (at most 3.2 % and 4.9 mm over 300 seeds).
    EXPECT_LT(with.offset, 0.05 * without.offset)
        << "with " << with.offset << " without " << without.offset << "; " << inputs;
    EXPECT_LT(with.offset, 0.008) << "without " << without.offset << "; " << inputs;
  }
}

}  // namespace
}  // namespace smoothsteer
