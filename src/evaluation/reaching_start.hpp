#pragma once
//! Internal: a dynamically feasible starting trajectory for the optimal reaching NLP.

#include <vector>

#include "smoothsteer/evaluation/optimal_reaching.hpp"

namespace smoothsteer::detail {

//! A dynamically feasible starting trajectory on the N + 1 nodes (e, psi, delta, u per node) and
//! its length S. x_ext is driven by a saturated cascade feedback: aim at the path with look-ahead
//! L, turn the heading towards it at 2/L, and steer towards the curvature that needs, within C1
//! and C2. L is long against lambda and against the steering swing delta-bar / delta-bar', so the
//! inner loops are faster than the outer one. S is the distance after which the state stays
//! within 1e-3 of 0.
struct StartingTrajectory {
  bool valid = false;
  double distance_m = 0.0;
  std::vector<double> e, psi, delta, u;
};

StartingTrajectory feedback_trajectory(const ReachingProblem& p);

}  // namespace smoothsteer::detail
