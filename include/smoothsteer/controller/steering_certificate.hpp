#pragma once
//! \file steering_certificate.hpp
//! Certified bounds of the steering command's rate and acceleration under the feedforward law
//! kappa_n = kappa_ff + kappa_sw (docs/feedforward.md, "certificate"), and the stationary
//! cornering relations of the chain. One home for this math: the controller, the tuner and the
//! tools call it.
//!
//! In sine-curvature coordinates sigma_{i-1} = sin(delta_i) / lambda_i every stage of the chain
//! is a LINEAR first-order lag in the arc length s_{i-1} of wheel i-1 (from paper-notes §1):
//!   d sigma_{i-1} / d s_{i-1} = (kappa_i - sigma_{i-1}) / lambda_i,
//!   kappa_{i-1} = tan(delta_i) / lambda_i = sigma_{i-1} / sqrt(1 - lambda_i^2 sigma_{i-1}^2).
//! Hence the response splits exactly into the response to kappa_ff and to kappa_sw. The part
//! from kappa_ff changes no faster than kappa_ff itself (|d kappa_ff / ds| <= L_ff); the part
//! from kappa_sw stays within kbar_sw, so a stage's rate is at most 2 kbar_sw / lambda. The
//! static maps between stages stretch both by their largest slope. With the paper's bound
//! |kappa_n| <= kbar_n alone the same argument gives the box bound 2 kbar / lambda; the split
//! replaces kbar_n by the much smaller kbar_sw and the path's own curvature rate.

#include <limits>

#include "smoothsteer/controller/controller_parameters.hpp"
#include "smoothsteer/controller/trailer_chain.hpp"

namespace smoothsteer {

//! Bounds on the real steering angle delta_veh per metre of rear-axle travel.
struct SteeringCertificate {
  double steering_angle_rad = 0.0;  //!< |delta_veh| (invariant sets, paper-notes §2)
  //! |d delta_veh / ds| [rad/m]; +inf when the parameters certify none (order 0, or an
  //! unlimited feedforward rate: then only the box bound of ChainBounds holds).
  double rate_per_meter = std::numeric_limits<double>::infinity();
  //! |d2 delta_veh / ds2| [rad/m^2]; +inf for n < 2 (kappa_n switches: delta_veh is C^0 only).
  double acceleration_per_meter2 = std::numeric_limits<double>::infinity();

  //! |d delta_veh / dt| <= |v| rate_per_meter [rad/s].
  double rate_radps(double speed_mps) const noexcept;
  //! |d2 delta_veh / dt2| <= v^2 acceleration_per_meter2 + |dv/dt| rate_per_meter [rad/s^2].
  double acceleration_radps2(double speed_mps, double acceleration_mps2) const noexcept;
};

//! The certificate of the split kappa_ff (|.| <= kbar_ff, |d/ds| <= L_ff) + kappa_sw
//! (|.| <= kbar_n - kbar_ff) for valid parameters of any order. It holds from a chain state
//! whose switching response is zero (stationary cornering with kappa_ff, as reset() sets up).
SteeringCertificate feedforward_certificate(const ControllerParameters& parameters) noexcept;
//! The same from chain bounds already computed for these parameters (no second computation).
SteeringCertificate feedforward_certificate(const ControllerParameters& parameters,
                                            const ChainBounds& bounds) noexcept;

//! Largest slope d delta_veh / d sigma_0 and |d2 delta_veh / d sigma_0^2| over
//! |sin delta_1| <= front_sine_bound, for delta_veh = atan(r tan delta_1), r = lambda_veh /
//! lambda_1, sigma_0 = sin(delta_1) / lambda_1 (closed-form upper bounds).
struct OutputSlopes {
  double first = 0.0;
  double second = 0.0;
};
OutputSlopes output_slope_bounds(double vehicle_wheelbase_m, double front_wheelbase_m,
                                 double front_sine_bound) noexcept;

//! Stationary cornering (every d delta_i / ds = 0): the wheels run on concentric circles with
//! R_i^2 = R_{i-1}^2 + lambda_i^2, so 1 / kappa_n^2 = 1 / kappa_0^2 + L^2, L^2 = sum lambda_i^2
//! (eq. cornering_constr generalised). Signs are kept; |kappa_n| L < 1 is required.
double stationary_rear_curvature(double lead_curvature, double chain_length_squared) noexcept;
double stationary_lead_curvature(double rear_curvature, double chain_length_squared) noexcept;

//! Eq. (cornering_constr), generalised: lambda_1 = sqrt(lambda_veh^2 - sum_{i>=2} lambda_i^2),
//! so that in stationary cornering the lead wheel runs in the real front wheel's track. Returns
//! 0 when the outer wheelbases are not shorter than lambda_veh (callers reject that).
double cornering_front_wheelbase(double vehicle_wheelbase_m, double outer_length_squared) noexcept;

}  // namespace smoothsteer
