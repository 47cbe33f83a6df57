#pragma once
//! \file gauss_legendre.hpp
//! The 8-point Gauss-Legendre rule on [-1, 1] (symmetric nodes, positive half listed), shared by
//! the arc length of the cubic spline pieces and the Fresnel integrals of the clothoid pieces.

#include <array>

namespace smoothsteer::detail {

inline constexpr std::array<double, 4> gauss_legendre_8_nodes{
    0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
inline constexpr std::array<double, 4> gauss_legendre_8_weights{
    0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

}  // namespace smoothsteer::detail
