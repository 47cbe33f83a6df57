// Natural cubic splines through waypoints: interpolation, continuity and curvature.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path.hpp"

namespace smoothsteer {
namespace {

std::vector<Vec2> points_on_circle(double radius, double sweep, int count) {
  std::vector<Vec2> points;
  for (int i = 0; i < count; ++i) {
    const double angle = sweep * static_cast<double>(i) / (count - 1);
    points.push_back(radius * unit_from_heading(angle));
  }
  return points;
}

TEST(PathSpline, PointsOnCircleGiveCurvatureOneOverRadiusInTheMiddle) {
  const double radius = 10.0;
  const Path path = Path::from_waypoints(points_on_circle(radius, 1.5 * pi, 40));
  // Natural end conditions force zero curvature at the ends; the middle is unaffected.
  for (double fraction = 0.3; fraction <= 0.7; fraction += 0.05) {
    const PathPoint point = path.evaluate(fraction * path.length());
    EXPECT_NEAR(point.curvature, 1.0 / radius, 0.02 / radius) << "fraction " << fraction;
    EXPECT_NEAR(norm(point.position), radius, 0.01);
  }
  EXPECT_NEAR(path.length(), 1.5 * pi * radius, 0.01);
}

TEST(PathSpline, PassesThroughItsWaypoints) {
  const std::vector<Vec2> waypoints{{0, 0}, {3, 1}, {5, 4}, {4, 8}, {7, 9}, {12, 9.5}};
  const Path path = Path::from_waypoints(waypoints);
  ASSERT_EQ(path.segment_count(), waypoints.size() - 1);
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    const double s = i < path.segment_count() ? path.segments()[i].s0 : path.length();
    const PathPoint point = path.evaluate(s);
    EXPECT_NEAR(point.position.x, waypoints[i].x, 1e-9) << "waypoint " << i;
    EXPECT_NEAR(point.position.y, waypoints[i].y, 1e-9) << "waypoint " << i;
    const PathProjection projection = path.project(waypoints[i]);
    EXPECT_NEAR(projection.lateral_error_m, 0.0, 1e-9) << "waypoint " << i;
    EXPECT_NEAR(projection.arc_length_m, s, 1e-7) << "waypoint " << i;
  }
}

TEST(PathSpline, HeadingAndCurvatureAreContinuousAtKnots) {
  const std::vector<Vec2> waypoints{{0, 0}, {2, 1}, {2.5, 3}, {1, 5}, {-2, 5.5}, {-4, 3}};
  const Path path = Path::from_waypoints(waypoints);
  const auto& segments = path.segments();
  for (std::size_t i = 1; i < segments.size(); ++i) {
    const PathPoint end = segments[i - 1].evaluate_parameter(segments[i - 1].parameter_end());
    const PathPoint begin = segments[i].evaluate_parameter(0.0);
    EXPECT_NEAR(norm(end.position - begin.position), 0.0, 1e-12) << "knot " << i;
    EXPECT_NEAR(wrap_angle(end.heading_rad - begin.heading_rad), 0.0, 1e-12) << "knot " << i;
    EXPECT_NEAR(end.curvature, begin.curvature, 1e-9) << "knot " << i;
  }
  // Natural end conditions.
  EXPECT_NEAR(path.evaluate(0.0).curvature, 0.0, 1e-12);
  EXPECT_NEAR(path.evaluate(path.length()).curvature, 0.0, 1e-12);
}

TEST(PathSpline, TwoWaypointsGiveALine) {
  const Path path = Path::from_waypoints({{1, 1}, {4, 5}});
  ASSERT_EQ(path.segment_count(), 1u);
  EXPECT_EQ(path.segments()[0].kind, PathSegment::Kind::line);
  EXPECT_NEAR(path.length(), 5.0, 1e-12);
  const PathProjection p = path.project({4, 1});
  EXPECT_NEAR(p.arc_length_m, 3.0 * 0.6, 1e-12);
  EXPECT_NEAR(p.lateral_error_m, -3.0 * 0.8, 1e-12);
}

TEST(PathSpline, ArcLengthInverseIsConsistent) {
  const Path path = Path::from_waypoints({{0, 0}, {4, 3}, {6, -1}, {11, 0}});
  for (const PathSegment& segment : path.segments()) {
    for (double fraction = 0.0; fraction <= 1.0; fraction += 0.125) {
      const double s = fraction * segment.length;
      EXPECT_NEAR(segment.arc_length_at(segment.parameter_at(s)), s, 1e-10);
    }
  }
}

}  // namespace
}  // namespace smoothsteer
