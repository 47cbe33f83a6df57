#include "smoothsteer/baselines/triple_integrator.hpp"

#include <algorithm>
#include <cmath>

#include "smoothsteer/math/angles.hpp"

namespace smoothsteer {

TripleIntegratorSwitching triple_integrator_switching(double x1, double x2, double x3,
                                                      double bound) noexcept {
  TripleIntegratorSwitching result;
  const double u = bound;
  const double s2 = x2 + x3 * std::abs(x3) / (2.0 * u);
  const double nu = s2 != 0.0 ? sign(s2) : -sign(x3);
  // nu x2 + x3^2 / (2U) >= nu S2 = |S2| >= 0; max() only removes round-off.
  const double radicand = std::max(0.0, nu * x2 + x3 * x3 / (2.0 * u));
  const double s3 = x1 + x3 * x3 * x3 / (3.0 * u * u) +
                    nu * (x2 * x3 / u + std::pow(radicand, 1.5) / std::sqrt(u));
  result.second_order_surface = s2;
  result.third_order_surface = s3;
  if (s3 != 0.0) {
    result.control_sign = -sign(s3);
  } else if (s2 != 0.0) {
    result.control_sign = -sign(s2);
  } else {
    result.control_sign = -sign(x3);
  }
  return result;
}

}  // namespace smoothsteer
