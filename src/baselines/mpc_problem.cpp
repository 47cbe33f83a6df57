#include "mpc_problem.hpp"

#include <algorithm>
#include <cmath>

namespace smoothsteer::detail {

MpcStep discretise_mpc_step(const MpcParameters& parameters, double speed_mps,
                            double curvature) noexcept {
  const double lambda = parameters.wheelbase_m;
  const double bound = parameters.limits.angle_rad;
  // Autoware clamps the linearisation point delta_r to the steering limit.
  const double reference = std::clamp(std::atan(lambda * curvature), -bound, bound);
  const double secant_squared = 1.0 / (std::cos(reference) * std::cos(reference));
  const double v = speed_mps;
  const double tau = parameters.steering_time_constant_s;
  Eigen::Matrix3d a;
  a << 0.0, v, 0.0, 0.0, 0.0, v / lambda * secant_squared, 0.0, 0.0, -1.0 / tau;
  const Eigen::Vector3d b(0.0, 0.0, 1.0 / tau);
  const Eigen::Vector3d w(
      0.0, -v * curvature + v / lambda * (std::tan(reference) - reference * secant_squared), 0.0);
  // Bilinear transform: A_d = (I - dt/2 A)^-1 (I + dt/2 A), B_d = (I - dt/2 A)^-1 B dt.
  const double dt = parameters.prediction_step_s;
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d inverse = (identity - 0.5 * dt * a).inverse();
  MpcStep step;
  step.a = inverse * (identity + 0.5 * dt * a);
  step.b = inverse * b * dt;
  step.w = inverse * w * dt;
  return step;
}

double mpc_reference_steering(const MpcParameters& parameters, double curvature) noexcept {
  const double reference = std::atan(parameters.wheelbase_m * curvature);
  return std::abs(reference) < parameters.zero_feedforward_angle_rad ? 0.0 : reference;
}

MpcLeastSquares::MpcLeastSquares(int horizon_steps)
    : horizon_(horizon_steps),
      rows_(Eigen::MatrixXd::Zero(5 * horizon_steps, horizon_steps)),
      targets_(Eigen::VectorXd::Zero(5 * horizon_steps)),
      gain_(3, horizon_steps),
      gain_scratch_(3, horizon_steps),
      normal_matrix_(horizon_steps, horizon_steps),
      normal_rhs_(horizon_steps),
      cholesky_(horizon_steps) {}

void MpcLeastSquares::build(const MpcParameters& parameters, const Eigen::Vector3d& initial_state,
                            double speed_mps, std::span<const double> curvatures,
                            const MpcBoundary& boundary) noexcept {
  const int n = horizon_;
  const double v2 = speed_mps * speed_mps;
  rows_.setZero();
  targets_.setZero();
  gain_.setZero();
  Eigen::Vector3d offset = initial_state;

  // Output rows: x_k = gain_ U + offset for k = i + 1 (Autoware's Qex on x_1 .. x_N).
  for (int i = 0; i < n; ++i) {
    const MpcStep step = discretise_mpc_step(parameters, speed_mps, curvatures[i]);
    if (i > 0) {
      gain_scratch_.leftCols(i).noalias() = step.a * gain_.leftCols(i);
      gain_.leftCols(i) = gain_scratch_.leftCols(i);
    }
    gain_.col(i) = step.b;
    offset = (step.a * offset + step.w).eval();
    const bool terminal = i == n - 1;
    const double lateral =
        terminal ? parameters.weight_terminal_lateral_error : parameters.weight_lateral_error;
    const double heading =
        (terminal ? parameters.weight_terminal_heading_error : parameters.weight_heading_error) +
        parameters.weight_heading_error_squared_speed * v2;
    const double root_lateral = std::sqrt(lateral), root_heading = std::sqrt(heading);
    rows_.row(2 * i).head(i + 1) = root_lateral * gain_.row(0).head(i + 1);
    rows_.row(2 * i + 1).head(i + 1) = root_heading * gain_.row(1).head(i + 1);
    targets_(2 * i) = -root_lateral * offset(0);
    targets_(2 * i + 1) = -root_heading * offset(1);
  }

  // Input rows: r (u_k - u_ref,k)^2 with r = r_0 + r_v v^2.
  const double root_input = std::sqrt(parameters.weight_steering_input +
                                      parameters.weight_steering_input_squared_speed * v2);
  for (int i = 0; i < n; ++i) {
    rows_(2 * n + i, i) = root_input;
    targets_(2 * n + i) = root_input * mpc_reference_steering(parameters, curvatures[i]);
  }

  // Steering-rate rows: w_rate ((u_0 - u_prev)/T_c)^2 + sum w_rate ((u_k - u_k-1)/dt)^2.
  const double dt = parameters.prediction_step_s;
  const double period = boundary.control_period_s;
  const double root_rate = std::sqrt(parameters.weight_steering_rate);
  const int rate_row = 3 * n;
  rows_(rate_row, 0) = root_rate / period;
  targets_(rate_row) = root_rate / period * boundary.previous_command;
  for (int i = 1; i < n; ++i) {
    rows_(rate_row + i, i) = root_rate / dt;
    rows_(rate_row + i, i - 1) = -root_rate / dt;
  }

  // Steering-acceleration rows (Autoware's addSteerWeightR/F): the second difference through
  // u_pprev, u_prev (period T_c) and the planned commands (step dt).
  const double root_acc = std::sqrt(parameters.weight_steering_acceleration);
  const int acc_row = 4 * n;
  rows_(acc_row, 0) = root_acc / (period * period);
  targets_(acc_row) =
      root_acc / (period * period) * (2.0 * boundary.previous_command - boundary.command_before);
  if (n > 1) {
    // sqrt(w) ((u_1 - u_0)/dt - (u_0 - u_prev)/T_c) / dt
    rows_(acc_row + 1, 1) = root_acc / (dt * dt);
    rows_(acc_row + 1, 0) = -root_acc / (dt * dt) - root_acc / (dt * period);
    targets_(acc_row + 1) = -root_acc / (dt * period) * boundary.previous_command;
  }
  for (int i = 2; i < n; ++i) {
    const double scale = root_acc / (dt * dt);
    rows_(acc_row + i, i) = scale;
    rows_(acc_row + i, i - 1) = -2.0 * scale;
    rows_(acc_row + i, i - 2) = scale;
  }

  normal_matrix_.setZero();
  normal_matrix_.selfadjointView<Eigen::Lower>().rankUpdate(rows_.transpose());
  normal_rhs_.noalias() = rows_.transpose() * targets_;
}

bool MpcLeastSquares::solve(Eigen::VectorXd& plan) noexcept {
  cholesky_.compute(normal_matrix_);
  if (cholesky_.info() != Eigen::Success) return false;
  plan = normal_rhs_;
  cholesky_.solveInPlace(plan);
  return plan.allFinite();
}

}  // namespace smoothsteer::detail
