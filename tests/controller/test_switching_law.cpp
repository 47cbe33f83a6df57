// The global switching law agrees in sign with the printed surface where that one is valid, and
// the cornering offset puts the rear axle on a circle.

#include <gtest/gtest.h>

#include <cmath>

#include "smoothsteer/controller/dubins_switching_law.hpp"
#include "smoothsteer/math/angles.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

using testing::case_seed;
using testing::property_cases;
using testing::Random;
using testing::seed_message;

TEST(SwitchingLaw, GlobalSignEqualsPaperSignInsideItsDomain) {
  ControllerParameters parameters;
  parameters.law.boundary_layer = 0.0;  // the pure sign law
  for (int c = 0; c < property_cases(2000); ++c) {
    const auto seed = case_seed(c);
    Random random(seed);
    const double kbar = random.uniform(0.01, 2.0);
    parameters.law.k_rob = random.uniform(0.0, 0.95);
    const double effective = (1.0 - parameters.law.k_rob) * kbar;
    const double e = random.uniform(-1.0, 1.0) / effective * 0.999;
    const double psi = random.uniform(-0.499, 0.499) * pi;  // cos(psi) > 0
    const double paper = paper_sliding_variable(e, psi, kbar, parameters.law.k_rob);
    if (std::abs(paper) < 1e-9) continue;
    parameters.law.surface = SlidingSurface::global;
    const SwitchingResult global = dubins_switching_law(e, psi, kbar, parameters);
    EXPECT_EQ(sign(global.curvature), sign(paper))
        << seed_message(seed) << " e=" << e << " psi=" << psi << " kbar=" << kbar;
  }
}

TEST(SwitchingLaw, ReferenceHeadingIsTheArcEndingTangentToThePath) {
  // On psi = psi_ref(e), turning at (1 - k_rob) kbar reaches e = 0 exactly with psi = 0.
  const double kbar = 0.25, k_rob = 0.3, effective = (1.0 - k_rob) * kbar;
  for (double e : {0.1, 1.0, 3.0, 5.0}) {
    const double psi = global_reference_heading(e, kbar, k_rob, pi / 2.0);
    EXPECT_NEAR((1.0 - std::cos(psi)) / effective, e, 1e-12);
    EXPECT_LT(psi, 0.0);
  }
  EXPECT_NEAR(global_reference_heading(100.0, kbar, k_rob, pi / 2.0), -pi / 2.0, 1e-12);
  EXPECT_NEAR(global_reference_heading(-100.0, kbar, k_rob, 1.0), 1.0, 1e-12);
  EXPECT_EQ(global_reference_heading(0.0, kbar, k_rob, pi / 2.0), 0.0);
}

TEST(SwitchingLaw, CorneringOffsetPlacesRearAxleOnTheCircle) {
  // Stationary chain on a circle: R_n^2 = R_0^2 + L^2. With R_0 = R the lead runs outside.
  for (double radius : {5.0, 20.0, 1000.0}) {
    for (double turn : {1.0, -1.0}) {
      const double curvature = turn / radius;
      const double length_squared = 2.7 * 2.7;
      const double offset = rear_axle_cornering_offset(curvature, length_squared);
      const double lead_radius = std::sqrt(radius * radius + length_squared);
      EXPECT_NEAR(std::abs(offset), lead_radius - radius, 1e-9);
      EXPECT_EQ(sign(offset), -turn);  // outside of the turn
    }
  }
  EXPECT_EQ(rear_axle_cornering_offset(0.0, 7.0), 0.0);
}

}  // namespace
}  // namespace smoothsteer
