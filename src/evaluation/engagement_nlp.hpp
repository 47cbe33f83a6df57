#pragma once
// Internal: the transcription of the engagement bound (engagement_bound.hpp) as an Ipopt TNLP,
// and the trajectories it starts from and returns.

#include <vector>

#include "ipopt_solve.hpp"
#include "smoothsteer/evaluation/engagement_bound.hpp"

namespace smoothsteer::detail {

//! Node values (N + 1 each) of s, e, psi, delta, r and the held u of the N intervals.
struct EngagementTrajectory {
  double time_step_s = 0.0;
  std::vector<double> s, e, psi, delta, r, u;
  int intervals() const noexcept { return static_cast<int>(u.size()); }
};

//! The NLP of `problem` on the grid of `start` (whose node 0 is the fixed initial state),
//! starting from `start`. finalize_solution() fills `result`'s trajectory and bound.
Ipopt::SmartPtr<Ipopt::TNLP> make_engagement_nlp(const EngagementBoundProblem& problem,
                                                 const EngagementTrajectory& start,
                                                 EngagementBound& result);

}  // namespace smoothsteer::detail
