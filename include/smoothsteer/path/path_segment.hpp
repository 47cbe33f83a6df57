#pragma once
//! \file path_segment.hpp
//! One piece of a reference path: a straight line, a circular arc, a clothoid (Euler spiral:
//! curvature linear in arc length) or a parametric cubic.
//! Paths (path.hpp) are G1-continuous sequences of these. Include path.hpp to use
//! evaluate_at(), whose PathPoint result is defined there.

#include <array>

#include "smoothsteer/math/vec2.hpp"

namespace smoothsteer {

struct PathPoint;  // path.hpp includes this header and then defines PathPoint

//! Closest point on a single segment, clamped to the segment.
struct SegmentProjection {
  double parameter = 0.0;           //!< local parameter: arc length (line, arc) or t (cubic)
  double local_arc_length_m = 0.0;  //!< arc length from the segment start [m]
  double distance_m = 0.0;          //!< |query - point| [m]
  double lateral_error_m = 0.0;     //!< signed distance, left of the segment direction positive
  double heading_rad = 0.0;         //!< tangent at the point [rad]
  double curvature = 0.0;           //!< [1/m]
  Vec2 point;                       //!< [m]
  //! The distance still decreases when moving backwards past the start: the closest point of
  //! the whole path may lie on the previous segment (or on the start extension).
  bool clamped_at_start = false;
  //! Same at the end: the closest point may lie on the next segment (or the end extension).
  bool clamped_at_end = false;
};

//! An axis-aligned box [lower, upper] [m].
struct SegmentBox {
  Vec2 lower;
  Vec2 upper;
};

//! All points within `radius` of the line segment [from, to] [m]: a tight container of a short
//! curve (its chord and the largest deviation from it), whose distance is a cheap lower bound.
struct SegmentCapsule {
  Vec2 from;
  Vec2 to;
  double radius = 0.0;
};

//! A plain segment record. Lines, arcs and clothoids are described by their start pose and
//! curvature, clothoids also by the curvature's rate along s (local parameter = local arc
//! length); cubics by polynomial coefficients
//! x(t) = x[0] + x[1] t + x[2] t^2 + x[3] t^3 (same for y), t in [0, t_end], which the spline
//! fit parametrizes by chord length so that |p'(t)| stays close to 1.
struct PathSegment {
  enum class Kind { line, arc, cubic, clothoid };

  Kind kind = Kind::line;
  double s0 = 0.0;      //!< arc length of the segment start along the path [m]
  double length = 0.0;  //!< arc length of the segment [m]

  // Line, arc and clothoid geometry.
  Vec2 start;                      //!< start point [m]
  double start_heading_rad = 0.0;  //!< tangent at the start [rad]
  double curvature = 0.0;       //!< [1/m] (at the start, for a clothoid), 0 for lines, > 0 = left
  double curvature_rate = 0.0;  //!< d curvature / ds of a clothoid [1/m^2], 0 otherwise

  // Cubic geometry.
  std::array<double, 4> x_coefficients{};  //!< x(t) polynomial, lowest order first
  std::array<double, 4> y_coefficients{};  //!< y(t) polynomial, lowest order first
  double t_end = 0.0;                      //!< parameter range [0, t_end]

  static PathSegment make_line(Vec2 from, double heading_rad, double length_m) noexcept;
  //! `curvature_per_m` must be nonzero; the arc turns by curvature_per_m * length_m [rad].
  static PathSegment make_arc(Vec2 from, double heading_rad, double curvature_per_m,
                              double length_m) noexcept;
  //! A clothoid whose curvature runs linearly from `curvature_start` to `curvature_end` over
  //! `length_m` (curvature_rate = (end - start) / length).
  static PathSegment make_clothoid(Vec2 from, double heading_rad, double curvature_start,
                                   double curvature_end, double length_m) noexcept;
  //! Computes `length` by quadrature.
  static PathSegment make_cubic(const std::array<double, 4>& x, const std::array<double, 4>& y,
                                double t_range) noexcept;

  //! Upper end of the local parameter: `length` for lines and arcs, `t_end` for cubics.
  double parameter_end() const noexcept { return kind == Kind::cubic ? t_end : length; }

  //! Curvature at the end of the segment [1/m].
  double end_curvature() const noexcept;

  //! Point at local arc length `local_s` in [0, length] (clamped).
  PathPoint evaluate_at(double local_s) const noexcept;
  //! Point at local parameter (see SegmentProjection::parameter), clamped to the segment.
  PathPoint evaluate_parameter(double parameter) const noexcept;
  //! Arc length from the start to local parameter `parameter` [m].
  double arc_length_at(double parameter) const noexcept;
  //! Inverse of arc_length_at().
  double parameter_at(double local_s) const noexcept;

  //! Closest point to `query` on this segment. `warm_parameter` seeds the cubic search and
  //! breaks the tie for a query at an arc's center. `exhaustive` = false searches a cubic from
  //! the warm parameter only (the warm-started walk, where the query moved little); true adds
  //! seeds at both ends and the middle to find the global minimum on the segment.
  SegmentProjection project_local(Vec2 query, double warm_parameter, bool exhaustive = true,
                                  bool with_arc_length = true) const noexcept;
};

}  // namespace smoothsteer
