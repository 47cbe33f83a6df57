#include "smoothsteer/baselines/optimal_reaching.hpp"

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "baseline_common.hpp"

namespace smoothsteer {

void ReachingProblem::validate() const {
  const char* owner = "ReachingProblem";
  detail::require(detail::positive_finite(wheelbase_m), owner, "wheelbase_m", wheelbase_m,
                  "must be finite and > 0");
  detail::require(
      detail::positive_finite(steering_angle_bound_rad) && steering_angle_bound_rad < pi / 2.0,
      owner, "steering_angle_bound_rad", steering_angle_bound_rad, "must be in (0, pi/2)");
  detail::require(detail::positive_finite(steering_rate_bound_per_m), owner,
                  "steering_rate_bound_per_m", steering_rate_bound_per_m, "must be finite and > 0");
  detail::require(std::isfinite(initial_lateral_error_m), owner, "initial_lateral_error_m",
                  initial_lateral_error_m, "must be finite");
  detail::require(std::isfinite(initial_heading_rad) && std::abs(initial_heading_rad) < pi / 2.0,
                  owner, "initial_heading_rad", initial_heading_rad,
                  "must be in (-pi/2, pi/2) (the approach is towards the path)");
  detail::require(std::abs(initial_steering_rad) <= steering_angle_bound_rad, owner,
                  "initial_steering_rad", initial_steering_rad,
                  "must satisfy C1: |delta(0)| <= steering_angle_bound_rad");
  detail::require(std::isfinite(terminal_lateral_tolerance_m) && terminal_lateral_tolerance_m >= 0,
                  owner, "terminal_lateral_tolerance_m", terminal_lateral_tolerance_m,
                  "must be finite and >= 0");
  detail::require(
      std::isfinite(terminal_heading_tolerance_rad) && terminal_heading_tolerance_rad >= 0, owner,
      "terminal_heading_tolerance_rad", terminal_heading_tolerance_rad, "must be finite and >= 0");
  detail::require(intervals >= 10 && intervals <= 5000, owner, "intervals", intervals,
                  "must be in [10, 5000]");
  detail::require(max_iterations >= 1, owner, "max_iterations", max_iterations, "must be >= 1");
  detail::require(detail::positive_finite(tolerance), owner, "tolerance", tolerance,
                  "must be finite and > 0");
}

namespace {

using Ipopt::Index;
using Ipopt::Number;

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

StartingTrajectory feedback_trajectory(const ReachingProblem& p) {
  const double swing = p.steering_angle_bound_rad / p.steering_rate_bound_per_m;
  const double look_ahead = 2.0 * p.wheelbase_m + 2.0 * swing + 1.0;
  const double max_curvature = 0.8 * std::tan(p.steering_angle_bound_rad) / p.wheelbase_m;
  const double step = 0.01 * std::min({p.wheelbase_m, swing, look_ahead});
  auto rates = [&](const std::array<double, 3>& x, double u) {
    return std::array<double, 3>{std::sin(x[1]), std::tan(x[2]) / p.wheelbase_m, u};
  };
  auto control = [&](const std::array<double, 3>& x) {
    const double heading = -std::atan(x[0] / look_ahead);
    const double curvature =
        std::clamp(2.0 * (heading - x[1]) / look_ahead, -max_curvature, max_curvature);
    const double steering = std::atan(p.wheelbase_m * curvature);
    return std::clamp(3.0 * (steering - x[2]) / swing, -p.steering_rate_bound_per_m,
                      p.steering_rate_bound_per_m);
  };
  std::vector<std::array<double, 4>> samples;  // e, psi, delta, u every `step` metres
  std::array<double, 3> x{p.initial_lateral_error_m, p.initial_heading_rad, p.initial_steering_rad};
  const int max_steps = static_cast<int>(400.0 * look_ahead / step);
  int last_outside = 0;
  for (int k = 0; k < max_steps; ++k) {
    const double u = control(x);
    samples.push_back({x[0], x[1], x[2], u});
    if (std::abs(x[0]) > 1e-3 || std::abs(x[1]) > 1e-3 || std::abs(x[2]) > 1e-3) last_outside = k;
    if (k - last_outside > static_cast<int>(10.0 * look_ahead / step)) break;
    // RK4 with u held over the step (it is re-evaluated every step).
    const auto k1 = rates(x, u);
    std::array<double, 3> y{};
    for (int c = 0; c < 3; ++c) y[c] = x[c] + 0.5 * step * k1[c];
    const auto k2 = rates(y, u);
    for (int c = 0; c < 3; ++c) y[c] = x[c] + 0.5 * step * k2[c];
    const auto k3 = rates(y, u);
    for (int c = 0; c < 3; ++c) y[c] = x[c] + step * k3[c];
    const auto k4 = rates(y, u);
    for (int c = 0; c < 3; ++c) x[c] += step / 6.0 * (k1[c] + 2.0 * k2[c] + 2.0 * k3[c] + k4[c]);
    x[2] = std::clamp(x[2], -p.steering_angle_bound_rad, p.steering_angle_bound_rad);
  }
  StartingTrajectory start;
  if (last_outside + 1 >= static_cast<int>(samples.size())) return start;  // did not settle
  start.valid = true;
  start.distance_m = std::max(step, (last_outside + 1) * step);
  const int n = p.intervals;
  for (int node = 0; node <= n; ++node) {
    const double position = static_cast<double>(node) / n * (last_outside + 1);
    const auto low = static_cast<std::size_t>(std::floor(position));
    const std::size_t high = std::min(low + 1, samples.size() - 1);
    const double t = position - static_cast<double>(low);
    auto at = [&](int c) { return (1.0 - t) * samples[low][c] + t * samples[high][c]; };
    start.e.push_back(at(0));
    start.psi.push_back(at(1));
    start.delta.push_back(at(2));
    start.u.push_back(at(3));
  }
  return start;
}

// Variable layout: x_k = (e, psi, delta) at z[3k..3k+2] for k = 0..N, u_k at z[3(N+1) + k],
// S at the last index. Constraint rows: 3 trapezoidal defects per interval,
//   d_k = x_{k+1} - x_k - S/(2N) (f(x_k, u_k) + f(x_{k+1}, u_{k+1})),  f = (sin psi, tan delta /
//   lambda, u).
class ReachingNlp final : public Ipopt::TNLP {
 public:
  ReachingNlp(const ReachingProblem& problem, double guess, ReachingSolution& solution,
              const StartingTrajectory* start = nullptr)
      : p_(problem), n_(problem.intervals), guess_(guess), solution_(solution), start_(start) {}

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac, Index& nnz_hess,
                    IndexStyleEnum& style) override {
    n = variable_count();
    m = 3 * n_;
    nnz_jac = 15 * n_;
    nnz_hess = 5 * (n_ + 1);
    style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index, Number* g_l,
                       Number* g_u) override {
    constexpr double free = 1e19;
    for (Index i = 0; i < n; ++i) {
      x_l[i] = -free;
      x_u[i] = free;
    }
    for (int k = 0; k <= n_; ++k) {
      x_l[3 * k + 2] = -p_.steering_angle_bound_rad;
      x_u[3 * k + 2] = p_.steering_angle_bound_rad;
      x_l[u_index(k)] = -p_.steering_rate_bound_per_m;
      x_u[u_index(k)] = p_.steering_rate_bound_per_m;
    }
    const double start[3] = {p_.initial_lateral_error_m, p_.initial_heading_rad,
                             p_.initial_steering_rad};
    for (int c = 0; c < 3; ++c) x_l[c] = x_u[c] = start[c];
    const int last = 3 * n_;
    x_l[last] = -p_.terminal_lateral_tolerance_m;
    x_u[last] = p_.terminal_lateral_tolerance_m;
    x_l[last + 1] = -p_.terminal_heading_tolerance_rad;
    x_u[last + 1] = p_.terminal_heading_tolerance_rad;
    if (!p_.terminal_steering_free) x_l[last + 2] = x_u[last + 2] = 0.0;
    x_l[s_index()] = 1e-3;
    x_u[s_index()] = 1e3;
    for (Index j = 0; j < 3 * n_; ++j) g_l[j] = g_u[j] = 0.0;
    return true;
  }

  bool get_starting_point(Index, bool, Number* x, bool, Number*, Number*, Index, bool,
                          Number*) override {
    if (start_ != nullptr && start_->valid) {
      for (int k = 0; k <= n_; ++k) {
        const auto node = static_cast<std::size_t>(k);
        x[3 * k] = start_->e[node];
        x[3 * k + 1] = start_->psi[node];
        x[3 * k + 2] = start_->delta[node];
        x[u_index(k)] = start_->u[node];
      }
      x[s_index()] = start_->distance_m;
      return true;
    }
    const double start[3] = {p_.initial_lateral_error_m, p_.initial_heading_rad,
                             p_.initial_steering_rad};
    for (int k = 0; k <= n_; ++k) {
      const double fraction = 1.0 - static_cast<double>(k) / n_;
      for (int c = 0; c < 3; ++c) x[3 * k + c] = fraction * start[c];
      x[u_index(k)] = 0.0;
    }
    x[s_index()] = guess_;
    return true;
  }

  bool eval_f(Index, const Number* x, bool, Number& objective) override {
    objective = x[s_index()];
    return true;
  }

  bool eval_grad_f(Index n, const Number*, bool, Number* gradient) override {
    std::fill(gradient, gradient + n, 0.0);
    gradient[s_index()] = 1.0;
    return true;
  }

  bool eval_g(Index, const Number* x, bool, Index, Number* g) override {
    const double half_step = x[s_index()] / (2.0 * n_);
    for (int k = 0; k < n_; ++k) {
      const Number* a = x + 3 * k;
      const Number* b = x + 3 * (k + 1);
      g[3 * k] = b[0] - a[0] - half_step * (std::sin(a[1]) + std::sin(b[1]));
      g[3 * k + 1] = b[1] - a[1] - half_step * (std::tan(a[2]) + std::tan(b[2])) / p_.wheelbase_m;
      g[3 * k + 2] = b[2] - a[2] - half_step * (x[u_index(k)] + x[u_index(k + 1)]);
    }
    return true;
  }

  bool eval_jac_g(Index, const Number* x, bool, Index, Index, Index* rows, Index* columns,
                  Number* values) override {
    Index entry = 0;
    if (values == nullptr) {
      for (int k = 0; k < n_; ++k) {
        const Index a = 3 * k, b = 3 * (k + 1);
        const Index pattern[3][5] = {{a, b, a + 1, b + 1, s_index()},
                                     {a + 1, b + 1, a + 2, b + 2, s_index()},
                                     {a + 2, b + 2, u_index(k), u_index(k + 1), s_index()}};
        for (int c = 0; c < 3; ++c) {
          for (int j = 0; j < 5; ++j) {
            rows[entry] = 3 * k + c;
            columns[entry] = pattern[c][j];
            ++entry;
          }
        }
      }
      return true;
    }
    const double scale = 1.0 / (2.0 * n_);
    const double half_step = x[s_index()] * scale;
    const double lambda = p_.wheelbase_m;
    for (int k = 0; k < n_; ++k) {
      const Number* a = x + 3 * k;
      const Number* b = x + 3 * (k + 1);
      const double sec_a = 1.0 + std::tan(a[2]) * std::tan(a[2]);
      const double sec_b = 1.0 + std::tan(b[2]) * std::tan(b[2]);
      const double rows_values[3][5] = {
          {-1.0, 1.0, -half_step * std::cos(a[1]), -half_step * std::cos(b[1]),
           -scale * (std::sin(a[1]) + std::sin(b[1]))},
          {-1.0, 1.0, -half_step * sec_a / lambda, -half_step * sec_b / lambda,
           -scale * (std::tan(a[2]) + std::tan(b[2])) / lambda},
          {-1.0, 1.0, -half_step, -half_step, -scale * (x[u_index(k)] + x[u_index(k + 1)])}};
      for (int c = 0; c < 3; ++c) {
        for (int j = 0; j < 5; ++j) values[entry++] = rows_values[c][j];
      }
    }
    return true;
  }

  //! Exact Hessian of the Lagrangian (the objective S is linear). Per node j, with Lambda_r(j)
  //! the sum of the multipliers of defect row r of the (one or two) intervals touching node j:
  //!   d2/dpsi_j^2    =  Lambda_0 S/(2N) sin psi_j        d2/dpsi_j dS   = -Lambda_0 cos psi_j/(2N)
  //!   d2/ddelta_j^2  = -Lambda_1 S/(2N lambda) 2 tan delta_j sec^2 delta_j
  //!   d2/ddelta_j dS = -Lambda_1 sec^2 delta_j/(2N lambda)   d2/du_j dS = -Lambda_2/(2N).
  bool eval_h(Index, const Number* x, bool, Number, Index, const Number* multipliers, bool, Index,
              Index* rows, Index* columns, Number* values) override {
    if (values == nullptr) {
      Index entry = 0;
      for (int j = 0; j <= n_; ++j) {
        const Index psi = 3 * j + 1, delta = 3 * j + 2;
        const Index pairs[5][2] = {{psi, psi}, {delta, delta}, {s_index(), psi},
                                   {s_index(), delta}, {s_index(), u_index(j)}};
        for (const auto& pair : pairs) {
          rows[entry] = pair[0];
          columns[entry] = pair[1];
          ++entry;
        }
      }
      return true;
    }
    const double scale = 1.0 / (2.0 * n_);
    const double distance = x[s_index()];
    const double lambda = p_.wheelbase_m;
    Index entry = 0;
    for (int j = 0; j <= n_; ++j) {
      double sum[3] = {0.0, 0.0, 0.0};
      for (int c = 0; c < 3; ++c) {
        if (j >= 1) sum[c] += multipliers[3 * (j - 1) + c];
        if (j < n_) sum[c] += multipliers[3 * j + c];
      }
      const double psi = x[3 * j + 1];
      const double tangent = std::tan(x[3 * j + 2]);
      const double secant_squared = 1.0 + tangent * tangent;
      values[entry++] = sum[0] * distance * scale * std::sin(psi);
      values[entry++] = -sum[1] * distance * scale / lambda * 2.0 * tangent * secant_squared;
      values[entry++] = -sum[0] * scale * std::cos(psi);
      values[entry++] = -sum[1] * scale * secant_squared / lambda;
      values[entry++] = -sum[2] * scale;
    }
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn status, Index, const Number* x, const Number*,
                         const Number*, Index, const Number*, const Number*, Number,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    solution_.converged = status == Ipopt::SUCCESS || status == Ipopt::STOP_AT_ACCEPTABLE_POINT;
    solution_.distance_m = x[s_index()];
    const auto count = static_cast<std::size_t>(n_ + 1);
    solution_.arc_length_m.resize(count);
    solution_.lateral_error_m.resize(count);
    solution_.heading_rad.resize(count);
    solution_.steering_rad.resize(count);
    solution_.steering_rate_per_m.resize(count);
    for (int k = 0; k <= n_; ++k) {
      const auto i = static_cast<std::size_t>(k);
      solution_.arc_length_m[i] = solution_.distance_m * k / n_;
      solution_.lateral_error_m[i] = x[3 * k];
      solution_.heading_rad[i] = x[3 * k + 1];
      solution_.steering_rad[i] = x[3 * k + 2];
      solution_.steering_rate_per_m[i] = x[u_index(k)];
    }
  }

 private:
  Index variable_count() const { return 4 * (n_ + 1) + 1; }
  Index u_index(int k) const { return 3 * (n_ + 1) + k; }
  Index s_index() const { return 4 * (n_ + 1); }

  ReachingProblem p_;
  int n_;
  double guess_;
  ReachingSolution& solution_;
  const StartingTrajectory* start_;
};

const char* status_text(Ipopt::ApplicationReturnStatus status) {
  switch (status) {
    case Ipopt::Solve_Succeeded:
      return "Solve_Succeeded";
    case Ipopt::Solved_To_Acceptable_Level:
      return "Solved_To_Acceptable_Level";
    case Ipopt::Infeasible_Problem_Detected:
      return "Infeasible_Problem_Detected";
    case Ipopt::Maximum_Iterations_Exceeded:
      return "Maximum_Iterations_Exceeded";
    case Ipopt::Restoration_Failed:
      return "Restoration_Failed";
    default:
      return "Ipopt_Error";
  }
}

}  // namespace

namespace {

ReachingSolution solve_with(const ReachingProblem& problem, double guess,
                            const StartingTrajectory* start, bool exact_hessian) {
  ReachingSolution solution;
  Ipopt::SmartPtr<Ipopt::TNLP> nlp = new ReachingNlp(problem, guess, solution, start);
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetIntegerValue("print_level", 0);
  app->Options()->SetStringValue("sb", "yes");
  app->Options()->SetStringValue("hessian_approximation", exact_hessian ? "exact" : "limited-memory");
  if (problem.check_derivatives) {
    app->Options()->SetStringValue("derivative_test", "second-order");
    app->Options()->SetIntegerValue("print_level", 4);
  }
  app->Options()->SetStringValue("mu_strategy", "adaptive");
  app->Options()->SetNumericValue("tol", problem.tolerance);
  app->Options()->SetIntegerValue("max_iter", static_cast<int>(problem.max_iterations));
  // Near bang-bang optima convergence can be slow at the end: accept a point
  // that is feasible to 1e-8 and optimal to 1e-6 for 10 iterations (resimulate_reaching checks
  // the result against C1, C2 and the end state anyway).
  app->Options()->SetNumericValue("acceptable_tol", 1e-6);
  app->Options()->SetNumericValue("acceptable_constr_viol_tol", 1e-8);
  app->Options()->SetIntegerValue("acceptable_iter", 10);
  if (app->Initialize() != Ipopt::Solve_Succeeded) {
    solution.solver_status = "Ipopt initialisation failed";
    return solution;
  }
  const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(nlp);
  solution.solver_status = status_text(status);
  solution.converged =
      status == Ipopt::Solve_Succeeded || status == Ipopt::Solved_To_Acceptable_Level;
  if (Ipopt::SmartPtr<Ipopt::SolveStatistics> statistics = app->Statistics();
      Ipopt::IsValid(statistics)) {
    solution.iterations = statistics->IterationCount();
  }
  return solution;
}

//! One start: Ipopt's L-BFGS first (typically 5-10x faster), capped at 600 iterations, then the
//! exact Hessian if it stalls. Neither alone converges on every random problem (L-BFGS: ~1 in
//! 400 runs into the iteration limit; exact: ~1 in 100 collapses to S -> 0 on coarse grids);
//! together they have on every one tested.
ReachingSolution solve_once(const ReachingProblem& problem, double guess,
                            const StartingTrajectory* start = nullptr) {
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
    const StartingTrajectory start = feedback_trajectory(problem);
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
