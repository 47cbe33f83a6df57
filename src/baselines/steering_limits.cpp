#include "smoothsteer/baselines/steering_limits.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "baseline_common.hpp"

namespace smoothsteer {

SaturatedController::SaturatedController(std::unique_ptr<SteeringController> inner,
                                         const SteeringLimits& limits, std::string name)
    : inner_(std::move(inner)), saturator_(limits), name_(std::move(name)) {
  if (!inner_) throw std::invalid_argument("SaturatedController: inner controller is null");
}

Status SaturatedController::reset(double measured_steering_angle_rad) noexcept {
  const Status status = inner_->reset(measured_steering_angle_rad);
  if (status != Status::ok) return status;
  saturator_.reset(measured_steering_angle_rad);
  return Status::ok;
}

Status SaturatedController::compute_command(const ControllerInput& input,
                                            ControllerOutput& output) noexcept {
  if (!detail::valid_input(input)) return Status::invalid_input;
  ControllerOutput raw = output;
  const Status status = inner_->update(input, raw);
  if (status != Status::ok) return status;
  // From the limiter's own previous rate (0 at reset, before the first update), so the reported
  // acceleration is the one the limiter bounds.
  double rate = 0.0, acceleration = 0.0;
  const double angle = saturator_.apply(raw.steering_angle_rad, input.period_s, rate, acceleration);
  output = raw;
  output.steering_angle_rad = angle;
  output.steering_rate_radps = rate;
  output.steering_acceleration_radps2 = acceleration;
  output.derivatives_available = 2;
  return Status::ok;
}

}  // namespace smoothsteer
