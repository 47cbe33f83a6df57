#pragma once
//! \file worst_case.hpp
//! Derivatives of the REAL steering angle with respect to the rear arc length s, per state of the
//! chain, and their worst case over the invariant-set box (paper Sec. III items 4-5).
//!
//! delta_veh = atan(r tan(delta_1)), r = lambda_veh / lambda_1 (paper_notes §3), so with
//! g = d delta_veh / d delta_1 = r / (cos^2 + r^2 sin^2):
//!   d delta_veh / ds   = g delta_1'
//!   d2 delta_veh / ds2 = g' delta_1'^2 + g delta_1''
//! Time derivatives: rate = v * (first), acceleration = v^2 * (second) + dv/dt * (first).

#include "smoothsteer/controller/controller_parameters.hpp"
#include "smoothsteer/controller/trailer_chain.hpp"

namespace smoothsteer {

struct SteeringDerivatives {
  double rate_per_meter = 0.0;           //!< d delta_veh / ds [rad/m]
  double acceleration_per_meter2 = 0.0;  //!< d2 delta_veh / ds2 [rad/m^2]; 0 for n = 1
};

//! At one chain state with lead curvature kappa_n (order >= 1; parameters assumed valid).
SteeringDerivatives vehicle_steering_derivatives(const ControllerParameters& parameters,
                                                 const ChainAngles& delta,
                                                 double lead_curvature) noexcept;

//! sup over the box |delta_i| <= asin(kbar_i lambda_i) and kappa_n in {-kbar_n, +kbar_n} of
//! |d delta_veh/ds| and |d2 delta_veh/ds2|. Order 1 or 2 (the acceleration bound needs n = 2; for
//! n = 1 it is +inf because kappa_1 switches). The rate is a 1-D supremum (its worst case puts
//! delta_2 on the box edge); the acceleration a smooth 2-D one, found by a dense grid that
//! includes the boundary plus pattern-search refinement of the best samples.
//! The box contains states the closed loop never reaches, so the bound is conservative
//! (docs/tuning.md). Throws std::invalid_argument for invalid parameters or n outside {1, 2}.
SteeringDerivatives worst_case_steering_derivatives(const ControllerParameters& parameters);

}  // namespace smoothsteer
