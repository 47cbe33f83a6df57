#include "smoothsteer/evaluation/engagement_bound.hpp"
#include <algorithm>
#include <chrono>
#include <cmath>

#include "engagement_model.hpp"
#include "engagement_nlp.hpp"
#include "smoothsteer/math/angles.hpp"

namespace smoothsteer {

std::optional<Violation> EngagementBoundProblem::first_violation() const noexcept {
  RuleChecker check("EngagementBoundProblem");
  check.require_positive({{"wheelbase_m", wheelbase_m}, {"speed_mps", speed_mps}});
  check.require(positive_finite(steering_angle_bound_rad) && steering_angle_bound_rad < pi / 2.0,
                "steering_angle_bound_rad", steering_angle_bound_rad, "must be in (0, pi/2)");
  check.require_positive(
      {{"steering_rate_bound_radps", steering_rate_bound_radps},
       {"steering_acceleration_bound_radps2", steering_acceleration_bound_radps2}});
  check.require(std::isfinite(start.position.x) && std::isfinite(start.position.y), "start",
                start.position.x, "must have a finite position");
  check.require(std::isfinite(start.heading_rad), "start.heading_rad", start.heading_rad,
                "must be finite");
  check.require(std::abs(initial_steering_rad) <= steering_angle_bound_rad, "initial_steering_rad",
                initial_steering_rad, "must satisfy |delta(0)| <= steering_angle_bound_rad");
  check.require(std::abs(initial_steering_rate_radps) <= steering_rate_bound_radps,
                "initial_steering_rate_radps", initial_steering_rate_radps,
                "must satisfy |r(0)| <= steering_rate_bound_radps");
  check.require_positive({{"duration_s", duration_s}});
  // The starting trajectory's inner loop needs h well below its 0.1 s time constant.
  check.require(positive_finite(time_step_s) && time_step_s <= 0.05, "time_step_s", time_step_s,
                "must be in (0, 0.05]");
  check.require(std::isfinite(duration_s / time_step_s) && duration_s / time_step_s <= 20000.0,
                "duration_s", duration_s, "must be at most 20000 time steps");
  check.require(max_iterations >= 1, "max_iterations", max_iterations, "must be >= 1");
  check.require_positive({{"tolerance", tolerance}});
  return check.first();
}

std::string EngagementBoundProblem::validation_error() const {
  if (!path) return "EngagementBoundProblem: path must be set";
  return describe(first_violation());
}

void EngagementBoundProblem::validate() const {
  if (const std::string error = validation_error(); !error.empty()) {
    throw std::invalid_argument(error);
  }
}

EngagementStart engagement_start(const EngagementBoundProblem& problem) {
  const PathProjection projection = problem.path->project(problem.start.position);
  return {projection.arc_length_m, projection.lateral_error_m,
          wrap_angle(problem.start.heading_rad - projection.heading_rad)};
}

namespace {

//! One RK4 step of the path-coordinate model (s, e, psi, delta, r) under the held u.
void frenet_step(const EngagementBoundProblem& p, double state[5], double u, double h) {
  auto derivative = [&](const double x[5], double out[5]) {
    const detail::FrenetRates f = detail::frenet_rates(
        p.speed_mps, p.wheelbase_m, detail::path_curvature(*p.path, x[0]), x[1], x[2], x[3]);
    std::copy(f.rate, f.rate + 3, out);
    out[3] = x[4];
    out[4] = u;
  };
  detail::rk4_step(state, h, derivative);
}

//! The starting trajectory: a saturated cascade feedback on the grid, each loop about three
//! times faster than the one around it (aim at the path within 2.5 s, heading in 0.8 s, angle in
//! 0.15 s, rate in 0.1 s), every command inside the limits, so the NLP starts feasible.
detail::EngagementTrajectory feedback_trajectory(const EngagementBoundProblem& p,
                                                 const EngagementStart& start, int intervals,
                                                 double h) {
  detail::EngagementTrajectory t;
  t.time_step_s = h;
  double x[5] = {start.arc_length_m, start.lateral_error_m, start.heading_error_rad,
                 p.initial_steering_rad, p.initial_steering_rate_radps};
  auto record = [&] {
    t.s.push_back(x[0]);
    t.e.push_back(x[1]);
    t.psi.push_back(x[2]);
    t.delta.push_back(x[3]);
    t.r.push_back(x[4]);
  };
  record();
  const double v = p.speed_mps;
  for (int k = 0; k < intervals; ++k) {
    const detail::PathCurvature c = detail::path_curvature(*p.path, x[0]);
    const double aim = -std::asin(std::clamp(x[1] / (2.5 * v), -0.5, 0.5));
    const double heading_rate = (aim - x[2]) / 0.8;
    const double s_dot = v * std::cos(x[2]) / (1.0 - c.kappa * x[1]);
    const double curvature = (c.kappa * s_dot + heading_rate) / v;
    const double angle =
        std::clamp(std::atan(p.wheelbase_m * curvature), -0.9 * p.steering_angle_bound_rad,
                   0.9 * p.steering_angle_bound_rad);
    const double rate = std::clamp((angle - x[3]) / 0.15, -0.9 * p.steering_rate_bound_radps,
                                   0.9 * p.steering_rate_bound_radps);
    const double u =
        std::clamp((rate - x[4]) / std::max(0.1, 2.0 * h), -p.steering_acceleration_bound_radps2,
                   p.steering_acceleration_bound_radps2);
    t.u.push_back(u);
    frenet_step(p, x, u, h);
    record();
  }
  return t;
}

EngagementBound solve_with(const EngagementBoundProblem& problem,
                           const detail::EngagementTrajectory& start, bool exact_hessian) {
  EngagementBound bound;
  Ipopt::SmartPtr<Ipopt::TNLP> nlp = detail::make_engagement_nlp(problem, start, bound);
  const detail::IpoptOutcome outcome = detail::solve_nlp(
      nlp, {problem.tolerance, problem.max_iterations, exact_hessian, problem.check_derivatives});
  bound.solver_status = outcome.status;
  bound.converged = outcome.converged;
  bound.iterations = outcome.iterations;
  return bound;
}

}  // namespace

EngagementBound solve_engagement_bound(const EngagementBoundProblem& problem) {
  problem.validate();
  const auto begin = std::chrono::steady_clock::now();
  const int intervals =
      static_cast<int>(std::ceil(problem.duration_s / problem.time_step_s - 1e-9));
  const double h = problem.duration_s / intervals;
  const detail::EngagementTrajectory start =
      feedback_trajectory(problem, engagement_start(problem), intervals, h);

  // The exact Hessian first (tens of iterations); Ipopt's L-BFGS from the same start if it fails.
  EngagementBound bound = solve_with(problem, start, true);
  if (!bound.converged) {
    const int iterations = bound.iterations;
    bound = solve_with(problem, start, false);
    bound.iterations += iterations;
  }
  bound.solve_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  return bound;
}

EngagementBoundCheck resimulate_engagement_bound(const EngagementBoundProblem& p,
                                                 const EngagementBound& bound, int substeps) {
  EngagementBoundCheck check;
  const std::size_t intervals = bound.steering_acceleration_radps2.size();
  if (intervals == 0 || substeps < 1 || bound.lateral_error_m.size() != intervals + 1) return check;
  // (x, y, theta, delta, r) in the world frame: independent of the path coordinates of the NLP.
  double x[5] = {p.start.position.x, p.start.position.y, p.start.heading_rad,
                 p.initial_steering_rad, p.initial_steering_rate_radps};
  const double v = p.speed_mps, h = bound.time_step_s / substeps;
  ProjectionHint hint;
  auto lateral_error = [&] { return p.path->project({x[0], x[1]}, hint).lateral_error_m; };
  auto note_limits = [&](double u) {
    check.max_steering_excess_rad =
        std::max(check.max_steering_excess_rad, std::abs(x[3]) - p.steering_angle_bound_rad);
    check.max_rate_excess_radps =
        std::max(check.max_rate_excess_radps, std::abs(x[4]) - p.steering_rate_bound_radps);
    check.max_acceleration_excess_radps2 = std::max(
        check.max_acceleration_excess_radps2, std::abs(u) - p.steering_acceleration_bound_radps2);
  };
  check.max_abs_lateral_error_m = std::abs(lateral_error());
  for (std::size_t k = 0; k < intervals; ++k) {
    const double u = bound.steering_acceleration_radps2[k];
    auto derivative = [&](const double y[5], double out[5]) {
      out[0] = v * std::cos(y[2]);
      out[1] = v * std::sin(y[2]);
      out[2] = v * std::tan(y[3]) / p.wheelbase_m;
      out[3] = y[4];
      out[4] = u;
    };
    for (int j = 0; j < substeps; ++j) {
      detail::rk4_step(x, h, derivative);
      note_limits(u);
      check.max_abs_lateral_error_m =
          std::max(check.max_abs_lateral_error_m, std::abs(lateral_error()));
    }
    check.max_node_lateral_deviation_m =
        std::max(check.max_node_lateral_deviation_m,
                 std::abs(lateral_error() - bound.lateral_error_m[k + 1]));
  }
  check.max_steering_excess_rad = std::max(0.0, check.max_steering_excess_rad);
  check.max_rate_excess_radps = std::max(0.0, check.max_rate_excess_radps);
  check.max_acceleration_excess_radps2 = std::max(0.0, check.max_acceleration_excess_radps2);
  return check;
}

}  // namespace smoothsteer
