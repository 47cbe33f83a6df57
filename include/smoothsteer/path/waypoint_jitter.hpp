#pragma once
//! \file waypoint_jitter.hpp
//! How much noise a planner's or a recording's waypoints carry, read from the waypoints alone
//! (docs/controller.md, "Paths as they come"). A stack rarely knows it, and the smoothing fit
//! needs it: a tolerance below the noise leaves the noise's curvature in the path (at a
//! motorway's 25 m/s, 1 mm of jitter on 1 m waypoints interpolated exactly put the car 0.9 m
//! off the road), one far above it cuts corners.

#include <cstddef>
#include <numbers>
#include <vector>

#include "smoothsteer/math/vec2.hpp"

namespace smoothsteer {

//! The standard deviation of the waypoints' jitter per coordinate [m], assuming they sample a
//! road made of lines, arcs and clothoids (curvature piecewise linear in arc length).
//!
//! At each interior waypoint the curvature of the circle through it and its neighbours,
//! k_i = 2 d_i / (a_i b_i) (d_i: the point's distance from the chord between its neighbours at
//! the point's share a_i / (a_i + b_i) of it; a_i, b_i the chords to them), is linear in arc
//! length on such a road, so its second divided difference over the arc length vanishes except
//! within two waypoints of a junction. On jitter of standard deviation sigma it is a linear
//! combination of five waypoints' lateral noise: divided by the norm of that combination's
//! coefficients it has standard deviation sigma. The median of its magnitudes, divided by
//! 0.6745 (the median of |N(0, 1)|), is the estimate: junctions are a few outliers the median
//! ignores while they are fewer than half the samples.
//!
//! Returns 0 for fewer than min_jitter_waypoints waypoints and
//! below min_jitter_m. Needs the waypoints
//! Path::from_waypoints accepts (no duplicates); set-up time, O(n).
double estimate_waypoint_jitter(const std::vector<Vec2>& waypoints);

//! The smoothing tolerance for jitter of standard deviation `jitter_std_m` per coordinate [m]:
//! Reinsch's criterion at the jitter's own RMS distance, sigma sqrt(2) (WaypointSmoothing).
inline double jitter_tolerance_m(double jitter_std_m) noexcept {
  return std::numbers::sqrt2 * jitter_std_m;
}

//! The fewest waypoints estimate_waypoint_jitter() reads; with fewer it returns 0. A short
//! window of a tight manoeuvre holds as many junctions as samples (the parking lot's reversing
//! piece, 13 m with four clothoid ends: 1.4-2.2 mm read from clean samples), and the median
//! cannot tell them from jitter; from 20 waypoints on, the shipped roads' clean windows read 0.
inline constexpr std::size_t min_jitter_waypoints = 20;
//! Below this the estimate is reported as 0 [m]: what a clean road that is not made of lines,
//! arcs and clothoids reads (samples of a C2 spline, as the lane changes' paths: up to 2.4e-5 m),
//! not noise a fit should follow. A fit at such a tolerance leaves the interpolating spline's
//! natural ends for the smoothing fit's extrapolated ones, which moved the 15 m/s lane change
//! in stack mode from 0.046 to 0.069 m.
inline constexpr double min_jitter_m = 1e-4;

}  // namespace smoothsteer
