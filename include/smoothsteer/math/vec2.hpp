#pragma once
//! \file vec2.hpp
//! A plain 2D point/vector. The real-time core deliberately avoids Eigen so that it stays
//! dependency-free; Eigen is used by the tuning and optimal-control modules.

#include <cmath>

namespace smoothsteer {

struct Vec2 {
  double x = 0.0;  //!< [m]
  double y = 0.0;  //!< [m]
};

constexpr Vec2 operator+(Vec2 a, Vec2 b) noexcept {
  return {a.x + b.x, a.y + b.y};
}
constexpr Vec2 operator-(Vec2 a, Vec2 b) noexcept {
  return {a.x - b.x, a.y - b.y};
}
constexpr Vec2 operator*(double k, Vec2 a) noexcept {
  return {k * a.x, k * a.y};
}
constexpr double dot(Vec2 a, Vec2 b) noexcept {
  return a.x * b.x + a.y * b.y;
}
//! z-component of the 3D cross product: positive when b points to the left of a.
constexpr double cross(Vec2 a, Vec2 b) noexcept {
  return a.x * b.y - a.y * b.x;
}
//! Euclidean length. Plain sqrt instead of std::hypot: path coordinates are far from overflow and
//! glibc's hypot costs several times more in the projection's inner loop.
inline double norm(Vec2 a) noexcept {
  return std::sqrt(a.x * a.x + a.y * a.y);
}
inline Vec2 unit_from_heading(double heading) noexcept {
  return {std::cos(heading), std::sin(heading)};
}

}  // namespace smoothsteer
