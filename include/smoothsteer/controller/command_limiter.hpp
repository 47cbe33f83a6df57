#pragma once
//! \file command_limiter.hpp
//! Steering limits of the held command: C1 (|delta| <= delta-bar), the time-domain rate limit of
//! C2 (|d delta/dt| <= v delta-bar', paper Sec. II-B) and the steering acceleration limit; and
//! SteeringSaturator, the second-order limiter that holds a command to them
//! (second_order_limiter.cpp; docs/baselines.md, "The limiter"): the command it returns keeps the
//! angle, rate and acceleration limits, differenced at the actual control periods, and brakes in
//! time so that it never has to leave the angle bound. A command that keeps the limits passes
//! unchanged; every clamp is counted. The comparison controllers run behind it
//! (baselines/steering_limits.hpp), and the steering system holds its offset compensation to it
//! (system/steering_offset_compensation.hpp).

#include <limits>
#include <optional>
#include <string>

#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct SteeringLimits {
  double angle_rad = 0.5;   //!< delta-bar, C1 [rad]
  double rate_radps = 0.6;  //!< bound on |d delta/dt| [rad/s] (C2 times the speed)
  //! Bound on |d2 delta/dt2| of the held command [rad/s^2]: the second difference of consecutive
  //! commands over the period squared. +infinity (the default): no acceleration limit.
  double acceleration_radps2 = std::numeric_limits<double>::infinity();

  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>".
  std::string validation_error() const { return describe(first_violation()); }
  //! Throws std::invalid_argument with validation_error().
  void validate() const { throw_if_violated(first_violation()); }
};

//! How often and by how much the raw command of a controller exceeded the limits.
struct SaturationStatistics {
  long updates = 0;        //!< successful update() calls
  long angle_limited = 0;  //!< updates whose raw command exceeded angle_rad
  long rate_limited = 0;   //!< updates whose (angle-clamped) change exceeded rate * dt
  //! Updates in which the acceleration limit moved the command off the angle- and rate-clamped
  //! one: the change of rate bounded to acceleration * dt, braking before the angle bound, or
  //! the braked approach to a target out of reach.
  long acceleration_limited = 0;
  long limited = 0;                    //!< updates with any of the three clamps
  double max_angle_excess_rad = 0.0;   //!< largest |raw| - angle_rad
  double max_rate_excess_radps = 0.0;  //!< largest |change| / dt - rate_radps
  //! Largest |change of rate| / dt - acceleration_radps2 of the angle- and rate-clamped command,
  //! from the previous applied rate.
  double max_acceleration_excess_radps2 = 0.0;

  //! Fraction of updates with any clamp, in [0, 1].
  double limited_fraction() const noexcept;
  void reset() noexcept { *this = SaturationStatistics{}; }
};

//! The limiter itself: remembers the previous command and its rate (difference quotient).
class SteeringSaturator {
 public:
  explicit SteeringSaturator(const SteeringLimits& limits);  // validates
  //! Returns the limited command and records the clamps. `rate_radps` receives the applied
  //! rate (change / period_s). A non-finite raw command is replaced by the previous command as
  //! the target (approached within the limits). A period that is not finite and > 0 returns the
  //! previous command with rate 0 and changes nothing. noexcept, allocation-free.
  double apply(double raw_angle_rad, double period_s, double& rate_radps) noexcept;
  //! The same, with `acceleration_radps2` the applied rate's change over the period (0 for a
  //! period that is not finite and > 0): the held command's differenced acceleration.
  double apply(double raw_angle_rad, double period_s, double& rate_radps,
               double& acceleration_radps2) noexcept;
  //! Restarts from the measured angle and rate, clamped into the set from which the limits can
  //! be kept (|angle| <= angle_rad, |rate| <= rate_radps, stopping distance inside the angle
  //! bound); a non-finite value counts as 0.
  void reset(double angle_rad, double rate_radps = 0.0) noexcept;
  const SteeringLimits& limits() const noexcept { return limits_; }
  const SaturationStatistics& statistics() const noexcept { return statistics_; }
  double previous() const noexcept { return previous_; }
  double previous_rate() const noexcept { return previous_rate_; }

 private:
  SteeringLimits limits_;
  SaturationStatistics statistics_;
  double previous_ = 0.0;
  double previous_rate_ = 0.0;
  double previous_target_ = 0.0;  //!< the last (angle-clamped) raw command, for its rate
};

}  // namespace smoothsteer
