#include "smoothsteer/controller/disturbance_estimator.hpp"

#include <algorithm>
#include <cmath>

#include "smoothsteer/math/angles.hpp"

namespace smoothsteer {

void DisturbanceEstimator::update(const ControllerInput& input, const Context& context,
                                  const DelayPrediction& commands) noexcept {
  const double course = input.heading_rad + input.rear_axle_side_slip_rad;
  if (context.enabled && has_previous_pose_ && commands.count() > 0 && context.direction > 0.0 &&
      input.speed_mps > 0.0) {
    const double distance = norm(input.rear_axle_position - previous_position_);
    if (distance > 1e-6) {
      // The steering in effect over the last period: issued `actuator_delay_s` earlier, plus
      // the lag of the tires' slip that the single-track inversion previews (lag / g metres).
      const double delay = context.delay_s + context.dynamics.slip_lag_m / input.speed_mps;
      const auto age = std::min<std::size_t>(
          commands.count() - 1, static_cast<std::size_t>(std::lround(delay / input.period_s)));
      const double commanded = std::tan(commands.issued(age).steering_rad) / context.wheelbase_m;
      // In the chain's units: the inversion steers g(kappa) kappa for a course curvature kappa
      // (understeer and the steady geometry are the model's, not a disturbance), so the
      // disturbance is g(kappa) kappa - command.
      const double course_curvature = wrap_angle(course - previous_course_) / distance;
      const double measured =
          context.dynamics.gain_at(course_curvature, context.wheelbase_m) * course_curvature;
      // Learn where the path has let the car settle: while the path's curvature moves, the slip
      // and actuator transients that the model leaves read as a disturbance. The path at the
      // rear axle counts as steady while its lateral jerk v^3 |d kappa / ds| stays below
      // steady_lateral_jerk_mps3; the weight grows from 0 to 1 over the settling distance after.
      const double v = input.speed_mps;
      const double moved = std::abs(rear_path_curvature_ - previous_rear_path_curvature_);
      const bool turning =
          commands.count() > 1 &&
          std::abs(commands.issued(0).steering_rad - commands.issued(1).steering_rad) >
              settled_steering_rate_radps * commands.issued(0).period_s;
      if (turning || moved > steady_lateral_jerk_mps3 / (v * v * v) * distance) {
        steady_path_m_ = 0.0;
      } else {
        steady_path_m_ += distance;
      }
      const double settling_m = std::max(min_settling_m, settling_time_s * v);
      engaged_ = engaged_ || std::abs(rear_lateral_error_m_) <= engaged_lateral_error_m;
      const bool trusted =
          engaged_ && v >= min_learning_speed_mps &&
          v * v * std::abs(rear_path_curvature_) <= max_learning_lateral_acceleration_mps2;
      const double weight = trusted ? std::clamp(steady_path_m_ / settling_m - 1.0, 0.0, 1.0) : 0.0;
      // A running mean whose memory grows with what it has learned, up to the estimation
      // length: the mean of all samples so far (weighted by distance), then a low-pass.
      learned_m_ = std::min(context.length_m, learned_m_ + weight * distance);
      const double memory =
          std::clamp(learned_m_, std::min(min_memory_m, context.length_m), context.length_m);
      const double gain = weight * std::min(1.0, distance / memory);
      const double bound = context.feedforward_bound;
      estimate_ = std::clamp(estimate_ + gain * (measured - commanded - estimate_), -bound, bound);
    }
  }
  previous_position_ = input.rear_axle_position;
  previous_course_ = course;
  previous_rear_path_curvature_ = rear_path_curvature_;
  has_previous_pose_ = true;
}

}  // namespace smoothsteer
