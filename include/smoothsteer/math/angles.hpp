#pragma once
//! \file angles.hpp
//! Small angle and sign helpers shared by the controller, the paths and the models.

#include <cmath>
#include <numbers>

namespace smoothsteer {

inline constexpr double pi = std::numbers::pi;

//! Wraps an angle to (-pi, pi].
inline double wrap_angle(double angle) noexcept {
  if (angle > -pi && angle <= pi) return angle;  // already wrapped: remainder would return it
  double wrapped = std::remainder(angle, 2.0 * pi);
  if (wrapped <= -pi) wrapped += 2.0 * pi;
  return wrapped;
}

//! sign(x) with sign(0) = 0, as in the paper's sign().
inline constexpr double sign(double x) noexcept {
  return (x > 0.0) - (x < 0.0);
}

//! sign(x) with sign(0) = +1, for choices that must pick a side.
inline constexpr double sign_nonzero(double x) noexcept {
  return x < 0.0 ? -1.0 : 1.0;
}

}  // namespace smoothsteer
