#include "kinetic_reference_nlp.hpp"

#include <algorithm>

namespace smoothsteer::detail {
namespace {

using Ipopt::Index;
using Ipopt::Number;

constexpr int n_x = kinetic_states;
constexpr double unbounded = 1e19;
constexpr int lateral_error = 0, steering = 4, steering_rate = 5;  // state components

// Variable layout: node k holds x_k at x[6k .. 6k + 5] for k = 0..N, the held u of interval k
// sits at x[6(N + 1) + k], z is the last. Rows: 6 per interval, the exact transition
//   x_{k+1} - phi x_k - gamma_u u_k = gamma_kappa kappa_k + gamma_kappa_rate kappa'_k
//   (equalities; kappa linear on each interval, IntervalCurvature),
// then 2 rows per node, e_k - z <= 0 and -e_k - z <= 0. Every row is linear: the Hessian of the
// Lagrangian is zero.
class KineticReferenceNlp final : public MinimumOfVariableNlp {
 public:
  KineticReferenceNlp(const KineticReferenceProblem& problem, const DiscreteKineticModel& model,
                      const IntervalCurvature& curvature, double h, KineticReference& result)
      : p_(problem),
        model_(model),
        curvature_(curvature),
        result_(result),
        n_(static_cast<int>(curvature.start.size())),
        h_(h) {}

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac, Index& nnz_hess,
                    IndexStyleEnum& style) override {
    n = z_index() + 1;
    m = n_x * n_ + 2 * (n_ + 1);
    nnz_jac = n_x * (n_x + 2) * n_ + 4 * (n_ + 1);
    nnz_hess = 0;
    style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l,
                       Number* g_u) override {
    std::fill(x_l, x_l + n, -unbounded);
    std::fill(x_u, x_u + n, unbounded);
    const VehicleParameters& car = p_.vehicle;
    // A limit the car does not have (+inf) leaves its variable free.
    const double angle = std::min(car.max_steering_angle_rad, unbounded);
    const double rate = std::min(car.max_steering_rate_radps, unbounded);
    const double acceleration = std::min(car.max_steering_acceleration_radps2, unbounded);
    for (int k = 0; k <= n_; ++k) {
      x_l[n_x * k + steering] = -angle;
      x_u[n_x * k + steering] = angle;
      x_l[n_x * k + steering_rate] = -rate;
      x_u[n_x * k + steering_rate] = rate;
    }
    for (int k = 0; k < n_; ++k) {
      x_l[u_index(k)] = -acceleration;
      x_u[u_index(k)] = acceleration;
    }
    // On the path, straight and at rest in the path's frame: the simulator's start.
    for (int c = 0; c < n_x; ++c) x_l[c] = x_u[c] = 0.0;
    x_l[z_index()] = 0.0;
    for (int k = 0; k < n_; ++k) {
      const double kappa = curvature_.start[static_cast<std::size_t>(k)];
      const double kappa_rate = curvature_.rate[static_cast<std::size_t>(k)];
      for (int i = 0; i < n_x; ++i) {
        g_l[n_x * k + i] = g_u[n_x * k + i] =
            model_.gamma_kappa(i) * kappa + model_.gamma_kappa_rate(i) * kappa_rate;
      }
    }
    std::fill(g_l + n_x * n_, g_l + m, -unbounded);
    std::fill(g_u + n_x * n_, g_u + m, 0.0);
    return true;
  }

  bool get_starting_point(Index n, bool, Number* x, bool, Number*, Number*, Index, bool,
                          Number*) override {
    std::fill(x, x + n, 0.0);
    x[z_index()] = 1.0;  // strictly inside the path rows
    return true;
  }

  bool eval_g(Index, const Number* x, bool, Index, Number* g) override {
    for (int k = 0; k < n_; ++k) {
      const Eigen::Map<const KineticState> now(x + n_x * k), next(x + n_x * (k + 1));
      const KineticState defect = next - model_.phi * now - model_.gamma_u * x[u_index(k)];
      std::copy(defect.data(), defect.data() + n_x, g + n_x * k);
    }
    min_max_rows().evaluate(x, g);
    return true;
  }

  void jacobian_pattern(Index* rows, Index* columns) const override {
    SparsityWriter pattern{rows, columns};
    for (int k = 0; k < n_; ++k) {
      for (int i = 0; i < n_x; ++i) {
        const Index row = n_x * k + i;
        for (int j = 0; j < n_x; ++j) pattern.add(row, n_x * k + j);
        pattern.add(row, n_x * (k + 1) + i);
        pattern.add(row, u_index(k));
      }
    }
    min_max_rows().append_pattern(pattern);
  }

  void jacobian_values(const Number*, Number* values) const override {
    Index entry = 0;
    for (int k = 0; k < n_; ++k) {
      for (int i = 0; i < n_x; ++i) {
        for (int j = 0; j < n_x; ++j) values[entry++] = -model_.phi(i, j);
        values[entry++] = 1.0;
        values[entry++] = -model_.gamma_u(i);
      }
    }
    min_max_rows().append_values(values, entry);
  }

  void hessian_pattern(Index*, Index*) const override {}
  void hessian_values(const Number*, const Number*, Number*) const override {}

  void finalize_solution(Ipopt::SolverReturn status, Index, const Number* x, const Number*,
                         const Number*, Index, const Number*, const Number*, Number,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    result_.converged = converged(status);
    result_.max_abs_lateral_error_m = x[z_index()];
    result_.time_step_s = h_;
    const auto nodes = static_cast<std::size_t>(n_ + 1);
    result_.time_s.resize(nodes);
    result_.lateral_error_m.resize(nodes);
    result_.steering_rad.resize(nodes);
    result_.steering_rate_radps.resize(nodes);
    for (std::size_t k = 0; k < nodes; ++k) {
      result_.time_s[k] = h_ * static_cast<double>(k);
      result_.lateral_error_m[k] = x[n_x * k + lateral_error];
      result_.steering_rad[k] = x[n_x * k + steering];
      result_.steering_rate_radps[k] = x[n_x * k + steering_rate];
    }
    result_.steering_acceleration_radps2.assign(x + u_index(0), x + u_index(0) + n_);
  }

 private:
  Index objective_index() const override { return z_index(); }
  Index u_index(int k) const { return n_x * (n_ + 1) + k; }
  Index z_index() const { return n_x * (n_ + 1) + n_; }
  MinMaxRows min_max_rows() const { return {n_x * n_, n_ + 1, n_x, lateral_error, z_index()}; }

  const KineticReferenceProblem& p_;
  const DiscreteKineticModel& model_;
  const IntervalCurvature& curvature_;
  KineticReference& result_;
  int n_;
  double h_;
};

}  // namespace

Ipopt::SmartPtr<Ipopt::TNLP> make_kinetic_reference_nlp(const KineticReferenceProblem& problem,
                                                        const DiscreteKineticModel& model,
                                                        const IntervalCurvature& curvature,
                                                        double time_step_s,
                                                        KineticReference& result) {
  return new KineticReferenceNlp(problem, model, curvature, time_step_s, result);
}

}  // namespace smoothsteer::detail
