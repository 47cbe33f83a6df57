//! PathBuilder: validated sequences of lines, arcs and clothoids.

#include "smoothsteer/path/path_builder.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "path_detail.hpp"

namespace smoothsteer {
namespace {

[[noreturn]] void fail(const char* where, const char* field, double value, const char* rule) {
  throw std::invalid_argument(std::string(where) + ": " + field + " = " +
                              detail::format_number(value) + " must be " + rule);
}

}  // namespace

PathBuilder::PathBuilder(Vec2 start, double heading_rad)
    : position_(start), heading_rad_(heading_rad) {
  constexpr const char* where = "PathBuilder::PathBuilder";
  if (!std::isfinite(start.x)) fail(where, "start.x", start.x, "finite");
  if (!std::isfinite(start.y)) fail(where, "start.y", start.y, "finite");
  if (!std::isfinite(heading_rad)) fail(where, "heading_rad", heading_rad, "finite");
}

PathBuilder& PathBuilder::line(double length_m) {
  if (!std::isfinite(length_m) || !(length_m > 0.0)) {
    fail("PathBuilder::line", "length_m", length_m, "finite and > 0");
  }
  append(PathSegment::make_line(position_, heading_rad_, length_m));
  return *this;
}

PathBuilder& PathBuilder::arc(double radius_m, double angle_rad) {
  if (!std::isfinite(radius_m) || !(radius_m > 0.0)) {
    fail("PathBuilder::arc", "radius_m", radius_m, "finite and > 0");
  }
  if (!std::isfinite(angle_rad) || angle_rad == 0.0) {
    fail("PathBuilder::arc", "angle_rad", angle_rad, "finite and nonzero");
  }
  const double curvature = (angle_rad > 0.0 ? 1.0 : -1.0) / radius_m;
  append(PathSegment::make_arc(position_, heading_rad_, curvature, radius_m * std::abs(angle_rad)));
  return *this;
}

PathBuilder& PathBuilder::clothoid(double length_m, double curvature_end) {
  constexpr const char* where = "PathBuilder::clothoid";
  if (!std::isfinite(length_m) || !(length_m > 0.0)) {
    fail(where, "length_m", length_m, "finite and > 0");
  }
  if (!std::isfinite(curvature_end) || curvature_end == curvature_) {
    fail(where, "curvature_end", curvature_end,
         ("finite and differ from the current end curvature " + detail::format_number(curvature_))
             .c_str());
  }
  const double turning = std::max(std::abs(curvature_), std::abs(curvature_end)) * length_m;
  if (!(turning <= detail::max_clothoid_turning_rad)) {
    fail(where, "max(|curvature|) * length_m", turning, "<= 4 pi (two full turns)");
  }
  append(PathSegment::make_clothoid(position_, heading_rad_, curvature_, curvature_end, length_m));
  return *this;
}

Path PathBuilder::build(bool closed) const {
  return Path::from_segments(segments_, closed);
}

void PathBuilder::append(const PathSegment& segment) {
  // The next piece starts exactly where this one ends, so joints are continuous up to the
  // rounding of one evaluation (no drift from re-deriving poses).
  const PathPoint end = segment.evaluate_at(segment.length);
  segments_.push_back(segment);
  position_ = end.position;
  heading_rad_ = end.heading_rad;
  curvature_ = segment.end_curvature();
}

}  // namespace smoothsteer
