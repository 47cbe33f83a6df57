// The single-track inversion under longitudinal acceleration (SingleTrackInversion, load
// transfer): braking moves load to the front axle, whose cornering stiffness grows with it, and
// the car turns more for the same steering. The inversion's gain, built from the vehicle file
// (inversion_slip_gradients, inversion_load_transfer), must predict the steering the Magic
// Formula plant (DynamicSingleTrack, axle loads at a_x) needs for a rear-axle course curvature,
// in the tires' linear range, while braking and accelerating.

#include <gtest/gtest.h>

#include <cmath>

#include "smoothsteer/controller/dynamics_inversion.hpp"
#include "smoothsteer/tuning/vehicle_steering_system.hpp"
#include "smoothsteer/vehicle/vehicle_model.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

using testing::case_seed;
using testing::property_cases;
using testing::Random;
using testing::seed_message;

//! The plant's lateral steady state at speed v and steering delta with the axle loads of a_x
//! (the speed held: only vy and r are integrated, RK4), as the rear axle's course curvature.
double plant_rear_course_curvature(const VehicleParameters& car, double v, double delta,
                                   double ax) {
  const DynamicSingleTrack model(car);
  VehicleState s;
  s.vx_mps = v;
  const double dt = 1e-3;
  const auto rates = [&](const VehicleState& at) { return model.derivative(at, delta, ax); };
  for (int i = 0; i < 20000; ++i) {
    const VehicleState k1 = rates(s);
    VehicleState m = s;
    m.vy_mps = s.vy_mps + 0.5 * dt * k1.vy_mps;
    m.yaw_rate_radps = s.yaw_rate_radps + 0.5 * dt * k1.yaw_rate_radps;
    const VehicleState k2 = rates(m);
    m.vy_mps = s.vy_mps + 0.5 * dt * k2.vy_mps;
    m.yaw_rate_radps = s.yaw_rate_radps + 0.5 * dt * k2.yaw_rate_radps;
    const VehicleState k3 = rates(m);
    m.vy_mps = s.vy_mps + dt * k3.vy_mps;
    m.yaw_rate_radps = s.yaw_rate_radps + dt * k3.yaw_rate_radps;
    const VehicleState k4 = rates(m);
    s.vy_mps += dt / 6.0 * (k1.vy_mps + 2.0 * k2.vy_mps + 2.0 * k3.vy_mps + k4.vy_mps);
    s.yaw_rate_radps += dt / 6.0 * (k1.yaw_rate_radps + 2.0 * k2.yaw_rate_radps +
                                    2.0 * k3.yaw_rate_radps + k4.yaw_rate_radps);
  }
  // In the steady state the rear axle's velocity keeps its angle to the body: its course turns
  // at the yaw rate.
  const double rear_lateral = s.vy_mps - car.cg_to_rear_axle_m * s.yaw_rate_radps;
  return s.yaw_rate_radps / std::hypot(v, rear_lateral);
}

SingleTrackInversion inversion_of(const VehicleParameters& car, bool load_transfer) {
  const InversionSlipGradients gradients = inversion_slip_gradients(car);
  const LoadTransfer transfer = load_transfer ? inversion_load_transfer(car) : LoadTransfer{};
  return {.enabled = true,
          .rear_slip_gradient_s2pm = gradients.rear_s2pm,
          .front_slip_gradient_s2pm = gradients.front_s2pm,
          .front_load_transfer_s2pm = transfer.front_s2pm,
          .rear_load_transfer_s2pm = transfer.rear_s2pm};
}

TEST(LoadTransferInversion, GainPredictsThePlantsSteeringWhileBrakingAndAccelerating) {
  int checked = 0;
  for (int k = 0; k < property_cases(24); ++k) {
    const auto seed = case_seed(k);
    Random random(seed);
    VehicleParameters car;
    car.mass_kg = random.uniform(900.0, 2500.0);
    car.yaw_inertia_kgm2 = car.mass_kg * random.uniform(1.2, 2.0);
    car.cg_to_front_axle_m = random.uniform(1.0, 1.6);
    car.cg_to_rear_axle_m = random.uniform(1.0, 1.6);
    car.cg_height_m = random.uniform(0.4, 1.0);
    car.front_tire.stiffness_factor_b = random.uniform(10.0, 20.0);
    car.rear_tire.stiffness_factor_b = random.uniform(10.0, 20.0);
    const double v = random.uniform(8.0, 30.0);
    const double ax = random.uniform(-4.0, 3.0);
    const double wheelbase = car.wheelbase_m();
    DynamicsInversion inversion;
    inversion.update(inversion_of(car, true), v, wheelbase, ax);
    // Far from the oversteer critical speed and from the gain's floor of 0.5.
    if (inversion.gain < 0.7) continue;
    ++checked;
    // Lateral acceleration about 0.3 m/s^2: the Magic Formula's linear range.
    const double delta = 0.3 * wheelbase * inversion.gain / (v * v);
    const double curvature = plant_rear_course_curvature(car, v, delta, ax);
    const double predicted = std::atan(wheelbase * inversion.gain * curvature);
    EXPECT_NEAR(predicted / delta, 1.0, 0.02)
        << seed_message(seed) << " v = " << v << " a_x = " << ax << " h = " << car.cg_height_m
        << " gain = " << inversion.gain;
  }
  EXPECT_GT(checked, property_cases(24) / 2);
}

TEST(LoadTransferInversion, WithoutAccelerationTheGainIsTheStaticOne) {
  const VehicleParameters car;
  const double v = 20.0, wheelbase = car.wheelbase_m();
  DynamicsInversion with_transfer, without_transfer;
  with_transfer.update(inversion_of(car, true), v, wheelbase, 0.0);
  without_transfer.update(inversion_of(car, false), v, wheelbase, 0.0);
  EXPECT_EQ(with_transfer.gain, without_transfer.gain);
  EXPECT_EQ(with_transfer.slip_lag_m, without_transfer.slip_lag_m);
  EXPECT_EQ(with_transfer.bend_m2, without_transfer.bend_m2);
  // Braking at 3 m/s^2 the passenger car oversteers: the gain falls below the static one.
  with_transfer.update(inversion_of(car, true), v, wheelbase, -3.0);
  EXPECT_LT(with_transfer.gain, without_transfer.gain - 0.1);
}

TEST(LoadTransferInversion, AnAxleKeepsAQuarterOfItsLoad) {
  const VehicleParameters car;
  const SingleTrackInversion inversion = inversion_of(car, true);
  const double v = 20.0, wheelbase = car.wheelbase_m();
  // Accelerating at 1e4 m/s^2 (the input range's bound) would unload the front axle completely
  // and load the rear one 500 times: the front slip gradient stops at 4 K_f, the rear one is
  // nearly 0.
  DynamicsInversion hard;
  hard.update(inversion, v, wheelbase, 1e4);
  EXPECT_NEAR(hard.gain,
              1.0 + 4.0 * inversion.front_slip_gradient_s2pm * v * v / wheelbase, 2e-3);
}

}  // namespace
}  // namespace smoothsteer
