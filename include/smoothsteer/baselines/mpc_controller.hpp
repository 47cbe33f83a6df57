#pragma once
//! \file mpc_controller.hpp
//! Linear time-varying MPC in the formulation of Autoware's `mpc_lateral_controller`
//! (autowarefoundation/autoware.universe, control/mpc_lateral_controller: vehicle model
//! `kinematics`, docs model_predictive_control_algorithm.md; the default horizon and weights of
//! param/lateral_controller_defaults.param.yaml). Formulation and differences: docs/baselines.md.
//!
//! Model: kinematic bicycle of the rear axle with a first-order steering lag tau,
//!   e' = v psi_e,  psi_e' = v/lambda (tan delta_r + (delta - delta_r)/cos^2 delta_r) - v kappa,
//!   delta' = (u - delta)/tau,   delta_r = atan(lambda kappa),
//! linearised along the reference curvature kappa(s0 + v t_k) of each prediction step and
//! discretised with the bilinear (Tustin) transform. The cost is the stacked least-squares
//! problem  min_U |G U - h|^2  over the N planned commands U (mpc_problem.hpp).
//!
//! Two solvers:
//!   unconstrained - normal equations G'G U = G'h by Cholesky (Eigen), then the first command is
//!                   clamped to the angle and rate limits (Autoware's `unconstraint_fast`);
//!   constrained   - the same cost with hard |u_k| <= delta-bar and rate constraints
//!                   |u_0 - u_prev| <= rate dt, |u_k - u_k-1| <= rate dt_pred, solved as a dense
//!                   QP by ALGLIB's minqp (dense interior point). ALGLIB allocates inside its
//!                   solver, so this variant's update() is noexcept but not allocation-free.
//!
//! All matrices are allocated at construction. The unconstrained update() allocates nothing.
//! Forward driving only: below min_speed_mps the last command is held.

#include <memory>
#include <span>

#include "smoothsteer/baselines/path_tracking_baseline.hpp"
#include "smoothsteer/baselines/steering_limits.hpp"
#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

enum class MpcSolver {
  unconstrained,  //!< least squares + saturation (Autoware's unconstraint_fast)
  constrained,    //!< hard angle and rate constraints, ALGLIB dense QP
};

//! Defaults: Autoware's lateral_controller_defaults.param.yaml (names in brackets).
struct MpcParameters {
  double wheelbase_m = 2.7;                           //!< lambda [m]
  double steering_time_constant_s = 0.3;              //!< tau [s] (vehicle_model_steer_tau)
  int horizon_steps = 50;                             //!< N (mpc_prediction_horizon)
  double prediction_step_s = 0.1;                     //!< dt_pred [s] (mpc_prediction_dt)
  double weight_lateral_error = 0.1;                  //!< q_e (mpc_weight_lat_error)
  double weight_heading_error = 0.0;                  //!< q_psi (mpc_weight_heading_error)
  double weight_heading_error_squared_speed = 0.3;    //!< q_psi,v: adds q_psi,v v^2 to q_psi
  double weight_steering_input = 1.0;                 //!< r (mpc_weight_steering_input)
  double weight_steering_input_squared_speed = 0.25;  //!< r_v: adds r_v v^2 to r
  double weight_steering_rate = 0.0;                  //!< w_rate (mpc_weight_steer_rate)
  double weight_steering_acceleration = 1e-6;         //!< w_acc (mpc_weight_steer_acc)
  double weight_terminal_lateral_error = 1.0;  //!< q_e at step N (mpc_weight_terminal_lat_error)
  double weight_terminal_heading_error = 0.1;  //!< q_psi at N (..._terminal_heading_error)
  double zero_feedforward_angle_rad = 0.00872664626;  //!< |u_ref| below this is 0 (0.5 deg)
  double min_speed_mps = 0.1;  //!< below this speed the command is held [m/s]
  SteeringLimits limits;       //!< saturation (unconstrained) or constraints (constrained)
  MpcSolver solver = MpcSolver::unconstrained;

  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>".
  std::string validation_error() const { return describe(first_violation()); }
  //! Throws std::invalid_argument with validation_error().
  void validate() const { throw_if_violated(first_violation()); }
};

namespace detail {
struct MpcWorkspace;
}

class MpcController final : public PathTrackingBaseline<MpcParameters> {
 public:
  MpcController(const MpcParameters& parameters, std::shared_ptr<const Path> path);
  ~MpcController() override;
  MpcController(const MpcController&) = delete;
  MpcController& operator=(const MpcController&) = delete;

  Status reset(double measured_steering_angle_rad = 0.0) noexcept override;
  const char* name() const noexcept override {
    return parameters_.solver == MpcSolver::constrained ? "mpc_constrained" : "mpc";
  }

  //! The N commands planned by the last solve (before the saturation of the first one).
  std::span<const double> planned_steering() const noexcept;
  //! Updates in which the constrained QP failed and the clamped unconstrained plan was used.
  long solver_failures() const noexcept { return solver_failures_; }

 protected:
  Status compute_command(const ControllerInput& input, ControllerOutput& output) noexcept override;

 private:
  std::unique_ptr<detail::MpcWorkspace> workspace_;
  double steering_estimate_ = 0.0;  //!< delta of the lag model, propagated from the commands
  double command_before_ = 0.0;     //!< u_pprev (steering-acceleration term)
  bool first_update_ = true;
  long solver_failures_ = 0;
};

}  // namespace smoothsteer
