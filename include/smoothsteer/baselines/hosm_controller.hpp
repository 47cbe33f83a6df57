#pragma once
//! \file hosm_controller.hpp
//! Constrained higher-order sliding-mode (HOSM) controller of the paper's Sec. IV-B, after
//! Incremona, Rubagotti, Ferrara, "Sliding mode control of constrained nonlinear systems"
//! (IEEE TAC 62(6), 2017, the paper's ref. Incremona2017), applied to the extended system
//! x_ext = (e, psi, delta), x_ext' = (sin psi, tan(delta)/lambda, delta') with C1 and C2.
//!
//! Sliding output sigma1 = e (relative degree 3, derivatives w.r.t. the rear arc length s):
//!   sigma2 = sin psi,  sigma3 = cos psi tan(delta) / lambda,
//!   sigma3' = f + g delta',  f = -sin psi (tan(delta)/lambda)^2,  g = cos psi / (lambda cos^2
//!   delta).
//! With |psi| <= psi-bar: g >= G = cos(psi-bar) / lambda and f <= F = sin(psi-bar)
//! (tan(delta-bar)/lambda)^2, so the triple integrator sees |u| <= alpha = G delta-bar' - F.
//! The paper prints g = |cos psi| >= cos(psi-bar); the factor 1/(lambda cos^2 delta) is missing
//! there (it is >= 1/lambda, so G = cos(psi-bar)/lambda is the correct lower bound).
//! Control: delta' = -delta-bar' sign(S3(sigma; alpha)) with the time-optimal triple-integrator
//! surface (triple_integrator.hpp, paper_notes §7); while |psi| >= psi-bar and the heading still
//! grows, delta' = -delta-bar' sign(sigma3) (the paper's second case) keeps |psi| bounded;
//! delta is held at +-delta-bar instead of leaving C1.
//! C1 and C2 hold by construction: delta is integrated from |delta'| <= delta-bar'.
//! Forward driving on (locally) straight paths is the design case; path curvature enters as an
//! unmodelled disturbance.

#include <memory>

#include "smoothsteer/baselines/path_tracking_baseline.hpp"
#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct HosmParameters {
  double wheelbase_m = 2.7;                //!< lambda of x_ext (the vehicle's) [m]
  double steering_angle_bound_rad = 0.5;   //!< delta-bar, C1 [rad]
  double steering_rate_bound_per_m = 0.1;  //!< delta-bar', C2 [rad/m]
  double heading_bound_rad = 0.6;          //!< psi-bar: |psi| <= psi-bar gives G and F [rad]
  //! Largest arc-length sub-step [m] at which the switching law is re-evaluated inside one
  //! control period (on the kinematic prediction); at most max_substeps per period.
  double substep_m = 0.01;
  int max_substeps = 64;

  //! alpha = G delta-bar' - F, the guaranteed control authority on sigma3' [1/m^3].
  double alpha() const noexcept;
  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>".
  std::string validation_error() const { return describe(first_violation()); }
  //! Throws std::invalid_argument with validation_error().
  void validate() const { throw_if_violated(first_violation()); }
};

class HosmController final : public PathTrackingBaseline<HosmParameters> {
 public:
  HosmController(const HosmParameters& parameters, std::shared_ptr<const Path> path);

  Status reset(double measured_steering_angle_rad = 0.0) noexcept override;
  const char* name() const noexcept override { return "hosm"; }

  //! delta' [rad/m] of the law at state (e, psi, delta); exposed for tests.
  double steering_rate_per_meter(double lateral_error_m, double heading_error_rad,
                                 double steering_angle_rad) const noexcept;

 protected:
  Status compute_command(const ControllerInput& input, ControllerOutput& output) noexcept override;

 private:
  double alpha_ = 0.0;
};

}  // namespace smoothsteer
