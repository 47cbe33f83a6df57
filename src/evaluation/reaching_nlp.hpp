#pragma once
//! Internal: the trapezoidal-collocation NLP of the optimal reaching manoeuvre, as an Ipopt TNLP.

#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>

#include <mutex>

#include "reaching_start.hpp"
#include "smoothsteer/evaluation/optimal_reaching.hpp"

namespace smoothsteer::detail {

//! The NLP for `problem`, starting from `start` if given (else a straight interpolation of the
//! initial state to 0 over S = guess). Ipopt's finalize_solution() fills `solution`.
Ipopt::SmartPtr<Ipopt::TNLP> make_reaching_nlp(const ReachingProblem& problem, double guess,
                                               ReachingSolution& solution,
                                               const StartingTrajectory* start);

//! Ipopt's return status as text.
const char* status_text(Ipopt::ApplicationReturnStatus status);

//! Held around every Ipopt solve of the process: this build's MUMPS (the sequential libdmumps
//! with its MPI stub) keeps global state, so two solves must not run at the same time.
std::mutex& ipopt_mutex();

}  // namespace smoothsteer::detail
