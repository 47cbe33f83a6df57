#include "smoothsteer/evaluation/kinetic_reference.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kinetic_error_model.hpp"
#include "kinetic_reference_nlp.hpp"

namespace smoothsteer {

std::optional<Violation> KineticReferenceProblem::first_violation() const noexcept {
  if (auto broken = vehicle.first_violation()) return broken;
  RuleChecker check("KineticReferenceProblem");
  check.require_positive({{"speed_mps", speed_mps}, {"duration_s", duration_s}});
  check.require(std::isfinite(start_arc_length_m), "start_arc_length_m", start_arc_length_m,
                "must be finite");
  check.require(positive_finite(time_step_s) && time_step_s <= 0.1, "time_step_s", time_step_s,
                "must be in (0, 0.1]");
  check.require(std::isfinite(duration_s / time_step_s) && duration_s / time_step_s <= 20000.0,
                "duration_s", duration_s, "must be at most 20000 time steps");
  check.require(max_iterations >= 1, "max_iterations", max_iterations, "must be >= 1");
  check.require_positive({{"tolerance", tolerance}});
  return check.first();
}

std::string KineticReferenceProblem::validation_error() const {
  if (!path) return "KineticReferenceProblem: path must be set";
  return describe(first_violation());
}

void KineticReferenceProblem::validate() const {
  if (const std::string error = validation_error(); !error.empty()) {
    throw std::invalid_argument(error);
  }
}

namespace {

//! The path's curvature at arc length s: beyond an open path's ends it runs straight on.
double curvature_at(const Path& path, double s) noexcept {
  if (!path.is_closed() && (s < 0.0 || s > path.length())) return 0.0;
  return path.evaluate(s).curvature;
}

}  // namespace

KineticReference solve_kinetic_reference(const KineticReferenceProblem& problem) {
  problem.validate();
  const int intervals =
      std::max(1, static_cast<int>(std::ceil(problem.duration_s / problem.time_step_s - 1e-9)));
  const double h = problem.duration_s / intervals;
  const detail::DiscreteKineticModel model =
      detail::discretise(detail::kinetic_error_model(problem.vehicle, problem.speed_mps), h);
  // The car progresses along the path at v (its errors small). On each interval kappa is taken
  // linear in time: its slope between the interval's ends and its mean by Simpson's rule, so that
  // an interval across a joint of two pieces still turns the path's heading by the right angle.
  detail::IntervalCurvature curvature;
  auto kappa = [&](double t) {
    return curvature_at(*problem.path, problem.start_arc_length_m + problem.speed_mps * t);
  };
  constexpr int simpson_panels = 8;
  for (int k = 0; k < intervals; ++k) {
    const double t0 = h * k;
    double mean = 0.0;
    for (int j = 0; j <= simpson_panels; ++j) {
      const double weight = (j == 0 || j == simpson_panels) ? 1.0 : (j % 2 == 1 ? 4.0 : 2.0);
      mean += weight * kappa(t0 + h * j / simpson_panels);
    }
    mean /= 3.0 * simpson_panels;
    const double rate = (kappa(t0 + h) - kappa(t0)) / h;
    curvature.start.push_back(mean - 0.5 * h * rate);
    curvature.rate.push_back(rate);
  }
  KineticReference reference;
  Ipopt::SmartPtr<Ipopt::TNLP> nlp =
      detail::make_kinetic_reference_nlp(problem, model, curvature, h, reference);
  const detail::IpoptOutcome outcome =
      detail::solve_nlp(nlp, {problem.tolerance, problem.max_iterations, true, false});
  reference.converged = outcome.converged;
  reference.solver_status = outcome.status;
  reference.iterations = outcome.iterations;
  return reference;
}

KineticReferenceCheck resimulate_kinetic_reference(const KineticReferenceProblem& problem,
                                                   const KineticReference& reference,
                                                   int substeps) {
  const detail::KineticErrorModel model =
      detail::kinetic_error_model(problem.vehicle, problem.speed_mps);
  const double h = reference.time_step_s / std::max(1, substeps);
  KineticReferenceCheck check;
  detail::KineticState x = detail::KineticState::Zero();
  for (std::size_t k = 0; k < reference.steering_acceleration_radps2.size(); ++k) {
    const double u = reference.steering_acceleration_radps2[k];
    check.max_node_lateral_deviation_m =
        std::max(check.max_node_lateral_deviation_m, std::abs(x(0) - reference.lateral_error_m[k]));
    for (int j = 0; j < std::max(1, substeps); ++j) {
      const double t = reference.time_s[k] + h * j;
      auto kappa = [&](double time) {
        return curvature_at(*problem.path, problem.start_arc_length_m + problem.speed_mps * time);
      };
      const detail::KineticState k1 = model.rates(x, u, kappa(t));
      const detail::KineticState k2 = model.rates(x + 0.5 * h * k1, u, kappa(t + 0.5 * h));
      const detail::KineticState k3 = model.rates(x + 0.5 * h * k2, u, kappa(t + 0.5 * h));
      const detail::KineticState k4 = model.rates(x + h * k3, u, kappa(t + h));
      x += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      check.max_abs_lateral_error_m = std::max(check.max_abs_lateral_error_m, std::abs(x(0)));
    }
  }
  if (!reference.lateral_error_m.empty()) {
    check.max_node_lateral_deviation_m = std::max(
        check.max_node_lateral_deviation_m, std::abs(x(0) - reference.lateral_error_m.back()));
  }
  return check;
}

}  // namespace smoothsteer
