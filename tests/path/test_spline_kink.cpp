// Path::max_abs_spline_kink() on a road sampled by a planner: a line, a clothoid, an arc, a
// clothoid back and a line, sampled at 0.5-1.25 m from a random phase and interpolated. The spline
// rings after each kink of the road's curvature (its knots' curvatures alternate about the
// road's); the measure reads the kink's step through that ringing.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

using testing::case_seed;
using testing::property_cases;
using testing::Random;
using testing::seed_message;

// Clothoids of 2.5-8 m to a radius of 8-40 m, sampled at 0.5-1.25 m (a planner's resolution; at
// least three samples along each clothoid): the measured step is within 10 % of the road's
// (0.97-1.06 over 4000 roads). Without the mean over a knot spacing a 2.5 m clothoid sampled
// every metre reads 1.21 times its step. Sampled coarser (1.5-2 m), the 2 m measure reads the
// step short (0.69-0.84 of it): the spline spreads a kink over more than the measure's reach.
TEST(SplineKink, ReadsTheRoadsKinkThroughTheSplinesRinging) {
  for (int k = 0; k < property_cases(32); ++k) {
    const auto seed = case_seed(k);
    Random random(seed);
    const double clothoid_m = random.uniform(2.5, 8.0);
    const double radius_m = random.uniform(8.0, 40.0);
    const double spacing_m = std::min(random.uniform(0.5, 1.25), clothoid_m / 3.0);
    const double phase = random.uniform(0.0, 1.0);
    const Path road = PathBuilder({0.0, 0.0}, 0.0)
                          .line(40.0)
                          .clothoid(clothoid_m, 1.0 / radius_m)
                          .arc(radius_m, 1.0)
                          .clothoid(clothoid_m, 0.0)
                          .line(40.0)
                          .build();
    std::vector<Vec2> waypoints;
    for (double s = phase * spacing_m; s <= road.length(); s += spacing_m)
      waypoints.push_back(road.evaluate(s).position);
    const Path spline = Path::from_waypoints(waypoints);
    const double step = 1.0 / (radius_m * clothoid_m);
    EXPECT_NEAR(spline.max_abs_spline_kink() / step, 1.0, 0.1)
        << seed_message(seed) << " clothoid " << clothoid_m << " m, R = " << radius_m
        << " m, spacing " << spacing_m << " m, phase " << phase;
  }
}

TEST(SplineKink, TheRoadsPiecesListTheirKinksInstead) {
  const Path road =
      PathBuilder({0.0, 0.0}, 0.0).line(20.0).clothoid(4.0, 0.1).arc(10.0, 1.0).build();
  EXPECT_EQ(road.max_abs_spline_kink(), 0.0);
  EXPECT_NEAR(road.max_abs_curvature_kink(), 0.1 / 4.0, 1e-12);
}

}  // namespace
}  // namespace smoothsteer
