#pragma once
//! \file optimal_reaching.hpp
//! The numerically optimal reaching manoeuvre under C1 and C2 (paper Sec. IV-B, "Optimal
//! solution"): the shortest rear-axle travel S until the rear axle is on a straight path and
//! stays there, for the extended system x_ext (paper eq. x_ext)
//!   e' = sin psi,  psi' = tan(delta) / lambda,  delta' = u,   (' = d/ds, s = rear arc length)
//!   |delta| <= delta-bar (C1),  |u| <= delta-bar' (C2),
//!   x(0) given,  x(S) = 0  (e = psi = delta = 0: with u = 0 afterwards the car stays on the path).
//! Direct transcription: trapezoidal collocation on N intervals of length S/N with S a decision
//! variable, solved by Ipopt with the exact, hand-derived constraint Jacobian and Hessian of the
//! Lagrangian (Ipopt's derivative checker finds no error in either). The terminal set can be
//! relaxed to |e| <= tol_e, |psi| <= tol_psi and delta free: the optimum of that problem is a lower
//! bound on the travel of ANY controller that satisfies C1/C2 and enters that set (used by the
//! tests against the controllers).

#include <string>
#include <vector>
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct ReachingProblem {
  double wheelbase_m = 1.0;                //!< lambda [m]
  double steering_angle_bound_rad = 0.5;   //!< delta-bar, C1 [rad]
  double steering_rate_bound_per_m = 1.0;  //!< delta-bar', C2 [rad/m]
  double initial_lateral_error_m = 0.5;    //!< e(0) [m]
  double initial_heading_rad = 0.0;        //!< psi(0) relative to the path [rad]
  double initial_steering_rad = 0.0;       //!< delta(0) [rad]
  //! Terminal set: |e(S)| <= tol_e and |psi(S)| <= tol_psi (0 = exact) ...
  double terminal_lateral_tolerance_m = 0.0;
  double terminal_heading_tolerance_rad = 0.0;
  //! ... and delta(S) = 0 unless this is set (then delta(S) is free within C1).
  bool terminal_steering_free = false;
  int intervals = 150;           //!< N collocation intervals
  double max_iterations = 3000;  //!< Ipopt max_iter
  double tolerance = 1e-9;       //!< Ipopt tol
  //! true: Ipopt's L-BFGS first (fast), the exact Hessian of the Lagrangian (hand-derived,
  //! eval_h) for a start where it stalls; false: L-BFGS only.
  bool exact_hessian = true;
  //! Runs Ipopt's finite-difference derivative test (printing) before solving; for development.
  bool check_derivatives = false;

  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>".
  std::string validation_error() const { return describe(first_violation()); }
  //! Throws std::invalid_argument with validation_error().
  void validate() const { throw_if_violated(first_violation()); }
};

struct ReachingSolution {
  bool converged = false;     //!< Ipopt reported Solve_Succeeded / Solved_To_Acceptable_Level
  std::string solver_status;  //!< Ipopt's status, as text
  int iterations = 0;
  double solve_time_s = 0.0;
  double distance_m = 0.0;  //!< S
  //! Node values, N + 1 each: s_k = k S / N, and e, psi, delta, u = delta' at s_k.
  std::vector<double> arc_length_m, lateral_error_m, heading_rad, steering_rad, steering_rate_per_m;
};

//! Solves the problem with Ipopt. Throws std::invalid_argument for invalid problems; a failed
//! solve is reported in `converged` / `solver_status`, not thrown. Initial guess: S = guess
//! (<= 0: a heuristic from e(0) and psi(0)) with states interpolated linearly; restarts from
//! 2x, 0.5x and 4x that guess when Ipopt does not converge, keeping the shortest converged S.
ReachingSolution solve_optimal_reaching(const ReachingProblem& problem,
                                        double distance_guess_m = 0.0);

//! Re-simulation of a solution's control sequence (u held at the interval mean of its node
//! values, the control the trapezoidal defect of delta integrates exactly; RK4 with `substeps`
//! per interval): the largest violations of C1 and C2 and the end state.
struct ReachingCheck {
  double max_steering_excess_rad = 0.0;  //!< max(|delta| - delta-bar, 0)
  double max_rate_excess_per_m = 0.0;    //!< max(|u| - delta-bar', 0)
  double final_lateral_error_m = 0.0;
  double final_heading_rad = 0.0;
  double final_steering_rad = 0.0;
};
ReachingCheck resimulate_reaching(const ReachingProblem& problem, const ReachingSolution& solution,
                                  int substeps = 20);

}  // namespace smoothsteer
