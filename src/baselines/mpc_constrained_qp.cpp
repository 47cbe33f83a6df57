#include "mpc_constrained_qp.hpp"

#include <optimization.h>

#include <cmath>

namespace smoothsteer::detail {

struct MpcConstrainedQp::Alglib {
  alglib::minqpstate state;
  alglib::minqpreport report;
  alglib::real_2d_array quadratic;
  alglib::real_2d_array differences;  // row 0: u_0; row k: u_k - u_k-1
  alglib::real_1d_array linear, difference_low, difference_high, solution;
};

MpcConstrainedQp::MpcConstrainedQp(int horizon_steps, const SteeringLimits& limits,
                                   double prediction_step_s)
    : alglib_(std::make_unique<Alglib>()), horizon_(horizon_steps), limits_(limits) {
  const alglib::ae_int_t n = horizon_steps;
  Alglib& qp = *alglib_;
  alglib::minqpcreate(n, qp.state);
  qp.quadratic.setlength(n, n);
  qp.differences.setlength(n, n);
  qp.linear.setlength(n);
  qp.difference_low.setlength(n);
  qp.difference_high.setlength(n);
  qp.solution.setlength(n);
  alglib::real_1d_array low, high, scale;
  low.setlength(n);
  high.setlength(n);
  scale.setlength(n);
  for (alglib::ae_int_t i = 0; i < n; ++i) {
    low[i] = -limits.angle_rad;
    high[i] = limits.angle_rad;
    scale[i] = 1.0;
    for (alglib::ae_int_t j = 0; j < n; ++j) qp.differences[i][j] = 0.0;
    qp.differences[i][i] = 1.0;
    if (i > 0) qp.differences[i][i - 1] = -1.0;
    qp.difference_low[i] = -limits.rate_radps * prediction_step_s;
    qp.difference_high[i] = limits.rate_radps * prediction_step_s;
  }
  alglib::minqpsetbc(qp.state, low, high);
  alglib::minqpsetscale(qp.state, scale);
  alglib::minqpsetalgodenseipm(qp.state, 1e-10);
}

MpcConstrainedQp::~MpcConstrainedQp() = default;

bool MpcConstrainedQp::solve(const Eigen::MatrixXd& hessian_lower,
                             const Eigen::VectorXd& gradient_target, double previous_command,
                             double control_period_s, Eigen::VectorXd& plan) noexcept {
  try {
    Alglib& qp = *alglib_;
    for (int i = 0; i < horizon_; ++i) {
      for (int j = 0; j <= i; ++j) qp.quadratic[i][j] = hessian_lower(i, j);
      qp.linear[i] = -gradient_target(i);
    }
    const double first_step = limits_.rate_radps * control_period_s;
    qp.difference_low[0] = previous_command - first_step;
    qp.difference_high[0] = previous_command + first_step;
    alglib::minqpsetquadraticterm(qp.state, qp.quadratic, false);
    alglib::minqpsetlinearterm(qp.state, qp.linear);
    alglib::minqpsetlc2dense(qp.state, qp.differences, qp.difference_low, qp.difference_high,
                             horizon_);
    alglib::minqpoptimize(qp.state);
    alglib::minqpresultsbuf(qp.state, qp.solution, qp.report);
    if (qp.report.terminationtype <= 0) return false;
    for (int i = 0; i < horizon_; ++i) {
      if (!std::isfinite(qp.solution[i])) return false;
    }
    for (int i = 0; i < horizon_; ++i) plan(i) = qp.solution[i];
    return true;
  } catch (...) {
    return false;
  }
}

}  // namespace smoothsteer::detail
