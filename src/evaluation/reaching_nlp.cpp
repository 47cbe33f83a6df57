#include "reaching_nlp.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace smoothsteer::detail {
namespace {

using Ipopt::Index;
using Ipopt::Number;

// Variable layout: x_k = (e, psi, delta) at z[3k..3k+2] for k = 0..N, u_k at z[3(N+1) + k],
// S at the last index. Constraint rows: 3 trapezoidal defects per interval,
//   d_k = x_{k+1} - x_k - S/(2N) (f(x_k, u_k) + f(x_{k+1}, u_{k+1})),  f = (sin psi, tan delta /
//   lambda, u).
class ReachingNlp final : public MinimumOfVariableNlp {
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

  void jacobian_pattern(Index* rows, Index* columns) const override {
    Index entry = 0;
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
  }

  void jacobian_values(const Number* x, Number* values) const override {
    Index entry = 0;
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
  }

  //! Exact Hessian of the Lagrangian (the objective S is linear). Per node j, with Lambda_r(j)
  //! the sum of the multipliers of defect row r of the (one or two) intervals touching node j:
  //!   d2/dpsi_j^2    =  Lambda_0 S/(2N) sin psi_j        d2/dpsi_j dS   = -Lambda_0 cos psi_j/(2N)
  //!   d2/ddelta_j^2  = -Lambda_1 S/(2N lambda) 2 tan delta_j sec^2 delta_j
  //!   d2/ddelta_j dS = -Lambda_1 sec^2 delta_j/(2N lambda)   d2/du_j dS = -Lambda_2/(2N).
  void hessian_pattern(Index* rows, Index* columns) const override {
    Index entry = 0;
    for (int j = 0; j <= n_; ++j) {
      const Index psi = 3 * j + 1, delta = 3 * j + 2;
      const Index pairs[5][2] = {{psi, psi},
                                 {delta, delta},
                                 {s_index(), psi},
                                 {s_index(), delta},
                                 {s_index(), u_index(j)}};
      append_pattern(pairs, rows, columns, entry);
    }
  }

  void hessian_values(const Number* x, const Number* multipliers, Number* values) const override {
    const double scale = 1.0 / (2.0 * n_);
    const double distance = x[s_index()];
    const double lambda = p_.wheelbase_m;
    Index entry = 0;
    for (int j = 0; j <= n_; ++j) {
      const std::array<double, 3> sum = node_multipliers(multipliers, j, n_, 3);
      const double psi = x[3 * j + 1];
      const double tangent = std::tan(x[3 * j + 2]);
      const double secant_squared = 1.0 + tangent * tangent;
      values[entry++] = sum[0] * distance * scale * std::sin(psi);
      values[entry++] = -sum[1] * distance * scale / lambda * 2.0 * tangent * secant_squared;
      values[entry++] = -sum[0] * scale * std::cos(psi);
      values[entry++] = -sum[1] * scale * secant_squared / lambda;
      values[entry++] = -sum[2] * scale;
    }
  }

  void finalize_solution(Ipopt::SolverReturn status, Index, const Number* x, const Number*,
                         const Number*, Index, const Number*, const Number*, Number,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    solution_.converged = converged(status);
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
  Index objective_index() const override { return s_index(); }
  Index variable_count() const { return 4 * (n_ + 1) + 1; }
  Index u_index(int k) const { return 3 * (n_ + 1) + k; }
  Index s_index() const { return 4 * (n_ + 1); }

  ReachingProblem p_;
  int n_;
  double guess_;
  ReachingSolution& solution_;
  const StartingTrajectory* start_;
};

}  // namespace

Ipopt::SmartPtr<Ipopt::TNLP> make_reaching_nlp(const ReachingProblem& problem, double guess,
                                               ReachingSolution& solution,
                                               const StartingTrajectory* start) {
  return new ReachingNlp(problem, guess, solution, start);
}

}  // namespace smoothsteer::detail
