#pragma once
//! Internal: the trapezoidal-collocation NLP of the optimal reaching manoeuvre, as an Ipopt TNLP.

#include "ipopt_solve.hpp"
#include "reaching_start.hpp"
#include "smoothsteer/evaluation/optimal_reaching.hpp"

namespace smoothsteer::detail {

//! The NLP for `problem`, starting from `start` if given (else a straight interpolation of the
//! initial state to 0 over S = guess). Ipopt's finalize_solution() fills `solution`.
Ipopt::SmartPtr<Ipopt::TNLP> make_reaching_nlp(const ReachingProblem& problem, double guess,
                                               ReachingSolution& solution,
                                               const StartingTrajectory* start);

}  // namespace smoothsteer::detail
