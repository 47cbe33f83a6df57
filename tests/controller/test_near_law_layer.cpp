// The near law's boundary layer under the governor (near_law_layer.hpp): the certified layer
// while the path's curvature moves, the steady law's l kbar_sw / 2 (l = 2 v tau) on steady
// stretches (tau growing with the speed above 13.3 m/s), never wider than the certified one, and
// back to steady once the activity is forgotten.

#include "smoothsteer/controller/near_law_layer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "support/property.hpp"

namespace smoothsteer {
namespace {

constexpr double period_s = 0.02;

double steady_layer(double certified, double bound, double speed) {
  const double time_constant = std::max(NearLawLayer::steady_time_constant_s,
                                        NearLawLayer::steady_time_constant_per_speed_s2pm * speed);
  const double length = std::max(NearLawLayer::min_steady_length_m, 2.0 * time_constant * speed);
  return std::min(certified, 0.5 * length * bound);
}

TEST(NearLawLayer, IsTheSteadyLawOnAStraightAndTheCertifiedOneInACurve) {
  NearLawLayer layer;
  const double v = 10.0, certified = 0.03, bound = 0.0056;
  for (int i = 0; i < 50; ++i) layer.observe(0.0, v * period_s, v);
  EXPECT_DOUBLE_EQ(layer.layer(certified, bound, v), 0.5 * 2.0 * bound);  // l = 2 m at 10 m/s
  // A clothoid entry at 0.002 1/m^2: lateral jerk v^3 * 0.002 = 2 m/s^3, above the threshold.
  double curvature = 0.0;
  for (int i = 0; i < 10; ++i) {
    curvature += 0.002 * v * period_s;
    layer.observe(curvature, v * period_s, v);
  }
  EXPECT_NEAR(layer.activity_mps3(), 2.0, 1e-9);
  EXPECT_DOUBLE_EQ(layer.layer(certified, bound, v), certified);
  // Then a steady arc: the activity decays by e per activity_memory_m and the layer returns
  // (after ten memories to within 1e-4 of its width).
  const int forget_periods =
      static_cast<int>(std::ceil(10.0 * NearLawLayer::activity_memory_m / (v * period_s)));
  for (int i = 0; i < forget_periods; ++i) layer.observe(curvature, v * period_s, v);
  EXPECT_NEAR(layer.layer(certified, bound, v), steady_layer(certified, bound, v), 1e-4);
  layer.reset();
  EXPECT_EQ(layer.activity_mps3(), 0.0);
}

TEST(NearLawLayer, StaysBetweenTheSteadyAndTheCertifiedLayer) {
  const int cases = testing::property_cases(200);
  for (int index = 0; index < cases; ++index) {
    const auto seed = testing::case_seed(index);
    testing::Random random(seed);
    const double v = random.uniform(0.0, 40.0);
    const double certified = random.uniform(0.0, 0.1);
    const double bound = random.uniform(0.0, 0.05);
    NearLawLayer layer;
    double curvature = 0.0;
    for (int i = 0; i < 100; ++i) {
      curvature += random.uniform(-1e-3, 1e-3) * (random.coin() ? 1.0 : 0.0);
      layer.observe(curvature, random.uniform(0.0, 1.0), v);
      const double epsilon = layer.layer(certified, bound, v);
      SCOPED_TRACE(testing::seed_message(seed) + " v=" + std::to_string(v) +
                   " certified=" + std::to_string(certified) + " bound=" + std::to_string(bound));
      ASSERT_TRUE(std::isfinite(epsilon));
      ASSERT_LE(epsilon, certified + 1e-15);
      ASSERT_GE(epsilon, steady_layer(certified, bound, v) - 1e-15);
    }
  }
}

}  // namespace
}  // namespace smoothsteer
