#pragma once
//! \file comparison_controllers.hpp
//! One factory for every controller of the comparison (issue "Comparison", item 1), so that
//! benchmarks and scenario files can name them:
//!
//!   name             controller                                        C1/C2 by construction
//!   dubins_smc       first-order Dubins-car SMC (paper eq. cntrllaw, n = 0)        no
//!   proposed_c0      lead-wheel controller, n = 1 (paper eq. ext1)                  yes
//!   proposed_c1      lead-wheel controller, n = 2 (paper eq. control_law)           yes
//!   hosm             constrained HOSM of Sec. IV-B (hosm_controller.hpp)            yes
//!   newton_raphson   Newton-Raphson flow, Shivam et al. ECC 2019                    yes (clamped)
//!   stanley          Stanley (geometric_controllers.hpp)                            no
//!   pure_pursuit     pure pursuit, speed-scaled look-ahead                          no
//!   lqr              LQR on the lateral-error dynamics + curvature feedforward      no
//!   mpc              Autoware's linear MPC, least squares + saturation (mpc_controller.hpp) no
//!   mpc_constrained  the same MPC with hard angle and rate constraints (ALGLIB QP)   yes (QP)
//!
//! Every controller comes wrapped in a SaturatedController with the same SteeringLimits, whose
//! second-order limiter holds the command to the angle, rate and acceleration limits where the
//! controller does not respect them itself, and counts how often and by how much.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "smoothsteer/baselines/geometric_controllers.hpp"
#include "smoothsteer/baselines/lqr_controller.hpp"
#include "smoothsteer/baselines/mpc_controller.hpp"
#include "smoothsteer/baselines/newton_raphson_controller.hpp"
#include "smoothsteer/baselines/steering_limits.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

//! What every controller of a comparison shares: the path, the vehicle and the limits.
struct ComparisonSetup {
  std::shared_ptr<const Path> path;
  double wheelbase_m = 2.7;         //!< lambda_veh [m]
  double nominal_speed_mps = 10.0;  //!< converts the rate limit to delta-bar' = rate / v [m/s]
  SteeringLimits limits;            //!< C1, the time-domain rate and the acceleration limit
  //! k_rob of the Dubins SMC and the proposed controllers (paper Sec. IV: 0.3).
  double k_rob = 0.3;
  //! psi-bar of the HOSM controller [rad]. It is lowered, if needed, to the largest value with
  //! alpha >= G delta-bar' / 2 (hosm_heading_bound_for), so that alpha > 0 at any speed.
  double hosm_heading_bound_rad = 0.6;
  //! lambda_l of proposed_c1 [m].
  double lead_wheelbase_m = 1.0;
  //! Gains of the baselines, defaults from their sources (docs/baselines.md). The factory
  //! overwrites their wheelbase with wheelbase_m, their limits with `limits`, and the MPC's
  //! solver by name (mpc / mpc_constrained).
  StanleyParameters stanley;
  PurePursuitParameters pure_pursuit;
  LqrParameters lqr;
  NewtonRaphsonParameters newton_raphson;
  MpcParameters mpc;

  //! Largest wheelbase_m accepted [m].
  static constexpr double max_wheelbase_m = 1e3;

  //! The first rule broken by a number (validation.hpp); the path is checked by the three below.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return path && !first_violation(); }
  //! Empty when valid, else "ComparisonSetup: <field> = <value> <rule>" (or the null path).
  std::string validation_error() const;
  //! Throws std::invalid_argument with validation_error().
  void validate() const;
};

//! Largest psi-bar <= requested with F <= G delta-bar' / 2, i.e. tan(psi-bar) <=
//! delta-bar' / (2 lambda kbar^2) with kbar = tan(delta-bar) / lambda (hosm_controller.hpp).
double hosm_heading_bound_for(double requested_rad, double wheelbase_m, double angle_bound_rad,
                              double rate_bound_per_m) noexcept;

//! Names accepted by make_comparison_controller, in table order.
const std::vector<std::string>& comparison_controller_names();

//! Builds the named controller. Throws std::invalid_argument for an unknown name (listing the
//! known ones) or invalid set-up.
std::unique_ptr<SaturatedController> make_comparison_controller(std::string_view name,
                                                                const ComparisonSetup& setup);

}  // namespace smoothsteer
