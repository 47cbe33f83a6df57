#pragma once
// Internal: the transcription of the kinetic tracking reference (kinetic_reference.hpp) as an
// Ipopt TNLP, a linear program.

#include <vector>

#include "ipopt_solve.hpp"
#include "kinetic_error_model.hpp"
#include "smoothsteer/evaluation/kinetic_reference.hpp"

namespace smoothsteer::detail {

//! The path's curvature on each interval, linear in time: at its start, and its rate [1/(m s)].
struct IntervalCurvature {
  std::vector<double> start, rate;
};

//! The LP of `problem` on curvature.start.size() intervals of `model`'s step.
//! finalize_solution() fills `result`.
Ipopt::SmartPtr<Ipopt::TNLP> make_kinetic_reference_nlp(const KineticReferenceProblem& problem,
                                                        const DiscreteKineticModel& model,
                                                        const IntervalCurvature& curvature,
                                                        double time_step_s,
                                                        KineticReference& result);

}  // namespace smoothsteer::detail
