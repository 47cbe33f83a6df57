#include "smoothsteer/baselines/steering_limits.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "baseline_common.hpp"

namespace smoothsteer {

std::optional<Violation> SteeringLimits::first_violation() const noexcept {
  RuleChecker check("SteeringLimits");
  check.require(positive_finite(angle_rad) && angle_rad < std::numbers::pi / 2.0, "angle_rad",
                angle_rad, "must be in (0, pi/2)");
  check.require(positive_finite(rate_radps), "rate_radps", rate_radps, "must be finite and > 0");
  return check.first();
}

double SaturationStatistics::limited_fraction() const noexcept {
  if (updates == 0) return 0.0;
  const long limited = std::max(angle_limited, rate_limited);
  return std::min(1.0, static_cast<double>(limited) / static_cast<double>(updates));
}

SteeringSaturator::SteeringSaturator(const SteeringLimits& limits) : limits_(limits) {
  limits_.validate();
}

void SteeringSaturator::reset(double angle_rad) noexcept {
  previous_ =
      std::isfinite(angle_rad) ? std::clamp(angle_rad, -limits_.angle_rad, limits_.angle_rad) : 0.0;
  previous_rate_ = 0.0;
}

double SteeringSaturator::apply(double raw_angle_rad, double period_s,
                                double& rate_radps) noexcept {
  // A tiny tolerance keeps round-off of controllers that respect the limits by construction
  // (HOSM, Newton-Raphson flow) from being counted as hits.
  constexpr double tolerance = 1e-9;
  ++statistics_.updates;
  double angle = std::isfinite(raw_angle_rad) ? raw_angle_rad : previous_;
  const double angle_excess = std::abs(angle) - limits_.angle_rad;
  if (angle_excess > tolerance) {
    ++statistics_.angle_limited;
    statistics_.max_angle_excess_rad = std::max(statistics_.max_angle_excess_rad, angle_excess);
    angle = std::clamp(angle, -limits_.angle_rad, limits_.angle_rad);
  }
  const double largest_change = limits_.rate_radps * period_s;
  const double change = angle - previous_;
  const double rate_excess = (std::abs(change) - largest_change) / period_s;
  if (rate_excess > tolerance) {
    ++statistics_.rate_limited;
    statistics_.max_rate_excess_radps = std::max(statistics_.max_rate_excess_radps, rate_excess);
    angle = previous_ + std::clamp(change, -largest_change, largest_change);
  }
  rate_radps = (angle - previous_) / period_s;
  previous_ = angle;
  previous_rate_ = rate_radps;
  return angle;
}

SaturatedController::SaturatedController(std::unique_ptr<SteeringController> inner,
                                         const SteeringLimits& limits, std::string name)
    : inner_(std::move(inner)), saturator_(limits), name_(std::move(name)) {
  if (!inner_) throw std::invalid_argument("SaturatedController: inner controller is null");
}

void SaturatedController::reset(double measured_steering_angle_rad) noexcept {
  inner_->reset(measured_steering_angle_rad);
  saturator_.reset(measured_steering_angle_rad);
  previous_rate_ = 0.0;
  first_ = true;
}

Status SaturatedController::compute_command(const ControllerInput& input,
                                            ControllerOutput& output) noexcept {
  if (!detail::valid_input(input)) return Status::invalid_input;
  ControllerOutput raw = output;
  const Status status = inner_->update(input, raw);
  if (status != Status::ok) return status;
  double rate = 0.0;
  const double angle = saturator_.apply(raw.steering_angle_rad, input.period_s, rate);
  output = raw;
  output.steering_angle_rad = angle;
  output.steering_rate_radps = rate;
  output.steering_acceleration_radps2 = first_ ? 0.0 : (rate - previous_rate_) / input.period_s;
  output.derivatives_available = 2;
  previous_rate_ = rate;
  first_ = false;
  return Status::ok;
}

}  // namespace smoothsteer
