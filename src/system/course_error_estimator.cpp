#include "smoothsteer/system/course_error_estimator.hpp"

#include <algorithm>
#include <cmath>

#include "smoothsteer/math/angles.hpp"

namespace smoothsteer {

std::optional<Violation> CourseErrorParameters::first_violation() const noexcept {
  RuleChecker check("CourseErrorParameters");
  check.require(position_noise_std_m > 0.0 && position_noise_std_m <= 10.0, "position_noise_std_m",
                position_noise_std_m, "must be in (0, 10] m");
  check.require(heading_noise_std_rad >= 0.0 && heading_noise_std_rad <= 0.5,
                "heading_noise_std_rad", heading_noise_std_rad, "must be in [0, 0.5] rad");
  check.require(initial_slip_error_std >= 0.0 && initial_slip_error_std <= 1.0,
                "initial_slip_error_std", initial_slip_error_std, "must be in [0, 1]");
  check.require(slip_error_process_std >= 0.0 && slip_error_process_std <= 1.0,
                "slip_error_process_std", slip_error_process_std, "must be in [0, 1] 1/sqrt(s)");
  check.require(initial_course_bias_std_rad >= 0.0 && initial_course_bias_std_rad <= 0.1,
                "initial_course_bias_std_rad", initial_course_bias_std_rad,
                "must be in [0, 0.1] rad");
  check.require(course_bias_process_std_radps >= 0.0 && course_bias_process_std_radps <= 0.1,
                "course_bias_process_std_radps", course_bias_process_std_radps,
                "must be in [0, 0.1] rad/sqrt(s)");
  check.require(max_slip_error >= 0.0 && max_slip_error <= 0.5, "max_slip_error", max_slip_error,
                "must be in [0, 0.5] (the slip gradients' scale stays in [0.5, 2])");
  check.require(max_course_bias_rad >= 0.0 && max_course_bias_rad <= 0.1, "max_course_bias_rad",
                max_course_bias_rad, "must be in [0, 0.1] rad");
  check.require(min_speed_mps >= 0.5 && min_speed_mps <= 100.0, "min_speed_mps", min_speed_mps,
                "must be in [0.5, 100] m/s");
  check.require(max_lateral_acceleration_mps2 > 0.0, "max_lateral_acceleration_mps2",
                max_lateral_acceleration_mps2, "must be > 0 m/s^2 (+inf: no bound)");
  check.require(max_innovation_sigmas >= 2.0 && max_innovation_sigmas <= 100.0,
                "max_innovation_sigmas", max_innovation_sigmas, "must be in [2, 100]");
  return check.first();
}

std::string CourseErrorParameters::validation_error() const {
  return describe(first_violation());
}

void CourseErrorParameters::validate() const {
  throw_if_violated(first_violation());
}

void CourseErrorEstimator::initialize(const CourseErrorParameters& parameters) noexcept {
  initialized_ = true;
  for (auto& row : covariance_) row[0] = row[1] = row[2] = 0.0;
  covariance_[1][1] = parameters.initial_slip_error_std * parameters.initial_slip_error_std;
  covariance_[2][2] =
      parameters.initial_course_bias_std_rad * parameters.initial_course_bias_std_rad;
}

void CourseErrorEstimator::restart_residual(double position_variance) noexcept {
  residual_ = 0.0;
  covariance_[0][0] = position_variance;
  covariance_[0][1] = covariance_[1][0] = covariance_[0][2] = covariance_[2][0] = 0.0;
}

double CourseErrorEstimator::update(const CourseErrorParameters& parameters,
                                    const Input& input) noexcept {
  if (!initialized_) initialize(parameters);
  const double slip_now = input.rear_axle_side_slip_rad;
  const double period_s = input.period_s;
  const auto correction = [&] { return slip_error_ * slip_now + course_bias_; };
  // Reversing, slow or standing: the model's slip means little and the step is short.
  if (!(input.speed_mps >= parameters.min_speed_mps)) {
    restart();
    return correction();
  }
  // The pose is pose_age_s old: its step is compared with the slip of its own time.
  head_ = (head_ + 1) % history;
  slips_[head_] = slip_now;
  count_ = std::min(count_ + 1, history);
  const double periods_back = std::clamp(input.pose_age_s / period_s, 0.0, double(history));
  const std::size_t back =
      std::min(count_ - 1, static_cast<std::size_t>(std::lround(periods_back)));
  const double slip = slips_[(head_ + history - back) % history];
  const double course = input.heading_rad + slip;
  const double length = input.speed_mps * period_s;
  if (std::abs(input.lateral_acceleration_mps2) > parameters.max_lateral_acceleration_mps2) {
    learnable_ = false;  // this pose's step is not compared (the tires beyond their linear range)
  }
  span_length_ += length;
  span_slip_ += slip * length;
  span_time_ += period_s;
  if (!input.new_pose) return correction();

  const double position_variance =
      parameters.position_noise_std_m * parameters.position_noise_std_m;
  if (!has_pose_ || !learnable_) {
    has_pose_ = true;
    restart_residual(position_variance);
  } else {
    // The step's lateral part across the course at its middle; what a and c predict of it.
    const double middle = last_course_ + 0.5 * wrap_angle(course - last_course_);
    const Vec2 step = input.position - last_position_;
    const double lateral = -std::sin(middle) * step.x + std::cos(middle) * step.y;
    const double fa = span_slip_, fc = span_length_;
    residual_ += lateral - (fa * slip_error_ + fc * course_bias_);
    // Prediction: P = F P F^T + Q, F = [[1, fa, fc], [0, 1, 0], [0, 0, 1]]; the pose's heading
    // noise moves the predicted step by about its std over the step (the mean of two headings).
    double(&p)[3][3] = covariance_;
    const double p01 = p[0][1] + fa * p[1][1] + fc * p[2][1];
    const double p02 = p[0][2] + fa * p[1][2] + fc * p[2][2];
    const double p00 = p[0][0] + 2.0 * fa * p[0][1] + 2.0 * fc * p[0][2] + fa * fa * p[1][1] +
                       2.0 * fa * fc * p[1][2] + fc * fc * p[2][2];
    const double heading_noise = parameters.heading_noise_std_rad * fc;
    p[0][0] = p00 + 0.5 * heading_noise * heading_noise;
    p[0][1] = p[1][0] = p01;
    p[0][2] = p[2][0] = p02;
    p[1][1] += parameters.slip_error_process_std * parameters.slip_error_process_std * span_time_;
    p[2][2] += parameters.course_bias_process_std_radps * parameters.course_bias_process_std_radps *
               span_time_;
    // Correction with the summed residual, measured with the pose's noise.
    const double innovation_variance = p[0][0] + position_variance;
    if (!(std::abs(residual_) <=
          parameters.max_innovation_sigmas * std::sqrt(innovation_variance))) {
      restart_residual(position_variance);  // a jump of the localization (or a NaN)
    } else {
      const double gain[3] = {p[0][0] / innovation_variance, p[1][0] / innovation_variance,
                              p[2][0] / innovation_variance};
      const double innovation = residual_;
      residual_ -= gain[0] * innovation;
      slip_error_ = std::clamp(slip_error_ + gain[1] * innovation, -parameters.max_slip_error,
                               parameters.max_slip_error);
      course_bias_ = std::clamp(course_bias_ + gain[2] * innovation,
                                -parameters.max_course_bias_rad, parameters.max_course_bias_rad);
      const double row[3] = {p[0][0], p[0][1], p[0][2]};
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) p[i][j] -= gain[i] * row[j];
      }
    }
  }
  last_position_ = input.position;
  last_course_ = course;
  span_length_ = span_slip_ = span_time_ = 0.0;
  learnable_ = true;
  return correction();
}

}  // namespace smoothsteer
