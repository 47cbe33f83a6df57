// The near law's boundary layer under the governor (near_law_layer.hpp): the certified layer
// while the path's curvature moves, the steady law's l kbar_sw / 2 (l = 2 v tau) on steady
// stretches (tau growing with the speed above 13.3 m/s), never wider than the certified one, and
// back to steady once the activity is forgotten; the certified layer only within reach of a
// reversal of the path's curvature, at most the single-corner layer elsewhere.

#include "smoothsteer/controller/near_law_layer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "smoothsteer/path/path_builder.hpp"
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

// A reversal counts where the curvature takes both signs beyond 1 / 500 m within the reach: an
// S-bend's second arc 30 m ahead does, a hairpin's single arc and a gentle opposite bend do not.
// A corner is gentle where its lateral acceleration at the speed stays below 3 m/s^2.
TEST(NearLawLayer, ReadsReversalsAndGentleCornersAhead) {
  const Path s_bend =
      PathBuilder({0.0, 0.0}, 0.0).line(20.0).arc(30.0, 0.5).arc(30.0, -0.5).line(50.0).build();
  const Path hairpin = PathBuilder({0.0, 0.0}, 0.0).line(20.0).arc(12.0, 3.0).line(50.0).build();
  const Path gentle =
      PathBuilder({0.0, 0.0}, 0.0).line(20.0).arc(30.0, 0.5).arc(1000.0, -0.02).line(50.0).build();
  const double v = 10.0;  // 3.3 m/s^2 on a 30 m radius, 8.3 on 12 m
  EXPECT_TRUE(NearLawLayer::path_ahead(s_bend, 20.0, 30.0, v).reversal);
  EXPECT_FALSE(NearLawLayer::path_ahead(s_bend, 20.0, 10.0, v).reversal);  // out of reach
  EXPECT_FALSE(NearLawLayer::path_ahead(s_bend, 55.0, 30.0, v).reversal);  // one arc left
  EXPECT_FALSE(NearLawLayer::path_ahead(hairpin, 10.0, 60.0, v).reversal);
  EXPECT_FALSE(NearLawLayer::path_ahead(gentle, 20.0, 60.0, v).reversal);
  EXPECT_FALSE(NearLawLayer::path_ahead(hairpin, 10.0, 60.0, v).gentle);
  EXPECT_TRUE(NearLawLayer::path_ahead(hairpin, 10.0, 60.0, 4.0).gentle);  // 1.3 m/s^2
  EXPECT_TRUE(NearLawLayer::path_ahead(hairpin, 0.0, 15.0, v).gentle);     // the straight only
  EXPECT_FALSE(NearLawLayer::path_ahead(gentle, 20.0, 60.0, v).gentle);
  EXPECT_TRUE(NearLawLayer::path_ahead(gentle, 20.0, 60.0, 9.0).gentle);  // 2.7 m/s^2
}

// The certified layer holds on a gentle path and for reversal_memory_m of travel past the last
// reversal seen ahead; a tight corner takes at most single_corner_layer until reversal_memory_m
// past the last period it was seen, unless a reversal is remembered.
TEST(NearLawLayer, RemembersReversalsAndTightCornersOverTheMemory) {
  NearLawLayer layer;
  layer.reset();
  const double certified = 0.03, step = 0.3;  // 15 m/s at 50 Hz
  const double single = std::min(certified, NearLawLayer::single_corner_layer);
  const NearLawLayer::PathAhead gentle{.reversal = false, .gentle = true};
  const NearLawLayer::PathAhead tight{.reversal = false, .gentle = false};
  const NearLawLayer::PathAhead reversal{.reversal = true, .gentle = false};
  // Travels the memory's length seeing `ahead` every step, expecting `held` throughout, then one
  // step beyond it, expecting `after`.
  const auto through_the_memory = [&](const NearLawLayer::PathAhead& ahead, double held,
                                      double after) {
    double travelled = 0.0;
    while (travelled + step <= NearLawLayer::reversal_memory_m - 1e-9) {
      layer.observe_ahead(ahead, step);
      travelled += step;
      EXPECT_EQ(layer.certified_layer(certified), held) << "after " << travelled << " m";
    }
    layer.observe_ahead(ahead, 2.0 * step);
    EXPECT_EQ(layer.certified_layer(certified), after);
  };
  EXPECT_EQ(layer.certified_layer(certified), certified);
  layer.observe_ahead(tight, step);
  EXPECT_EQ(layer.certified_layer(certified), single);
  // The corner's exit: stiff while the memory lasts, then the certified layer again.
  through_the_memory(gentle, single, certified);
  // A reversal wins over a tight corner for as long as it is remembered.
  layer.observe_ahead(reversal, step);
  EXPECT_EQ(layer.certified_layer(certified), certified);
  through_the_memory(tight, certified, single);
  // A layer already below the single-corner one stays as it is.
  EXPECT_EQ(layer.certified_layer(0.005), 0.005);
  layer.reset();
  EXPECT_EQ(layer.certified_layer(certified), certified);
}

}  // namespace
}  // namespace smoothsteer
