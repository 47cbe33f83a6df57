//! Path factories, their validation, assembly and evaluation.

#include "smoothsteer/path/path.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "path_detail.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/waypoint_jitter.hpp"

namespace smoothsteer {
namespace {

//! G1 tolerances of from_segments; generous against rounding, tight against real gaps.
constexpr double kPositionTolerance_m = 1e-6;
constexpr double kHeadingTolerance_rad = 1e-6;
//! Waypoints closer than this are duplicates: the chord-length parameter would degenerate.
constexpr double kDuplicateDistance_m = 1e-9;

[[noreturn]] void fail(const std::string& message) {
  throw std::invalid_argument(message);
}

void require_finite(const char* where, const std::string& field, double value) {
  if (!std::isfinite(value)) {
    fail(std::string(where) + ": " + field + " = " + detail::format_number(value) +
         " must be finite");
  }
}

void require_positive(const char* where, const std::string& field, double value) {
  if (!std::isfinite(value) || !(value > 0.0)) {
    fail(std::string(where) + ": " + field + " = " + detail::format_number(value) +
         " must be finite and > 0");
  }
}

void require_coordinate(const char* where, const std::string& field, double value) {
  require_finite(where, field, value);
  if (!(std::abs(value) <= Path::max_extent_m)) {
    fail(std::string(where) + ": " + field + " = " + detail::format_number(value) +
         " must have magnitude <= 1e9 m (Path::max_extent_m)");
  }
}

void require_extent(const char* where, const std::string& field, double value, double most) {
  require_positive(where, field, value);
  if (!(value <= most)) {
    fail(std::string(where) + ": " + field + " = " + detail::format_number(value) + " must be <= " +
         detail::format_number(most) + " m (Path::max_extent_m, Path::max_length_m)");
  }
}

void validate_segment(const PathSegment& segment, std::size_t index) {
  constexpr const char* where = "Path::from_segments";
  const std::string name = "segments[" + std::to_string(index) + "]";
  require_extent(where, name + ".length", segment.length, Path::max_length_m);
  if (segment.kind == PathSegment::Kind::cubic) {
    for (std::size_t i = 0; i < 4; ++i) {
      require_finite(where, name + ".x_coefficients[" + std::to_string(i) + "]",
                     segment.x_coefficients[i]);
      require_finite(where, name + ".y_coefficients[" + std::to_string(i) + "]",
                     segment.y_coefficients[i]);
    }
    require_positive(where, name + ".t_end", segment.t_end);
    const double computed = detail::cubic_arc_length(segment, segment.t_end);
    if (std::abs(computed - segment.length) > 1e-6 * (1.0 + computed)) {
      fail(std::string(where) + ": " + name + ".length = " + detail::format_number(segment.length) +
           " must match the arc length of the coefficients, " + detail::format_number(computed));
    }
    return;
  }
  require_coordinate(where, name + ".start.x", segment.start.x);
  require_coordinate(where, name + ".start.y", segment.start.y);
  require_finite(where, name + ".start_heading_rad", segment.start_heading_rad);
  require_finite(where, name + ".curvature", segment.curvature);
  if (segment.kind == PathSegment::Kind::arc && segment.curvature == 0.0) {
    fail(std::string(where) + ": " + name + ".curvature = 0 must be nonzero for an arc");
  }
  if (segment.kind == PathSegment::Kind::arc &&
      !(std::abs(segment.curvature) >= 1.0 / Path::max_extent_m)) {
    fail(std::string(where) + ": " + name +
         ".curvature = " + detail::format_number(segment.curvature) +
         " must have magnitude >= 1e-9 1/m (radius <= Path::max_extent_m)");
  }
  require_finite(where, name + ".curvature_rate", segment.curvature_rate);
  if (segment.kind == PathSegment::Kind::clothoid) {
    if (segment.curvature_rate == 0.0) {
      fail(std::string(where) + ": " + name +
           ".curvature_rate = 0 must be nonzero for a clothoid (else it is a line or an arc)");
    }
    const double turning =
        std::max(std::abs(segment.curvature), std::abs(segment.end_curvature())) * segment.length;
    if (!(turning <= detail::max_clothoid_turning_rad)) {
      fail(std::string(where) + ": " + name + " max(|curvature|, |end curvature|) * length = " +
           detail::format_number(turning) + " rad must be <= 4 pi (two full turns)");
    }
    return;
  }
  if (segment.curvature_rate != 0.0) {
    fail(std::string(where) + ": " + name + ".curvature_rate = " +
         detail::format_number(segment.curvature_rate) + " must be 0 for a line or an arc");
  }
  if (segment.kind == PathSegment::Kind::line && segment.curvature != 0.0) {
    fail(std::string(where) + ": " + name +
         ".curvature = " + detail::format_number(segment.curvature) + " must be 0 for a line");
  }
}

void check_joint(const PathSegment& before, std::size_t before_index, const PathSegment& after,
                 std::size_t after_index) {
  const PathPoint end = before.evaluate_parameter(before.parameter_end());
  const PathPoint begin = after.evaluate_parameter(0.0);
  const std::string joint = "segments[" + std::to_string(after_index) + "] (after segments[" +
                            std::to_string(before_index) + "])";
  const double gap = norm(begin.position - end.position);
  if (!(gap <= kPositionTolerance_m)) {
    fail("Path::from_segments: " + joint + " starts " + detail::format_number(gap) +
         " m from the previous end; G1 continuity needs <= 1e-06 m");
  }
  const double kink = std::abs(wrap_angle(begin.heading_rad - end.heading_rad));
  if (!(kink <= kHeadingTolerance_rad)) {
    fail("Path::from_segments: " + joint + " heading jumps by " + detail::format_number(kink) +
         " rad; G1 continuity needs <= 1e-06 rad");
  }
}

}  // namespace

std::string detail::format_number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

Path Path::straight_line(Vec2 start, double heading_rad, double length_m) {
  constexpr const char* where = "Path::straight_line";
  require_coordinate(where, "start.x", start.x);
  require_coordinate(where, "start.y", start.y);
  require_finite(where, "heading_rad", heading_rad);
  require_extent(where, "length_m", length_m, max_length_m);
  return assemble({PathSegment::make_line(start, heading_rad, length_m)}, false);
}

Path Path::circle(Vec2 center, double radius_m, bool counter_clockwise, double start_angle_rad) {
  constexpr const char* where = "Path::circle";
  require_coordinate(where, "center.x", center.x);
  require_coordinate(where, "center.y", center.y);
  require_extent(where, "radius_m", radius_m, max_extent_m);
  require_finite(where, "start_angle_rad", start_angle_rad);
  const double turn = counter_clockwise ? 1.0 : -1.0;
  const Vec2 start = center + radius_m * unit_from_heading(start_angle_rad);
  const double heading = wrap_angle(start_angle_rad + turn * 0.5 * pi);
  return assemble({PathSegment::make_arc(start, heading, turn / radius_m, 2.0 * pi * radius_m)},
                  true);
}

namespace {

//! The interpolating overload's checks: finite, >= 2 points, no consecutive duplicates, no
//! reversal (each named by index).
void validate_waypoints(const char* where, const std::vector<Vec2>& waypoints) {
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    require_coordinate(where, "waypoints[" + std::to_string(i) + "].x", waypoints[i].x);
    require_coordinate(where, "waypoints[" + std::to_string(i) + "].y", waypoints[i].y);
  }
  if (waypoints.size() < 2) {
    fail(std::string(where) + ": waypoints.size() = " + std::to_string(waypoints.size()) +
         " must be >= 2 (at least 2 distinct points)");
  }
  // Rejecting consecutive duplicates also guarantees >= 2 distinct points.
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    const double gap = norm(waypoints[i] - waypoints[i - 1]);
    if (!(gap >= kDuplicateDistance_m)) {
      fail(std::string(where) + ": waypoints[" + std::to_string(i - 1) + "] and waypoints[" +
           std::to_string(i) + "] are " + detail::format_number(gap) +
           " m apart; consecutive waypoints must be >= 1e-09 m apart");
    }
  }
  if (const std::optional<std::size_t> turn = Path::find_reversal(waypoints)) {
    const Vec2 before = waypoints[*turn] - waypoints[*turn - 1];
    const Vec2 after = waypoints[*turn + 1] - waypoints[*turn];
    const double angle = std::abs(std::atan2(cross(before, after), dot(before, after)));
    fail(std::string(where) + ": waypoints[" + std::to_string(*turn) + "]: the path turns by " +
         detail::format_number(angle) +
         " rad there (with the turns within 1 mm after it, more than max_waypoint_turn_rad = 2 "
         "pi / 3): it doubles back on itself; a change of direction needs one path per "
         "direction (PathPlan, docs/cusps.md)");
  }
}

//! The path through exactly two waypoints.
PathSegment chord_line(const std::vector<Vec2>& waypoints) {
  const Vec2 chord = waypoints[1] - waypoints[0];
  return PathSegment::make_line(waypoints[0], std::atan2(chord.y, chord.x), norm(chord));
}

}  // namespace

Path Path::from_waypoints(const std::vector<Vec2>& waypoints) {
  validate_waypoints("Path::from_waypoints", waypoints);
  if (waypoints.size() == 2) return assemble({chord_line(waypoints)}, false);
  return assemble(detail::natural_cubic_spline(waypoints), false);
}

Path Path::from_waypoints(const std::vector<Vec2>& waypoints, WaypointSmoothing smoothing) {
  constexpr const char* where = "Path::from_waypoints";
  validate_waypoints(where, waypoints);
  double tolerance = smoothing.tolerance_m;
  if (!std::isfinite(tolerance) || !(tolerance >= 0.0) || !(tolerance <= max_extent_m)) {
    fail(std::string(where) + ": smoothing.tolerance_m = " + detail::format_number(tolerance) +
         " must be finite and in [0, 1e9] m");
  }
  const double jitter_tolerance =
      smoothing.estimate_jitter ? jitter_tolerance_m(estimate_waypoint_jitter(waypoints)) : 0.0;
  const bool estimated = jitter_tolerance > tolerance;
  if (estimated) tolerance = jitter_tolerance;
  // Where the fit fails, what it was fitted with (built only then).
  const auto fitted_with = [&] {
    return estimated ? "the tolerance " + detail::format_number(tolerance) +
                           " m estimated from the waypoints' jitter (smoothing.estimate_jitter)"
                     : "smoothing.tolerance_m = " + detail::format_number(tolerance);
  };
  if (waypoints.size() == 2) return assemble({chord_line(waypoints)}, false);
  if (tolerance == 0.0) return assemble(detail::natural_cubic_spline(waypoints), false);
  std::vector<PathSegment> segments =
      detail::smoothing_cubic_spline(waypoints, tolerance, smoothing.restore_corners);
  // Heavy smoothing of a sharp turn can fold the fit back on itself: refuse it by index.
  std::vector<Vec2> knots;
  knots.reserve(segments.size() + 1);
  for (const PathSegment& segment : segments) knots.push_back(segment.start);
  knots.push_back(segments.back().evaluate_parameter(segments.back().t_end).position);
  for (std::size_t i = 1; i < knots.size(); ++i) {
    if (!(norm(knots[i] - knots[i - 1]) >= kDuplicateDistance_m) ||
        !(segments[i - 1].length >= kDuplicateDistance_m)) {
      fail(std::string(where) + ": " + fitted_with() + " collapses the fit between waypoints[" +
           std::to_string(i - 1) + "] and [" + std::to_string(i) + "]; use a smaller tolerance");
    }
  }
  if (const std::optional<std::size_t> turn = find_reversal(knots)) {
    fail(std::string(where) + ": " + fitted_with() +
         " folds the fitted path back on itself at waypoints[" + std::to_string(*turn) +
         "]; use a smaller tolerance");
  }
  return assemble(std::move(segments), false);
}

Path Path::from_segments(std::vector<PathSegment> segments, bool closed) {
  if (segments.empty()) {
    fail("Path::from_segments: segments is empty; need at least 1 segment");
  }
  for (std::size_t i = 0; i < segments.size(); ++i) validate_segment(segments[i], i);
  for (std::size_t i = 1; i < segments.size(); ++i) {
    check_joint(segments[i - 1], i - 1, segments[i], i);
  }
  if (closed) check_joint(segments.back(), segments.size() - 1, segments.front(), 0);
  return assemble(std::move(segments), closed);
}

Path Path::assemble(std::vector<PathSegment> segments, bool closed) {
  if (segments.size() >= std::numeric_limits<std::uint32_t>::max() / 2) {
    fail("Path: segment count = " + std::to_string(segments.size()) +
         " must be < 2^31 (the projection index uses 32-bit node indices)");
  }
  Path path;
  path.closed_ = closed;
  path.capsules_.reserve(segments.size());
  std::vector<SegmentBox> boxes;
  boxes.reserve(segments.size());
  double s = 0.0;
  for (PathSegment& segment : segments) {
    segment.s0 = s;
    s += segment.length;
    // Every point of a curve lies within half its length (along the curve) of its middle.
    struct {
      Vec2 center;
      double radius;
    } bound{segment.evaluate_at(0.5 * segment.length).position, 0.5 * segment.length};
    if (segment.kind == PathSegment::Kind::arc) {
      path.max_abs_curvature_ = std::max(path.max_abs_curvature_, std::abs(segment.curvature));
      const double radius = 1.0 / std::abs(segment.curvature);
      if (radius < bound.radius) {
        const Vec2 forward = unit_from_heading(segment.start_heading_rad);
        bound = {segment.start + (1.0 / segment.curvature) * Vec2{-forward.y, forward.x}, radius};
      }
    } else if (segment.kind == PathSegment::Kind::clothoid) {
      path.max_abs_curvature_ = std::max({path.max_abs_curvature_, std::abs(segment.curvature),
                                          std::abs(segment.end_curvature())});
    } else if (segment.kind == PathSegment::Kind::cubic) {
      // Sampled maximum: exact at the samples, a close estimate in between.
      constexpr int kSamples = 32;
      for (int i = 0; i <= kSamples; ++i) {
        const double t = segment.t_end * static_cast<double>(i) / kSamples;
        path.max_abs_curvature_ =
            std::max(path.max_abs_curvature_, std::abs(segment.evaluate_parameter(t).curvature));
      }
    }
    const Vec2 reach{bound.radius, bound.radius};
    path.capsules_.push_back(detail::segment_capsule(segment));
    boxes.push_back(detail::tighten_box(segment, {bound.center - reach, bound.center + reach}));
  }
  path.length_ = s;
  path.start_ = segments.front().evaluate_parameter(0.0);
  path.end_ = segments.back().evaluate_parameter(segments.back().parameter_end());
  path.segments_ = std::move(segments);
  path.tree_.reserve(2 * boxes.size() / leaf_size + 2);
  path.build_tree(boxes, 0, static_cast<std::uint32_t>(boxes.size()));
  // Curvature samples for the feedforward's preview (docs/feedforward.md): every 0.5 m, coarser
  // on paths so long that this would exceed max_curvature_samples.
  path.curvature_spacing_ = std::max(curvature_sample_spacing,
                                     path.length_ / static_cast<double>(max_curvature_samples - 1));
  const auto count =
      static_cast<std::size_t>(std::ceil(path.length_ / path.curvature_spacing_)) + 1;
  path.curvature_samples_.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double at = std::min(path.length_, static_cast<double>(i) * path.curvature_spacing_);
    path.curvature_samples_[i] = path.evaluate(at).curvature;
  }
  // Curvature steps at the joints, and against the straight extensions of an open path.
  const auto& pieces = path.segments_;
  auto start_curvature = [](const PathSegment& p) { return p.evaluate_parameter(0.0).curvature; };
  auto end_curvature = [](const PathSegment& p) { return p.end_curvature(); };
  auto add_jump = [&path](double at, double before, double after) {
    if (std::abs(after - before) > min_curvature_jump)
      path.curvature_jumps_.push_back({at, before, after});
  };
  add_jump(0.0, closed ? end_curvature(pieces.back()) : 0.0, start_curvature(pieces.front()));
  for (std::size_t i = 1; i < pieces.size(); ++i)
    add_jump(pieces[i].s0, end_curvature(pieces[i - 1]), start_curvature(pieces[i]));
  if (!closed) add_jump(path.length_, end_curvature(pieces.back()), 0.0);
  // Slope steps at the joints of lines, arcs and clothoids (a cubic piece's slope is that of a
  // smooth curve, and its joints are not listed).
  auto slope = [](const PathSegment& p) {
    return p.kind == PathSegment::Kind::clothoid ? p.curvature_rate : 0.0;
  };
  auto cubic = [](const PathSegment& p) { return p.kind == PathSegment::Kind::cubic; };
  auto add_kink = [&path](double at, double before, double after) {
    if (std::abs(after - before) > min_curvature_kink) {
      path.curvature_kinks_.push_back({at, before, after});
      path.max_abs_curvature_kink_ =
          std::max(path.max_abs_curvature_kink_, std::abs(after - before));
    }
  };
  if (!cubic(pieces.front()) && (!closed || !cubic(pieces.back()))) {
    add_kink(0.0, closed ? slope(pieces.back()) : 0.0, slope(pieces.front()));
  }
  for (std::size_t i = 1; i < pieces.size(); ++i) {
    if (!cubic(pieces[i - 1]) && !cubic(pieces[i])) {
      add_kink(pieces[i].s0, slope(pieces[i - 1]), slope(pieces[i]));
    }
  }
  if (!closed && !cubic(pieces.back())) add_kink(path.length_, slope(pieces.back()), 0.0);
  if (std::any_of(pieces.begin(), pieces.end(), cubic)) {
    double cubic_length = 0.0;
    std::size_t cubic_count = 0;
    for (const PathSegment& piece : pieces) {
      if (cubic(piece)) {
        cubic_length += piece.length;
        ++cubic_count;
      }
    }
    path.max_abs_spline_kink_ =
        spline_kink(path.curvature_samples_, path.curvature_spacing_,
                    cubic_length / static_cast<double>(cubic_count), closed);
  }
  return path;
}

double Path::spline_kink(const std::vector<double>& samples, double spacing, double knot_spacing,
                         bool closed) noexcept {
  const auto count = static_cast<long>(samples.size());
  const long spread = std::max(1L, std::lround(spline_kink_spread_m / spacing));
  // A natural spline's ends hold zero curvature, which bends an open path's first and last
  // metres away from the road it samples: they are not a kink of the road.
  const long skip = closed ? 0 : std::lround(spline_end_margin_m / spacing);
  // An interpolating cubic spline rings after a kink of the curvature it samples: its knots'
  // curvatures alternate about the road's, decaying by 2 - sqrt(3) per knot, so the slope
  // right after a kink overshoots its step (a 2.5 m clothoid sampled every metre reads 1.21
  // times its step). The mean over one knot spacing (a trapezoid over the samples) cancels the
  // alternation before the slopes are compared. It is clamped at the samples' ends (a closed
  // path's joint is read as an open one's, within a knot spacing of it).
  const long half = std::clamp(std::lround(0.5 * knot_spacing / spacing), 0L, 2 * spread);
  std::vector<double> knot_mean(samples.size());
  for (long i = 0; i < count; ++i) {
    double sum = 0.0, weight = 0.0;
    for (long j = -half; j <= half; ++j) {
      const double w = (half > 0 && (j == -half || j == half)) ? 0.5 : 1.0;
      sum += w * samples[static_cast<std::size_t>(std::clamp(i + j, 0L, count - 1))];
      weight += w;
    }
    knot_mean[static_cast<std::size_t>(i)] = sum / weight;
  }
  double largest = 0.0;
  for (long i = skip; i + spread + 1 < count - skip; ++i) {
    const auto at = static_cast<std::size_t>(i);
    const auto ahead = static_cast<std::size_t>(i + spread);
    const double before = knot_mean[at + 1] - knot_mean[at];
    const double after = knot_mean[ahead + 1] - knot_mean[ahead];
    largest = std::max(largest, std::abs(after - before) / spacing);
  }
  return largest;
}

double Path::sampled_curvature(double arc_length_m) const noexcept {
  if (curvature_samples_.empty() || !std::isfinite(arc_length_m)) return 0.0;
  double s = arc_length_m;
  if (closed_) {
    s = std::fmod(s, length_);
    if (s < 0.0) s += length_;
  } else if (s < 0.0 || s > length_) {
    return 0.0;  // the end extensions are straight
  }
  const auto index = static_cast<std::size_t>(std::lround(s / curvature_spacing_));
  return curvature_samples_[std::min(index, curvature_samples_.size() - 1)];
}

double Path::curvature_sample_outside(long index) const noexcept {
  const auto count = static_cast<long>(curvature_samples_.size());
  if (count == 0 || !closed_) return 0.0;  // the straight end extensions
  // The last sample sits at s = length(), the same point as the first.
  const long period = std::max(1L, count - 1);
  index %= period;
  if (index < 0) index += period;
  return curvature_samples_[static_cast<std::size_t>(index)];
}

PathPoint Path::evaluate(double arc_length_m) const noexcept {
  if (segments_.empty()) return {};
  double s = arc_length_m;
  if (closed_) {
    s = std::fmod(s, length_);
    if (s < 0.0) s += length_;
    if (s >= length_) s = 0.0;
  } else if (s < 0.0) {
    return {start_.position + s * unit_from_heading(start_.heading_rad), start_.heading_rad, 0.0};
  } else if (s > length_) {
    return {end_.position + (s - length_) * unit_from_heading(end_.heading_rad), end_.heading_rad,
            0.0};
  }
  const auto after =
      std::upper_bound(segments_.begin(), segments_.end(), s,
                       [](double value, const PathSegment& segment) { return value < segment.s0; });
  const std::size_t index =
      after == segments_.begin() ? 0 : static_cast<std::size_t>(after - segments_.begin()) - 1;
  const PathSegment& segment = segments_[index];
  return segment.evaluate_at(s - segment.s0);
}

}  // namespace smoothsteer
