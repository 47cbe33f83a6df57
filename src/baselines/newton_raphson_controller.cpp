#include "smoothsteer/baselines/newton_raphson_controller.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "baseline_common.hpp"

namespace smoothsteer {

std::optional<Violation> NewtonRaphsonParameters::first_violation() const noexcept {
  RuleChecker check("NewtonRaphsonParameters");
  check.require_positive({{"wheelbase_m", wheelbase_m},
                          {"horizon_s", horizon_s},
                          {"gain_per_s", gain_per_s},
                          {"min_speed_mps", min_speed_mps}});
  check.include(limits.first_violation());
  return check.first();
}

ArcPrediction predict_arc(double steering_angle_rad, double wheelbase_m,
                          double distance_m) noexcept {
  // Local coordinates of the end of an arc of curvature k and length d:
  //   forward = sin(k d) / k,  left = (1 - cos(k d)) / k,  dk/d delta = (1 + tan^2 delta)/lambda.
  constexpr double taylor_threshold = 1e-4;
  const double tangent = std::tan(steering_angle_rad);
  const double k = tangent / wheelbase_m;
  const double dk = (1.0 + tangent * tangent) / wheelbase_m;
  const double d = distance_m;
  const double kd = k * d;
  ArcPrediction p;
  p.heading_change_rad = kd;
  double d_forward_dk = 0.0, d_left_dk = 0.0;
  if (std::abs(kd) < taylor_threshold) {
    p.forward_m = d - k * k * d * d * d / 6.0;
    p.left_m = k * d * d / 2.0 - k * k * k * d * d * d * d / 24.0;
    d_forward_dk = -k * d * d * d / 3.0;
    d_left_dk = d * d / 2.0 - k * k * d * d * d * d / 8.0;
  } else {
    const double s = std::sin(kd), c = std::cos(kd);
    p.forward_m = s / k;
    p.left_m = (1.0 - c) / k;
    d_forward_dk = (d * c * k - s) / (k * k);
    d_left_dk = (d * s * k - (1.0 - c)) / (k * k);
  }
  p.d_forward_d_steering = d_forward_dk * dk;
  p.d_left_d_steering = d_left_dk * dk;
  return p;
}

NewtonRaphsonController::NewtonRaphsonController(const NewtonRaphsonParameters& parameters,
                                                 std::shared_ptr<const Path> path)
    : PathTrackingBaseline(parameters, std::move(path), "NewtonRaphsonController") {
  (void)reset(0.0);
}

Status NewtonRaphsonController::reset(double measured_steering_angle_rad) noexcept {
  if (!valid_reset_angle(measured_steering_angle_rad, parameters_.limits.angle_rad)) {
    return Status::invalid_input;
  }
  restart(measured_steering_angle_rad, parameters_.limits.angle_rad);
  rate_ = 0.0;
  return Status::ok;
}

Status NewtonRaphsonController::compute_command(const ControllerInput& input,
                                                ControllerOutput& output) noexcept {
  if (!detail::valid_input(input)) return Status::invalid_input;
  const detail::RearTracking rear = detail::track_rear_axle(*path_, rear_hint_, input);
  const double speed = input.speed_mps;
  double rate = 0.0;
  double offset = 0.0;
  if (speed >= parameters_.min_speed_mps) {
    const double distance = speed * parameters_.horizon_s;
    // r(t + T): where the rear axle should be after T on the path.
    const PathPoint reference = path_->evaluate(rear.projection.arc_length_m + distance);
    const ArcPrediction arc = predict_arc(steering_, parameters_.wheelbase_m, distance);
    const Vec2 forward = unit_from_heading(input.heading_rad);
    const Vec2 left{-forward.y, forward.x};
    const Vec2 predicted = input.rear_axle_position + arc.forward_m * forward + arc.left_m * left;
    const Vec2 normal{-std::sin(reference.heading_rad), std::cos(reference.heading_rad)};
    offset = dot(normal, predicted - reference.position);  // g - r along the normal
    const double derivative =
        dot(normal, arc.d_forward_d_steering * forward + arc.d_left_d_steering * left);
    constexpr double smallest_derivative = 1e-9;
    if (std::abs(derivative) > smallest_derivative) {
      rate = -parameters_.gain_per_s * offset / derivative;
    }
  }
  const double rate_bound = parameters_.limits.rate_radps;
  const double angle_bound = parameters_.limits.angle_rad;
  rate = std::clamp(std::isfinite(rate) ? rate : 0.0, -rate_bound, rate_bound);
  const double previous = steering_;
  steering_ = std::clamp(steering_ + rate * input.period_s, -angle_bound, angle_bound);
  const double applied_rate = (steering_ - previous) / input.period_s;
  detail::fill_output(*path_, front_hint_, input, rear, parameters_.wheelbase_m, steering_,
                      previous, offset, output, 1, (applied_rate - rate_) / input.period_s);
  rate_ = applied_rate;
  return Status::ok;
}

}  // namespace smoothsteer
