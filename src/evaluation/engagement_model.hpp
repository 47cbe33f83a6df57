#pragma once
// Internal: the kinematic single-track model (eq. kappar, rear axle) in path coordinates along a
// curved path, its Jacobian, and the path's curvature with its arc-length derivative; shared by
// the engagement bound's NLP and its starting trajectory (engagement_bound.hpp).

#include <cmath>

#include "smoothsteer/path/path.hpp"

namespace smoothsteer::detail {

//! kappa(s), dkappa/ds and d2kappa/ds2 by centred differences of Path::evaluate (the path has
//! no analytic derivative of its curvature). The steps are far below the 1 m knot spacing of the
//! shipped splines and far above the rounding noise of the curvature.
struct PathCurvature {
  double kappa = 0.0;
  double derivative = 0.0;         //!< dkappa/ds [1/m^2]
  double second_derivative = 0.0;  //!< d2kappa/ds2 [1/m^3] (for the Hessian only)
};
inline PathCurvature path_curvature(const Path& path, double s) noexcept {
  constexpr double step_m = 1e-4, wide_step_m = 1e-3;
  const double at = path.evaluate(s).curvature;
  const double ahead = path.evaluate(s + step_m).curvature;
  const double behind = path.evaluate(s - step_m).curvature;
  const double far_ahead = path.evaluate(s + wide_step_m).curvature;
  const double far_behind = path.evaluate(s - wide_step_m).curvature;
  return {at, (ahead - behind) / (2.0 * step_m),
          (far_ahead - 2.0 * at + far_behind) / (wide_step_m * wide_step_m)};
}

//! Rates of (s, e, psi) in path coordinates at speed v, wheelbase L:
//!   s' = v cos psi / D,  e' = v sin psi,  psi' = v tan(delta) / L - kappa(s) s',  D = 1 - kappa e,
//! and their partial derivatives jacobian[i][j] by (s, e, psi, delta).
struct FrenetRates {
  double rate[3] = {0.0, 0.0, 0.0};
  double jacobian[3][4] = {};
};
inline FrenetRates frenet_rates(double v, double L, const PathCurvature& c, double e, double psi,
                                double delta) noexcept {
  FrenetRates out;
  const double denominator = 1.0 - c.kappa * e;
  const double cos_psi = std::cos(psi), sin_psi = std::sin(psi), tan_delta = std::tan(delta);
  const double s_dot = v * cos_psi / denominator;
  const double ds_ds = v * cos_psi * e * c.derivative / (denominator * denominator);
  const double ds_de = v * cos_psi * c.kappa / (denominator * denominator);
  const double ds_dpsi = -v * sin_psi / denominator;
  out.rate[0] = s_dot;
  out.rate[1] = v * sin_psi;
  out.rate[2] = v * tan_delta / L - c.kappa * s_dot;
  out.jacobian[0][0] = ds_ds;
  out.jacobian[0][1] = ds_de;
  out.jacobian[0][2] = ds_dpsi;
  out.jacobian[1][2] = v * cos_psi;
  out.jacobian[2][0] = -c.derivative * s_dot - c.kappa * ds_ds;
  out.jacobian[2][1] = -c.kappa * ds_de;
  out.jacobian[2][2] = -c.kappa * ds_dpsi;
  out.jacobian[2][3] = v * (1.0 + tan_delta * tan_delta) / L;
  return out;
}

//! Second derivatives of the three rates of frenet_rates: hessian[i] holds, for rate i, the
//! entries (s,s), (e,s), (e,e), (psi,s), (psi,e), (psi,psi), (delta,delta) (all others are 0).
//! With g = 1 / D: dg/de = kappa g^2, dg/ds = kappa' e g^2.
struct FrenetCurvatureTerms {
  double hessian[3][7] = {};
};
inline FrenetCurvatureTerms frenet_second_derivatives(double v, double L, const PathCurvature& c,
                                                      double e, double psi, double delta) noexcept {
  FrenetCurvatureTerms out;
  const double g = 1.0 / (1.0 - c.kappa * e);
  const double cos_psi = std::cos(psi), sin_psi = std::sin(psi), tan_delta = std::tan(delta);
  const double k1 = c.derivative, k2 = c.second_derivative;
  const double f0 = v * cos_psi * g;
  const double f0_s = v * cos_psi * e * k1 * g * g;
  const double f0_e = v * cos_psi * c.kappa * g * g;
  const double f0_psi = -v * sin_psi * g;
  double* h0 = out.hessian[0];
  h0[0] = v * cos_psi * e * (k2 * g * g + 2.0 * k1 * k1 * e * g * g * g);
  h0[1] = v * cos_psi * k1 * g * g * (1.0 + 2.0 * c.kappa * e * g);
  h0[2] = 2.0 * v * cos_psi * c.kappa * c.kappa * g * g * g;
  h0[3] = -v * sin_psi * k1 * e * g * g;
  h0[4] = -v * sin_psi * c.kappa * g * g;
  h0[5] = -v * cos_psi * g;
  out.hessian[1][5] = -v * sin_psi;
  double* h2 = out.hessian[2];
  h2[0] = -(k2 * f0 + 2.0 * k1 * f0_s + c.kappa * h0[0]);
  h2[1] = -(k1 * f0_e + c.kappa * h0[1]);
  h2[2] = -c.kappa * h0[2];
  h2[3] = -(k1 * f0_psi + c.kappa * h0[3]);
  h2[4] = -c.kappa * h0[4];
  h2[5] = -c.kappa * h0[5];
  h2[6] = 2.0 * v * tan_delta * (1.0 + tan_delta * tan_delta) / L;
  return out;
}

//! One classic RK4 step of x' = derivative(x) for a 5-state model (the chain's held control is
//! captured by `derivative`).
template <class Derivative>
void rk4_step(double x[5], double h, const Derivative& derivative) noexcept {
  double stages[4][5], probe[5];
  derivative(x, stages[0]);
  for (int stage = 1; stage < 4; ++stage) {
    const double weight = stage == 3 ? h : 0.5 * h;
    for (int c = 0; c < 5; ++c) probe[c] = x[c] + weight * stages[stage - 1][c];
    derivative(probe, stages[stage]);
  }
  for (int c = 0; c < 5; ++c) {
    x[c] += h / 6.0 * (stages[0][c] + 2.0 * stages[1][c] + 2.0 * stages[2][c] + stages[3][c]);
  }
}

}  // namespace smoothsteer::detail
