#pragma once
//! \file dubins_switching_law.hpp
//! The Dubins-car sliding-mode law kappa = kbar sign(sigma) (paper eqs. cntrllaw, sigma, kappan)
//! and its globally convergent extension (docs/global_convergence.md).

#include "smoothsteer/controller/controller_parameters.hpp"

namespace smoothsteer {

struct SwitchingResult {
  double sliding_variable = 0.0;  //!< sigma [m] (paper surface) or the heading gap z [rad] (global)
  double curvature = 0.0;         //!< kappa = kbar * sign(...) [1/m]
};

//! Eq. (sigma) as printed: sigma = -e - (1 - cos psi) / ((1 - k_rob) kbar) * sign(sin psi).
double paper_sliding_variable(double lateral_error, double relative_heading, double curvature_bound,
                              double k_rob) noexcept;

//! Reference heading of the global law (docs/global_convergence.md):
//! psi_ref(e) = -sign(e) acos(max(1 - (1 - k_rob) kbar |e|, cos psi_max)).
//! The curve psi = psi_ref(e) is the paper's surface sigma = 0 for |e| <= (1 - cos psi_max) /
//! ((1 - k_rob) kbar) and a straight approach at psi_max beyond.
double global_reference_heading(double lateral_error, double curvature_bound, double k_rob,
                                double approach_angle) noexcept;

//! kappa for a Dubins car at lateral error e and heading psi relative to the path, with the
//! boundary layer of the parameters.
SwitchingResult dubins_switching_law(double lateral_error, double relative_heading,
                                     double curvature_bound,
                                     const ControllerParameters& parameters) noexcept;
//! The same with the boundary layer epsilon >= 0 given (the governed split scales it with kbar).
SwitchingResult dubins_switching_law(double lateral_error, double relative_heading,
                                     double curvature_bound, double boundary_layer,
                                     const ControllerParameters& parameters) noexcept;

//! Lateral offset of the lead wheel from the path at which the rear axle lies on the path in
//! stationary cornering on curvature kappa: the chain's radii satisfy R_n^2 = R_0^2 + sum
//! lambda_i^2, so e_lead = -(sqrt(1 + kappa^2 L^2) - 1) / kappa with L^2 = sum lambda_i^2 (outside
//! the turn).
double rear_axle_cornering_offset(double path_curvature, double chain_length_squared) noexcept;

}  // namespace smoothsteer
