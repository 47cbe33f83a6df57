// Seeded randomized properties of the projection on random splines, line/arc paths and
// circles. A failure prints the seed; replay it with the printed environment variables.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

using smoothsteer::testing::case_seed;
using smoothsteer::testing::property_cases;
using smoothsteer::testing::Random;
using smoothsteer::testing::seed_message;

struct RandomPath {
  Path path;
  //! Offsets below this keep the closest point unique (well inside the radius of curvature,
  //! and the heading stays within +-1 rad of the start so the path never folds back on itself).
  double reach_m = 0.0;
};

RandomPath random_spline(Random& rng) {
  std::vector<Vec2> points{{rng.uniform(-10, 10), rng.uniform(-10, 10)}};
  const double base = rng.uniform(-pi, pi);
  double heading = 0.0;
  const int count = rng.integer(3, 30);
  for (int i = 1; i < count; ++i) {
    heading = std::clamp(heading + rng.uniform(-0.4, 0.4), -0.8, 0.8);
    points.push_back(points.back() + rng.uniform(2.0, 6.0) * unit_from_heading(base + heading));
  }
  Path path = Path::from_waypoints(points);
  const double reach = std::min(1.0, 0.3 / std::max(path.max_abs_curvature(), 1e-3));
  return {std::move(path), reach};
}

RandomPath random_line_arc(Random& rng) {
  PathBuilder builder({rng.uniform(-10, 10), rng.uniform(-10, 10)}, rng.uniform(-pi, pi));
  double turned = 0.0;
  double min_radius = std::numeric_limits<double>::infinity();
  const int pieces = rng.integer(1, 8);
  for (int i = 0; i < pieces; ++i) {
    if (rng.coin()) {
      builder.line(rng.uniform(1.0, 10.0));
    } else {
      const double radius = rng.uniform(3.0, 20.0);
      double angle = rng.uniform(0.1, 1.0);
      if (std::abs(turned + angle) > 1.0) angle = -angle;  // keep |turned| <= 1 rad
      turned += angle;
      builder.arc(radius, angle);
      min_radius = std::min(min_radius, radius);
    }
  }
  return {builder.build(), std::min(1.0, 0.3 * min_radius)};
}

RandomPath random_closed(Random& rng) {
  const double radius = rng.uniform(1.0, 20.0);
  if (rng.coin()) {
    return {Path::circle({rng.uniform(-5, 5), rng.uniform(-5, 5)}, radius, rng.coin(),
                         rng.uniform(-pi, pi)),
            0.3 * radius};
  }
  const double straight = rng.uniform(1.0, 20.0);
  const double turn = rng.coin() ? pi : -pi;
  return {PathBuilder({rng.uniform(-5, 5), rng.uniform(-5, 5)}, rng.uniform(-pi, pi))
              .line(straight)
              .arc(radius, turn)
              .line(straight)
              .arc(radius, turn)
              .build(true),
          0.3 * radius};
}

//! A road: straights and bends of clothoid, arc, clothoid (or clothoids straight into the
//! next bend), the heading within +-1 rad of the start.
RandomPath random_clothoid_road(Random& rng) {
  const double base = rng.uniform(-pi, pi);
  PathBuilder builder({rng.uniform(-10, 10), rng.uniform(-10, 10)}, base);
  double min_radius = std::numeric_limits<double>::infinity();
  const int bends = rng.integer(1, 5);
  for (int i = 0; i < bends; ++i) {
    if (rng.coin()) builder.line(rng.uniform(1.0, 10.0));
    const double turned = wrap_angle(builder.end_heading_rad() - base);
    const double radius = rng.uniform(3.0, 20.0);
    const double angle = rng.uniform(0.1, 0.9);
    const double turn = std::abs(turned + angle) > 1.0 ? -1.0 : 1.0;   // keep |turned| <= 1 rad
    const double transition = rng.uniform(0.1, 0.8) * angle * radius;  // both turn T / (2 R)
    builder.clothoid(transition, turn / radius);
    if (rng.coin()) builder.arc(radius, turn * (angle - transition / radius));
    builder.clothoid(transition, 0.0);
    min_radius = std::min(min_radius, radius);
  }
  return {builder.build(), std::min(1.0, 0.3 * min_radius)};
}

RandomPath random_path(Random& rng, int case_index) {
  switch (case_index % 4) {
    case 0:
      return random_spline(rng);
    case 1:
      return random_line_arc(rng);
    case 2:
      return random_closed(rng);
    default:
      return random_clothoid_road(rng);
  }
}

double arc_length_gap(const Path& path, double a, double b) {
  const double gap = std::abs(a - b);
  return path.is_closed() ? std::min(gap, path.length() - gap) : gap;
}

TEST(PathProperties, WarmStartedProjectionEqualsGlobalAlongSmoothTrajectories) {
  for (int c = 0; c < property_cases(); ++c) {
    const auto seed = case_seed(c);
    SCOPED_TRACE(seed_message(seed));
    Random rng(seed);
    const RandomPath random = random_path(rng, c);
    const Path& path = random.path;
    const double amplitude = 0.9 * random.reach_m;
    const double frequency = rng.uniform(0.05, 1.0);
    const double phase = rng.uniform(0.0, 2.0 * pi);
    const double begin = path.is_closed() ? 0.0 : -5.0;
    const double end = path.is_closed() ? 2.5 * path.length() : path.length() + 5.0;
    ProjectionHint hint;
    for (double tau = begin; tau <= end; tau += rng.uniform(0.02, 0.5)) {
      const PathPoint on_path = path.evaluate(tau);
      const double offset = amplitude * std::sin(frequency * tau + phase);
      const Vec2 query = on_path.position + offset * Vec2{-std::sin(on_path.heading_rad),
                                                          std::cos(on_path.heading_rad)};
      const PathProjection warm = path.project(query, hint);
      const PathProjection global = path.project(query);
      ASSERT_NEAR(std::abs(warm.lateral_error_m), std::abs(global.lateral_error_m), 1e-9)
          << "tau " << tau;
      ASSERT_NEAR(warm.lateral_error_m, offset, 1e-6) << "tau " << tau;
      ASSERT_LT(arc_length_gap(path, warm.arc_length_m, global.arc_length_m), 1e-6)
          << "tau " << tau;
      ASSERT_EQ(hint.segment_index, warm.segment_index);
    }
  }
}

TEST(PathProperties, ProjectionIsNoFartherThanAnySampledPathPoint) {
  for (int c = 0; c < property_cases(); ++c) {
    const auto seed = case_seed(c);
    SCOPED_TRACE(seed_message(seed));
    Random rng(seed);
    const RandomPath random = random_path(rng, c);
    const Path& path = random.path;
    const int samples = std::max(2000, static_cast<int>(path.length() / 0.01));
    std::vector<Vec2> dense(static_cast<std::size_t>(samples) + 1);
    Vec2 low{1e300, 1e300};
    Vec2 high{-1e300, -1e300};
    for (int k = 0; k <= samples; ++k) {
      dense[static_cast<std::size_t>(k)] = path.evaluate(path.length() * k / samples).position;
      low = {std::min(low.x, dense[k].x), std::min(low.y, dense[k].y)};
      high = {std::max(high.x, dense[k].x), std::max(high.y, dense[k].y)};
    }
    for (int trial = 0; trial < 20; ++trial) {
      const Vec2 query{rng.uniform(low.x - 3.0, high.x + 3.0),
                       rng.uniform(low.y - 3.0, high.y + 3.0)};
      const PathProjection p = path.project(query);
      double nearest = std::numeric_limits<double>::infinity();
      for (const Vec2& sample : dense) nearest = std::min(nearest, norm(query - sample));
      const double distance = norm(query - p.closest_point);
      EXPECT_LE(distance, nearest + 1e-6) << "query " << query.x << ", " << query.y;
      EXPECT_NEAR(std::abs(p.lateral_error_m), distance, 1e-9);
      const PathPoint at = path.evaluate(p.arc_length_m);
      EXPECT_NEAR(at.position.x, p.closest_point.x, 1e-7);
      EXPECT_NEAR(at.position.y, p.closest_point.y, 1e-7);
      EXPECT_NEAR(wrap_angle(at.heading_rad - p.heading_rad), 0.0, 1e-7);
      if (path.is_closed()) {
        EXPECT_GE(p.arc_length_m, 0.0);
        EXPECT_LT(p.arc_length_m, path.length());
      }
      ProjectionHint cold;
      EXPECT_NEAR(std::abs(path.project(query, cold).lateral_error_m), distance, 1e-9);
    }
  }
}

TEST(PathProperties, WarmProjectionOnTenThousandWaypointsVisitsFewSegments) {
  std::vector<Vec2> waypoints;
  for (int i = 0; i < 10000; ++i) {
    const double x = 0.5 * i;
    waypoints.push_back({x, 3.0 * std::sin(0.05 * x) + 0.5 * std::sin(0.31 * x)});
  }
  const Path path = Path::from_waypoints(waypoints);
  // No distance fallback and only 3 steps per call: the walk itself must keep up.
  Path::ProjectionOptions options;
  options.global_search_distance_m = std::numeric_limits<double>::infinity();
  options.max_local_steps = 3;
  ProjectionHint hint;
  std::size_t previous = 0;
  std::size_t largest_jump = 0;
  int steps = 0;
  for (double s = 0.0; s < path.length(); s += 0.37, ++steps) {
    const PathPoint on_path = path.evaluate(s);
    const double offset = 0.2 * std::sin(0.1 * s);
    const Vec2 query = on_path.position +
                       offset * Vec2{-std::sin(on_path.heading_rad), std::cos(on_path.heading_rad)};
    const PathProjection warm = path.project(query, hint, options);
    ASSERT_NEAR(warm.lateral_error_m, offset, 1e-6) << "s " << s;
    ASSERT_NEAR(warm.arc_length_m, s, 1e-6) << "s " << s;
    if (steps > 0) {
      ASSERT_GE(warm.segment_index, previous) << "s " << s;
      largest_jump = std::max(largest_jump, warm.segment_index - previous);
    }
    previous = warm.segment_index;
    if (steps % 500 == 0) {
      ASSERT_NEAR(std::abs(warm.lateral_error_m), std::abs(path.project(query).lateral_error_m),
                  1e-9)
          << "s " << s;
    }
  }
  EXPECT_LE(largest_jump, 2u);
  EXPECT_EQ(previous, path.segment_count() - 1);
}

}  // namespace
}  // namespace smoothsteer
