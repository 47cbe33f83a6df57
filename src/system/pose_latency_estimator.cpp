#include "smoothsteer/system/pose_latency_estimator.hpp"

#include <algorithm>
#include <cmath>

#include "smoothsteer/math/angles.hpp"

namespace smoothsteer {

double PoseLatencyEstimator::update(double heading_rad, bool new_pose, double yaw_rate_radps,
                                    double period_s, double max_age_s) noexcept {
  // The gyro's integral at this period's time (trapezoid: a rate read at the end of each
  // period would shift every candidate by half a period).
  const double rate = std::isfinite(yaw_rate_radps) ? yaw_rate_radps : last_rate_;
  if (count_ > 0) integral_ += 0.5 * (rate + last_rate_) * period_s;
  last_rate_ = rate;
  turned_[head_] = integral_;
  const std::size_t now = head_;
  head_ = (head_ + 1) % history;
  count_ = std::min(count_ + 1, history);
  auto turned_at = [&](std::size_t periods_ago) {
    return turned_[(now + history - periods_ago) % history];
  };

  if (!new_pose) {
    ++since_pose_;
    since_pose_s_ += period_s;
  } else {
    const std::size_t span = since_pose_ + 1;  // periods between the two poses' deliveries
    const std::size_t lags = std::min<std::size_t>(
        max_lags, static_cast<std::size_t>(std::floor(max_age_s / period_s + 1e-9)) + 1);
    if (has_pose_ && span + lags - 1 < count_) {
      const double pose_turned = wrap_angle(heading_rad - last_pose_heading_);
      const double span_s = since_pose_s_ + period_s;
      weight_ = forgetting * weight_ + span_s;
      // Per lag, the weighted variance second - first^2 / weight.
      std::array<double, max_lags> misfit{};
      for (std::size_t j = 0; j < lags; ++j) {
        const double gyro_turned = turned_at(j) - turned_at(j + span);
        const double rate_difference = (pose_turned - gyro_turned) / span_s;
        first_[j] = forgetting * first_[j] + span_s * rate_difference;
        second_[j] = forgetting * second_[j] + span_s * rate_difference * rate_difference;
        misfit[j] = std::max(0.0, second_[j] - first_[j] * first_[j] / weight_);
      }
      const auto best = static_cast<std::size_t>(
          std::min_element(misfit.begin(), misfit.begin() + static_cast<long>(lags)) -
          misfit.begin());
      const std::size_t current = std::min(lag_, lags - 1);
      if (misfit[best] < switch_ratio * misfit[current] &&
          misfit[current] - misfit[best] > min_evidence) {
        lag_ = best;
      }
      // Between the grid lags: the vertex of the parabola through the sums around the lag.
      double refined = static_cast<double>(lag_);
      if (lag_ > 0 && lag_ + 1 < lags) {
        const double before = misfit[lag_ - 1], at = misfit[lag_], after = misfit[lag_ + 1];
        const double curvature = before - 2.0 * at + after;
        if (curvature > 0.0) refined += std::clamp(0.5 * (before - after) / curvature, -0.5, 0.5);
      }
      latency_s_ = refined * period_s;
    }
    has_pose_ = true;
    last_pose_heading_ = heading_rad;
    since_pose_ = 0;
    since_pose_s_ = 0.0;
  }
  return std::clamp(latency_s_ + since_pose_s_, 0.0, max_age_s);
}

}  // namespace smoothsteer
