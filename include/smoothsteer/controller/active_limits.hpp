#pragma once
//! \file active_limits.hpp
//! The limits a steering command can be at, as bits: what the controller's step reports
//! (SteeringController::active_limits) and the steering system adds (SteeringSystemOutput), so
//! that an integrator can see why it steers as it does.

#include <cstdint>
#include <string>

namespace smoothsteer {

//! Which limits the command is at (a bit set; SteeringSystemOutput::active_limits). Each controller
//! reports its own (SteeringController::active_limits); the steering system adds the last two.
enum ActiveLimit : std::uint32_t {
  limit_none = 0,
  //! |kappa_n| at kbar_n: the lead wheel's whole curvature authority is used.
  limit_lead_curvature = 1u << 0,
  //! |kappa_ff| at kbar_ff: the feedforward is saturated.
  limit_feedforward_bound = 1u << 1,
  //! The friction guard (FrictionGuard::max_lateral_acceleration_mps2) binds at this speed.
  limit_friction_guard = 1u << 2,
  //! |kappa_n - kappa_ff| at or beyond kbar_sw: the switching part uses its certified authority.
  limit_switching_bound = 1u << 3,
  //! The chain's front angle delta_1 at its invariant-set bound (the steering angle limit).
  limit_steering_angle = 1u << 4,
  //! The path asks more curvature or curvature rate than the domain the system was certified
  //! for allows at this speed (SteeringSystemParameters::domain): it is followed as well as
  //! the limits allow.
  limit_path_beyond_domain = 1u << 5,
  //! |v| above SteeringSystemParameters::certified_max_speed_mps: the controller's certificate
  //! does not cover this speed (the car's limits may still hold through the governor).
  limit_beyond_certified_speed = 1u << 6,
};
//! "lead_curvature|friction_guard", or "none".
std::string describe_active_limits(std::uint32_t limits);

}  // namespace smoothsteer
