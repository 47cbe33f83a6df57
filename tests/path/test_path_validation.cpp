// Every invalid input throws std::invalid_argument naming the field, index or value.

#include <gtest/gtest.h>

#include <functional>
#include <limits>
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

}  // namespace
}  // namespace smoothsteer
