#pragma once
// Plant integration of the closed-loop simulation over one control period (internal to
// src/sim). Methods (PlantIntegrator):
//   - fixed_rk4: classic RK4 of the vehicle at the sub-step, the actuator by RK4 at the same
//     step (the method of earlier releases, kept as the reference);
//   - rkf78 and dopri5: the actuator solved exactly, rate and angle saturation included
//     (exact_actuator.hpp: closed-form lags, the instants where a saturation begins or ends
//     located on that solution), the vehicle by the embedded Runge-Kutta pair Fehlberg 7(8) or
//     Dormand-Prince 5(4) with error control (Boost.Odeint), restarted at every control instant
//     and at those instants and the speed ramp's kinks.
// docs/simulation.md describes both; docs/benchmarks.md compares them.

#include <array>
#include <cstdint>

#include "smoothsteer/sim/simulation.hpp"

namespace smoothsteer::detail {

//! What one control period of plant integration needs besides the state.
struct PlantContext {
  const VehicleModel& model;
  const SpeedProfile& speed;
  SteeringActuator& actuator;
  double plant_disturbance = 0.0;  //!< matched disturbance applied in the plant [1/m]
  double substep_s = 0.001;
  int substeps = 20;
  PlantIntegrator integrator = PlantIntegrator::fixed_rk4;
  double tolerance = 1e-8;
  std::uint64_t* model_evaluations = nullptr;
  std::uint64_t* fallback_periods = nullptr;  //!< periods left to fixed_rk4 by rkf78 / dopri5
  double* input_buffer = nullptr;             //!< room for `substeps` delayed inputs
  double steering_offset_rad = 0.0;           //!< the road wheels steer delta + this [rad]
  //! Lateral acceleration of the crossfall on the body, -g sin(phi) [m/s^2].
  double crossfall_acceleration_mps2 = 0.0;
  SideForce side_force;  //!< on the body from side_force.start_s on
  //! Whether the two above act (false: the model's derivative as it is).
  bool external() const noexcept {
    return crossfall_acceleration_mps2 != 0.0 || side_force.active();
  }
};

//! The angle the plant's road wheels steer for the actuator's `delta`: with the rack offset and
//! the matched disturbance of `c`.
double plant_steering_angle(const PlantContext& c, double delta) noexcept;

//! What the crossfall (with_crossfall) and the side force of `c` add to the body's lateral
//! acceleration [m/s^2] and yaw acceleration [rad/s^2] at time t, faded out with the model's
//! blend to the kinematic model at low speed (a car at rest on a cross slope does not slide).
struct BodyAcceleration {
  double lateral = 0.0;
  double yaw = 0.0;
};
BodyAcceleration body_acceleration(const PlantContext& c, const VehicleState& state, double t,
                                   bool with_crossfall) noexcept;

//! The model's derivative with the crossfall and the side force of `c` at time `t` added. The
//! integrators pass the middle of the piece they integrate (split at the side force's start),
//! as for the speed profile's acceleration: a step read at a stage time on the piece's end
//! would leak into the piece before it.
VehicleState plant_derivative(const PlantContext& c, const VehicleState& state, double delta,
                              double acceleration, double t) noexcept;

//! Advances the vehicle state, the actuator (its delay line included) and the travelled
//! distance of the rear axle over one control period from time t with the held command.
//! Returns the last delayed actuator input (for the actuator's rate at the next sample).
double advance_plant(const PlantContext& context, double t, double command, VehicleState& state,
                     double& distance_m) noexcept;

}  // namespace smoothsteer::detail
