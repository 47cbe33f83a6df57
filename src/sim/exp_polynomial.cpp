// Event location on exponential polynomials (src/sim/exp_polynomial.hpp).

#include "exp_polynomial.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace smoothsteer::detail {
namespace {

//! Roots of c0 + c1 q + c2 q^2 in (a, b), ascending; cancellation-free form of the formula.
Roots quadratic_roots(double c0, double c1, double c2, double a, double b) noexcept {
  Roots roots;
  auto add = [&](double q) {
    if (q > a && q < b) roots.at[static_cast<std::size_t>(roots.count++)] = q;
  };
  if (c2 == 0.0) {
    if (c1 != 0.0) add(-c0 / c1);
    return roots;
  }
  const double discriminant = c1 * c1 - 4.0 * c2 * c0;
  if (discriminant < 0.0) return roots;
  const double s = -0.5 * (c1 + std::copysign(std::sqrt(discriminant), c1));
  double first = s / c2;
  double second = s != 0.0 ? c0 / s : first;
  if (first > second) std::swap(first, second);
  add(first);
  if (second != first) add(second);
  return roots;
}

//! The root of a monotone f in [lo, hi] with f(lo) and f(hi) of opposite signs: the Illinois
//! variant of regula falsi (superlinear, keeps the bracket), to a bracket of ~1e-15 in q.
double bracketed_root(const ExpPolynomial& f, double lo, double hi, double f_lo,
                      double f_hi) noexcept {
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  int kept = 0;  // +1: lo kept last time, -1: hi kept last time
  for (int iteration = 0; iteration < 200; ++iteration) {
    if (hi - lo <= 1e-15 * std::max(1.0, std::abs(hi))) break;
    double q = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(q > lo && q < hi)) q = 0.5 * (lo + hi);
    const double f_q = f(q);
    if (f_q == 0.0) return q;
    if ((f_q > 0.0) == (f_hi > 0.0)) {
      hi = q;
      f_hi = f_q;
      if (kept == 1) f_lo *= 0.5;
      kept = 1;
    } else {
      lo = q;
      f_lo = f_q;
      if (kept == -1) f_hi *= 0.5;
      kept = -1;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace

Roots roots_inside(const ExpPolynomial& f, double a, double b) noexcept {
  if (f.alpha == 0.0 && f.beta == 0.0) return quadratic_roots(f.c0, f.c1, f.c2, a, b);
  // Between the roots of f' (found the same way, one level down) f is monotone.
  const Roots breaks = roots_inside(f.derivative(), a, b);
  Roots roots;
  double lo = a, f_lo = f(a);
  for (int i = 0; i <= breaks.count && roots.count < static_cast<int>(roots.at.size()); ++i) {
    const double hi = i < breaks.count ? breaks.at[static_cast<std::size_t>(i)] : b;
    const double f_hi = f(hi);
    if ((f_lo < 0.0 && f_hi > 0.0) || (f_lo > 0.0 && f_hi < 0.0)) {
      const double root = bracketed_root(f, lo, hi, f_lo, f_hi);
      if (root > a && root < b) roots.at[static_cast<std::size_t>(roots.count++)] = root;
    } else if (f_hi == 0.0 && hi < b) {
      roots.at[static_cast<std::size_t>(roots.count++)] = hi;
    }
    lo = hi;
    f_lo = f_hi;
  }
  return roots;
}

double first_exit(const ExpPolynomial& margin, double a, double b) noexcept {
  const Roots breaks = roots_inside(margin.derivative(), a, b);
  double lo = a, m_lo = margin(a);
  for (int i = 0; i <= breaks.count; ++i) {
    const double hi = i < breaks.count ? breaks.at[static_cast<std::size_t>(i)] : b;
    const double m_hi = margin(hi);
    if (m_hi <= 0.0) return m_lo > 0.0 ? bracketed_root(margin, lo, hi, m_lo, m_hi) : a;
    // m_hi > 0: either positive throughout, or (first piece only) rising out of <= 0.
    lo = hi;
    m_lo = m_hi;
  }
  return b + 1.0;
}

}  // namespace smoothsteer::detail
