#pragma once
//! \file vehicle_limits.hpp
//! What a user knows about the vehicle: its wheelbase and the limits of the steering actuator
//! (paper Sec. II-C constraints C1-C3, in the time domain).

#include <limits>
#include <string>
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct VehicleLimits {
  double wheelbase_m = 2.578;             //!< lambda_veh [m]
  double max_steering_angle_rad = 1.066;  //!< C1: |delta_veh| <= this [rad], < pi/2
  double max_steering_rate_radps = 0.4;   //!< C2: |d delta_veh/dt| <= this [rad/s]
  //! C3: |d2 delta_veh/dt2| <= this [rad/s^2]; +inf = no limit (required for order n = 1).
  double max_steering_acceleration_radps2 = std::numeric_limits<double>::infinity();
  //! Friction limit of the lateral acceleration, mu g [m/s^2]; +inf = none. The feedforward
  //! tuner keeps the rear axle's curvature bound kbar_0 <= this / v^2 at every speed.
  double max_lateral_acceleration_mps2 = std::numeric_limits<double>::infinity();

  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>".
  std::string validation_error() const { return describe(first_violation()); }
  //! Throws std::invalid_argument with validation_error().
  void validate() const { throw_if_violated(first_violation()); }
};

}  // namespace smoothsteer
