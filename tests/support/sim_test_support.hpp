#pragma once
// Shared helpers of the simulation tests.

#include <cmath>
#include <random>

#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/vehicle/side_slip_observer.hpp"
#include "smoothsteer/vehicle/vehicle_model.hpp"

namespace smoothsteer::testing {

//! Holds a fixed steering angle (open loop).
class ConstantSteering final : public SteeringController {
 public:
  explicit ConstantSteering(double angle) : angle_(angle) {}
  Status compute_command(const ControllerInput&, ControllerOutput& output) noexcept override {
    output = ControllerOutput{};
    output.steering_angle_rad = angle_;
    output.derivatives_available = 2;
    return Status::ok;
  }
  Status reset(double) noexcept override { return Status::ok; }
  const char* name() const noexcept override { return "constant"; }

 private:
  double angle_;
};

//! The rear axle's course angle and speed: the direction and magnitude of its velocity.
struct RearAxleCourse {
  double angle_rad, speed_mps;
};
inline RearAxleCourse rear_axle_course(const VehicleParameters& car, const VehicleState& s) {
  const double lateral = s.vy_mps - car.cg_to_rear_axle_m * s.yaw_rate_radps;
  return {s.heading_rad + std::atan2(lateral, s.vx_mps), std::hypot(s.vx_mps, lateral)};
}

//! A random car as the single-track inversion models it: mass and axle positions drawn from
//! those of passenger cars and vans, the yaw inertia of two point masses on the axles, m lf lr
//! (docs/vehicle_dynamics.md, section 3; the shipped car's is within 0.3 % of it).
template <typename RandomSource>
VehicleParameters random_two_mass_car(RandomSource& random) {
  VehicleParameters car;
  car.mass_kg = random.uniform(900.0, 2500.0);
  car.cg_to_front_axle_m = random.uniform(1.0, 1.6);
  car.cg_to_rear_axle_m = random.uniform(1.0, 1.6);
  car.yaw_inertia_kgm2 = car.mass_kg * car.cg_to_front_axle_m * car.cg_to_rear_axle_m;
  return car;
}

//! One classic RK4 step of the vehicle model with the steering and the longitudinal
//! acceleration held.
inline VehicleState vehicle_rk4_step(const VehicleModel& model, const VehicleState& x, double delta,
                                     double h, double acceleration = 0.0) {
  auto add = [](const VehicleState& a, const VehicleState& b, double k) {
    return VehicleState{
        a.x_m + k * b.x_m,       a.y_m + k * b.y_m,       a.heading_rad + k * b.heading_rad,
        a.vx_mps + k * b.vx_mps, a.vy_mps + k * b.vy_mps, a.yaw_rate_radps + k * b.yaw_rate_radps};
  };
  const VehicleState k1 = model.derivative(x, delta, acceleration);
  const VehicleState k2 = model.derivative(add(x, k1, h / 2), delta, acceleration);
  const VehicleState k3 = model.derivative(add(x, k2, h / 2), delta, acceleration);
  const VehicleState k4 = model.derivative(add(x, k3, h), delta, acceleration);
  VehicleState out = x;
  out = add(out, k1, h / 6);
  out = add(out, k2, h / 3);
  out = add(out, k3, h / 3);
  out = add(out, k4, h / 6);
  return out;
}

//! What a car's sensors report at state x with the road-wheel angle delta: speed, a gyro with
//! 0.002 rad/s and an accelerometer at the CG with 0.05 m/s^2 of Gaussian noise.
inline SideSlipMeasurement noisy_slip_sensors(const VehicleModel& model, const VehicleState& x,
                                              double delta, std::mt19937_64& engine) {
  std::normal_distribution<double> normal(0.0, 1.0);
  const VehicleState rates = model.derivative(x, delta, 0.0);
  SideSlipMeasurement m;
  m.speed_mps = x.vx_mps;
  m.yaw_rate_radps = x.yaw_rate_radps + 0.002 * normal(engine);
  m.lateral_acceleration_mps2 = rates.vy_mps + x.vx_mps * x.yaw_rate_radps + 0.05 * normal(engine);
  m.steering_angle_rad = delta;
  return m;
}

}  // namespace smoothsteer::testing
