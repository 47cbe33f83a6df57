// Exact cases: lines, circles, line/arc sequences and the end extensions, against closed-form
// geometry.

#include <gtest/gtest.h>

#include <cmath>

#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_builder.hpp"

namespace smoothsteer {
namespace {

constexpr double kTol = 1e-12;

Vec2 left_normal(double heading) {
  return {-std::sin(heading), std::cos(heading)};
}

TEST(PathLine, ProjectionGivesArcLengthLateralErrorAndHeading) {
  const double heading = pi / 4.0;
  const Vec2 start{1.0, 2.0};
  const Path path = Path::straight_line(start, heading, 10.0);
  const Vec2 t = unit_from_heading(heading);
  const Vec2 n = left_normal(heading);

  const PathProjection left = path.project(start + 3.0 * t + 2.0 * n);
  EXPECT_NEAR(left.arc_length_m, 3.0, kTol);
  EXPECT_NEAR(left.lateral_error_m, 2.0, kTol);
  EXPECT_NEAR(left.heading_rad, heading, kTol);
  EXPECT_EQ(left.curvature, 0.0);

  const PathProjection right = path.project(start + 7.5 * t - 0.5 * n);
  EXPECT_NEAR(right.arc_length_m, 7.5, kTol);
  EXPECT_NEAR(right.lateral_error_m, -0.5, kTol);
  EXPECT_NEAR(path.length(), 10.0, kTol);
  EXPECT_FALSE(path.is_closed());
}

TEST(PathLine, EndExtensionsGiveNegativeAndBeyondLengthArcLength) {
  const double heading = -0.3;
  const Vec2 start{-2.0, 5.0};
  const Path path = Path::straight_line(start, heading, 10.0);
  const Vec2 t = unit_from_heading(heading);
  const Vec2 n = left_normal(heading);

  const PathProjection before = path.project(start - 4.0 * t + 1.0 * n);
  EXPECT_NEAR(before.arc_length_m, -4.0, kTol);
  EXPECT_NEAR(before.lateral_error_m, 1.0, kTol);
  EXPECT_EQ(before.curvature, 0.0);

  const PathProjection after = path.project(start + 15.0 * t - 1.5 * n);
  EXPECT_NEAR(after.arc_length_m, 15.0, kTol);
  EXPECT_NEAR(after.lateral_error_m, -1.5, kTol);

  const PathPoint behind = path.evaluate(-2.0);
  EXPECT_NEAR(behind.position.x, start.x - 2.0 * t.x, kTol);
  EXPECT_NEAR(behind.position.y, start.y - 2.0 * t.y, kTol);
  const PathPoint ahead = path.evaluate(12.0);
  EXPECT_NEAR(ahead.position.x, start.x + 12.0 * t.x, kTol);
  EXPECT_NEAR(ahead.heading_rad, heading, kTol);
}

TEST(PathCircle, ProjectionMatchesCenterGeometry) {
  const Vec2 center{1.0, -1.0};
  const double radius = 3.0;
  const double angle = 0.7;
  for (const bool ccw : {true, false}) {
    SCOPED_TRACE(ccw ? "counter-clockwise" : "clockwise");
    const Path path = Path::circle(center, radius, ccw, 1.0);
    EXPECT_TRUE(path.is_closed());
    EXPECT_NEAR(path.length(), 2.0 * pi * radius, kTol);
    const double turn = ccw ? 1.0 : -1.0;
    for (const double distance : {2.0, 4.5}) {
      const PathProjection p = path.project(center + distance * unit_from_heading(angle));
      // Inside a left turn is left of the path: e = R - d, mirrored for a right turn.
      EXPECT_NEAR(p.lateral_error_m, turn * (radius - distance), kTol);
      EXPECT_NEAR(p.curvature, turn / radius, kTol);
      EXPECT_NEAR(wrap_angle(p.heading_rad - (angle + turn * pi / 2.0)), 0.0, kTol);
      const Vec2 expected = center + radius * unit_from_heading(angle);
      EXPECT_NEAR(p.closest_point.x, expected.x, 1e-12);
      EXPECT_NEAR(p.closest_point.y, expected.y, 1e-12);
      // Travelled angle from the start angle 1.0, wrapped into [0, 2 pi).
      double travelled = std::fmod(turn * (angle - 1.0) + 4.0 * pi, 2.0 * pi);
      EXPECT_NEAR(p.arc_length_m, travelled * radius, 1e-12);
    }
  }
}

TEST(PathCircle, EvaluateWrapsArcLength) {
  const Path path = Path::circle({0.0, 0.0}, 2.0);
  const double length = path.length();
  for (const double s : {0.5, 3.0, 10.0}) {
    const PathPoint base = path.evaluate(s);
    for (const double shifted : {s + length, s - length, s + 3.0 * length}) {
      const PathPoint other = path.evaluate(shifted);
      EXPECT_NEAR(other.position.x, base.position.x, 1e-9);
      EXPECT_NEAR(other.position.y, base.position.y, 1e-9);
    }
  }
  const PathPoint start = path.evaluate(0.0);
  EXPECT_NEAR(start.position.x, 2.0, kTol);
  EXPECT_NEAR(start.heading_rad, pi / 2.0, kTol);
  EXPECT_NEAR(path.max_abs_curvature(), 0.5, kTol);
  // The projection of the start wraps into [0, L).
  const PathProjection p = path.project({2.5, -1e-13});
  EXPECT_GE(p.arc_length_m, 0.0);
  EXPECT_LT(p.arc_length_m, length);
}

TEST(PathBuilder, LineArcLineIsContinuousWithKnownPoints) {
  const Path path = PathBuilder({0.0, 0.0}, 0.0).line(10.0).arc(5.0, pi / 2.0).line(10.0).build();
  ASSERT_EQ(path.segment_count(), 3u);
  EXPECT_NEAR(path.length(), 20.0 + 2.5 * pi, kTol);
  EXPECT_NEAR(path.max_abs_curvature(), 0.2, kTol);

  const PathPoint mid_arc = path.evaluate(10.0 + 1.25 * pi);
  EXPECT_NEAR(mid_arc.position.x, 10.0 + 5.0 * std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(mid_arc.position.y, 5.0 - 5.0 * std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(mid_arc.heading_rad, pi / 4.0, 1e-12);
  EXPECT_NEAR(mid_arc.curvature, 0.2, 1e-12);

  const PathPoint end = path.evaluate(path.length());
  EXPECT_NEAR(end.position.x, 15.0, 1e-12);
  EXPECT_NEAR(end.position.y, 15.0, 1e-12);
  EXPECT_NEAR(end.heading_rad, pi / 2.0, 1e-12);

  // Position and heading are continuous across the joints.
  for (const PathSegment& segment : path.segments()) {
    const PathPoint a = path.evaluate(segment.s0 - 1e-9);
    const PathPoint b = path.evaluate(segment.s0 + 1e-9);
    EXPECT_NEAR(norm(a.position - b.position), 2e-9, 1e-10);
    EXPECT_NEAR(wrap_angle(a.heading_rad - b.heading_rad), 0.0, 1e-9);
  }

  // Right of an upward line (+x side) is negative.
  const PathProjection p = path.project({20.0, 10.0});
  EXPECT_NEAR(p.lateral_error_m, -5.0, 1e-12);
  EXPECT_NEAR(p.arc_length_m, 15.0 + 2.5 * pi, 1e-12);
  EXPECT_EQ(p.segment_index, 2u);
  // Inside the arc, toward its center (10, 5): left.
  const PathProjection q = path.project({12.0, 3.0});
  EXPECT_NEAR(q.lateral_error_m, 5.0 - norm(Vec2{2.0, -2.0}), 1e-12);
  EXPECT_NEAR(q.curvature, 0.2, 1e-12);
}

TEST(PathBuilder, RightTurnAndClosedLoop) {
  const Path right = PathBuilder({0.0, 0.0}, 0.0).arc(2.0, -pi / 2.0).build();
  const PathPoint end = right.evaluate(right.length());
  EXPECT_NEAR(end.position.x, 2.0, 1e-12);
  EXPECT_NEAR(end.position.y, -2.0, 1e-12);
  EXPECT_NEAR(end.curvature, -0.5, 1e-12);

  const Path loop =
      PathBuilder({0.0, 0.0}, 0.0).line(10.0).arc(2.0, pi).line(10.0).arc(2.0, pi).build(true);
  EXPECT_TRUE(loop.is_closed());
  const PathProjection p = loop.project({-1.0, 2.0});  // left of the far end's half circle
  EXPECT_NEAR(p.lateral_error_m, 1.0, 1e-12);
  EXPECT_GE(p.arc_length_m, 0.0);
  EXPECT_LT(p.arc_length_m, loop.length());
  const PathPoint wrapped = loop.evaluate(loop.length() + 1.0);
  EXPECT_NEAR(wrapped.position.x, 1.0, 1e-9);
  EXPECT_NEAR(wrapped.position.y, 0.0, 1e-9);
}

TEST(PathCurvatureJumps, ListsEachJointStepAndTheOpenEnds) {
  // line 10 | arc r 4 left | arc r 5 right | line 3: steps at 0 (none), 10, 10 + 2 pi, ... end.
  const Path open = PathBuilder({0.0, 0.0}, 0.0)
                        .line(10.0)
                        .arc(4.0, pi / 2.0)
                        .arc(5.0, -pi / 2.0)
                        .line(3.0)
                        .build();
  const auto& jumps = open.curvature_jumps();
  ASSERT_EQ(jumps.size(), 3u);  // the line ends meet their straight extensions: no step there
  const double first = 10.0, second = first + 4.0 * pi / 2.0, third = second + 5.0 * pi / 2.0;
  EXPECT_NEAR(jumps[0].arc_length_m, first, 1e-12);
  EXPECT_NEAR(jumps[0].before, 0.0, 1e-12);
  EXPECT_NEAR(jumps[0].after, 0.25, 1e-12);
  EXPECT_NEAR(jumps[1].arc_length_m, second, 1e-9);
  EXPECT_NEAR(jumps[1].before, 0.25, 1e-12);
  EXPECT_NEAR(jumps[1].after, -0.2, 1e-12);
  EXPECT_NEAR(jumps[2].arc_length_m, third, 1e-9);
  EXPECT_NEAR(jumps[2].after, 0.0, 1e-12);

  // An open path ending in an arc steps back to its straight extension at the end.
  const Path arc_end = PathBuilder({0.0, 0.0}, 0.0).arc(2.0, 1.0).build();
  ASSERT_EQ(arc_end.curvature_jumps().size(), 2u);
  EXPECT_NEAR(arc_end.curvature_jumps()[0].arc_length_m, 0.0, 1e-12);
  EXPECT_NEAR(arc_end.curvature_jumps()[1].arc_length_m, 2.0, 1e-12);
  EXPECT_NEAR(arc_end.curvature_jumps()[1].after, 0.0, 1e-12);

  // A closed loop lists its wrap joint at 0 (line -> arc) once; a circle and a line have none.
  const Path loop =
      PathBuilder({0.0, 0.0}, 0.0).line(10.0).arc(2.0, pi).line(10.0).arc(2.0, pi).build(true);
  ASSERT_EQ(loop.curvature_jumps().size(), 4u);
  EXPECT_NEAR(loop.curvature_jumps()[0].arc_length_m, 0.0, 1e-12);
  EXPECT_NEAR(loop.curvature_jumps()[0].before, 0.5, 1e-12);
  EXPECT_TRUE(Path::circle({0.0, 0.0}, 3.0).curvature_jumps().empty());
  EXPECT_TRUE(Path::straight_line({0.0, 0.0}, 0.3).curvature_jumps().empty());
}

}  // namespace
}  // namespace smoothsteer
