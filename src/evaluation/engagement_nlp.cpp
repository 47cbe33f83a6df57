#include "engagement_nlp.hpp"

#include <algorithm>
#include <array>

#include "engagement_model.hpp"

namespace smoothsteer::detail {
namespace {

using Ipopt::Index;
using Ipopt::Number;

constexpr int state_count = 5;  // s, e, psi, delta, r
constexpr double unbounded = 1e19;

// Variable layout: node k holds (s, e, psi, delta, r) at x[5k .. 5k + 4] for k = 0..N, the held
// u of interval k sits at x[5(N + 1) + k], z is the last. Rows: 5 defects per interval,
//   kinematics  x_{k+1} - x_k - h/2 (f(x_k) + f(x_{k+1}))   for (s, e, psi), f = frenet_rates,
//   delta       delta_{k+1} - delta_k - h/2 (r_k + r_{k+1}),
//   r           r_{k+1} - r_k - h u_k,
// then 2 rows per node, e_k - z <= 0 and -e_k - z <= 0.
class EngagementNlp final : public MinimumOfVariableNlp {
 public:
  EngagementNlp(const EngagementBoundProblem& problem, const EngagementTrajectory& start,
                EngagementBound& result)
      : p_(problem), start_(start), result_(result), n_(start.intervals()), h_(start.time_step_s) {}

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac, Index& nnz_hess,
                    IndexStyleEnum& style) override {
    n = z_index() + 1;
    m = state_count * n_ + 2 * (n_ + 1);
    nnz_jac = 31 * n_ + 4 * (n_ + 1);
    nnz_hess = 7 * (n_ + 1);
    style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l,
                       Number* g_u) override {
    std::fill(x_l, x_l + n, -unbounded);
    std::fill(x_u, x_u + n, unbounded);
    for (int k = 0; k <= n_; ++k) {
      x_l[5 * k + 3] = -p_.steering_angle_bound_rad;
      x_u[5 * k + 3] = p_.steering_angle_bound_rad;
      x_l[5 * k + 4] = -p_.steering_rate_bound_radps;
      x_u[5 * k + 4] = p_.steering_rate_bound_radps;
    }
    for (int k = 0; k < n_; ++k) {
      x_l[u_index(k)] = -p_.steering_acceleration_bound_radps2;
      x_u[u_index(k)] = p_.steering_acceleration_bound_radps2;
    }
    const double initial[state_count] = {start_.s[0], start_.e[0], start_.psi[0], start_.delta[0],
                                         start_.r[0]};
    for (int c = 0; c < state_count; ++c) x_l[c] = x_u[c] = initial[c];
    x_l[z_index()] = 0.0;
    const Index defects = state_count * n_;
    std::fill(g_l, g_l + defects, 0.0);
    std::fill(g_u, g_u + defects, 0.0);
    std::fill(g_l + defects, g_l + m, -unbounded);
    std::fill(g_u + defects, g_u + m, 0.0);
    return true;
  }

  bool get_starting_point(Index, bool, Number* x, bool, Number*, Number*, Index, bool,
                          Number*) override {
    double largest = 0.0;
    for (int k = 0; k <= n_; ++k) {
      const auto i = static_cast<std::size_t>(k);
      const double node[state_count] = {start_.s[i], start_.e[i], start_.psi[i], start_.delta[i],
                                        start_.r[i]};
      std::copy(node, node + state_count, x + 5 * k);
      largest = std::max(largest, std::abs(start_.e[i]));
    }
    for (int k = 0; k < n_; ++k) x[u_index(k)] = start_.u[static_cast<std::size_t>(k)];
    // Strictly inside the path rows, where an interior-point method starts best.
    x[z_index()] = largest + 0.01;
    return true;
  }

  bool eval_g(Index, const Number* x, bool, Index, Number* g) override {
    FrenetRates a = rates(x, 0);
    for (int k = 0; k < n_; ++k) {
      const FrenetRates b = rates(x, k + 1);
      const Number* xa = x + 5 * k;
      const Number* xb = x + 5 * (k + 1);
      Number* row = g + state_count * k;
      for (int i = 0; i < 3; ++i) row[i] = xb[i] - xa[i] - 0.5 * h_ * (a.rate[i] + b.rate[i]);
      row[3] = xb[3] - xa[3] - 0.5 * h_ * (xa[4] + xb[4]);
      row[4] = xb[4] - xa[4] - h_ * x[u_index(k)];
      a = b;
    }
    min_max_rows().evaluate(x, g);
    return true;
  }

  void jacobian_pattern(Index* rows, Index* columns) const override {
    SparsityWriter pattern{rows, columns};
    for (int k = 0; k < n_; ++k) {
      const Index a = 5 * k, b = 5 * (k + 1), row = state_count * k;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) pattern.add(row + i, a + j);
        for (int j = 0; j < 4; ++j) pattern.add(row + i, b + j);
      }
      pattern.add(row + 3, a + 3);
      pattern.add(row + 3, b + 3);
      pattern.add(row + 3, a + 4);
      pattern.add(row + 3, b + 4);
      pattern.add(row + 4, a + 4);
      pattern.add(row + 4, b + 4);
      pattern.add(row + 4, u_index(k));
    }
    min_max_rows().append_pattern(pattern);
  }

  void jacobian_values(const Number* x, Number* values) const override {
    Index entry = 0;
    const double half = 0.5 * h_;
    FrenetRates a = rates(x, 0);
    for (int k = 0; k < n_; ++k) {
      const FrenetRates b = rates(x, k + 1);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j)
          values[entry++] = (i == j ? -1.0 : 0.0) - half * a.jacobian[i][j];
        for (int j = 0; j < 4; ++j)
          values[entry++] = (i == j ? 1.0 : 0.0) - half * b.jacobian[i][j];
      }
      const double chain[7] = {-1.0, 1.0, -half, -half, -1.0, 1.0, -h_};
      for (const double value : chain) values[entry++] = value;
      a = b;
    }
    min_max_rows().append_values(values, entry);
  }

  //! Hessian of the Lagrangian (the objective and all but the kinematic rows are linear): at
  //! node j, -h/2 sum_i Lambda_i(j) d2f_i, with Lambda_i(j) the multipliers of kinematic row i of
  //! the one or two intervals that touch node j (frenet_second_derivatives).
  void hessian_pattern(Index* rows, Index* columns) const override {
    Index entry = 0;
    for (int j = 0; j <= n_; ++j) {
      const Index s = 5 * j;
      const Index pairs[7][2] = {{s, s},         {s + 1, s},     {s + 1, s + 1}, {s + 2, s},
                                 {s + 2, s + 1}, {s + 2, s + 2}, {s + 3, s + 3}};
      append_pattern(pairs, rows, columns, entry);
    }
  }

  void hessian_values(const Number* x, const Number* multipliers, Number* values) const override {
    Index entry = 0;
    for (int j = 0; j <= n_; ++j) {
      const std::array<double, 3> sum = node_multipliers(multipliers, j, n_, state_count);
      const Number* node = x + 5 * j;
      const FrenetCurvatureTerms terms =
          frenet_second_derivatives(p_.speed_mps, p_.wheelbase_m, path_curvature(*p_.path, node[0]),
                                    node[1], node[2], node[3]);
      for (int c = 0; c < 7; ++c) {
        double value = 0.0;
        for (int i = 0; i < 3; ++i) value += sum[i] * terms.hessian[i][c];
        values[entry++] = -0.5 * h_ * value;
      }
    }
  }

  void finalize_solution(Ipopt::SolverReturn status, Index, const Number* x, const Number*,
                         const Number*, Index, const Number*, const Number*, Number,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    result_.converged = converged(status);
    result_.max_abs_lateral_error_m = x[z_index()];
    result_.time_step_s = h_;
    const auto nodes = static_cast<std::size_t>(n_ + 1);
    std::vector<double>* columns[state_count] = {&result_.arc_length_m, &result_.lateral_error_m,
                                                 &result_.heading_error_rad, &result_.steering_rad,
                                                 &result_.steering_rate_radps};
    result_.time_s.resize(nodes);
    for (std::vector<double>* column : columns) column->resize(nodes);
    for (std::size_t k = 0; k < nodes; ++k) {
      result_.time_s[k] = h_ * static_cast<double>(k);
      for (int c = 0; c < state_count; ++c)
        (*columns[c])[k] = x[5 * k + static_cast<std::size_t>(c)];
    }
    result_.steering_acceleration_radps2.assign(x + u_index(0), x + u_index(0) + n_);
  }

 private:
  Index objective_index() const override { return z_index(); }
  Index u_index(int k) const { return state_count * (n_ + 1) + k; }
  Index z_index() const { return state_count * (n_ + 1) + n_; }
  MinMaxRows min_max_rows() const { return {state_count * n_, n_ + 1, 5, 1, z_index()}; }

  FrenetRates rates(const Number* x, int k) const {
    const Number* node = x + 5 * k;
    return frenet_rates(p_.speed_mps, p_.wheelbase_m, path_curvature(*p_.path, node[0]), node[1],
                        node[2], node[3]);
  }

  const EngagementBoundProblem& p_;
  const EngagementTrajectory& start_;
  EngagementBound& result_;
  int n_;
  double h_;
};

}  // namespace

Ipopt::SmartPtr<Ipopt::TNLP> make_engagement_nlp(const EngagementBoundProblem& problem,
                                                 const EngagementTrajectory& start,
                                                 EngagementBound& result) {
  return new EngagementNlp(problem, start, result);
}

}  // namespace smoothsteer::detail
