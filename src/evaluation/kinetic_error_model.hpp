#pragma once
// Internal: the linear single-track model about the path of kinetic_reference.hpp, continuous
// and exactly discretised, shared by the transcription and its re-simulation.

#include <Eigen/Dense>

#include "smoothsteer/vehicle/vehicle_parameters.hpp"

namespace smoothsteer::detail {

constexpr int kinetic_states = 6;  // e, psi, vy, r, delta, delta'

using KineticState = Eigen::Matrix<double, kinetic_states, 1>;
using KineticMatrix = Eigen::Matrix<double, kinetic_states, kinetic_states>;

//! x' = A x + b_u u + b_kappa kappa (kinetic_reference.hpp).
struct KineticErrorModel {
  KineticMatrix a;
  KineticState input_u;
  KineticState input_kappa;
  KineticState rates(const KineticState& x, double u, double kappa) const {
    return a * x + input_u * u + input_kappa * kappa;
  }
};

KineticErrorModel kinetic_error_model(const VehicleParameters& vehicle, double speed_mps);

//! x_{k+1} = phi x_k + gamma_u u_k + gamma_kappa kappa_k + gamma_kappa_rate (kappa_{k+1} -
//! kappa_k) / h, with u held over the interval and kappa linear in time between its node values
//! (exact on clothoids): the matrix exponential of the model augmented by u, kappa and kappa'.
struct DiscreteKineticModel {
  KineticMatrix phi;
  KineticState gamma_u;
  KineticState gamma_kappa;
  KineticState gamma_kappa_rate;
};

DiscreteKineticModel discretise(const KineticErrorModel& model, double time_step_s);

}  // namespace smoothsteer::detail
