#pragma once
//! \file curvature_speed_profile.hpp
//! A speed profile from the path's curvature, as a driver or a road designer would set it:
//! v(s) <= min(max_speed, sqrt(a_lat,max / |kappa(s)|)), then a forward pass that holds the
//! acceleration to a_long,max and a backward pass that holds the braking to a_brake,max
//! (v_{i+1}^2 <= v_i^2 + 2 a ds; the usual two-pass construction of minimum-time speed profiles,
//! e.g. Lipp and Boyd, "Minimum-time speed optimisation over a fixed path", Int. J. Control
//! 87(6), 2014). The result is mapped to time along the path's arc length (constant acceleration
//! between grid points: dt = 2 ds / (v_i + v_{i+1})), as a tabulated SpeedProfile.

#include <optional>
#include <string>
#include <vector>

#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_plan.hpp"
#include "smoothsteer/sim/speed_profile.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct CurvatureSpeedLimits {
  double max_speed_mps = 10.0;                 //!< design speed, on straights [m/s]
  double max_lateral_acceleration_mps2 = 2.0;  //!< v^2 |kappa| bound [m/s^2]
  double max_acceleration_mps2 = 1.0;          //!< dv/dt bound when speeding up [m/s^2]
  double max_deceleration_mps2 = 2.0;          //!< -dv/dt bound when braking [m/s^2]
  //! Speed at s = 0 [m/s]; empty: the limit there. Clamped to the limit there.
  std::optional<double> initial_speed_mps;
  double spacing_m = 0.5;  //!< grid of the passes [m]
  //! On a PathPlan: how long the car stands at each cusp before it moves off in the other gear
  //! [s] (the gear change; the steering may settle meanwhile).
  double cusp_rest_s = 1.0;

  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  std::string validation_error() const { return describe(first_violation()); }
  void validate() const { throw_if_violated(first_violation()); }
};

//! Most points of the grid of one profile (all pieces of a plan together): 1e6 at the default
//! spacing of 0.5 m is a path of 500 km, about 80 MB while it is sampled.
inline constexpr std::size_t max_speed_grid_points = 1'000'000;

//! The limited speed at s_i = i * spacing_m from 0 to the path's length (the last point at the
//! length). Each point's curvature bound uses the largest |kappa| of the path within one spacing
//! of it, so a curvature jump between grid points is met at full bound. Throws
//! std::invalid_argument on bad limits (validate()) and on a path whose grid would have more
//! than max_speed_grid_points points.
std::vector<double> curvature_limited_speeds(const Path& path, const CurvatureSpeedLimits& limits);

//! The same as a time table: knots at the grid points, speed linear in time between them.
SpeedProfile curvature_speed_profile(const Path& path, const CurvatureSpeedLimits& limits);

//! A signed profile for a path with gear changes: on each piece the limits above, from rest
//! (after a cusp; piece 0 from initial_speed_mps or its limit) to rest (at every cusp and at the
//! plan's end), signed by the piece's gear, with a rest of cusp_rest_s at every cusp
//! (SpeedProfile::signed_speeds; simulate() on the plan switches pieces there). Throws
//! std::invalid_argument naming the piece if one is not longer than two grid spacings.
SpeedProfile curvature_speed_profile(const PathPlan& plan, const CurvatureSpeedLimits& limits);

}  // namespace smoothsteer
