// Localization latency of the closed loop (pose_delay.hpp).

#include "pose_delay.hpp"

#include <cmath>

namespace smoothsteer::detail {
namespace {

// k T and the latency are sums of rounded decimals: a look-back that lands on a control
// instant within this many periods is taken as that instant.
constexpr double snap_periods = 1e-6;

}  // namespace

PoseDelay::PoseDelay(double latency_s, std::optional<double> rate_hz, double control_period_s,
                     const Pose2& start, double speed_mps)
    : active_(latency_s > 0.0 || rate_hz.has_value()),
      latency_s_(latency_s),
      rate_hz_(rate_hz),
      period_s_(control_period_s),
      start_(start),
      speed_mps_(speed_mps) {
  if (!active_) return;
  // The oldest step read at step k is k - ceil((latency + 1 / rate) / T) - 1 (interpolation).
  const double look_back_s = latency_s + (rate_hz ? 1.0 / *rate_hz : 0.0);
  ring_.resize(static_cast<std::size_t>(std::ceil(look_back_s / control_period_s)) + 3);
}

double PoseDelay::sampled_time(long k) const noexcept {
  const double t = static_cast<double>(k) * period_s_ - latency_s_;
  if (!rate_hz_) return t;
  const double f = *rate_hz_;
  return std::floor(t * f + snap_periods) / f;
}

Pose2 PoseDelay::recorded(long j) const noexcept {
  if (j >= 0) return ring_[static_cast<std::size_t>(j) % ring_.size()];
  // Before t = 0 the car drove straight along its start heading at the start speed.
  const double back = -static_cast<double>(j) * period_s_ * speed_mps_;
  Pose2 pose = start_;
  pose.position.x -= back * std::cos(start_.heading_rad);
  pose.position.y -= back * std::sin(start_.heading_rad);
  return pose;
}

Pose2 PoseDelay::deliver(long k, const Pose2& truth) noexcept {
  if (!active_) return truth;
  ring_[static_cast<std::size_t>(k) % ring_.size()] = truth;
  const double steps = sampled_time(k) / period_s_;
  const double whole = std::floor(steps + snap_periods);
  double fraction = steps - whole;
  if (fraction < snap_periods) fraction = 0.0;
  const long j = static_cast<long>(whole);
  const Pose2 before = recorded(j);
  if (fraction == 0.0 || j >= k) return before;
  const Pose2 after = recorded(j + 1);
  Pose2 pose;
  pose.position.x = before.position.x + fraction * (after.position.x - before.position.x);
  pose.position.y = before.position.y + fraction * (after.position.y - before.position.y);
  // The state's heading is continuous (not wrapped), so that the blend needs no unwrapping.
  pose.heading_rad = before.heading_rad + fraction * (after.heading_rad - before.heading_rad);
  return pose;
}

}  // namespace smoothsteer::detail
