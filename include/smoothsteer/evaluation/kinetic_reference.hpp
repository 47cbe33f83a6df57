#pragma once
//! \file kinetic_reference.hpp
//! The tracking reference on the kinetic model (docs/corners.md): the least max |e| of the rear
//! axle that ANY steering reaches on the linear single-track model (Rajamani, Vehicle Dynamics
//! and Control, eqs. 2.31 and 2.45, written at the rear axle) at constant speed v, under the
//! car's steering angle, rate and acceleration limits, from the path's start. The state about
//! the path, with the heading error psi small, is x = (e, psi, vy, r, delta, delta'):
//!   e' = v psi + vy - lr r,   psi' = r - v kappa(s0 + v t),
//!   vy' = (Fyf + Fyr) / m - v r,   r' = (lf Fyf - lr Fyr) / Iz,   delta'' = u,
//!   Fyf = Cf (delta - (vy + lf r) / v),   Fyr = -Cr (vy - lr r) / v,
//! linear in x, u and the path's curvature: with u held and kappa linear in time on each interval
//! of a uniform time grid, the transition is the matrix exponential (exact), and minimising z
//! subject to -z <= e_k <= z at the nodes is a linear program (Ipopt). Unlike the kinematic
//! reference of engagement_bound.hpp it carries the slip's lag behind the steering; it leaves out
//! the tires' saturation (the Magic Formula's slope falls with the load) and the actuator's lag,
//! both of which only make a corner harder.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "smoothsteer/path/path.hpp"
#include "smoothsteer/validation.hpp"
#include "smoothsteer/vehicle/vehicle_parameters.hpp"

namespace smoothsteer {

struct KineticReferenceProblem {
  std::shared_ptr<const Path> path;  //!< the reference path, driven from start_arc_length_m
  VehicleParameters vehicle;        //!< m, Iz, lf, lr, the axle stiffnesses and the steering limits
  double speed_mps = 8.0;           //!< v, constant [m/s]
  double start_arc_length_m = 0.0;  //!< where the car starts, on the path, straight and at rest
  double duration_s = 10.0;         //!< horizon T [s]
  double time_step_s = 0.02;        //!< grid spacing h (N = ceil(T / h)) [s]
  int max_iterations = 3000;        //!< Ipopt max_iter
  double tolerance = 1e-9;          //!< Ipopt tol

  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>" (or the missing path).
  std::string validation_error() const;
  //! Throws std::invalid_argument with validation_error().
  void validate() const;
};

struct KineticReference {
  bool converged = false;     //!< Ipopt reported Solve_Succeeded / Solved_To_Acceptable_Level
  std::string solver_status;  //!< Ipopt's status, as text
  int iterations = 0;
  double max_abs_lateral_error_m = 0.0;  //!< z: the reference
  double time_step_s = 0.0;              //!< h = T / N
  //! Node values, N + 1 each: t_k = k h, and e, delta, delta' at t_k.
  std::vector<double> time_s, lateral_error_m, steering_rad, steering_rate_radps;
  //! The held control u on each of the N intervals [rad/s^2].
  std::vector<double> steering_acceleration_radps2;
};

//! Solves the problem with Ipopt. Throws std::invalid_argument for an invalid problem; a failed
//! solve is reported in `converged` / `solver_status`, not thrown. Thread-safe (the Ipopt solves
//! of the process are serialised).
KineticReference solve_kinetic_reference(const KineticReferenceProblem& problem);

//! Independent re-simulation of a reference's held controls on the same model (RK4 with
//! `substeps` per interval, the path's curvature read at every stage): the largest |e| over every
//! sub-step, and the largest node deviation from the reference's e_k.
struct KineticReferenceCheck {
  double max_abs_lateral_error_m = 0.0;
  double max_node_lateral_deviation_m = 0.0;
};
KineticReferenceCheck resimulate_kinetic_reference(const KineticReferenceProblem& problem,
                                                   const KineticReference& reference,
                                                   int substeps = 10);

}  // namespace smoothsteer
