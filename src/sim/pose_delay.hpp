#pragma once
// Localization latency of the closed loop (internal to src/sim; SimulationParameters::
// pose_latency_s and pose_rate_hz): the pose delivered at a control instant is the true pose of
// an earlier time, read from a ring buffer of the poses at the control instants, sized at
// set-up by the largest look-back (latency + one pose period) so that it never allocates later.

#include <cstddef>
#include <optional>
#include <vector>

#include "smoothsteer/math/pose2.hpp"

namespace smoothsteer::detail {

class PoseDelay {
 public:
  //! `start` and `speed_mps`: the straight drive before t = 0 that the run starts from.
  PoseDelay(double latency_s, std::optional<double> rate_hz, double control_period_s,
            const Pose2& start, double speed_mps);

  //! false: the pose is delivered as it is (no latency, every step).
  bool active() const noexcept { return active_; }
  //! The time whose true pose is delivered at control step k (t_k = k T).
  double sampled_time(long k) const noexcept;
  //! Records the true pose of step k (called for k = 0, 1, ... in order) and returns the pose
  //! delivered at step k.
  Pose2 deliver(long k, const Pose2& truth) noexcept;

 private:
  Pose2 recorded(long j) const noexcept;

  bool active_ = false;
  double latency_s_;
  std::optional<double> rate_hz_;
  double period_s_;
  Pose2 start_;
  double speed_mps_;
  std::vector<Pose2> ring_;  //!< pose of step j at ring_[j % size]
};

}  // namespace smoothsteer::detail
