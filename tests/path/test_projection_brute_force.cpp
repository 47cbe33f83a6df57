// The projection against a brute-force dense sampling of the path, end extensions included:
// random open paths that may fold back on themselves (so that an extension can be nearer than
// any segment) and random closed paths, with query points near every part of them. Seeded; a
// failure prints the seed and the query.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

//! How far beyond each end queries may lie along the extensions.
constexpr double kExtensionReach_m = 40.0;
constexpr double kSpacing_m = 0.005;
//! Tolerance of the cubic segments' Newton search on tightly folding splines (see below).
constexpr double kNewtonSlack_m = 1e-4;

//! kind 0: spline, 1: lines and arcs (both open), 2: circle, 3: closed loop.
Path random_folding_path(Random& rng, int kind) {
  const Vec2 start{rng.uniform(-10, 10), rng.uniform(-10, 10)};
  const double heading = rng.uniform(-pi, pi);
  switch (kind) {
    case 0: {  // a spline whose heading wanders by up to +-1.5 rad per waypoint
      std::vector<Vec2> points{start};
      double direction = heading;
      const int count = rng.integer(3, 25);
      for (int i = 1; i < count; ++i) {
        direction += rng.uniform(-1.5, 1.5);
        points.push_back(points.back() + rng.uniform(2.0, 8.0) * unit_from_heading(direction));
      }
      return Path::from_waypoints(points);
    }
    case 1: {  // lines, arcs and clothoids (up to 2.5 rad each) turning by up to 2 pi in total
      PathBuilder builder(start, heading);
      const int pieces = rng.integer(1, 7);
      for (int i = 0; i < pieces; ++i) {
        const int piece = rng.integer(0, 2);
        if (piece == 0) {
          builder.line(rng.uniform(1.0, 30.0));
        } else if (piece == 1) {
          builder.arc(rng.uniform(2.0, 15.0), rng.uniform(-3.0, 3.0) + 1e-3);
        } else {
          // Curvature from the current end to a random one within 1/2 1/m: a spiral that can
          // fold around the query.
          const double end = rng.coin() ? 0.0 : rng.uniform(-0.5, 0.5);
          const double largest = std::max(std::abs(end), std::abs(builder.end_curvature()));
          const double length = rng.uniform(1.0, 30.0);
          if (end != builder.end_curvature()) {
            builder.clothoid(largest > 0.0 ? std::min(length, 2.5 / largest) : length, end);
          } else {
            builder.line(length);
          }
        }
      }
      return builder.build();
    }
    case 2:
      return Path::circle(start, rng.uniform(1.0, 20.0), rng.coin(), heading);
    default: {
      const double radius = rng.uniform(1.0, 15.0);
      const double straight = rng.uniform(1.0, 30.0);
      const double turn = rng.coin() ? pi : -pi;
      return PathBuilder(start, heading)
          .line(straight)
          .arc(radius, turn)
          .line(straight)
          .arc(radius, turn)
          .build(true);
    }
  }
}

//! Samples of the path and of `reach_m` of each extension.
//! An open path whose heading stays within +-1.2 rad of its start: no part of it or of its
//! extensions comes back near another, so the nearest branch is unique along the drive.
Path random_gentle_path(Random& rng) {
  const Vec2 start{rng.uniform(-10, 10), rng.uniform(-10, 10)};
  const double base = rng.uniform(-pi, pi);
  double turned = 0.0;
  if (rng.coin()) {
    std::vector<Vec2> points{start};
    const int count = rng.integer(3, 25);
    for (int i = 1; i < count; ++i) {
      turned = std::clamp(turned + rng.uniform(-0.4, 0.4), -1.0, 1.0);
      points.push_back(points.back() + rng.uniform(2.0, 8.0) * unit_from_heading(base + turned));
    }
    return Path::from_waypoints(points);
  }
  PathBuilder builder(start, base);
  const int pieces = rng.integer(1, 7);
  for (int i = 0; i < pieces; ++i) {
    if (rng.coin()) {
      builder.line(rng.uniform(1.0, 30.0));
    } else {
      double angle = rng.uniform(0.1, 1.0);
      if (std::abs(turned + angle) > 1.2) angle = -angle;
      turned += angle;
      const double radius = rng.uniform(3.0, 15.0);
      if (rng.coin()) {
        builder.arc(radius, angle);
      } else {  // the same turn through clothoid, arc, clothoid (each clothoid turns T / (2 R))
        const double transition = rng.uniform(0.1, 0.9) * std::abs(angle) * radius;
        const double turn = angle > 0.0 ? 1.0 : -1.0;
        if (builder.end_curvature() != 0.0) builder.line(1.0);  // start straight
        builder.clothoid(transition, turn / radius)
            .arc(radius, angle - turn * transition / radius)
            .clothoid(transition, 0.0);
      }
    }
  }
  return builder.build();
}

std::vector<Vec2> dense_samples(const Path& path, double reach_m) {
  const double begin = path.is_closed() ? 0.0 : -reach_m;
  const double end = path.is_closed() ? path.length() : path.length() + reach_m;
  std::vector<Vec2> samples;
  for (double s = begin; s <= end; s += kSpacing_m) samples.push_back(path.evaluate(s).position);
  return samples;
}

//! A query near a random part of the path: on it, on an extension, or up to 6 m beside them.
Vec2 random_query(Random& rng, const Path& path) {
  const double reach = path.is_closed() ? 0.0 : 0.5 * kExtensionReach_m;
  const PathPoint at = path.evaluate(rng.uniform(-reach, path.length() + reach));
  const double offset = rng.coin() ? 0.0 : rng.uniform(-6.0, 6.0);
  return at.position + offset * Vec2{-std::sin(at.heading_rad), std::cos(at.heading_rad)};
}

TEST(ProjectionBruteForce, GlobalAndWarmProjectionMatchDenseSamplingWithExtensions) {
  for (int c = 0; c < property_cases(); ++c) {
    const auto seed = case_seed(c);
    SCOPED_TRACE(seed_message(seed));
    Random rng(seed);
    const Path path = random_folding_path(rng, rng.integer(0, 3));
    std::vector<Vec2> queries;
    for (int trial = 0; trial < 25; ++trial) queries.push_back(random_query(rng, path));
    // The closest point of an extension is no farther from its end point than the query is.
    double reach = 0.0;
    for (const Vec2& query : queries) {
      reach = std::max({reach, norm(query - path.evaluate(0.0).position),
                        norm(query - path.evaluate(path.length()).position)});
    }
    const std::vector<Vec2> samples = dense_samples(path, reach + 1.0);
    for (const Vec2& query : queries) {
      SCOPED_TRACE("query " + std::to_string(query.x) + ", " + std::to_string(query.y));
      double nearest = std::numeric_limits<double>::infinity();
      for (const Vec2& sample : samples) nearest = std::min(nearest, norm(query - sample));
      // The sampled minimum overestimates the true one by at most half the spacing (squared
      // terms aside), so the projection lies in [nearest - spacing, nearest].
      const PathProjection global = path.project(query);
      const double distance = norm(query - global.closest_point);
      // kNewtonSlack_m: on tightly folding splines the cubic's Newton search can stop a few
      // tens of micrometres short (a query near a center of curvature).
      ASSERT_LE(distance, nearest + kNewtonSlack_m) << "excess " << distance - nearest;
      ASSERT_GE(distance, nearest - kSpacing_m);
      ASSERT_NEAR(std::abs(global.lateral_error_m), distance, 1e-9);
      const PathPoint on_path = path.evaluate(global.arc_length_m);
      ASSERT_NEAR(norm(on_path.position - global.closest_point), 0.0, 1e-7);

      ProjectionHint cold;
      ASSERT_NEAR(std::abs(path.project(query, cold).lateral_error_m), distance, 1e-9);
    }
  }
}

// Driving along the path and on past its end: the warm start must follow onto the extension
// (no jump to a distant segment). (On folding paths whose branches cross, the warm start rightly
// stays on its branch, so this property needs paths without crossings.)
TEST(ProjectionBruteForce, WarmProjectionFollowsOntoTheExtensions) {
  for (int c = 0; c < property_cases(); ++c) {
    const auto seed = case_seed(c);
    SCOPED_TRACE(seed_message(seed));
    Random rng(seed);
    const Path path = random_gentle_path(rng);
    const double offset = rng.uniform(-0.5, 0.5);
    ProjectionHint hint;
    for (double s = -kExtensionReach_m; s <= path.length() + kExtensionReach_m; s += 0.1) {
      const PathPoint at = path.evaluate(s);
      const Vec2 query =
          at.position + offset * Vec2{-std::sin(at.heading_rad), std::cos(at.heading_rad)};
      const PathProjection warm = path.project(query, hint);
      const PathProjection global = path.project(query);
      // The point at s is |offset| away, so neither search may report more (a nearer branch
      // of a folding path may report less).
      ASSERT_LE(std::abs(warm.lateral_error_m), std::abs(offset) + kNewtonSlack_m) << "s " << s;
      ASSERT_LE(std::abs(global.lateral_error_m), std::abs(offset) + kNewtonSlack_m) << "s " << s;
      if (s < 0.0 || s > path.length()) {  // on an extension nothing is approximate
        ASSERT_LE(std::abs(global.lateral_error_m), std::abs(offset) + 1e-9) << "s " << s;
      }
    }
  }
}

// Far from the path the warm start turns into a global search that its own hint's segment and a
// nearby point's hint bound from the start. The nearby hint changes nothing of the result: with
// it, the projection is the one without it (a warm walk's local closest point where the own hint
// is near, else the global closest point), to the Newton search's slack on folding splines.
TEST(ProjectionBruteForce, SeededGlobalSearchFindsTheGlobalClosestPoint) {
  for (int c = 0; c < property_cases(); ++c) {
    const auto seed = case_seed(c);
    SCOPED_TRACE(seed_message(seed));
    Random rng(seed + 71);
    const Path path = random_folding_path(rng, rng.integer(0, 3));
    for (int trial = 0; trial < 25; ++trial) {
      const PathPoint at = path.evaluate(rng.uniform(0.0, path.length()));
      const double offset = rng.uniform(-60.0, 60.0);
      const Vec2 query =
          at.position + offset * Vec2{-std::sin(at.heading_rad), std::cos(at.heading_rad)};
      ProjectionHint own, nearby;
      if (rng.coin()) path.project(random_query(rng, path), own);
      if (rng.coin()) path.project(random_query(rng, path), nearby);
      SCOPED_TRACE("query " + std::to_string(query.x) + ", " + std::to_string(query.y) +
                   " own hint " + std::to_string(own.segment_index) + " nearby hint " +
                   std::to_string(nearby.segment_index));
      const bool cold = own.segment_index == ProjectionHint::none;
      ProjectionHint unseeded_hint = own;
      const PathProjection unseeded = path.project(query, unseeded_hint);
      const PathProjection seeded =
          path.project(query, own, Path::ProjectionOptions{.nearby = &nearby});
      ASSERT_NEAR(std::abs(seeded.lateral_error_m), std::abs(unseeded.lateral_error_m),
                  kNewtonSlack_m);
      ASSERT_NEAR(norm(query - seeded.closest_point), std::abs(seeded.lateral_error_m), 1e-9);
      // Without an own hint the search is global from the start, the nearby hint its bound.
      if (cold) {
        ASSERT_NEAR(std::abs(seeded.lateral_error_m), std::abs(path.project(query).lateral_error_m),
                    kNewtonSlack_m);
      }
    }
  }
}

TEST(ProjectionBruteForce, PointOnTheEndExtensionOfAUTurn) {
  // A point that once projected wrongly: (-100, 20) lies on the end extension of this U-turn.
  const Path path = PathBuilder({0, 0}, 0).line(100).arc(10, pi).line(50).build();
  const PathProjection projection = path.project({-100.0, 20.0});
  EXPECT_NEAR(projection.lateral_error_m, 0.0, 1e-9);
  EXPECT_NEAR(projection.arc_length_m, path.length() + 150.0, 1e-9);
  EXPECT_NEAR(std::abs(wrap_angle(projection.heading_rad - pi)), 0.0, 1e-12);
  ProjectionHint hint;
  EXPECT_NEAR(path.project({-100.0, 20.0}, hint).lateral_error_m, 0.0, 1e-9);
  // And beside the start extension, behind the start.
  EXPECT_NEAR(path.project({-30.0, 1.0}).lateral_error_m, 1.0, 1e-9);
  EXPECT_NEAR(path.project({-30.0, 1.0}).arc_length_m, -30.0, 1e-9);
}

}  // namespace
}  // namespace smoothsteer
