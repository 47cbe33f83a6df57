#pragma once
//! \file governor_stage.hpp
//! Stage of LeadWheelController::compute_command() under the steering governor
//! (ControllerParameters::governor, docs/governor.md): the split's authority, the blend of the
//! near-path and the far law, and the clamp of kappa_n into eq. (governor_interval). It owns the
//! governor's memory between sub-steps and periods. While the governor is off (or n = 0, or the
//! car stands) every call leaves the step as it would be without it.
//!
//! Per period: begin_period(); per sub-step: authority(), blend(), clamp(), end_substep(); then
//! end_period().

#include "smoothsteer/controller/controller_parameters.hpp"
#include "smoothsteer/controller/near_law_layer.hpp"
#include "smoothsteer/controller/steering_governor.hpp"
#include "smoothsteer/controller/trailer_chain.hpp"

namespace smoothsteer {

class GovernorStage {
 public:
  //! What the governor needs to know about one control period.
  struct Period {
    double speed_magnitude = 0.0;    //!< |v| [m/s]
    double acceleration_mps2 = 0.0;  //!< the measured dv/dt [m/s^2]
    double period_s = 0.0;           //!< the control period [s]
    double step_length_m = 0.0;      //!< the sub-step's rear arc length h [m]
  };
  //! The switching part's authority kbar_sw and boundary layer epsilon in one sub-step.
  struct Authority {
    double bound = 0.0;
    double layer = 0.0;
  };
  //! The lead wheel's state from its target curve in one sub-step, and the far law's curvature.
  struct LeadWheelError {
    double path_curvature = 0.0;     //!< the path's curvature at the lead wheel's closest point
    double lateral_error_m = 0.0;    //!< e
    double relative_heading = 0.0;   //!< psi [rad]
    double far_law_curvature = 0.0;  //!< the law at the authority() this sub-step gave [1/m]
    //! The single-track inversion's slip lag (K_f + K_r) v^2 / g [m] (dynamics_inversion.hpp).
    double slip_lag_m = 0.0;
    //! The path within NearLawLayer::reversal_lookahead_s of travel ahead of the lead wheel
    //! (NearLawLayer::path_ahead; read on the first sub-step only).
    NearLawLayer::PathAhead ahead{};
  };

  //! The chain restarts in stationary cornering at kappa_ff (a reset, a change of direction):
  //! no rate, no far law, the envelopes at the restart's values.
  void restart(double feedforward_curvature) noexcept;
  //! A new engagement: no speed of a last period to difference.
  void forget_speed() noexcept { previous_speed_ = -1.0; }

  //! Once per period, before the sub-steps. Also remembers |v| for the next period's speed
  //! change, governed or not.
  void begin_period(const ControllerParameters& parameters, const Period& period) noexcept;
  //! Whether the governor acts in this period (enabled, n > 0 and the car moves).
  bool governed() const noexcept { return governed_; }
  //! The rate kappa_ff may move at in this period [1/m^2]: L_ff, or under the governor at least
  //! eq. (governed_feedforward_rate).
  double feedforward_rate() const noexcept { return feedforward_rate_; }

  //! Per sub-step, first: the far law's authority from the envelope of |kappa_ff| (updated here)
  //! and its layer at eq. (governed_law_length); the ungoverned kbar_sw and epsilon otherwise.
  Authority authority(const ControllerParameters& parameters,
                      double feedforward_curvature) noexcept;
  //! The switching law's curvature: the far law blended with the certified near law as the
  //! latter's sliding variable leaves its layer or the lead wheel's error leaves the hand-over
  //! error (SteeringGovernor::far_law_slip_lag_share); `error.far_law_curvature` when
  //! ungoverned.
  //! first_substep: the near layer observes the path's curvature once per period.
  double blend(const ControllerParameters& parameters, const LeadWheelError& error,
               bool first_substep) noexcept;
  //! Eq. (governor_interval): kappa_n clamped into the interval that keeps the car's limits over
  //! the sub-step, inside |kappa_n| <= kbar_n. Only while governed().
  double clamp(double lead_curvature, const ChainAngles& angles,
               const ControllerParameters& parameters, double direction) const noexcept;
  //! After the chain's sub-step: for n = 1 the command's rate, which bounds the next sub-step's.
  void end_substep(const ChainAngles& angles, const ControllerParameters& parameters,
                   double direction, double lead_curvature) noexcept;
  //! After the sub-steps: keeps the rate for the next period.
  void end_period() noexcept;

  //! The command's rate at the end of the last period (n = 1) [rad/s].
  double rate_radps() const noexcept { return rate_radps_; }
  //! Decaying max of |kappa_ff|, the far law's authority's complement [1/m].
  double feedforward_envelope() const noexcept { return feedforward_envelope_; }
  //! Weight of the far law in kappa_sw, in [0, 1].
  double far_share() const noexcept { return far_share_; }
  //! Decaying max of the lead wheel's |heading error| [rad].
  double heading_envelope() const noexcept { return heading_envelope_; }

 private:
  // Memory across periods.
  double rate_radps_ = 0.0;
  double feedforward_envelope_ = 0.0;
  double far_share_ = 0.0;
  double heading_envelope_ = 0.0;
  NearLawLayer near_layer_{};
  double previous_speed_ = -1.0;
  // This period's.
  bool governed_ = false;
  double speed_magnitude_ = 0.0;
  double travelled_m_ = 0.0;
  double step_length_m_ = 0.0;
  double feedforward_rate_ = 0.0;
  double switching_bound_ = 0.0;
  double near_bound_ = 0.0;
  double reversal_bound_ = 0.0;
  double heading_decay_ = 1.0;
  GovernorStep step_{};
};

}  // namespace smoothsteer
