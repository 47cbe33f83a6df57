#pragma once
//! \file lqr_controller.hpp
//! LQR on the linearised lateral-error dynamics of the kinematic single-track model (rear axle),
//! with curvature feedforward (issue "Comparison" f).
//!
//! With e the rear-axle lateral error, psi_e the heading error and delta = delta_ff + delta_fb,
//! delta_ff = atan(lambda kappa_path), the linearisation at speed v > 0 is
//!   d/dt [e, psi_e] = [[0, v], [0, 0]] [e, psi_e] + [0, v/lambda] delta_fb.
//! The cost  integral q_e e^2 + q_psi psi_e^2 + r delta_fb^2 dt  is solved in closed form: with
//! z = (e, v psi_e) and w = v^2/lambda delta_fb the system is the double integrator z1' = z2,
//! z2' = w with Q' = diag(q_e, q_psi / v^2), R' = r lambda^2 / v^4, whose Riccati solution gives
//!   k1 = sqrt(q_e / R'),  k2 = sqrt(Q'_22 / R' + 2 k1),  w = -k1 z1 - k2 z2.
//! The gains are re-evaluated at every update from the measured speed (gain scheduling, no
//! allocation). Forward driving only; the speed is floored at min_speed_mps.

#include <memory>

#include "smoothsteer/baselines/path_tracking_baseline.hpp"
#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct LqrParameters {
  double wheelbase_m = 2.7;     //!< lambda_veh [m]
  double weight_lateral = 1.0;  //!< q_e [1/m^2]
  double weight_heading = 1.0;  //!< q_psi [1/rad^2]
  double weight_steering =
      100.0;                   //!< r [1/rad^2]; small r limit-cycles against a 0.6 rad/s rate limit
  double min_speed_mps = 1.0;  //!< gains are computed at max(v, this) [m/s]
  bool curvature_feedforward = true;
  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>".
  std::string validation_error() const { return describe(first_violation()); }
  //! Throws std::invalid_argument with validation_error().
  void validate() const { throw_if_violated(first_violation()); }
};

//! Feedback gains delta_fb = -(k_e e + k_psi psi_e) at speed v (closed-form continuous LQR).
struct LqrGains {
  double lateral = 0.0;  //!< k_e [rad/m]
  double heading = 0.0;  //!< k_psi [rad/rad]
};
LqrGains lqr_gains(const LqrParameters& parameters, double speed_mps) noexcept;

class LqrController final : public PathTrackingBaseline<LqrParameters> {
 public:
  LqrController(const LqrParameters& parameters, std::shared_ptr<const Path> path);
  const char* name() const noexcept override { return "lqr"; }

 protected:
  Status compute_command(const ControllerInput& input, ControllerOutput& output) noexcept override;
};

}  // namespace smoothsteer
