#pragma once
// Event location on the exact solution of the steering actuator (internal to src/sim).
// Every quantity that decides the actuator's saturation mode is, in the scaled time q = p tau
// of one stretch of constant input, of the form
//   f(q) = (c0 + c1 q + c2 q^2) e^{-q} + alpha + beta q
// (three equal lags: polynomials of degree <= 2 times e^{-q}; a rate-saturated output adds the
// linear term). f' has the same form with beta = 0 and f'' the same with alpha = beta = 0, so the
// monotone pieces of f follow from a quadratic's roots and at most two nested root searches:
// the first crossing of a level is found exactly, not by sampling (docs/simulation.md).

#include <array>
#include <cmath>

namespace smoothsteer::detail {

struct ExpPolynomial {
  double c0 = 0.0, c1 = 0.0, c2 = 0.0;  //!< polynomial factor of e^{-q}
  double alpha = 0.0, beta = 0.0;       //!< affine part

  double operator()(double q) const noexcept {
    return (c0 + q * (c1 + q * c2)) * std::exp(-q) + alpha + beta * q;
  }
  //! d/dq: (c1 - c0 + (2 c2 - c1) q - c2 q^2) e^{-q} + beta.
  ExpPolynomial derivative() const noexcept { return {c1 - c0, 2.0 * c2 - c1, -c2, beta, 0.0}; }
};

//! At most three roots of f in an interval (f' has at most three, see above).
struct Roots {
  std::array<double, 3> at{};
  int count = 0;
};

//! The roots of f inside the open interval (a, b), ascending (a sign change of f, or a zero of
//! the quadratic factor when f has no affine part).
Roots roots_inside(const ExpPolynomial& f, double a, double b) noexcept;

//! The first q in [a, b] at which `margin` becomes <= 0 while it was > 0 just before (or a
//! itself, when margin(a) <= 0 and it does not rise on its first monotone piece); b + 1 when
//! margin stays positive. A margin at or below 0 that rises at a is a state just entering the
//! mode it guards, which is no exit.
double first_exit(const ExpPolynomial& margin, double a, double b) noexcept;

}  // namespace smoothsteer::detail
