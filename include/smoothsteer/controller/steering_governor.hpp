#pragma once
//! \file steering_governor.hpp
//! The steering governor (docs/governor.md): inside the control step it keeps the held command's
//! rate and acceleration within the car's limits by choosing the lead curvature kappa_n from the
//! interval that keeps them, eq. (governor_interval).
//!
//! In the sine-curvature coordinates of steering_certificate.hpp the chain is a cascade of
//! linear lags, so for a given chain state:
//!   n = 1: d delta_veh / dt is affine in kappa_n; its change per sub-step is bounded instead of
//!          its derivative (the command is C^0 in kappa_n);
//!   n = 2: d delta_veh / dt depends on the state only, and d2 delta_veh / dt2 is affine in
//!   kappa_n.
//! The interval of kappa_n that keeps |rate| <= R at the end of the sub-step and |acceleration|
//! <= A (less the share |dv/dt| |rate| / v that a speed change adds to the held command's second
//! difference) is therefore one division away. It never contains values that break the limits
//! while the chain moves as predicted; the sub-step's drift is covered by `margin`.

#include "smoothsteer/controller/controller_parameters.hpp"
#include "smoothsteer/controller/trailer_chain.hpp"

namespace smoothsteer {

//! delta_veh's time derivatives for a chain state and lead curvature: d/dt = v d/ds and
//! d2/dt2 = v^2 d2/ds2 + dv/dt d/ds (paper_notes §3 for delta_veh(delta_1)). The acceleration is
//! 0 for n < 2 (kappa_n switches there).
struct CommandDerivatives {
  double rate_radps = 0.0;
  double acceleration_radps2 = 0.0;
};
CommandDerivatives steering_derivatives(const ChainAngles& angles,
                                        const ControllerParameters& parameters, double direction,
                                        double speed_magnitude, double acceleration_mps2,
                                        double lead_curvature) noexcept;

//! What the governor needs to know about the sub-step it constrains.
struct GovernorStep {
  double speed_magnitude = 0.0;  //!< |v| [m/s]
  //! |dv/dt| [m/s^2] to budget for: the largest of the measured, the differenced and the
  //! configured one (SteeringGovernor::max_longitudinal_acceleration_mps2).
  double longitudinal_acceleration = 0.0;
  double duration_s = 0.0;           //!< the sub-step's duration h [s]
  double previous_rate_radps = 0.0;  //!< the command's rate at the end of the last sub-step
};

struct CurvatureInterval {
  double low = 0.0;
  double high = 0.0;
};

//! Eq. (governor_interval): the lead curvatures for which the limits of parameters.governor hold
//! over the next sub-step, unbounded where they do not depend on kappa_n. When no kappa_n can
//! keep them (a rate already above R after a retune or a speed jump), the interval is the one
//! point that brakes the rate hardest within A. Requires order 1 or 2.
CurvatureInterval governed_lead_curvature_interval(const ChainAngles& angles,
                                                   const ControllerParameters& parameters,
                                                   double direction,
                                                   const GovernorStep& step) noexcept;

//! Eq. (governed_reversal): the far law's largest authority at speed |v| [1/m], d R / (2
//! lambda_veh |v|): reversing the steering of +-kbar at the rate limit R takes 2 lambda_veh kbar /
//! R seconds, and the car must not travel more than d meanwhile, or the law overshoots its surface
//! into a limit cycle; d = l for n = 2, l / 2 for n = 1 (docs/governor.md, section 4), with l the
//! far_law_length() at governed_reversal_heading_rad.
double governed_reversal_curvature(const ControllerParameters& parameters,
                                   double speed_mps) noexcept;
//! The heading error [rad] at which the reversal bound takes the law length: there
//! governed_law_length() is 0.7 sqrt(|v| lambda_veh / R), the length the bound was sized with.
inline constexpr double governed_reversal_heading_rad = 0.245;

//! Eq. (governed_feedforward_rate): the rate [1/m^2] at which the feedforward's lead curvature may
//! change under the governor, R / (lambda_veh |v|): the steering follows it at the car's rate
//! limit (d delta / dt ~ lambda_veh |v| d kappa / ds), and the governor holds the rate and the
//! acceleration that result. The certified L_ff bounds the rate over the whole box instead; the
//! feedforward uses the larger of the two (docs/governor.md, section 4). +inf at standstill.
double governed_feedforward_rate(const ControllerParameters& parameters, double speed_mps) noexcept;

//! Eq. (governed_authority): the parameters at speed |v| under the governor, from certified ones
//! (a schedule entry, whose wheelbases, k_rob and L_ff are kept). The lead curvature bound
//! becomes the largest the car's angle and friction limits allow (never less than the certified
//! one), and kbar_ff at least governed_feedforward_share of it; the near-path law's authority
//! (SteeringGovernor::near_law_switching_bound) is lowered to the certified kbar_sw. Returns
//! `certified` unchanged when the governor is off or the widened set would leave the invariant
//! sets (kbar_i lambda_i >= 1).
ControllerParameters governed_parameters(const ControllerParameters& certified,
                                         double speed_mps) noexcept;
inline constexpr double governed_feedforward_share = 0.8;
//! Eq. (governed_law_length), l(v, psi) [m]: the far law's length scale, from the travel the rate
//! limit needs to turn a heading error psi (docs/governor.md, section 4). The controller passes
//! the envelope of its lead wheel's heading error, so that l shortens for a small error and does
//! not shrink in the middle of correcting a large one.
double governed_law_length(const ControllerParameters& parameters, double speed_mps,
                           double heading_error_rad) noexcept;
//! The far law's length the governor uses [m]: SteeringGovernor::law_length_m when the
//! parameters fix it (fixed_law_length), else governed_law_length().
double far_law_length(const ControllerParameters& parameters, double speed_mps,
                      double heading_error_rad) noexcept;

}  // namespace smoothsteer
