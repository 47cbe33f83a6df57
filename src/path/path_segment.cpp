//! Line and arc geometry (closed form) and the per-kind dispatch of PathSegment.

#include "smoothsteer/path/path_segment.hpp"

#include <algorithm>
#include <cmath>

#include "path_detail.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path.hpp"

namespace smoothsteer {
namespace {

//! A query closer than this fraction of the radius to an arc's center has no meaningful
//! closest point (all are equally close); the warm parameter picks one.
constexpr double kCenterFraction = 1e-12;

//! Pose on a line or arc at local arc length s. The arc uses sin(ks)/k and 2 sin^2(ks/2)/k,
//! which stay accurate for nearly straight arcs, instead of going through the far center.
PathPoint line_or_arc_point(const PathSegment& segment, double s) noexcept {
  const double k = segment.curvature;
  double along = s;
  double left = 0.0;
  if (k != 0.0) {
    const double half_turn = 0.5 * k * s;
    along = std::sin(2.0 * half_turn) / k;
    left = 2.0 * std::sin(half_turn) * std::sin(half_turn) / k;
  }
  const Vec2 forward = unit_from_heading(segment.start_heading_rad);
  const Vec2 normal{-forward.y, forward.x};
  return PathPoint{segment.start + along * forward + left * normal,
                   wrap_angle(segment.start_heading_rad + k * s), k};
}

SegmentProjection project_line(const PathSegment& segment, Vec2 query) noexcept {
  const Vec2 forward = unit_from_heading(segment.start_heading_rad);
  const Vec2 offset = query - segment.start;
  double along = dot(offset, forward);
  SegmentProjection result;
  result.clamped_at_start = along < 0.0;
  result.clamped_at_end = along > segment.length;
  along = std::clamp(along, 0.0, segment.length);
  result.parameter = along;
  result.local_arc_length_m = along;
  result.point = segment.start + along * forward;
  result.heading_rad = wrap_angle(segment.start_heading_rad);
  if (result.clamped_at_start || result.clamped_at_end) {
    result.lateral_error_m = detail::signed_distance(forward, query - result.point);
  } else {
    result.lateral_error_m = cross(forward, offset);
  }
  result.distance_m = std::abs(result.lateral_error_m);
  return result;
}

//! Closed form through the center: the closest point of the full circle lies on the ray from
//! the center through the query; outside the arc's sweep the nearer end point wins, because
//! the distance to a circle point grows monotonically with the angle to that ray.
SegmentProjection project_arc(const PathSegment& segment, Vec2 query, double warm) noexcept {
  const double k = segment.curvature;
  const double radius = 1.0 / std::abs(k);
  const double turn = sign_nonzero(k);
  const Vec2 forward = unit_from_heading(segment.start_heading_rad);
  const Vec2 center = segment.start + (1.0 / k) * Vec2{-forward.y, forward.x};
  const Vec2 from_center = query - center;
  const double center_distance = norm(from_center);
  const double sweep = std::abs(k) * segment.length;
  const bool full_circle = sweep >= 2.0 * pi * (1.0 - 1e-12);

  SegmentProjection result;
  double s = std::clamp(warm, 0.0, segment.length);
  if (center_distance > kCenterFraction * radius) {
    // Tangent direction at the circle point nearest to the query, then the angle travelled
    // from the start heading in the direction of motion, in [0, 2 pi).
    const double tangent = std::atan2(from_center.y, from_center.x) + turn * 0.5 * pi;
    double travelled = std::fmod(turn * (tangent - segment.start_heading_rad), 2.0 * pi);
    if (travelled < 0.0) travelled += 2.0 * pi;
    if (full_circle || travelled <= sweep) {
      s = std::min(travelled * radius, segment.length);
    } else if (travelled - sweep < 2.0 * pi - travelled) {
      s = segment.length;
      result.clamped_at_end = true;
    } else {
      s = 0.0;
      result.clamped_at_start = true;
    }
  }
  const PathPoint point = line_or_arc_point(segment, s);
  result.parameter = s;
  result.local_arc_length_m = s;
  result.point = point.position;
  result.heading_rad = point.heading_rad;
  result.curvature = k;
  if (result.clamped_at_start || result.clamped_at_end) {
    result.lateral_error_m =
        detail::signed_distance(unit_from_heading(point.heading_rad), query - point.position);
  } else {
    // The center lies on the left of a left turn: inside the circle is left.
    result.lateral_error_m = turn * (radius - center_distance);
  }
  result.distance_m = std::abs(result.lateral_error_m);
  return result;
}

}  // namespace

PathSegment PathSegment::make_line(Vec2 from, double heading_rad, double length_m) noexcept {
  PathSegment segment;
  segment.kind = Kind::line;
  segment.start = from;
  segment.start_heading_rad = heading_rad;
  segment.length = length_m;
  return segment;
}

PathSegment PathSegment::make_arc(Vec2 from, double heading_rad, double curvature_per_m,
                                  double length_m) noexcept {
  PathSegment segment = make_line(from, heading_rad, length_m);
  segment.kind = Kind::arc;
  segment.curvature = curvature_per_m;
  return segment;
}

PathSegment PathSegment::make_clothoid(Vec2 from, double heading_rad, double curvature_start,
                                       double curvature_end, double length_m) noexcept {
  PathSegment segment = make_line(from, heading_rad, length_m);
  segment.kind = Kind::clothoid;
  segment.curvature = curvature_start;
  segment.curvature_rate = (curvature_end - curvature_start) / length_m;
  return segment;
}

double PathSegment::end_curvature() const noexcept {
  if (kind == Kind::clothoid) return curvature + curvature_rate * length;
  if (kind == Kind::cubic) return detail::cubic_point(*this, t_end).curvature;
  return curvature;
}

PathSegment PathSegment::make_cubic(const std::array<double, 4>& x, const std::array<double, 4>& y,
                                    double t_range) noexcept {
  PathSegment segment;
  segment.kind = Kind::cubic;
  segment.x_coefficients = x;
  segment.y_coefficients = y;
  segment.t_end = t_range;
  segment.start = {x[0], y[0]};
  segment.start_heading_rad = std::atan2(y[1], x[1]);
  segment.length = detail::cubic_arc_length(segment, t_range);
  return segment;
}

PathPoint PathSegment::evaluate_at(double local_s) const noexcept {
  return evaluate_parameter(parameter_at(local_s));
}

PathPoint PathSegment::evaluate_parameter(double parameter) const noexcept {
  const double clamped = std::clamp(parameter, 0.0, parameter_end());
  if (kind == Kind::cubic) return detail::cubic_point(*this, clamped);
  if (kind == Kind::clothoid) return detail::clothoid_point(*this, clamped);
  return line_or_arc_point(*this, clamped);
}

double PathSegment::arc_length_at(double parameter) const noexcept {
  const double clamped = std::clamp(parameter, 0.0, parameter_end());
  return kind == Kind::cubic ? detail::cubic_arc_length(*this, clamped) : clamped;
}

double PathSegment::parameter_at(double local_s) const noexcept {
  const double clamped = std::clamp(local_s, 0.0, length);
  return kind == Kind::cubic ? detail::cubic_parameter_at(*this, clamped) : clamped;
}

SegmentProjection PathSegment::project_local(Vec2 query, double warm_parameter, bool exhaustive,
                                             bool with_arc_length) const noexcept {
  switch (kind) {
    case Kind::line:
      return project_line(*this, query);
    case Kind::arc:
      // A zero-curvature arc is rejected by Path::from_segments; treat it as the line it is.
      return curvature != 0.0 ? project_arc(*this, query, warm_parameter)
                              : project_line(*this, query);
    case Kind::cubic:
      return detail::cubic_project(*this, query, warm_parameter, exhaustive, with_arc_length);
    case Kind::clothoid:
      return detail::clothoid_project(*this, query, warm_parameter, exhaustive);
  }
  return project_line(*this, query);
}

}  // namespace smoothsteer
