#include "smoothsteer/baselines/lqr_controller.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "baseline_common.hpp"

namespace smoothsteer {

std::optional<Violation> LqrParameters::first_violation() const noexcept {
  RuleChecker check("LqrParameters");
  check.require_positive({{"wheelbase_m", wheelbase_m}});
  check.require(positive_finite(weight_lateral), "weight_lateral", weight_lateral,
                "must be finite and > 0 (else e is not stabilised)");
  check.require(std::isfinite(weight_heading) && weight_heading >= 0.0, "weight_heading",
                weight_heading, "must be finite and >= 0");
  check.require_positive({{"weight_steering", weight_steering}, {"min_speed_mps", min_speed_mps}});
  return check.first();
}

LqrGains lqr_gains(const LqrParameters& parameters, double speed_mps) noexcept {
  const double v = std::max(std::abs(speed_mps), parameters.min_speed_mps);
  const double lambda = parameters.wheelbase_m;
  const double r = parameters.weight_steering * lambda * lambda / (v * v * v * v);
  const double k1 = std::sqrt(parameters.weight_lateral / r);
  const double k2 = std::sqrt(parameters.weight_heading / (v * v) / r + 2.0 * k1);
  // w = v^2/lambda delta_fb = -k1 e - k2 v psi_e.
  const double scale = lambda / (v * v);
  return {scale * k1, scale * k2 * v};
}

LqrController::LqrController(const LqrParameters& parameters, std::shared_ptr<const Path> path)
    : PathTrackingBaseline(parameters, std::move(path), "LqrController") {}

Status LqrController::compute_command(const ControllerInput& input,
                                      ControllerOutput& output) noexcept {
  if (!detail::valid_input(input)) return Status::invalid_input;
  const detail::RearTracking rear = detail::track_rear_axle(*path_, rear_hint_, input);
  const double previous = steering_;
  if (input.speed_mps > 0.0) {
    const LqrGains gains = lqr_gains(parameters_, input.speed_mps);
    const double feedforward = parameters_.curvature_feedforward
                                   ? std::atan(parameters_.wheelbase_m * rear.projection.curvature)
                                   : 0.0;
    steering_ = feedforward - gains.lateral * rear.projection.lateral_error_m -
                gains.heading * rear.heading_error_rad;
  }
  detail::fill_output(*path_, front_hint_, input, rear, parameters_.wheelbase_m, steering_,
                      previous, rear.projection.lateral_error_m, output);
  return Status::ok;
}

}  // namespace smoothsteer
