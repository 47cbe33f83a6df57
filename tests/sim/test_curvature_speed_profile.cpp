// The speed profile from the path's curvature (curvature_speed_profile.hpp): on random clothoid
// roads it keeps v <= v_max, v^2 |kappa| <= a_lat at every grid point and its acceleration within
// [-a_brake, a_up]; it is the largest such profile (at each point one limit is active); its time
// table covers the path's length; and bad limits are rejected by name.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/sim/curvature_speed_profile.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

using smoothsteer::testing::case_seed;
using smoothsteer::testing::property_cases;
using smoothsteer::testing::Random;
using smoothsteer::testing::seed_message;

Path random_road(Random& rng) {
  PathBuilder builder({0.0, 0.0}, 0.0);
  builder.line(rng.uniform(5.0, 60.0));
  for (int i = rng.integer(1, 4); i > 0; --i) {
    const double radius = rng.uniform(8.0, 300.0);
    const double turn = rng.coin() ? 1.0 : -1.0;
    const double transition = rng.uniform(0.1, 1.0) * radius;  // A^2 / R with A in [R/3, R]
    builder.clothoid(transition, turn / radius);
    builder.arc(radius, turn * rng.uniform(0.2, 2.0));
    builder.clothoid(transition, 0.0);
    if (rng.coin()) builder.line(rng.uniform(1.0, 80.0));
    if (rng.coin()) builder.arc(rng.uniform(20.0, 100.0), rng.uniform(-0.5, 0.5) + 1e-3);  // a jump
  }
  return builder.build();
}

TEST(CurvatureSpeedProfile, KeepsItsLimitsAndIsTheLargestSuchProfile) {
  for (int c = 0; c < property_cases(); ++c) {
    const auto seed = case_seed(c);
    SCOPED_TRACE(seed_message(seed));
    Random rng(seed);
    const Path path = random_road(rng);
    CurvatureSpeedLimits limits;
    limits.max_speed_mps = rng.uniform(3.0, 35.0);
    limits.max_lateral_acceleration_mps2 = rng.uniform(1.0, 8.0);
    limits.max_acceleration_mps2 = rng.uniform(0.3, 3.0);
    limits.max_deceleration_mps2 = rng.uniform(0.5, 6.0);
    if (rng.coin()) limits.initial_speed_mps = rng.uniform(1.0, 40.0);
    SCOPED_TRACE("v_max " + std::to_string(limits.max_speed_mps) + " a_lat " +
                 std::to_string(limits.max_lateral_acceleration_mps2));
    const std::vector<double> v = curvature_limited_speeds(path, limits);
    const double ds = path.length() / static_cast<double>(v.size() - 1);
    ASSERT_LE(ds, limits.spacing_m * (1 + 1e-12));
    for (std::size_t i = 0; i < v.size(); ++i) {
      const double s = ds * static_cast<double>(i);
      // The bound uses the largest |kappa| within one spacing: check it at s and around it.
      // (The profile books a jump at its nearest sample of ds / 8, so for the maximality check
      // below the window reaches ds / 16 farther.)
      auto largest_curvature = [&](double reach) {
        double kappa = 0.0;
        for (double d = -reach; d <= reach + 1e-12; d += ds / 16.0) {
          kappa = std::max(
              kappa, std::abs(path.evaluate(std::clamp(s + d, 0.0, path.length())).curvature));
        }
        return kappa;
      };
      const double kappa = largest_curvature(ds);
      const double kappa_wide = largest_curvature(ds + ds / 16.0);
      ASSERT_LE(v[i], limits.max_speed_mps * (1 + 1e-12)) << "i " << i;
      ASSERT_LE(v[i] * v[i] * kappa, limits.max_lateral_acceleration_mps2 * (1 + 1e-9))
          << "i " << i;
      if (i > 0) {
        const double a = (v[i] * v[i] - v[i - 1] * v[i - 1]) / (2.0 * ds);
        ASSERT_LE(a, limits.max_acceleration_mps2 * (1 + 1e-9)) << "i " << i;
        ASSERT_GE(a, -limits.max_deceleration_mps2 * (1 + 1e-9)) << "i " << i;
      }
      // Maximal: the point sits on its own limit, or the acceleration from the previous point or
      // the braking to the next one is at its bound.
      const double own = kappa_wide > 0.0
                             ? std::sqrt(limits.max_lateral_acceleration_mps2 / kappa_wide)
                             : limits.max_speed_mps;
      bool active = v[i] >= std::min(own, limits.max_speed_mps) * (1 - 1e-3);
      if (i == 0 && limits.initial_speed_mps) {
        active = active || v[0] >= *limits.initial_speed_mps * (1 - 1e-9);
      }
      if (i > 0) {
        active = active ||
                 v[i] * v[i] >=
                     (v[i - 1] * v[i - 1] + 2.0 * limits.max_acceleration_mps2 * ds) * (1 - 1e-9);
      }
      if (i + 1 < v.size()) {
        active = active ||
                 v[i] * v[i] >=
                     (v[i + 1] * v[i + 1] + 2.0 * limits.max_deceleration_mps2 * ds) * (1 - 1e-9);
      }
      ASSERT_TRUE(active) << "i " << i << " v " << v[i];
    }
    // The time table: the same speeds, covering the path's length at those speeds.
    const SpeedProfile profile = curvature_speed_profile(path, limits);
    ASSERT_TRUE(profile.is_valid()) << profile.validation_error();
    const auto& knots = *profile.knots;
    ASSERT_EQ(knots.size(), v.size());
    double covered = 0.0;
    for (std::size_t i = 1; i < knots.size(); ++i) {
      ASSERT_DOUBLE_EQ(knots[i].speed_mps, v[i]);
      const double dt = knots[i].time_s - knots[i - 1].time_s;
      covered += 0.5 * (knots[i].speed_mps + knots[i - 1].speed_mps) * dt;
      const double middle = 0.5 * (knots[i].time_s + knots[i - 1].time_s);
      ASSERT_NEAR(profile.speed(middle), 0.5 * (v[i] + v[i - 1]), 1e-9);
      ASSERT_NEAR(profile.acceleration(middle), (v[i] - v[i - 1]) / dt, 1e-9);
    }
    ASSERT_NEAR(covered, path.length(), 1e-6 * path.length());
    EXPECT_EQ(profile.speed(knots.back().time_s + 10.0), v.back());
    EXPECT_EQ(profile.acceleration(knots.back().time_s + 10.0), 0.0);
  }
}

TEST(CurvatureSpeedProfile, HairpinSpeedIsTheLateralLimit) {
  // R = 12 m at 6 m/s^2: sqrt(72) = 8.485 m/s on the arc, the design speed on the straights.
  const Path path = PathBuilder({0, 0}, 0)
                        .line(100)
                        .clothoid(6, 1.0 / 12)
                        .arc(12, 2.5)
                        .clothoid(6, 0.0)
                        .line(100)
                        .build();
  CurvatureSpeedLimits limits;
  limits.max_speed_mps = 20.0;
  limits.max_lateral_acceleration_mps2 = 6.0;
  const std::vector<double> v = curvature_limited_speeds(path, limits);
  const double ds = path.length() / static_cast<double>(v.size() - 1);
  EXPECT_NEAR(v[static_cast<std::size_t>((106.0 + 15.0) / ds)], std::sqrt(72.0), 1e-9);
  EXPECT_DOUBLE_EQ(v.front(), 20.0);
  EXPECT_NEAR(v.back(), std::min(20.0, std::sqrt(std::pow(std::sqrt(72.0), 2) + 2.0 * 100.0)), 1.0);
}

TEST(CurvatureSpeedProfile, BadLimitsAreNamed) {
  const Path path = Path::straight_line({0, 0}, 0.0, 10.0);
  auto message = [&](CurvatureSpeedLimits limits) {
    try {
      curvature_limited_speeds(path, limits);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  CurvatureSpeedLimits limits;
  limits.max_speed_mps = 0.0;
  EXPECT_NE(message(limits).find("CurvatureSpeedLimits: max_speed_mps = 0"), std::string::npos);
  limits = {};
  limits.max_lateral_acceleration_mps2 = std::nan("");
  EXPECT_NE(message(limits).find("max_lateral_acceleration_mps2 = nan"), std::string::npos);
  limits = {};
  limits.max_deceleration_mps2 = -1.0;
  EXPECT_NE(message(limits).find("max_deceleration_mps2 = -1"), std::string::npos);
  limits = {};
  limits.initial_speed_mps = 0.0;
  EXPECT_NE(message(limits).find("initial_speed_mps = 0"), std::string::npos);
}

}  // namespace
}  // namespace smoothsteer
