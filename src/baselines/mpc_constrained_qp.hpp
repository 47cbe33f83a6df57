#pragma once
// The constrained MPC's dense QP, solved by ALGLIB's minqp (dense interior point; Debian's
// libalglib-dev). Internal; see docs/baselines.md "MPC".
//
//   min 1/2 U' H U - g' U   s.t.  |u_k| <= delta-bar,
//                                 |u_0 - u_prev| <= rate T_c,  |u_k - u_k-1| <= rate dt_pred.
//
// ALGLIB allocates inside minqpoptimize(), so solve() is noexcept but not allocation-free.

#include <Eigen/Dense>
#include <memory>

#include "smoothsteer/baselines/steering_limits.hpp"

namespace smoothsteer::detail {

class MpcConstrainedQp {
 public:
  MpcConstrainedQp(int horizon_steps, const SteeringLimits& limits, double prediction_step_s);
  ~MpcConstrainedQp();
  MpcConstrainedQp(const MpcConstrainedQp&) = delete;
  MpcConstrainedQp& operator=(const MpcConstrainedQp&) = delete;

  //! `hessian_lower`: H (lower triangle read). Returns false if ALGLIB reports a failure or
  //! throws; `plan` is then unchanged.
  bool solve(const Eigen::MatrixXd& hessian_lower, const Eigen::VectorXd& gradient_target,
             double previous_command, double control_period_s, Eigen::VectorXd& plan) noexcept;

 private:
  struct Alglib;
  std::unique_ptr<Alglib> alglib_;
  int horizon_;
  SteeringLimits limits_;
};

}  // namespace smoothsteer::detail
