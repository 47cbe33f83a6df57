#include "smoothsteer/baselines/geometric_controllers.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "baseline_common.hpp"
#include "geometric_reverse.hpp"

namespace smoothsteer {

std::optional<Violation> StanleyParameters::first_violation() const noexcept {
  RuleChecker check("StanleyParameters");
  check.require_positive(
      {{"wheelbase_m", wheelbase_m}, {"gain_per_s", gain_per_s}, {"softening_mps", softening_mps}});
  return check.first();
}

StanleyController::StanleyController(const StanleyParameters& parameters,
                                     std::shared_ptr<const Path> path)
    : PathTrackingBaseline(parameters, std::move(path), "StanleyController") {}

Status StanleyController::compute_command(const ControllerInput& input,
                                          ControllerOutput& output) noexcept {
  if (!detail::valid_input(input)) return Status::invalid_input;
  const detail::RearTracking rear = detail::track_rear_axle(*path_, rear_hint_, input);
  const Vec2 front_axle =
      input.rear_axle_position + parameters_.wheelbase_m * unit_from_heading(input.heading_rad);
  ProjectionHint& hint = front_hint_;
  const PathProjection front = path_->project(front_axle, hint);
  const double previous = steering_;
  if (input.speed_mps > 0.0) {
    const double heading_error = wrap_angle(input.heading_rad - front.heading_rad);
    steering_ = -heading_error - std::atan(parameters_.gain_per_s * front.lateral_error_m /
                                           (parameters_.softening_mps + input.speed_mps));
  } else if (input.speed_mps < 0.0) {
    steering_ = reverse_stanley_steering(rear.projection, input, parameters_);
  }
  detail::fill_output(*path_, front_hint_, input, rear, parameters_.wheelbase_m, steering_,
                      previous, front.lateral_error_m, output);
  return Status::ok;
}

std::optional<Violation> PurePursuitParameters::first_violation() const noexcept {
  RuleChecker check("PurePursuitParameters");
  check.require_positive({{"wheelbase_m", wheelbase_m}, {"min_lookahead_m", min_lookahead_m}});
  check.require(std::isfinite(lookahead_time_s) && lookahead_time_s >= 0.0, "lookahead_time_s",
                lookahead_time_s, "must be finite and >= 0");
  check.require(std::isfinite(max_lookahead_m) && max_lookahead_m >= min_lookahead_m,
                "max_lookahead_m", max_lookahead_m, "must be finite and >= min_lookahead_m");
  return check.first();
}

PurePursuitController::PurePursuitController(const PurePursuitParameters& parameters,
                                             std::shared_ptr<const Path> path)
    : PathTrackingBaseline(parameters, std::move(path), "PurePursuitController") {}

double PurePursuitController::lookahead_m(double speed_mps) const noexcept {
  return std::clamp(
      parameters_.min_lookahead_m + parameters_.lookahead_time_s * std::abs(speed_mps),
      parameters_.min_lookahead_m, parameters_.max_lookahead_m);
}

Status PurePursuitController::compute_command(const ControllerInput& input,
                                              ControllerOutput& output) noexcept {
  if (!detail::valid_input(input)) return Status::invalid_input;
  const detail::RearTracking rear = detail::track_rear_axle(*path_, rear_hint_, input);
  const double previous = steering_;
  const double lookahead = lookahead_m(input.speed_mps);
  const PathPoint target = path_->evaluate(rear.projection.arc_length_m + lookahead);
  const Vec2 to_target = target.position - input.rear_axle_position;
  const double distance = norm(to_target);
  if (input.speed_mps > 0.0 && distance > 1e-6) {
    const double bearing = wrap_angle(std::atan2(to_target.y, to_target.x) - input.heading_rad);
    steering_ = std::atan(2.0 * parameters_.wheelbase_m * std::sin(bearing) / distance);
  } else if (input.speed_mps < 0.0 && distance > 1e-6) {
    steering_ = reverse_pure_pursuit_steering(to_target, distance, input, parameters_);
  }
  detail::fill_output(*path_, front_hint_, input, rear, parameters_.wheelbase_m, steering_,
                      previous, lookahead, output);
  return Status::ok;
}

}  // namespace smoothsteer
