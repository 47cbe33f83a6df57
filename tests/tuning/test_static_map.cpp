// The static map (paper Sec. III items 4-5) and the closed-form bounds of the invariant sets
// (paper_notes §2): exact cases, comparison with the paper's corrected eq. (kappalmax), and seeded
// random states inside the invariant sets that must never exceed the map.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "smoothsteer/controller/trailer_chain.hpp"
#include "smoothsteer/tuning/invariant_bounds.hpp"
#include "smoothsteer/tuning/static_map.hpp"
#include "smoothsteer/tuning/worst_case.hpp"
#include "support/property.hpp"
#include "support/shared_static_map.hpp"

namespace smoothsteer {
namespace {

using namespace smoothsteer::testing;

TEST(InvariantBounds, CorrectedKappalmaxForSecondOrder) {
  // Paper-paper_notes §2: kbar_l = sin(dbar) / sqrt(lambda^2 + lambda_l^2 sin^2 dbar) with dbar the
  // fictive front-angle bound; the real bound is tan(dbar_veh) = lambda_veh tan(dbar) / lambda.
  Random random(case_seed(0));
  for (int k = 0; k < property_cases(40); ++k) {
    const double vehicle = random.uniform(1.5, 4.0);
    const double lead = random.uniform(0.05, 0.95) * vehicle;
    const double real_bound = random.uniform(0.1, 1.4);
    ControllerParameters p = ControllerParameters::paper_c1(vehicle, lead, 0.01, 0.3);
    const double lambda = p.chain.wheelbases_m[0];
    const double fictive = std::atan(lambda * std::tan(real_bound) / vehicle);
    const double expected =
        std::sin(fictive) /
        std::sqrt(lambda * lambda + lead * lead * std::pow(std::sin(fictive), 2));
    const double kbar = lead_curvature_bound_for_steering_angle(p, real_bound);
    EXPECT_NEAR(kbar, expected, 1e-12 * expected);
    // With eq. (cornering_constr) the bound does not depend on lambda_l: sin(dbar) / lambda_veh.
    EXPECT_NEAR(kbar, std::sin(real_bound) / vehicle, 1e-12);
    p.chain.lead_curvature_bound = kbar;
    EXPECT_NEAR(compute_chain_bounds(p).steering_angle_rad, real_bound, 1e-12);
  }
}

TEST(InvariantBounds, AnyOrderRoundTrip) {
  for (int k = 0; k < property_cases(40); ++k) {
    Random random(case_seed(k));
    ControllerParameters p;
    p.chain.order = random.integer(1, 6);
    p.chain.vehicle_wheelbase_m = random.uniform(1.5, 4.0);
    for (int i = 0; i < p.chain.order; ++i)
      p.chain.wheelbases_m[i] = random.uniform(0.2, 0.9) * p.chain.vehicle_wheelbase_m;
    const double bound = random.uniform(0.05, 1.45);
    p.chain.lead_curvature_bound = lead_curvature_bound_for_steering_angle(p, bound);
    SCOPED_TRACE(seed_message(case_seed(k)));
    ASSERT_TRUE(p.validation_error().empty()) << p.validation_error();
    EXPECT_NEAR(steering_angle_bound(p), bound, 1e-11);
  }
}

TEST(InvariantBounds, FictiveWheelbaseKeepsLeadWheelInFrontTrack) {
  const double outer[2] = {1.0, 0.5};
  const double lambda = fictive_wheelbase(2.7, outer, 2);
  EXPECT_NEAR(lambda * lambda + 1.25, 2.7 * 2.7, 1e-12);
  EXPECT_THROW(fictive_wheelbase(1.0, outer, 2), std::invalid_argument);
}

TEST(InvariantBounds, MinimumKRob) {
  EXPECT_NEAR(minimum_k_rob(0.01, 0.02, 0.1), 0.3, 1e-15);
  EXPECT_NEAR(minimum_k_rob(0.0, 0.0, 0.1, 0.25), 0.25, 1e-15);
  try {
    minimum_k_rob(0.05, 0.06, 0.1);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("kbar_l"), std::string::npos) << error.what();
  }
  EXPECT_THROW(minimum_k_rob(std::nan(""), 0.0, 0.1), std::invalid_argument);
  EXPECT_THROW(minimum_k_rob(0.0, 0.0, 0.0), std::invalid_argument);
}

TEST(WorstCase, FirstOrderRateIsTwiceRearCurvature) {
  // n = 1 with lambda = lambda_veh: sup (kbar/cos d + tan d/lambda) = 2 kbar_0 at the set's edge.
  const ControllerParameters p = ControllerParameters::paper_c0(2.5, 0.3, 0.3);
  const ChainBounds bounds = compute_chain_bounds(p);
  const SteeringDerivatives worst = worst_case_steering_derivatives(p);
  EXPECT_NEAR(worst.rate_per_meter, 2.0 * bounds.curvature[0], 1e-9);
  EXPECT_TRUE(std::isinf(worst.acceleration_per_meter2));
}

TEST(WorstCase, AgreesWithDenseGridAndChainBounds) {
  for (int k = 0; k < property_cases(10); ++k) {
    Random random(case_seed(k) + 11);
    const double vehicle = random.uniform(1.5, 4.0);
    const double lead = random.uniform(0.05, 0.95) * vehicle;
    const double q = std::sin(random.uniform(0.05, 1.4));
    const ControllerParameters p = ControllerParameters::paper_c1(vehicle, lead, q / vehicle, 0.3);
    std::ostringstream text;
    text << seed_message(case_seed(k)) << " lambda_veh=" << vehicle << " lambda_l=" << lead
         << " kbar_l=" << p.chain.lead_curvature_bound;
    SCOPED_TRACE(text.str());
    const SteeringDerivatives worst = worst_case_steering_derivatives(p);
    const ChainBounds bounds = compute_chain_bounds(p);
    EXPECT_NEAR(worst.rate_per_meter, bounds.steering_rate_per_meter,
                1e-8 * bounds.steering_rate_per_meter);
    double dense = 0.0;
    constexpr int samples = 300;
    for (int i = 0; i <= samples; ++i) {
      for (int j = 0; j <= samples; ++j) {
        ChainAngles delta{};
        delta[0] = bounds.angle[0] * (2.0 * i / samples - 1.0);
        delta[1] = bounds.angle[1] * (2.0 * j / samples - 1.0);
        for (double sign : {-1.0, 1.0}) {
          dense = std::max(dense, std::abs(vehicle_steering_derivatives(
                                               p, delta, sign * p.chain.lead_curvature_bound)
                                               .acceleration_per_meter2));
        }
      }
    }
    EXPECT_GE(worst.acceleration_per_meter2, dense * (1.0 - 1e-12));
    EXPECT_LE(worst.acceleration_per_meter2, dense * (1.0 + 1e-3));
  }
}

TEST(StaticMap, NeverExceededByStatesInTheInvariantSets) {
  const StaticMap& map = shared_map();
  int checked = 0;
  for (int k = 0; k < property_cases(40); ++k) {
    Random random(case_seed(k) + 3);
    const double vehicle = random.uniform(1.0, 5.0);
    const double lead = random.uniform(map.options().ratio_min, map.options().ratio_max) * vehicle;
    const double angle = random.uniform(0.02, map.options().max_steering_angle_rad);
    const ControllerParameters p =
        ControllerParameters::paper_c1(vehicle, lead, std::sin(angle) / vehicle, 0.3);
    std::ostringstream text;
    text << seed_message(case_seed(k)) << " lambda_veh=" << vehicle << " lambda_l=" << lead
         << " kbar_l=" << p.chain.lead_curvature_bound;
    SCOPED_TRACE(text.str());
    const MapValue bound = map.lookup(vehicle, lead, p.chain.lead_curvature_bound);
    const SteeringDerivatives exact = worst_case_steering_derivatives(p);
    EXPECT_GE(bound.rate, exact.rate_per_meter * (1.0 - 1e-9));
    EXPECT_GE(bound.acceleration, exact.acceleration_per_meter2 * (1.0 - 1e-9));
    const ChainBounds chain = compute_chain_bounds(p);
    for (int sample = 0; sample < 2000; ++sample) {
      ChainAngles delta{};
      // Half of the samples on the box boundary, where the extremes tend to be.
      delta[0] = random.uniform(-1.0, 1.0) * chain.angle[0];
      delta[1] = (random.coin() ? (random.coin() ? 1.0 : -1.0) : random.uniform(-1.0, 1.0)) *
                 chain.angle[1];
      const double kappa = (random.coin() ? 1.0 : -1.0) * p.chain.lead_curvature_bound;
      const SteeringDerivatives d = vehicle_steering_derivatives(p, delta, kappa);
      ASSERT_TRUE(std::isfinite(d.rate_per_meter) && std::isfinite(d.acceleration_per_meter2));
      ASSERT_LE(std::abs(d.rate_per_meter), bound.rate * (1.0 + 1e-12))
          << "delta=(" << delta[0] << "," << delta[1] << ") kappa=" << kappa;
      ASSERT_LE(std::abs(d.acceleration_per_meter2), bound.acceleration * (1.0 + 1e-12))
          << "delta=(" << delta[0] << "," << delta[1] << ") kappa=" << kappa;
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
}

TEST(StaticMap, RateGrowsWithLeadWheelbaseAccelerationHasInteriorMinimum) {
  // Paper Sec. III items 4-5: the rate is smallest for small lambda_l, the acceleration for
  // lambda_l near lambda_veh.
  const StaticMap& map = shared_map();
  const double q = std::sin(0.5);
  EXPECT_LT(map.lookup_node(0, q).rate, map.lookup_node(map.ratio_count() - 1, q).rate);
  EXPECT_GT(map.lookup_node(0, q).acceleration,
            map.lookup_node(map.ratio_count() / 2, q).acceleration);
}

TEST(StaticMap, InvalidOptionsNameTheField) {
  StaticMapOptions options;
  options.ratio_max = 1.2;
  try {
    StaticMap map(options);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("ratio_max = 1.2"), std::string::npos) << error.what();
  }
}

TEST(StaticMap, ShippedTableEqualsTheComputedOne) {
  // src/tuning/static_map_table.inc is generated (apps/static_map_table.cpp); a change to the
  // worst-case computation without regenerating it fails here. The numbers are printed exactly,
  // so only a different compiler's rounding may move them, far below 1e-12 relative.
  const StaticMap shipped{};
  const StaticMap computed = StaticMap::computed();
  ASSERT_EQ(shipped.ratio_count(), computed.ratio_count());
  ASSERT_EQ(shipped.angle_count(), computed.angle_count());
  for (int i = 0; i < shipped.ratio_count(); ++i) {
    for (int j = 0; j < shipped.angle_count(); ++j) {
      const MapValue a = shipped.node(i, j);
      const MapValue b = computed.node(i, j);
      ASSERT_NEAR(a.rate, b.rate, 1e-12 * std::abs(b.rate)) << "node " << i << ", " << j;
      ASSERT_NEAR(a.acceleration, b.acceleration, 1e-12 * std::abs(b.acceleration))
          << "node " << i << ", " << j;
    }
  }
  // Other options build their own table.
  StaticMapOptions coarse;
  coarse.angle_samples = 8;
  EXPECT_EQ(StaticMap(coarse).angle_count(), 9);
}

}  // namespace
}  // namespace smoothsteer
