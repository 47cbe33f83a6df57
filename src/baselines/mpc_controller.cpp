#include "smoothsteer/baselines/mpc_controller.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "baseline_common.hpp"
#include "mpc_constrained_qp.hpp"
#include "mpc_problem.hpp"

namespace smoothsteer {

std::optional<Violation> MpcParameters::first_violation() const noexcept {
  RuleChecker check("MpcParameters");
  check.require_positive(
      {{"wheelbase_m", wheelbase_m}, {"steering_time_constant_s", steering_time_constant_s}});
  check.require(horizon_steps >= 2 && horizon_steps <= 200, "horizon_steps", horizon_steps,
                "must be in [2, 200]");
  check.require_positive({{"prediction_step_s", prediction_step_s}});
  check.require_non_negative(
      {{"weight_lateral_error", weight_lateral_error},
       {"weight_heading_error", weight_heading_error},
       {"weight_heading_error_squared_speed", weight_heading_error_squared_speed}});
  // r > 0 keeps G'G positive definite whatever the other weights.
  check.require(positive_finite(weight_steering_input), "weight_steering_input",
                weight_steering_input, "must be finite and > 0 (keeps the QP strictly convex)");
  check.require_non_negative(
      {{"weight_steering_input_squared_speed", weight_steering_input_squared_speed},
       {"weight_steering_rate", weight_steering_rate},
       {"weight_steering_acceleration", weight_steering_acceleration},
       {"weight_terminal_lateral_error", weight_terminal_lateral_error},
       {"weight_terminal_heading_error", weight_terminal_heading_error},
       {"zero_feedforward_angle_rad", zero_feedforward_angle_rad}});
  check.require_positive({{"min_speed_mps", min_speed_mps}});
  check.include(limits.first_violation());
  check.require(limits.angle_rad < pi / 2.0, "limits.angle_rad", limits.angle_rad,
                "must be < pi/2 (tan delta of the model)");
  return check.first();
}

namespace detail {

struct MpcWorkspace {
  MpcWorkspace(const MpcParameters& parameters)
      : problem(parameters.horizon_steps),
        curvatures(static_cast<std::size_t>(parameters.horizon_steps), 0.0),
        plan(Eigen::VectorXd::Zero(parameters.horizon_steps)) {
    if (parameters.solver == MpcSolver::constrained) {
      qp = std::make_unique<MpcConstrainedQp>(parameters.horizon_steps, parameters.limits,
                                              parameters.prediction_step_s);
    }
  }
  MpcLeastSquares problem;
  std::unique_ptr<MpcConstrainedQp> qp;
  std::vector<double> curvatures;
  Eigen::VectorXd plan;
};

}  // namespace detail

MpcController::MpcController(const MpcParameters& parameters, std::shared_ptr<const Path> path)
    : PathTrackingBaseline(parameters, std::move(path), "MpcController") {
  workspace_ = std::make_unique<detail::MpcWorkspace>(parameters_);
  (void)reset(0.0);
}

MpcController::~MpcController() = default;

std::span<const double> MpcController::planned_steering() const noexcept {
  return {workspace_->plan.data(), static_cast<std::size_t>(workspace_->plan.size())};
}

Status MpcController::reset(double measured_steering_angle_rad) noexcept {
  if (!valid_reset_angle(measured_steering_angle_rad, parameters_.limits.angle_rad)) {
    return Status::invalid_input;
  }
  // Clamped, so that the constrained QP (|u_0 - u_prev| <= rate T_c) stays feasible.
  restart(measured_steering_angle_rad, parameters_.limits.angle_rad);
  steering_estimate_ = command_before_ = steering_;
  workspace_->plan.setConstant(steering_);
  first_update_ = true;
  return Status::ok;
}

Status MpcController::compute_command(const ControllerInput& input,
                                      ControllerOutput& output) noexcept {
  if (!detail::valid_input(input)) return Status::invalid_input;
  const detail::RearTracking rear = detail::track_rear_axle(*path_, rear_hint_, input);
  const double period = input.period_s;
  // No steering measurement in ControllerInput: the lag model predicts delta from the issued
  // commands (Autoware's use_steer_prediction).
  if (!first_update_) {
    const double blend = 1.0 - std::exp(-period / parameters_.steering_time_constant_s);
    steering_estimate_ += blend * (steering_ - steering_estimate_);
  }
  first_update_ = false;
  double command = steering_;
  if (input.speed_mps >= parameters_.min_speed_mps) {
    detail::MpcWorkspace& work = *workspace_;
    const double step_length = input.speed_mps * parameters_.prediction_step_s;
    for (std::size_t k = 0; k < work.curvatures.size(); ++k) {
      work.curvatures[k] =
          path_->evaluate(rear.projection.arc_length_m + step_length * static_cast<double>(k))
              .curvature;
    }
    const Eigen::Vector3d initial(rear.projection.lateral_error_m, rear.heading_error_rad,
                                  steering_estimate_);
    work.problem.build(parameters_, initial, input.speed_mps, work.curvatures,
                       {steering_, command_before_, period});
    bool solved = work.problem.solve(work.plan);
    if (solved && work.qp) {
      if (!work.qp->solve(work.problem.normal_matrix_lower(), work.problem.normal_rhs(), steering_,
                          period, work.plan)) {
        ++solver_failures_;
      }
    }
    if (!solved) {
      (void)reset(steering_);
      return Status::numerical_error;
    }
    // Saturation of the applied command (Autoware clamps to steer_lim and the rate limit).
    const double angle = parameters_.limits.angle_rad;
    const double step = parameters_.limits.rate_radps * period;
    command =
        std::clamp(std::clamp(work.plan(0), -angle, angle), steering_ - step, steering_ + step);
  }
  detail::fill_output(*path_, front_hint_, input, rear, parameters_.wheelbase_m, command, steering_,
                      rear.projection.lateral_error_m, output);
  command_before_ = steering_;
  steering_ = command;
  return Status::ok;
}

}  // namespace smoothsteer
