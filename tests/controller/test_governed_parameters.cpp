// Eq. (governed_authority), governed_parameters(): on random certified parameters and car limits
// it widens kbar_n from the car's angle and friction limits, never below the certified one, and
// hands the near-path law the certified kbar_sw as an explicit setting
// (SteeringGovernor::near_law_switching_bound), which validate() checks like any other field.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "smoothsteer/controller/steering_governor.hpp"
#include "support/property.hpp"
#include "support/random_setup.hpp"

namespace smoothsteer {
namespace {

using namespace smoothsteer::testing;

constexpr double inf = std::numeric_limits<double>::infinity();

//! Certified parameters of order 1 or 2 under the governor, with the car's limits.
ControllerParameters certified(Random& random) {
  ControllerParameters p =
      random_parameters(random, random.integer(1, 2), random.uniform(0.2, 0.6));
  p.feedforward.share = random.uniform(0.0, 0.8);
  SteeringGovernor& g = p.governor;
  g.enabled = true;
  g.max_steering_rate_radps = random.uniform(0.2, 2.0);
  g.max_steering_acceleration_radps2 = random.uniform(2.0, 20.0);
  g.max_steering_angle_rad = random.uniform(0.4, 1.2);
  g.max_lateral_acceleration_mps2 = random.coin() ? random.uniform(2.0, 10.0) : inf;
  return p;
}

std::string inputs(const ControllerParameters& p, double speed) {
  return describe(p) + " share=" + std::to_string(p.feedforward.share) +
         " angle=" + std::to_string(p.governor.max_steering_angle_rad) +
         " mu_g=" + std::to_string(p.governor.max_lateral_acceleration_mps2) +
         " near=" + std::to_string(p.governor.near_law_switching_bound) +
         " v=" + std::to_string(speed);
}

TEST(GovernedParameters, NearLawKeepsTheCertifiedSwitchingAuthority) {
  const int cases = property_cases(200);
  int widened = 0;
  for (int index = 0; index < cases; ++index) {
    const auto seed = case_seed(index);
    Random random(seed + 4421);
    ControllerParameters p = certified(random);
    const bool preset = random.coin();
    if (preset) {
      p.governor.near_law_switching_bound =
          random.uniform(0.1, 2.0) * p.switching_curvature_bound();
    }
    const double speed = random.uniform(0.0, 30.0);
    SCOPED_TRACE(seed_message(seed) + " " + inputs(p, speed));
    ASSERT_TRUE(p.is_valid()) << p.validation_error();
    const ControllerParameters g = governed_parameters(p, speed);
    ASSERT_TRUE(g.is_valid()) << g.validation_error();
    EXPECT_GE(g.chain.lead_curvature_bound, p.chain.lead_curvature_bound);
    if (g.chain.lead_curvature_bound > p.chain.lead_curvature_bound) {
      // Widened no further than the car's angle allows (eq. kappalmax, corrected).
      EXPECT_LE(g.chain.lead_curvature_bound, std::sin(p.governor.max_steering_angle_rad) /
                                                  p.chain.vehicle_wheelbase_m * (1.0 + 1e-12));
      ++widened;
    }
    const double expected =
        preset ? std::min(p.governor.near_law_switching_bound, p.switching_curvature_bound())
               : p.switching_curvature_bound();
    // Where the widened set would leave the invariant sets, governed_parameters() returns the
    // certified parameters as they are: the near law's authority is the same either way (and
    // never more than the widened kbar_sw, which the 0.8 share can make the smaller).
    EXPECT_EQ(std::min(g.governor.near_law_switching_bound, g.switching_curvature_bound()),
              std::min(expected, g.switching_curvature_bound()));
    if (g.chain.lead_curvature_bound > p.chain.lead_curvature_bound) {
      EXPECT_EQ(g.governor.near_law_switching_bound, expected);
    }
    // Retuning the widened parameters again leaves the near law's authority where it was.
    const ControllerParameters again = governed_parameters(g, speed);
    EXPECT_EQ(std::min(again.governor.near_law_switching_bound, again.switching_curvature_bound()),
              std::min(g.governor.near_law_switching_bound, g.switching_curvature_bound()));
  }
  // The draws must exercise the widening, not only its refusal.
  EXPECT_GT(widened, cases / 4);
}

TEST(GovernedParameters, WithoutTheGovernorTheParametersStayAsTheyAre) {
  Random random(case_seed(0) + 4423);
  ControllerParameters p = random_parameters(random, 2, 0.4);
  const ControllerParameters g = governed_parameters(p, 10.0);
  EXPECT_EQ(g.chain.lead_curvature_bound, p.chain.lead_curvature_bound);
  EXPECT_EQ(g.feedforward.share, p.feedforward.share);
  EXPECT_EQ(g.governor.near_law_switching_bound, inf);
}

TEST(GovernedParameters, CarLimitsAreCheckedAsFields) {
  Random random(case_seed(0) + 4429);
  const ControllerParameters p = certified(random);
  for (const double bad : {0.0, -0.5, std::nan("")}) {
    ControllerParameters angle = p, friction = p;
    angle.governor.max_steering_angle_rad = bad;
    friction.governor.max_lateral_acceleration_mps2 = bad;
    EXPECT_NE(angle.validation_error().find("governor.max_steering_angle_rad"), std::string::npos)
        << bad;
    EXPECT_NE(friction.validation_error().find("governor.max_lateral_acceleration_mps2"),
              std::string::npos)
        << bad;
  }
  ControllerParameters none = p;
  none.governor.max_steering_angle_rad = none.governor.max_lateral_acceleration_mps2 = inf;
  EXPECT_TRUE(none.is_valid()) << none.validation_error();
}

TEST(GovernedParameters, NearLawBoundIsCheckedAsAField) {
  Random random(case_seed(0) + 4427);
  ControllerParameters p = certified(random);
  for (const double bad : {0.0, -0.1, std::nan("")}) {
    ControllerParameters q = p;
    q.governor.near_law_switching_bound = bad;
    EXPECT_NE(q.validation_error().find("governor.near_law_switching_bound"), std::string::npos)
        << bad;
    EXPECT_NE(q.validation_error().find("must be > 0 1/m"), std::string::npos)
        << q.validation_error();
  }
  p.governor.near_law_switching_bound = 0.05;
  EXPECT_TRUE(p.is_valid()) << p.validation_error();
  ControllerParameters off;
  off.governor.near_law_switching_bound = 0.05;
  EXPECT_NE(off.validation_error().find("governor.near_law_switching_bound = 0.05 has no effect "
                                        "while governor.enabled is false"),
            std::string::npos)
      << off.validation_error();
}

}  // namespace
}  // namespace smoothsteer
