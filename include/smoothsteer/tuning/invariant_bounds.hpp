#pragma once
//! \file invariant_bounds.hpp
//! Closed-form parameter bounds from the invariant sets of the trailer chain (paper Sec. III
//! items 1-3, paper_notes §2, §3, §5). Valid for any order n >= 1.
//!
//! Going down the chain, kbar_{i-1} = kbar_i / sqrt(1 - kbar_i^2 lambda_i^2); going up, the
//! inverse kbar_i = kbar_{i-1} / sqrt(1 + kbar_{i-1}^2 lambda_i^2). Hence
//!   1 / kbar_n^2 = 1 / kbar_0^2 + sum_i lambda_i^2,   kbar_0 = tan(dbar_veh) / lambda_veh.
//! With the cornering constraint sum_i lambda_i^2 = lambda_veh^2 (eq. cornering_constr for
//! n = 2) this becomes kbar_n = sin(dbar_veh) / lambda_veh, independent of lambda_l: the lead
//! radius equals the radius of the real front wheel at full lock. For n = 2 and in terms of the
//! fictive angle bound dbar = asin(kbar_1 lambda) it is the corrected eq. (kappalmax)
//!   kbar_l = sin(dbar) / sqrt(lambda^2 + lambda_l^2 sin^2(dbar)).

#include "smoothsteer/controller/controller_parameters.hpp"

namespace smoothsteer {

//! Largest kbar_n whose invariant sets keep |delta_veh| <= max_steering_angle_rad, for the chain
//! wheelbases lambda_1..lambda_n of `parameters` (its lead_curvature_bound is ignored). Any n.
//! Throws std::invalid_argument for an angle outside (0, pi/2) or invalid wheelbases.
double lead_curvature_bound_for_steering_angle(const ControllerParameters& parameters,
                                               double max_steering_angle_rad);

//! The inverse: the bound on |delta_veh| implied by the parameters' kbar_n (= atan(lambda_veh
//! kbar_0), as compute_chain_bounds()).
double steering_angle_bound(const ControllerParameters& parameters);

//! Eq. (cornering_constr), generalized: lambda_1 = sqrt(lambda_veh^2 - sum_{i>=2} lambda_i^2),
//! so that in stationary cornering the lead wheel runs in the real front wheel's track (the
//! radius of wheel i satisfies R_i^2 = R_{i-1}^2 + lambda_i^2). `outer_wheelbases` holds
//! lambda_2..lambda_n (count entries). Throws if sum lambda_i^2 >= lambda_veh^2.
double fictive_wheelbase(double vehicle_wheelbase_m, const double* outer_wheelbases, int count);

//! Paper Sec. III item 2 with paper_notes §5/§6: k_rob >= (kappa_d + kbar_path) / kbar_n, where a
//! curved reference path acts as a matched disturbance of at most its curvature bound. Returns
//! max(k_rob_floor, that ratio). Throws std::invalid_argument naming the inputs when the result
//! is not below k_rob_ceiling (< 1: eq. sigma divides by 1 - k_rob).
double minimum_k_rob(double matched_disturbance_curvature, double path_curvature_bound,
                     double lead_curvature_bound, double k_rob_floor = 0.0,
                     double k_rob_ceiling = 0.95);

//! Parameters of order n = 2 from (lambda_veh, lambda_l, kbar_l, k_rob) with lambda from eq.
//! (cornering_constr); other fields copied from `base`. Not validated.
ControllerParameters second_order_parameters(const ControllerParameters& base,
                                             double vehicle_wheelbase_m, double lead_wheelbase_m,
                                             double lead_curvature_bound, double k_rob) noexcept;

}  // namespace smoothsteer
