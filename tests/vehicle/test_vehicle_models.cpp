// Kinetic single-track model: linear-bicycle steady state, straight driving, no NaN, blending.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "smoothsteer/sim/simulation.hpp"
#include "support/property.hpp"
#include "support/sim_test_support.hpp"

namespace smoothsteer {
namespace {

using testing::case_seed;
using testing::ConstantSteering;
using testing::property_cases;
using testing::Random;
using testing::seed_message;

SimulationParameters open_loop(double duration) {
  SimulationParameters p;
  p.duration_s = duration;
  p.stop_at_path_end = false;
  return p;
}

ActuatorParameters ideal_actuator() {
  ActuatorParameters a;
  a.ideal = true;
  a.dead_time_s = 0.0;
  return a;
}

// Rajamani eq. 3.23 per axle: delta_ss = L / R + K a_y, i.e. yaw-rate gain r / delta =
// vx / (L + K vx^2) with K = m/L (lr/Cf - lf/Cr) and Cf, Cr = B C D of the Magic Formula.
TEST(DynamicSingleTrack, SmallSlipSteadyStateMatchesLinearUndersteerGradient) {
  const Path path = Path::straight_line({0, 0}, 0.0, 1000.0);
  for (int k = 0; k < property_cases(12); ++k) {
    const auto seed = case_seed(k);
    Random random(seed);
    VehicleParameters car;
    car.mass_kg = random.uniform(900.0, 2200.0);
    car.yaw_inertia_kgm2 = car.mass_kg * random.uniform(1.2, 2.0);
    car.cg_to_front_axle_m = random.uniform(1.0, 1.6);
    car.cg_to_rear_axle_m = random.uniform(1.0, 1.6);
    car.front_tire.stiffness_factor_b = random.uniform(8.0, 20.0);
    car.rear_tire.stiffness_factor_b = random.uniform(8.0, 20.0);
    const double speed = random.uniform(6.0, 20.0);
    const double wheelbase = car.wheelbase_m();
    const double gradient = car.understeer_gradient();
    const double denominator = wheelbase + gradient * speed * speed;
    if (denominator < 0.5 * wheelbase) continue;  // too close to the oversteer critical speed
    // Small slip: lateral acceleration 0.3 m/s^2.
    const double delta = 0.3 * denominator / (speed * speed);
    DynamicSingleTrack model(car);
    SpeedProfile profile{speed, speed, 0.0, 0.0};
    ConstantSteering controller(delta);
    const SimulationResult result = simulate(path, model, ideal_actuator(), profile,
                                             open_loop(15.0), {{0, 0}, 0.0}, controller);
    ASSERT_FALSE(result.non_finite) << seed_message(seed);
    const double expected = speed * delta / denominator;
    EXPECT_NEAR(result.final_state.yaw_rate_radps / expected, 1.0, 0.02)
        << seed_message(seed) << " K = " << gradient << " v = " << speed;
  }
}

TEST(DynamicSingleTrack, ZeroSteeringDrivesStraight) {
  const Path path = Path::straight_line({0, 0}, 0.0, 1000.0);
  for (int k = 0; k < property_cases(10); ++k) {
    const auto seed = case_seed(k);
    Random random(seed);
    const double heading = random.uniform(-3.0, 3.0);
    const double speed = random.uniform(0.5, 30.0);
    DynamicSingleTrack model(VehicleParameters{});
    ConstantSteering controller(0.0);
    SpeedProfile profile{speed, speed, 0.0, 0.0};
    const SimulationResult result = simulate(path, model, ideal_actuator(), profile, open_loop(5.0),
                                             {{1.0, 2.0}, heading}, controller);
    const Pose2 end = rear_axle_pose(result.final_state, model.parameters());
    EXPECT_NEAR(end.heading_rad, heading, 1e-12) << seed_message(seed);
    const Vec2 moved = end.position - Vec2{1.0, 2.0};
    EXPECT_NEAR(cross(unit_from_heading(heading), moved), 0.0, 1e-9) << seed_message(seed);
    EXPECT_NEAR(dot(unit_from_heading(heading), moved), speed * 5.0, 1e-6) << seed_message(seed);
    EXPECT_EQ(result.final_state.vy_mps, 0.0);
  }
}

TEST(DynamicSingleTrack, LongRunsWithLargeSteeringProduceNoNaN) {
  const Path path = Path::straight_line({0, 0}, 0.0, 1000.0);
  for (int k = 0; k < property_cases(6); ++k) {
    const auto seed = case_seed(k);
    Random random(seed);
    ActuatorParameters actuator;  // saturating third-order actuator
    SimulationParameters parameters = open_loop(120.0);
    parameters.position_noise_std_m = 0.05;
    DynamicSingleTrack model(VehicleParameters{});
    ConstantSteering controller(random.uniform(-1.5, 1.5));
    SpeedProfile profile{random.uniform(0.2, 3.0), random.uniform(10.0, 30.0),
                         random.uniform(0.5, 3.0), random.uniform(0.0, 10.0)};
    const SimulationResult result =
        simulate(path, model, actuator, profile, parameters, {{0, 0}, 0.0}, controller);
    EXPECT_FALSE(result.non_finite) << seed_message(seed);
    EXPECT_EQ(result.stop_reason, "duration") << seed_message(seed);
    // The actuator saturates the angle at the car's limit.
    EXPECT_LE(std::abs(result.trace.back().steering_actual_rad), actuator.max_angle_rad + 1e-12);
  }
}

TEST(DynamicSingleTrack, BlendsToKinematicAtLowSpeed) {
  VehicleParameters car;
  DynamicSingleTrack dynamic(car);
  KinematicVehicleModel kinematic(car);
  VehicleState state{0, 0, 0.3, 0.5, 0.0, 0.0};
  kinematic.constrain(state, 0.2);
  const VehicleState a = dynamic.derivative(state, 0.2, 0.0);
  const VehicleState b = kinematic.derivative(state, 0.2, 0.0);
  // Below kinematic_below_mps, on the kinematic manifold, both models agree exactly.
  EXPECT_NEAR(a.x_m, b.x_m, 1e-12);
  EXPECT_NEAR(a.y_m, b.y_m, 1e-12);
  EXPECT_NEAR(a.heading_rad, b.heading_rad, 1e-12);
  EXPECT_NEAR(a.vy_mps, 0.0, 1e-12);
  EXPECT_NEAR(a.yaw_rate_radps, 0.0, 1e-12);
}

// Rajamani eqs. 4.17-4.18 without aerodynamics and grade: Fz_f = m (g lr - a_x h) / L,
// Fz_r = m (g lf + a_x h) / L; their sum stays the weight while neither reaches 0.
TEST(VehicleParameters, AxleLoadsShiftWithTheLongitudinalAcceleration) {
  for (int k = 0; k < property_cases(40); ++k) {
    const auto seed = case_seed(k);
    Random random(seed);
    VehicleParameters car;
    car.mass_kg = random.uniform(500.0, 3000.0);
    car.cg_to_front_axle_m = random.uniform(0.8, 2.0);
    car.cg_to_rear_axle_m = random.uniform(0.8, 2.0);
    car.cg_height_m = random.uniform(0.0, 1.2);
    const double ax = random.uniform(-10.0, 10.0);
    const double L = car.wheelbase_m(), m = car.mass_kg, g = car.gravity_mps2;
    const double front = m * (g * car.cg_to_rear_axle_m - ax * car.cg_height_m) / L;
    const double rear = m * (g * car.cg_to_front_axle_m + ax * car.cg_height_m) / L;
    EXPECT_NEAR(car.front_axle_load_n(ax), std::max(0.0, front), 1e-9 * m * g)
        << seed_message(seed);
    EXPECT_NEAR(car.rear_axle_load_n(ax), std::max(0.0, rear), 1e-9 * m * g) << seed_message(seed);
    if (front > 0.0 && rear > 0.0) {
      EXPECT_NEAR(car.front_axle_load_n(ax) + car.rear_axle_load_n(ax), m * g, 1e-9 * m * g)
          << seed_message(seed);
    }
  }
  const VehicleParameters car;
  EXPECT_EQ(car.front_axle_load_n(0.0), car.front_axle_load_n());
  EXPECT_EQ(car.front_axle_load_n(1e4), 0.0);  // a wheelie: the front axle lifts
}

TEST(VehicleParameters, ValidationNamesFieldValueAndRule) {
  VehicleParameters car;
  car.mass_kg = -3.0;
  const std::string message = car.validation_error();
  EXPECT_NE(message.find("mass_kg"), std::string::npos);
  EXPECT_NE(message.find("-3"), std::string::npos);
  EXPECT_NE(message.find("> 0"), std::string::npos);
  EXPECT_THROW(DynamicSingleTrack{car}, std::invalid_argument);
}

}  // namespace
}  // namespace smoothsteer
