// Path sections of scenario files: straight, circle, segments, lane_change, waypoints and
// waypoints_csv (docs/scenarios.md).

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "smoothsteer/io/waypoint_csv.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer::runner {
using io::ConfigError;
using io::ConfigSection;
using io::max_input_magnitude;
using io::max_waypoints;
using io::parse_number;
using io::Range;
using io::read_waypoint_csv;
namespace {

Vec2 point(ConfigSection& c, const std::string& key, Vec2 fallback) {
  const auto xy = c.numbers(key, {fallback.x, fallback.y}, 2, 2);
  return {xy[0], xy[1]};
}

//! Falcone et al. 2007 double lane change (paper_notes §8): Y(X) with the published constants.
double lane_change_y(double x) {
  const double shape = 2.4, dx1 = 25.0, dx2 = 21.95, dy1 = 4.05, dy2 = 5.7;
  const double xs1 = 27.19, xs2 = 56.46;
  const double z1 = shape / dx1 * (x - xs1) - shape / 2.0;
  const double z2 = shape / dx2 * (x - xs2) - shape / 2.0;
  return dy1 / 2.0 * (1.0 + std::tanh(z1)) - dy2 / 2.0 * (1.0 + std::tanh(z2));
}

//! A clothoid piece: from the curvature the previous piece ends with (0 at the start) to
//! `end_curvature_per_m`, over `clothoid_m`, or over A^2 |k_end - k_start| for the clothoid
//! parameter A = `clothoid_parameter_m` (A^2 = L / |delta kappa|, the road designer's measure).
void add_clothoid(ConfigSection& piece, PathBuilder& builder) {
  if (piece.has("clothoid_m") && piece.has("clothoid_parameter_m")) {
    piece.fail("clothoid_parameter_m", "give either clothoid_m or clothoid_parameter_m, not both");
  }
  const double end = piece.required_number("end_curvature_per_m", {-10.0, 10.0});
  const double start = builder.end_curvature();
  if (end == start) {
    piece.fail("end_curvature_per_m",
               "must differ from the curvature the previous piece ends with, " +
                   exact_number(start) + " 1/m (a clothoid changes it)");
  }
  double length = 0.0;
  if (piece.has("clothoid_m")) {
    length = piece.required_number("clothoid_m", Range::positive());
  } else {
    const double parameter = piece.required_number("clothoid_parameter_m", Range::positive());
    length = parameter * parameter * std::abs(end - start);
  }
  const double turning = std::max(std::abs(start), std::abs(end)) * length;
  if (!(turning <= 4.0 * 3.141592653589793)) {
    piece.fail(piece.has("clothoid_m") ? "clothoid_m" : "clothoid_parameter_m",
               "gives max(|curvature|) * length = " + exact_number(turning) +
                   " rad; at most 4 pi (two full turns)");
  }
  builder.clothoid(length, end);
}

//! `smoothing_tolerance_m` of a waypoints path: the RMS distance [m] a smoothing spline keeps
//! from noisy waypoints (Path::from_waypoints); absent or 0 interpolates them. `estimate_jitter`
//! (default false): at least the jitter the waypoints show; `restore_corners` (default true):
//! twice a fit through a tight corner (WaypointSmoothing).
WaypointSmoothing smoothing(ConfigSection& c) {
  WaypointSmoothing smoothing;
  if (c.has("smoothing_tolerance_m")) {
    smoothing.tolerance_m = c.number("smoothing_tolerance_m", 0.0, {0.0, 10.0});
  }
  smoothing.estimate_jitter = c.boolean("estimate_jitter", false);
  smoothing.restore_corners = c.boolean("restore_corners", true);
  return smoothing;
}

}  // namespace

std::shared_ptr<const Path> make_path(ConfigSection& c, const std::string& base_directory,
                                      std::shared_ptr<const PathPlan>* plan) {
  const std::string type =
      c.text("type", "straight",
             {"straight", "circle", "segments", "lane_change", "waypoints", "waypoints_csv"});
  try {
    if (type == "straight") {
      const Vec2 start = point(c, "start", {0.0, 0.0});
      const double heading = c.number("heading_rad", 0.0);
      const double length = c.number("length_m", 200.0, Range::positive());
      return std::make_shared<const Path>(Path::straight_line(start, heading, length));
    }
    if (type == "circle") {
      const Vec2 center = point(c, "center", {0.0, 0.0});
      const double radius = c.required_number("radius_m", Range::positive());
      const bool ccw = c.boolean("counter_clockwise", true);
      const double start_angle = c.number("start_angle_rad", 0.0);
      return std::make_shared<const Path>(Path::circle(center, radius, ccw, start_angle));
    }
    if (type == "segments") {
      PathBuilder builder(point(c, "start", {0.0, 0.0}), c.number("heading_rad", 0.0));
      // Gear changes (docs/cusps.md): a piece with `gear` other than the current one starts a
      // new path at the cusp, in the new direction of travel (heading + pi).
      Gear gear = Gear::forward;
      std::vector<PathPiece> runs;
      bool run_started = false;
      const YAML::Node pieces = c.raw("pieces");
      if (!pieces || !pieces.IsSequence() || pieces.size() == 0) {
        c.fail("pieces",
               "expected a non-empty list of {line_m: L}, {arc_radius_m: R, arc_angle_rad: A}, "
               "{clothoid_m: L, end_curvature_per_m: k} or "
               "{clothoid_parameter_m: A, end_curvature_per_m: k}");
      }
      YAML::Node resolved(YAML::NodeType::Sequence);
      for (std::size_t i = 0; i < pieces.size(); ++i) {
        ConfigSection piece(pieces[i], c.full_key("pieces") + "[" + std::to_string(i) + "]",
                            c.file());
        if (piece.has("gear")) {
          const Gear next = piece.text("gear", "forward", {"forward", "reverse"}) == "forward"
                                ? Gear::forward
                                : Gear::reverse;
          if (next != gear && !run_started) gear = next;  // the first piece's gear
          if (next != gear) {
            if (!plan) piece.fail("gear", "a change of gear needs a closed-loop run on a plan");
            if (runs.size() == PathPlan::max_cusps) {
              piece.fail("gear", "more than PathPlan::max_cusps = " +
                                     std::to_string(PathPlan::max_cusps) + " gear changes");
            }
            runs.push_back({std::make_shared<const Path>(builder.build()), gear});
            builder = PathBuilder(builder.end_position(), builder.end_heading_rad() + pi);
            gear = next;
          }
        }
        run_started = true;
        if (piece.has("line_m")) {
          builder.line(piece.number("line_m", 0.0, Range::positive()));
        } else if (piece.has("clothoid_m") || piece.has("clothoid_parameter_m")) {
          add_clothoid(piece, builder);
        } else {
          const double radius = piece.required_number("arc_radius_m", Range::positive());
          const double angle = piece.required_number("arc_angle_rad", {-6.3, 6.3});
          if (angle == 0.0) piece.fail("arc_angle_rad", "must be nonzero");
          builder.arc(radius, angle);
        }
        piece.finish();
        resolved.push_back(piece.resolved());
      }
      c.store("pieces", resolved);
      const bool closed = c.boolean("closed", false);
      if (!runs.empty() || gear == Gear::reverse) {
        if (closed) c.fail("closed", "a path with gears (gear: reverse) cannot be closed");
        runs.push_back({std::make_shared<const Path>(builder.build()), gear});
        *plan = std::make_shared<const PathPlan>(PathPlan::from_pieces(runs));
        return (*plan)->piece(0).path;
      }
      return std::make_shared<const Path>(builder.build(closed));
    }
    if (type == "lane_change") {
      const double x_start = c.number("x_start_m", -30.0);
      const double x_end = c.number("x_end_m", 150.0);
      const double spacing = c.number("spacing_m", 1.0, {0.05, 10.0});
      if (!(x_end > x_start + 2.0 * spacing))
        c.fail("x_end_m", "must exceed x_start_m by 2 spacings");
      // Counted, not accumulated: x += spacing stalls once x >> spacing (a far x_start_m would
      // otherwise loop and allocate without end).
      const double count = std::floor((x_end - x_start) / spacing + 1e-9) + 1.0;
      if (count > static_cast<double>(max_waypoints)) {
        c.fail("x_end_m", "gives " + std::to_string(static_cast<long long>(count)) +
                              " samples at spacing_m; at most " + std::to_string(max_waypoints));
      }
      std::vector<Vec2> points;
      for (long i = 0; i < static_cast<long>(count); ++i) {
        const double x = x_start + static_cast<double>(i) * spacing;
        points.push_back({x, lane_change_y(x)});
      }
      return std::make_shared<const Path>(Path::from_waypoints(points));
    }
    if (type == "waypoints") {
      const YAML::Node list = c.raw("points");
      if (!list || !list.IsSequence()) c.fail("points", "expected a list of [x, y]");
      std::vector<Vec2> points;
      YAML::Node resolved(YAML::NodeType::Sequence);
      for (std::size_t i = 0; i < list.size(); ++i) {
        const bool pair = list[i].IsSequence() && list[i].size() == 2 && list[i][0].IsScalar() &&
                          list[i][1].IsScalar();
        const auto x = pair ? parse_number(list[i][0].Scalar()) : std::nullopt;
        const auto y = pair ? parse_number(list[i][1].Scalar()) : std::nullopt;
        if (!x || !y || std::abs(*x) > max_input_magnitude || std::abs(*y) > max_input_magnitude) {
          c.fail("points", "element " + std::to_string(i) +
                               ": expected [x, y] with two numbers of magnitude <= 1e9");
        }
        if (points.size() == max_waypoints) {
          c.fail("points", "more than " + std::to_string(max_waypoints) + " waypoints");
        }
        points.push_back({*x, *y});
        resolved.push_back(list[i]);
      }
      if (const std::optional<std::size_t> turn = Path::find_reversal(points)) {
        c.fail("points", "element " + std::to_string(*turn) +
                             ": the path turns back on itself there (more than 120 degrees from "
                             "the previous chord to the next, alone or with the turns within 1 "
                             "mm after it); a path that changes direction "
                             "needs one path per direction (docs/cusps.md)");
      }
      c.store("points", resolved);
      return std::make_shared<const Path>(Path::from_waypoints(points, smoothing(c)));
    }
    // waypoints_csv
    std::string csv = c.required_text("file");
    std::filesystem::path csv_path(csv);
    if (csv_path.is_relative()) csv_path = std::filesystem::path(base_directory) / csv_path;
    std::vector<Vec2> points;
    try {
      points = read_waypoint_csv(csv_path.string());
    } catch (const ConfigError& error) {
      c.fail("file", error.what());  // names the key that gave the file
    }
    return std::make_shared<const Path>(Path::from_waypoints(points, smoothing(c)));
  } catch (const std::invalid_argument& error) {
    throw ConfigError(c.file() + ": key '" + c.full_key("") + "': " + error.what());
  }
}

}  // namespace smoothsteer::runner
