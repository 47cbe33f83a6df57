#include "smoothsteer/evaluation/optimal_reaching.hpp"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "reaching_nlp.hpp"
#include "reaching_start.hpp"
#include "smoothsteer/baselines/parameter_checks.hpp"

namespace smoothsteer {

std::optional<Violation> ReachingProblem::first_violation() const noexcept {
  RuleChecker check("ReachingProblem");
  detail::require_x_ext_limits(check, wheelbase_m, steering_angle_bound_rad,
                               steering_rate_bound_per_m);
  check.require(std::isfinite(initial_lateral_error_m), "initial_lateral_error_m",
                initial_lateral_error_m, "must be finite");
  check.require(std::isfinite(initial_heading_rad) && std::abs(initial_heading_rad) < pi / 2.0,
                "initial_heading_rad", initial_heading_rad,
                "must be in (-pi/2, pi/2) (the approach is towards the path)");
  check.require(std::abs(initial_steering_rad) <= steering_angle_bound_rad, "initial_steering_rad",
                initial_steering_rad, "must satisfy C1: |delta(0)| <= steering_angle_bound_rad");
  check.require(std::isfinite(terminal_lateral_tolerance_m) && terminal_lateral_tolerance_m >= 0,
                "terminal_lateral_tolerance_m", terminal_lateral_tolerance_m,
                "must be finite and >= 0");
  check.require(
      std::isfinite(terminal_heading_tolerance_rad) && terminal_heading_tolerance_rad >= 0,
      "terminal_heading_tolerance_rad", terminal_heading_tolerance_rad, "must be finite and >= 0");
  check.require(intervals >= 10 && intervals <= 5000, "intervals", intervals,
                "must be in [10, 5000]");
  check.require(max_iterations >= 1, "max_iterations", max_iterations, "must be >= 1");
  check.require_positive({{"tolerance", tolerance}});
  return check.first();
}

namespace {

ReachingSolution solve_with(const ReachingProblem& problem, double guess,
                            const detail::StartingTrajectory* start, bool exact_hessian) {
  ReachingSolution solution;
  Ipopt::SmartPtr<Ipopt::TNLP> nlp = detail::make_reaching_nlp(problem, guess, solution, start);
  const detail::IpoptOutcome outcome =
      detail::solve_nlp(nlp, {problem.tolerance, static_cast<int>(problem.max_iterations),
                              exact_hessian, problem.check_derivatives});
  solution.solver_status = outcome.status;
  solution.converged = outcome.converged;
  solution.iterations = outcome.iterations;
  return solution;
}

//! One start: Ipopt's L-BFGS first (typically 5-10x faster), capped at 600 iterations, then the
//! exact Hessian if it stalls. Neither alone converges on every random problem (L-BFGS: ~1 in
//! 400 runs into the iteration limit; exact: ~1 in 100 collapses to S -> 0 on coarse grids);
//! together they have on every one tested.
ReachingSolution solve_once(const ReachingProblem& problem, double guess,
                            const detail::StartingTrajectory* start = nullptr) {
  if (!problem.exact_hessian) return solve_with(problem, guess, start, false);
  ReachingProblem quick = problem;
  quick.max_iterations = std::min(problem.max_iterations, 600.0);
  ReachingSolution solution = solve_with(quick, guess, start, false);
  if (!solution.converged) {
    const int iterations = solution.iterations;
    solution = solve_with(problem, guess, start, true);
    solution.iterations += iterations;
  }
  return solution;
}

}  // namespace

ReachingSolution solve_optimal_reaching(const ReachingProblem& problem, double distance_guess_m) {
  problem.validate();
  double guess = distance_guess_m;
  if (!(guess > 0.0)) {
    guess = 2.0 * std::abs(problem.initial_lateral_error_m) +
            4.0 * problem.wheelbase_m * std::abs(problem.initial_heading_rad) + 1.0;
  }
  // The NLP is non-convex: from a poor guess of S Ipopt can stall in an infeasible point. A few
  // restarts from longer and shorter guesses; the shortest converged S wins.
  const auto begin = std::chrono::steady_clock::now();
  ReachingSolution best;
  int iterations = 0;
  // Second chance for the rare problem where all of these stall: the feasible feedback
  // trajectory as the starting point.
  for (const double factor : {1.0, 2.0, 0.5, 4.0}) {
    ReachingSolution candidate = solve_once(problem, factor * guess);
    iterations += candidate.iterations;
    if (candidate.converged && (!best.converged || candidate.distance_m < best.distance_m)) {
      best = std::move(candidate);
    } else if (!best.converged && best.solver_status.empty()) {
      best = std::move(candidate);
    }
    if (best.converged && factor >= 2.0) break;
  }
  if (!best.converged) {
    const detail::StartingTrajectory start = detail::feedback_trajectory(problem);
    if (start.valid) {
      ReachingSolution candidate = solve_once(problem, start.distance_m, &start);
      iterations += candidate.iterations;
      if (candidate.converged) best = std::move(candidate);
    }
  }
  best.iterations = iterations;
  best.solve_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  return best;
}

ReachingCheck resimulate_reaching(const ReachingProblem& problem, const ReachingSolution& solution,
                                  int substeps) {
  ReachingCheck check;
  const std::size_t nodes = solution.steering_rate_per_m.size();
  if (nodes < 2 || substeps < 1) return check;
  const double lambda = problem.wheelbase_m;
  double e = problem.initial_lateral_error_m, psi = problem.initial_heading_rad,
         delta = problem.initial_steering_rad;
  auto note = [&](double steering, double rate) {
    check.max_steering_excess_rad = std::max(check.max_steering_excess_rad,
                                             std::abs(steering) - problem.steering_angle_bound_rad);
    check.max_rate_excess_per_m =
        std::max(check.max_rate_excess_per_m, std::abs(rate) - problem.steering_rate_bound_per_m);
  };
  const double h = solution.distance_m / static_cast<double>(nodes - 1) / substeps;
  for (std::size_t k = 0; k + 1 < nodes; ++k) {
    // Zero-order hold of the interval mean: exactly what the trapezoidal defect of delta
    // integrates, so delta is piecewise linear and C1 at the nodes implies C1 everywhere.
    const double mean =
        0.5 * (solution.steering_rate_per_m[k] + solution.steering_rate_per_m[k + 1]);
    const double u0 = mean, u1 = mean;
    for (int j = 0; j < substeps; ++j) {
      auto control = [&](double fraction) { return u0 + (u1 - u0) * fraction; };
      const double f0 = static_cast<double>(j) / substeps, f1 = (j + 1.0) / substeps;
      const double fm = 0.5 * (f0 + f1);
      // RK4 on (e, psi, delta) with u(s) linear in the interval.
      auto derivative = [&](double pe, double pp, double pd, double u, double out[3]) {
        (void)pe;
        out[0] = std::sin(pp);
        out[1] = std::tan(pd) / lambda;
        out[2] = u;
      };
      double k1[3], k2[3], k3[3], k4[3];
      derivative(e, psi, delta, control(f0), k1);
      derivative(e + 0.5 * h * k1[0], psi + 0.5 * h * k1[1], delta + 0.5 * h * k1[2], control(fm),
                 k2);
      derivative(e + 0.5 * h * k2[0], psi + 0.5 * h * k2[1], delta + 0.5 * h * k2[2], control(fm),
                 k3);
      derivative(e + h * k3[0], psi + h * k3[1], delta + h * k3[2], control(f1), k4);
      e += h / 6.0 * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0]);
      psi += h / 6.0 * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1]);
      delta += h / 6.0 * (k1[2] + 2.0 * k2[2] + 2.0 * k3[2] + k4[2]);
      note(delta, control(f1));
    }
  }
  check.max_steering_excess_rad = std::max(0.0, check.max_steering_excess_rad);
  check.max_rate_excess_per_m = std::max(0.0, check.max_rate_excess_per_m);
  check.final_lateral_error_m = e;
  check.final_heading_rad = psi;
  check.final_steering_rad = delta;
  return check;
}

}  // namespace smoothsteer
