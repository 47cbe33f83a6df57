// Clothoid segments: positions against an independent evaluation of the Fresnel integrals (their
// power series in long double, Abramowitz and Stegun 7.3.11 and 7.3.13), heading and curvature
// in closed form, the builder's joints without curvature jumps, and validation messages.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

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

//! The standard clothoid from the origin along +x with curvature c u at arc length u:
//! (x, y)(u) = sqrt(pi / |c|) (C(t), sign(c) S(t)), t = u sqrt(|c| / pi), with the Fresnel
//! integrals C(t) = int_0^t cos(pi x^2 / 2) dx and S(t) = int_0^t sin(pi x^2 / 2) dx summed as
//! power series (A&S 7.3.11, 7.3.13) in long double; |u| sqrt(|c|) <= 4 keeps the cancellation
//! of the series below 1e-12 relative.
Vec2 standard_clothoid(double c, double u) {
  const long double t = static_cast<long double>(u) * std::sqrt(std::abs(c) / pi);
  const long double half_pi = static_cast<long double>(pi) / 2.0L;
  long double sum_c = 0.0L, sum_s = 0.0L;
  long double power = 1.0L;  // (pi / 2)^k t^(2k) / k!
  for (int k = 0; k < 200; ++k) {
    if (k > 0) power *= half_pi * t * t / static_cast<long double>(k);
    const long double term = power * t / static_cast<long double>(2 * k + 1);
    const int sign = (k / 2) % 2 == 0 ? 1 : -1;  // i^k: 1, i, -1, -i
    if (k % 2 == 0) {
      sum_c += sign * term;
    } else {
      sum_s += sign * term;
    }
  }
  const long double scale = std::sqrt(static_cast<long double>(pi) / std::abs(c));
  const double side = c > 0.0 ? 1.0 : -1.0;
  return {static_cast<double>(scale * sum_c), side * static_cast<double>(scale * sum_s)};
}

TEST(Clothoid, PositionsMatchTheFresnelSeriesInGeneralPosition) {
  for (int k = 0; k < property_cases(); ++k) {
    const auto seed = case_seed(k);
    SCOPED_TRACE(seed_message(seed));
    Random rng(seed);
    // A piece [u0, u0 + L] of the standard clothoid of rate c, started at its pose there and
    // then moved to a random pose: the segment must reproduce the series' points.
    const double c = (rng.coin() ? 1.0 : -1.0) * std::exp(rng.uniform(std::log(1e-4), 0.0));
    const double reach = 4.0 / std::sqrt(std::abs(c));
    const double u0 = rng.uniform(-0.9 * reach, 0.5 * reach);
    const double length = rng.uniform(0.05, 0.95 * reach - u0);
    const Vec2 origin{rng.uniform(-100, 100), rng.uniform(-100, 100)};
    const double rotation = rng.uniform(-pi, pi);
    auto place = [&](Vec2 p) {
      const Vec2 q = p - standard_clothoid(c, u0);
      return origin + Vec2{std::cos(rotation) * q.x - std::sin(rotation) * q.y,
                           std::sin(rotation) * q.x + std::cos(rotation) * q.y};
    };
    const double heading0 = rotation + 0.5 * c * u0 * u0;
    const PathSegment segment =
        PathSegment::make_clothoid(origin, heading0, c * u0, c * (u0 + length), length);
    SCOPED_TRACE("c " + std::to_string(c) + " u0 " + std::to_string(u0) + " L " +
                 std::to_string(length));
    for (int i = 0; i <= 20; ++i) {
      const double s = length * i / 20.0;
      const PathPoint point = segment.evaluate_at(s);
      const Vec2 expected = place(standard_clothoid(c, u0 + s));
      ASSERT_NEAR(point.position.x, expected.x, 1e-9) << "s " << s;
      ASSERT_NEAR(point.position.y, expected.y, 1e-9) << "s " << s;
      const double u = u0 + s;
      ASSERT_NEAR(wrap_angle(point.heading_rad - (rotation + 0.5 * c * u * u)), 0.0, 1e-12);
      ASSERT_NEAR(point.curvature, c * u, 1e-12 * (1.0 + std::abs(c * u)));
    }
  }
}

TEST(Clothoid, KnownValueOfTheFresnelIntegrals) {
  // C(1) = 0.7798934003768228, S(1) = 0.4382591473903548 (A&S table 7.7): the clothoid of rate
  // pi from curvature 0 over length 1 ends at (C(1), S(1)).
  const PathSegment segment = PathSegment::make_clothoid({0, 0}, 0.0, 0.0, pi, 1.0);
  const PathPoint end = segment.evaluate_at(1.0);
  EXPECT_NEAR(end.position.x, 0.7798934003768228, 1e-13);
  EXPECT_NEAR(end.position.y, 0.4382591473903548, 1e-13);
  EXPECT_NEAR(end.heading_rad, 0.5 * pi, 1e-15);
}

TEST(Clothoid, BuilderJointsHaveNoCurvatureJumpAndTheTurnClosesExactly) {
  // Straight, clothoid A = 20 m into R = 40 m, arc, clothoid out, straight: a 90 degree bend
  // whose clothoids turn by L / (2 R) each.
  const double radius = 40.0, parameter = 20.0;
  const double transition = parameter * parameter / radius;  // L = A^2 / R
  const double arc_angle = 0.5 * pi - transition / radius;
  const Path path = PathBuilder({0, 0}, 0.0)
                        .line(50.0)
                        .clothoid(transition, 1.0 / radius)
                        .arc(radius, arc_angle)
                        .clothoid(transition, 0.0)
                        .line(50.0)
                        .build();
  EXPECT_TRUE(path.curvature_jumps().empty());
  EXPECT_DOUBLE_EQ(path.max_abs_curvature(), 1.0 / radius);
  EXPECT_NEAR(path.evaluate(path.length()).heading_rad, 0.5 * pi, 1e-12);
  // C1 with continuous curvature across every joint.
  for (const PathSegment& segment : path.segments()) {
    if (segment.s0 == 0.0) continue;
    const PathPoint before = path.evaluate(segment.s0 - 1e-7);
    const PathPoint after = path.evaluate(segment.s0 + 1e-7);
    EXPECT_NEAR(norm(after.position - before.position), 2e-7, 1e-9);
    EXPECT_NEAR(wrap_angle(after.heading_rad - before.heading_rad), 0.0, 1e-8);
    EXPECT_NEAR(after.curvature - before.curvature, 0.0, 1e-8);
  }
  // The middle of the bend lies on the symmetry axis of the two straights (heading pi / 4).
  const Vec2 a = path.evaluate(0.0).position;
  const Vec2 b = path.evaluate(path.length()).position;
  const Vec2 middle = path.evaluate(0.5 * path.length()).position;
  EXPECT_NEAR(std::abs(norm(middle - a) - norm(middle - b)), 0.0, 1e-9);
}

TEST(Clothoid, ProjectionOntoAClothoidFindsTheFootOfTheNormal) {
  const Path path = PathBuilder({0, 0}, 0.3).clothoid(30.0, 0.1).build();
  for (double s = 0.5; s < 30.0; s += 2.5) {
    const PathPoint at = path.evaluate(s);
    for (const double offset : {-3.0, -0.5, 0.0, 0.7, 4.0}) {
      const Vec2 query =
          at.position + offset * Vec2{-std::sin(at.heading_rad), std::cos(at.heading_rad)};
      const PathProjection projection = path.project(query);
      EXPECT_NEAR(projection.arc_length_m, s, 1e-9) << "s " << s << " offset " << offset;
      EXPECT_NEAR(projection.lateral_error_m, offset, 1e-9) << "s " << s;
      EXPECT_NEAR(projection.curvature, at.curvature, 1e-12);
      ProjectionHint hint;
      hint.segment_index = 0;
      hint.parameter = std::max(0.0, s - 1.0);
      EXPECT_NEAR(path.project(query, hint).arc_length_m, s, 1e-9);
    }
  }
}

std::string message_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "<no std::invalid_argument thrown>";
}

TEST(Clothoid, ValidationNamesTheField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(message_of([] {
              PathBuilder({0, 0}, 0).clothoid(0.0, 0.1);
            }).find("PathBuilder::clothoid: length_m = 0"),
            std::string::npos);
  EXPECT_NE(message_of([nan] {
              PathBuilder({0, 0}, 0).clothoid(1.0, nan);
            }).find("curvature_end = nan"),
            std::string::npos);
  EXPECT_NE(message_of([] {
              PathBuilder({0, 0}, 0).line(1).clothoid(1.0, 0.0);
            }).find("differ from the current end curvature 0"),
            std::string::npos);
  EXPECT_NE(message_of([] {
              PathBuilder({0, 0}, 0).clothoid(100.0, 1.0);
            }).find("max(|curvature|) * length_m = 100"),
            std::string::npos);
  PathSegment flat = PathSegment::make_clothoid({0, 0}, 0.0, 0.1, 0.2, 1.0);
  flat.curvature_rate = 0.0;
  EXPECT_NE(message_of([&] {
              Path::from_segments({flat});
            }).find("segments[0].curvature_rate = 0 must be nonzero"),
            std::string::npos);
  PathSegment line = PathSegment::make_line({0, 0}, 0.0, 1.0);
  line.curvature_rate = 0.5;
  EXPECT_NE(message_of([&] {
              Path::from_segments({line});
            }).find("segments[0].curvature_rate = 0.5 must be 0"),
            std::string::npos);
}

}  // namespace
}  // namespace smoothsteer
