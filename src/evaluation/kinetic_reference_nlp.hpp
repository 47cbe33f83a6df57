#pragma once
// Internal: the transcription of the kinetic tracking reference (kinetic_reference.hpp) as an
// Ipopt TNLP, a linear program.

#include <vector>

#include "ipopt_solve.hpp"
#include "kinetic_error_model.hpp"
#include "smoothsteer/evaluation/kinetic_reference.hpp"

namespace smoothsteer::detail {

//! The LP of `problem` on `intervals` intervals of `model`'s step, the path's curvature held at
//! each interval's middle (`curvature`, one per interval). finalize_solution() fills `result`.
Ipopt::SmartPtr<Ipopt::TNLP> make_kinetic_reference_nlp(const KineticReferenceProblem& problem,
                                                        const DiscreteKineticModel& model,
                                                        const std::vector<double>& curvature,
                                                        double time_step_s,
                                                        KineticReference& result);

}  // namespace smoothsteer::detail
