#include "kinetic_error_model.hpp"

#include <unsupported/Eigen/MatrixFunctions>

namespace smoothsteer::detail {

KineticErrorModel kinetic_error_model(const VehicleParameters& vehicle, double v) {
  const double m = vehicle.mass_kg, iz = vehicle.yaw_inertia_kgm2;
  const double lf = vehicle.cg_to_front_axle_m, lr = vehicle.cg_to_rear_axle_m;
  const double cf = vehicle.front_cornering_stiffness_npr();
  const double cr = vehicle.rear_cornering_stiffness_npr();
  KineticErrorModel model;
  model.a.setZero();
  model.input_u.setZero();
  model.input_kappa.setZero();
  enum { e, psi, vy, r, delta, rate };
  // e' = v psi + vy - lr r: the rear axle's lateral velocity across the path.
  model.a(e, psi) = v;
  model.a(e, vy) = 1.0;
  model.a(e, r) = -lr;
  // psi' = r - v kappa.
  model.a(psi, r) = 1.0;
  model.input_kappa(psi) = -v;
  // Rajamani eq. 2.31 per axle: the forces of the slip angles delta - (vy + lf r) / v and
  // -(vy - lr r) / v.
  model.a(vy, vy) = -(cf + cr) / (m * v);
  model.a(vy, r) = (cr * lr - cf * lf) / (m * v) - v;
  model.a(vy, delta) = cf / m;
  model.a(r, vy) = (cr * lr - cf * lf) / (iz * v);
  model.a(r, r) = -(cf * lf * lf + cr * lr * lr) / (iz * v);
  model.a(r, delta) = cf * lf / iz;
  model.a(delta, rate) = 1.0;
  model.input_u(rate) = 1.0;
  return model;
}

DiscreteKineticModel discretise(const KineticErrorModel& model, double h) {
  constexpr int n = kinetic_states;
  // (x, u, kappa, kappa'): u and kappa' constant, kappa' the derivative of kappa.
  using Augmented = Eigen::Matrix<double, n + 3, n + 3>;
  Augmented augmented = Augmented::Zero();
  augmented.topLeftCorner<n, n>() = model.a * h;
  augmented.block<n, 1>(0, n) = model.input_u * h;
  augmented.block<n, 1>(0, n + 1) = model.input_kappa * h;
  augmented(n + 1, n + 2) = h;
  const Augmented exponential = augmented.exp();
  DiscreteKineticModel discrete;
  discrete.phi = exponential.topLeftCorner<n, n>();
  discrete.gamma_u = exponential.block<n, 1>(0, n);
  discrete.gamma_kappa = exponential.block<n, 1>(0, n + 1);
  discrete.gamma_kappa_rate = exponential.block<n, 1>(0, n + 2);
  return discrete;
}

}  // namespace smoothsteer::detail
