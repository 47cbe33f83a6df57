#pragma once
//! \file steering_limits.hpp
//! Steering limits C1 (|delta| <= delta-bar) and the time-domain rate limit of C2
//! (|d delta/dt| <= v delta-bar', paper Sec. II-B) for comparison controllers that do not
//! respect them by construction, and the accounting of how often and by how much they hit them.
//!
//! SaturatedController wraps any SteeringController: it clamps the command to the angle limit,
//! then limits its change per period to rate_radps * dt, and counts every clamp.

#include <memory>
#include <string>
#include <utility>

#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct SteeringLimits {
  double angle_rad = 0.5;   //!< delta-bar, C1 [rad]
  double rate_radps = 0.6;  //!< bound on |d delta/dt| [rad/s] (C2 times the speed)

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
  long updates = 0;                    //!< successful update() calls
  long angle_limited = 0;              //!< updates whose raw command exceeded angle_rad
  long rate_limited = 0;               //!< updates whose (angle-clamped) change exceeded rate * dt
  double max_angle_excess_rad = 0.0;   //!< largest |raw| - angle_rad
  double max_rate_excess_radps = 0.0;  //!< largest |change| / dt - rate_radps

  //! Fraction of updates with any clamp, in [0, 1].
  double limited_fraction() const noexcept;
  void reset() noexcept { *this = SaturationStatistics{}; }
};

//! The clamp itself: remembers the previous command for the rate limit.
class SteeringSaturator {
 public:
  explicit SteeringSaturator(const SteeringLimits& limits);  // validates
  //! Returns the limited command and records the clamps. `rate_radps` receives the applied
  //! rate (limited change / dt). noexcept, allocation-free.
  double apply(double raw_angle_rad, double period_s, double& rate_radps) noexcept;
  void reset(double angle_rad) noexcept;
  const SteeringLimits& limits() const noexcept { return limits_; }
  const SaturationStatistics& statistics() const noexcept { return statistics_; }
  double previous() const noexcept { return previous_; }

 private:
  SteeringLimits limits_;
  SaturationStatistics statistics_;
  double previous_ = 0.0;
  double previous_rate_ = 0.0;
};

//! A comparison controller behind the common interface, with its output limited to C1/C2.
//! The applied command's rate and acceleration are reported from differences (derivatives = 2).
class SaturatedController final : public SteeringController {
 public:
  SaturatedController(std::unique_ptr<SteeringController> inner, const SteeringLimits& limits,
                      std::string name);

 protected:
  Status compute_command(const ControllerInput& input, ControllerOutput& output) noexcept override;

 public:
  void reset(double measured_steering_angle_rad = 0.0) noexcept override;
  const char* name() const noexcept override { return name_.c_str(); }
  //! Forwarded: the wrapped controller decides whether it has a matched-disturbance input.
  Status set_path(std::shared_ptr<const Path> path) noexcept override {
    return inner_->set_path(std::move(path));
  }
  bool set_matched_disturbance(double lead_curvature_disturbance) noexcept override {
    return inner_->set_matched_disturbance(lead_curvature_disturbance);
  }

  const SaturationStatistics& saturation() const noexcept { return saturator_.statistics(); }
  const SteeringLimits& limits() const noexcept { return saturator_.limits(); }
  SteeringController& inner() noexcept { return *inner_; }

 private:
  std::unique_ptr<SteeringController> inner_;
  SteeringSaturator saturator_;
  std::string name_;
  double previous_rate_ = 0.0;
  bool first_ = true;
};

}  // namespace smoothsteer
