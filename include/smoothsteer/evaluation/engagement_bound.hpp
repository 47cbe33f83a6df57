#pragma once
//! \file engagement_bound.hpp
//! The physical reference of an engagement (docs/engagement.md): the least possible max over a
//! run of the rear axle's |e| that ANY steering can achieve on the kinematic single-track model
//! (eq. kappar, rear-axle reference) at constant speed v, under the car's steering angle, rate
//! and acceleration limits, from a start pose off the path. In path (Frenet) coordinates:
//!   s' = v cos psi / (1 - kappa(s) e),  e' = v sin psi,  psi' = v tan(delta) / L - kappa(s) s',
//!   delta' = r,  r' = u,   |delta| <= delta-bar,  |r| <= R,  |u| <= A   (' = d/dt),
//!   minimise z subject to -z <= e(t_k) <= z at every node.
//! Direct transcription on a uniform time grid: trapezoidal defects for (s, e, psi, delta), and
//! u held constant on each interval, so r is piecewise linear and the defects of (delta, r) are
//! exact for the held control. Ipopt gets the exact sparse Jacobian and Hessian of the Lagrangian
//! (hand-derived; kappa'(s) and kappa''(s) by centred differences of Path::evaluate), with its
//! L-BFGS approximation as the fallback.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "smoothsteer/math/pose2.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct EngagementBoundProblem {
  std::shared_ptr<const Path> path;                 //!< the reference path (open or closed)
  double wheelbase_m = 2.578;                       //!< L = lambda_veh [m]
  double speed_mps = 15.0;                          //!< v, constant [m/s]
  double steering_angle_bound_rad = 1.066;          //!< delta-bar [rad]
  double steering_rate_bound_radps = 0.4;           //!< R [rad/s]
  double steering_acceleration_bound_radps2 = 8.0;  //!< A [rad/s^2]
  Pose2 start;                                      //!< rear-axle start pose (world frame)
  double initial_steering_rad = 0.0;                //!< delta(0) [rad]
  double initial_steering_rate_radps = 0.0;         //!< r(0) [rad/s]
  double duration_s = 10.0;                         //!< horizon T [s]
  double time_step_s = 0.04;                        //!< grid spacing h (N = ceil(T / h)) [s]
  int max_iterations = 3000;                        //!< Ipopt max_iter
  double tolerance = 1e-8;                          //!< Ipopt tol
  //! Runs Ipopt's second-order derivative test (printing) before solving; for development.
  bool check_derivatives = false;

  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>" (or the missing path).
  std::string validation_error() const;
  //! Throws std::invalid_argument with validation_error().
  void validate() const;
};

struct EngagementBound {
  bool converged = false;     //!< Ipopt reported Solve_Succeeded / Solved_To_Acceptable_Level
  std::string solver_status;  //!< Ipopt's status, as text
  int iterations = 0;
  double solve_time_s = 0.0;
  double max_abs_lateral_error_m = 0.0;  //!< z: the bound
  double time_step_s = 0.0;              //!< h = T / N
  //! Node values, N + 1 each: t_k = k h, and s, e, psi, delta, r at t_k.
  std::vector<double> time_s, arc_length_m, lateral_error_m, heading_error_rad, steering_rad,
      steering_rate_radps;
  //! The held control u on each of the N intervals [rad/s^2].
  std::vector<double> steering_acceleration_radps2;
};

//! The initial path coordinates of `problem.start`: s(0), e(0) and psi(0) (closest point).
struct EngagementStart {
  double arc_length_m = 0.0;
  double lateral_error_m = 0.0;
  double heading_error_rad = 0.0;
};
EngagementStart engagement_start(const EngagementBoundProblem& problem);

//! Solves the problem with Ipopt from a feasible starting trajectory (a saturated cascade
//! feedback simulated on the grid). Throws std::invalid_argument for an invalid problem; a
//! failed solve is reported in `converged` / `solver_status`, not thrown. Thread-safe (the
//! Ipopt solves of the process are serialised: this Ipopt's MUMPS is not re-entrant).
EngagementBound solve_engagement_bound(const EngagementBoundProblem& problem);

//! Independent re-simulation of a bound's held controls on the Cartesian kinematic model
//! (x' = v cos theta, y' = v sin theta, theta' = v tan(delta) / L, delta' = r, r' = u; RK4 with
//! `substeps` per interval), e by projection onto the path at every sub-step.
struct EngagementBoundCheck {
  double max_abs_lateral_error_m = 0.0;         //!< over every sub-step
  double max_node_lateral_deviation_m = 0.0;    //!< max_k |e_resim(t_k) - e_k|
  double max_steering_excess_rad = 0.0;         //!< max(|delta| - delta-bar, 0)
  double max_rate_excess_radps = 0.0;           //!< max(|r| - R, 0)
  double max_acceleration_excess_radps2 = 0.0;  //!< max(|u| - A, 0)
};
EngagementBoundCheck resimulate_engagement_bound(const EngagementBoundProblem& problem,
                                                 const EngagementBound& bound, int substeps = 10);

}  // namespace smoothsteer
