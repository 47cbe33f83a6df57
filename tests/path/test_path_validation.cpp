// Every invalid input throws std::invalid_argument naming the field, index or value.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_builder.hpp"

namespace smoothsteer {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

//! Message of the std::invalid_argument thrown by `action`, or a marker if none was thrown.
std::string message_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "<no std::invalid_argument thrown>";
}

void expect_message(const std::function<void()>& action, const std::vector<std::string>& parts) {
  const std::string message = message_of(action);
  for (const std::string& part : parts) {
    EXPECT_NE(message.find(part), std::string::npos)
        << "message: " << message << "\nmissing: " << part;
  }
}

TEST(PathValidation, Waypoints) {
  expect_message(
      [] {
        Path::from_waypoints({{0, 0}, {kNan, 1}, {2, 2}});
      },
      {"waypoints[1].x", "nan", "finite"});
  expect_message(
      [] {
        Path::from_waypoints({{0, 0}, {1, 1}, {2, kInf}});
      },
      {"waypoints[2].y", "inf"});
  expect_message([] { Path::from_waypoints({{0, 0}}); }, {"waypoints.size() = 1", ">= 2"});
  expect_message([] { Path::from_waypoints({}); }, {"waypoints.size() = 0"});
  expect_message(
      [] {
        Path::from_waypoints({{0, 0}, {1, 1}, {1, 1}, {2, 0}});
      },
      {"waypoints[1]", "waypoints[2]", "1e-09"});
  // Fewer than two distinct points.
  expect_message([] { Path::from_waypoints({{3, 3}, {3, 3}}); }, {"waypoints[0]", "waypoints[1]"});
}

TEST(PathValidation, FactoriesRejectNonPositiveSizes) {
  expect_message([] { Path::circle({0, 0}, -1.0); }, {"radius_m = -1", "> 0"});
  expect_message([] { Path::circle({0, 0}, 0.0); }, {"radius_m = 0"});
  expect_message([] { Path::circle({kNan, 0}, 1.0); }, {"center.x"});
  expect_message([] { Path::straight_line({0, 0}, 0.0, 0.0); }, {"length_m = 0", "> 0"});
  expect_message([] { Path::straight_line({0, 0}, 0.0, -3.0); }, {"length_m = -3"});
  expect_message([] { Path::straight_line({0, 0}, kInf, 1.0); }, {"heading_rad"});
}

TEST(PathValidation, Segments) {
  expect_message([] { Path::from_segments({}); }, {"segments", "empty"});
  expect_message(
      [] {
        Path::from_segments(
            {PathSegment::make_line({0, 0}, 0, 1), PathSegment::make_line({1, 0}, 0, -2)});
      },
      {"segments[1].length = -2"});
  expect_message(
      [] {
        Path::from_segments(
            {PathSegment::make_line({0, 0}, 0, 1), PathSegment::make_line({1.1, 0}, 0, 1)});
      },
      {"segments[1]", "G1", "m"});
  expect_message(
      [] {
        Path::from_segments({PathSegment::make_line({0, 0}, 0, 1),
                             PathSegment::make_line({1, 0}, 0, 1),
                             PathSegment::make_line({2, 0}, 0.01, 1)});
      },
      {"segments[2]", "heading", "rad"});
  expect_message(
      [] {
        Path::from_segments(
            {PathSegment::make_line({0, 0}, 0, 1), PathSegment::make_line({1, 0}, 0, 1)}, true);
      },
      {"segments[0]", "segments[1]"});
  expect_message(
      [] {
        Path::from_segments({PathSegment::make_line({kNan, 0}, 0, 1)});
      },
      {"segments[0].start.x"});
  expect_message(
      [] {
        Path::from_segments({PathSegment::make_arc({0, 0}, 0, 0.0, 1)});
      },
      {"segments[0].curvature", "nonzero"});
}

TEST(PathValidation, Builder) {
  expect_message([] { PathBuilder({0, 0}, 0).line(-1); }, {"PathBuilder::line", "length_m = -1"});
  expect_message(
      [] {
        PathBuilder({0, 0}, 0).arc(-2, 1);
      },
      {"PathBuilder::arc: radius_m = -2 must be", "> 0"});
  expect_message([] { PathBuilder({0, 0}, 0).arc(2, 0); }, {"angle_rad = 0", "nonzero"});
  expect_message([] { PathBuilder({0, 0}, 0).arc(2, kNan); }, {"angle_rad = nan"});
  expect_message([] { PathBuilder({kNan, 0}, 0); }, {"start.x"});
  expect_message([] { PathBuilder({0, 0}, 0).build(); }, {"segments", "empty"});
  expect_message([] { PathBuilder({0, 0}, 0).line(1).arc(1, pi).build(true); }, {"segments[0]"});
}

// Extents whose squares overflow used to throw std::length_error (the curvature samples of a
// circle of radius 1e308) or project to e = -inf (radius 1e200).
TEST(PathValidation, ExtentsBeyondTheArithmeticAreRefused) {
  expect_message(
      [] {
        Path::circle({0, 0}, 1e308);
      },
      {"Path::circle", "radius_m = 1e+308", "1e+09"});
  expect_message([] { Path::circle({0, 0}, 1e200); }, {"radius_m = 1e+200"});
  expect_message([] { Path::circle({1e300, 0}, 5.0); }, {"center.x = 1e+300", "1e9 m"});
  expect_message([] { Path::straight_line({0, 0}, 0.0, 1e300); }, {"length_m = 1e+300"});
  expect_message([] { Path::from_waypoints({{0, 0}, {1e200, 1}}); }, {"waypoints[1].x = 1e+200"});
  expect_message(
      [] {
        PathBuilder({0, 0}, 0).arc(1e300, 1e-299).build();
      },
      {"segments[0]", "1e-9 1/m"});
  // The largest accepted circle still projects to a finite error.
  const Path largest = Path::circle({0, 0}, 1e9);  // Path::max_extent_m
  const PathProjection p = largest.project({0.0, 0.5e9});
  EXPECT_TRUE(std::isfinite(p.lateral_error_m));
  EXPECT_NEAR(p.lateral_error_m, 0.5e9, 1.0);
}

// 0 -> 30 -> 0 on one line: the spline has a cusp at 30 and the projection sticks there.
TEST(PathValidation, WaypointsThatDoubleBackAreRefused) {
  expect_message(
      [] {
        Path::from_waypoints({{0, 0}, {30, 0}, {0, 0}});
      },
      {"Path::from_waypoints", "waypoints[1]", "doubles back", "PathPlan"});
  expect_message(
      [] {
        Path::from_waypoints({{0, 0}, {10, 0}, {20, 0}, {15, 1}});
      },
      {"waypoints[2]", "doubles back"});
  expect_message([] { Path::from_waypoints({{0, 0}, {30, 0}, {0, 0.5}}); }, {"waypoints[1]"});
  EXPECT_NO_THROW(Path::from_waypoints({{0, 0}, {10, 0}, {10, 10}, {20, 10}}));           // 90 deg
  EXPECT_NO_THROW(Path::from_waypoints({{0, 0}, {10, 0}, {8, 10}}));                      // 101 deg
  EXPECT_THROW(Path::from_waypoints({{0, 0}, {10, 0}, {0, 10}}), std::invalid_argument);  // 135
}

// Turns close together double back as one sharp turn does: two of 90 degrees 1 um apart (or
// three of 60 degrees) passed one at a time, and the car ended 9 m off. Turns 1 mm or more
// apart, and turns that cancel (a zigzag), are separate turns.
TEST(PathValidation, TurnsCloseTogetherThatDoubleBackAreRefused) {
  const double um = 1e-6;
  expect_message(
      [&] {
        Path::from_waypoints({{0, 0}, {10, 0}, {10, um}, {0, um}});
      },
      {"waypoints[1]", "doubles back", "within 1 mm"});
  const double c = 0.5 * um, h = std::sqrt(3.0) / 2.0 * um;  // a 1 um hexagon's corner
  EXPECT_EQ(Path::find_reversal({{0, 0}, {10, 0}, {10 + c, h}, {10, 2 * h}, {0, 2 * h}}),
            std::optional<std::size_t>(1));
  EXPECT_EQ(Path::find_reversal({{0, 0}, {10, 0}, {20, 0}, {20, um}, {10, um}}),
            std::optional<std::size_t>(2));
  // 2 mm apart: two turns of 90 degrees, each allowed.
  EXPECT_EQ(Path::find_reversal({{0, 0}, {10, 0}, {10, 2e-3}, {0, 2e-3}}), std::nullopt);
  // A zigzag of +-90 degrees 1 um apart turns back and forth, not round.
  EXPECT_EQ(Path::find_reversal({{0, 0}, {10, 0}, {10, um}, {20, um}}), std::nullopt);
  // Densely sampled: a U-turn of radius 1 m with 0.1 mm chords.
  std::vector<Vec2> dense{{-10, -1}};
  for (int i = 0; i <= 31416; ++i) {
    const double angle = -std::numbers::pi / 2 + i * 1e-4;
    dense.push_back({std::cos(angle), std::sin(angle)});
  }
  dense.push_back({-10, 1});
  EXPECT_EQ(Path::find_reversal(dense), std::nullopt);
}

}  // namespace
}  // namespace smoothsteer
