#pragma once
//! \file path_detail.hpp
//! Internals shared by the files of src/path/ (not installed).

#include <string>
#include <vector>

#include "smoothsteer/path/path.hpp"

namespace smoothsteer::detail {

//! Shortest round-trip text of a number, for validation messages.
std::string format_number(double value);

//! Natural cubic spline through >= 3 validated waypoints (finite, no consecutive duplicates),
//! chord-length parametrized; one cubic segment per pair of consecutive waypoints.
std::vector<PathSegment> natural_cubic_spline(const std::vector<Vec2>& waypoints);

//! Smoothing cubic spline (Reinsch) through >= 3 validated waypoints: the natural cubic spline
//! with knots at their chord-length parameters that is closest to them in the RMS sense
//! allowed by `tolerance_m` (> 0) with the least integral of squared second derivative;
//! `restore_corners`: WaypointSmoothing::restore_corners.
std::vector<PathSegment> smoothing_cubic_spline(const std::vector<Vec2>& waypoints,
                                                double tolerance_m, bool restore_corners);

//! One cubic segment per knot interval of the cubic spline with the given knot points, second
//! derivatives (moments) at the knots and knot spacing (knot_points.size() = moments.size() =
//! knot_spacing.size() + 1).
std::vector<PathSegment> cubic_segments_from_moments(const std::vector<Vec2>& knot_points,
                                                     const std::vector<Vec2>& moments,
                                                     const std::vector<double>& knot_spacing);

// Cubic segment internals (cubic_segment.cpp), called by PathSegment's dispatchers.
PathPoint cubic_point(const PathSegment& segment, double t) noexcept;
double cubic_arc_length(const PathSegment& segment, double t) noexcept;
double cubic_parameter_at(const PathSegment& segment, double local_s) noexcept;
SegmentProjection cubic_project(const PathSegment& segment, Vec2 query, double warm_parameter,
                                bool exhaustive, bool with_arc_length) noexcept;

// Clothoid segment internals (clothoid_segment.cpp). The local parameter is the arc length.
//! Most brackets of the clothoid's global closest-point search (its turning bound in
//! Path::from_segments keeps below it).
inline constexpr int max_clothoid_brackets = 64;
//! Largest max(|kappa_start|, |kappa_end|) * length of a clothoid segment [rad].
inline constexpr double max_clothoid_turning_rad = 12.566370614359172;  // two full turns
PathPoint clothoid_point(const PathSegment& segment, double s) noexcept;
SegmentProjection clothoid_project(const PathSegment& segment, Vec2 query, double warm_parameter,
                                   bool exhaustive) noexcept;

//! The tightest cheap box around `segment` inside `box` (which must contain it): exact for
//! lines, the control-point hull of the Bezier form for cubics, `box` itself for arcs.
SegmentBox tighten_box(const PathSegment& segment, const SegmentBox& box) noexcept;

//! A capsule containing `segment`: the chord and the largest distance of the Bezier control
//! points from it (cubics), the chord and the sagitta (arcs up to a half turn; longer arcs get
//! their circle's disk), the segment itself (lines), the chord and the half minor axis of the
//! ellipse with the chord's ends as foci and the length as major axis (clothoids: a curve of
//! length L between two points lies in that ellipse).
SegmentCapsule segment_capsule(const PathSegment& segment) noexcept;

//! Signed distance with the side of `offset` relative to `tangent` (left positive). A point
//! straight ahead or behind counts as left; it only happens on clamped segment ends.
inline double signed_distance(Vec2 tangent, Vec2 offset) noexcept {
  const double distance = norm(offset);
  return cross(tangent, offset) < 0.0 ? -distance : distance;
}

}  // namespace smoothsteer::detail
