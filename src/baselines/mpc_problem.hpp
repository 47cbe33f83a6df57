#pragma once
// The MPC's stacked least-squares problem (internal; docs/baselines.md "MPC"): the prediction
// of the linearised lag model over N steps and the cost rows of Autoware's formulation.

#include <Eigen/Dense>
#include <span>

#include "smoothsteer/baselines/mpc_controller.hpp"

namespace smoothsteer::detail {

//! One step x_k+1 = a x_k + b u_k + w of the lag model (x = e, psi_e, delta), linearised at
//! curvature kappa and speed v and discretised with the bilinear (Tustin) transform.
struct MpcStep {
  Eigen::Matrix3d a;
  Eigen::Vector3d b;
  Eigen::Vector3d w;
};
MpcStep discretise_mpc_step(const MpcParameters& parameters, double speed_mps,
                            double curvature) noexcept;

//! u_ref = atan(lambda kappa), zero below zero_feedforward_angle_rad (Autoware's
//! mpc_zero_ff_steer_deg: ignores curvature noise).
double mpc_reference_steering(const MpcParameters& parameters, double curvature) noexcept;

//! The commands before the horizon, which the rate and acceleration rows difference against.
struct MpcBoundary {
  double previous_command = 0.0;  //!< u_prev, applied one control period ago [rad]
  double command_before = 0.0;    //!< u_pprev, applied two control periods ago [rad]
  double control_period_s = 0.02;
};

//! min_U |G U - h|^2. Rows: 2N output rows (sqrt q_e e_k, sqrt q_psi psi_k, k = 1..N), N input
//! rows sqrt r (u_k - u_ref,k), N steering-rate rows and N steering-acceleration rows.
class MpcLeastSquares {
 public:
  explicit MpcLeastSquares(int horizon_steps);

  //! Fills G, h and the normal equations H = G'G (lower triangle), g = G'h. No allocation.
  void build(const MpcParameters& parameters, const Eigen::Vector3d& initial_state,
             double speed_mps, std::span<const double> curvatures,
             const MpcBoundary& boundary) noexcept;
  //! Unconstrained optimum by Cholesky of H; false if H is not positive definite.
  bool solve(Eigen::VectorXd& plan) noexcept;

  const Eigen::MatrixXd& normal_matrix_lower() const noexcept { return normal_matrix_; }
  const Eigen::VectorXd& normal_rhs() const noexcept { return normal_rhs_; }

 private:
  int horizon_;
  Eigen::MatrixXd rows_;                           // G
  Eigen::VectorXd targets_;                        // h
  Eigen::Matrix<double, 3, Eigen::Dynamic> gain_;  // x_k = gain_ U + offset_
  Eigen::Matrix<double, 3, Eigen::Dynamic> gain_scratch_;
  Eigen::MatrixXd normal_matrix_;
  Eigen::VectorXd normal_rhs_;
  Eigen::LLT<Eigen::MatrixXd, Eigen::Lower> cholesky_;
};

}  // namespace smoothsteer::detail
