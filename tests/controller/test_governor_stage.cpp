// The governor stage of the control step (governor_stage.hpp): off, it hands the step the
// ungoverned authority and law unchanged; on, on random chain states, errors and speeds, the
// authority never falls below the certified near law's, the layer is eq. (governed_law_length)'s
// l kbar_sw / 2, the blend is a convex combination of the far and the near law, the clamp lands
// in eq. (governor_interval) within |kappa_n| <= kbar_n, and the rate it keeps for the next
// period is the command's rate at the end of the last sub-step.

#include "smoothsteer/controller/governor_stage.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "smoothsteer/controller/dubins_switching_law.hpp"
#include "smoothsteer/controller/steering_governor.hpp"
#include "support/property.hpp"
#include "support/random_setup.hpp"

namespace smoothsteer {
namespace {

using namespace smoothsteer::testing;

//! Governed parameters of order n (as test_steering_governor.cpp draws them, fewer choices).
ControllerParameters governed(Random& random, int order) {
  ControllerParameters p = random_parameters(random, order, random.uniform(0.3, 0.8));
  p.feedforward.share = random.uniform(0.0, 0.9);
  p.law.boundary_layer = random.uniform(0.005, 0.05);
  SteeringGovernor& g = p.governor;
  g.enabled = true;
  g.max_steering_rate_radps = random.uniform(0.2, 2.0);
  g.max_steering_acceleration_radps2 =
      random.uniform(1.2, 6.0) * (45.0 * g.max_steering_rate_radps / p.chain.wheelbases_m[0] +
                                  3.0 * g.max_steering_rate_radps);
  g.fixed_law_length = random.coin();
  if (g.fixed_law_length) g.law_length_m = random.uniform(2.0, 20.0);
  // Lowered as governed_parameters() lowers it, or left at its default (the whole kbar_sw).
  if (random.coin()) {
    g.near_law_switching_bound = random.uniform(0.2, 1.0) * p.switching_curvature_bound();
  }
  return p;
}

ChainAngles random_angles(Random& random, const ControllerParameters& p) {
  const ChainBounds bounds = compute_chain_bounds(p);
  ChainAngles angles{};
  for (int i = 0; i < p.chain.order; ++i) {
    const auto k = static_cast<std::size_t>(i);
    angles[k] = random.uniform(-1.0, 1.0) * bounds.angle[k];
  }
  return angles;
}

TEST(GovernorStage, OffLeavesTheStepUngoverned) {
  const int cases = property_cases(40);
  for (int index = 0; index < cases; ++index) {
    const auto seed = case_seed(index);
    Random random(seed + 811);
    ControllerParameters p = random_parameters(random, random.integer(1, 2), 0.5);
    p.feedforward.curvature_rate = random.uniform(0.001, 0.1);
    const double speed = random.uniform(0.0, 30.0), far = random.uniform(-0.2, 0.2);
    SCOPED_TRACE(seed_message(seed) + " " + describe(p) + " v=" + std::to_string(speed) +
                 " far=" + std::to_string(far));
    GovernorStage stage;
    stage.begin_period(p, {.speed_magnitude = speed, .period_s = 0.02, .step_length_m = 0.1});
    EXPECT_FALSE(stage.governed());
    EXPECT_EQ(stage.feedforward_rate(), p.feedforward.curvature_rate);
    const GovernorStage::Authority authority = stage.authority(p, random.uniform(-0.1, 0.1));
    EXPECT_EQ(authority.bound, p.switching_curvature_bound());
    EXPECT_EQ(authority.layer, p.law.boundary_layer);
    EXPECT_EQ(stage.blend(p, {.lateral_error_m = 1.0, .far_law_curvature = far}, true), far);
    stage.end_period();
    EXPECT_EQ(stage.rate_radps(), 0.0);
  }
}

TEST(GovernorStage, StandstillIsUngoverned) {
  Random random(case_seed(0));
  const ControllerParameters p = governed(random, 1);
  GovernorStage stage;
  stage.begin_period(p, {.speed_magnitude = 0.0, .period_s = 0.02, .step_length_m = 0.0});
  EXPECT_FALSE(stage.governed());
  stage.begin_period(p, {.speed_magnitude = 5.0, .period_s = 0.02, .step_length_m = 0.1});
  EXPECT_TRUE(stage.governed());
  EXPECT_GE(stage.feedforward_rate(), p.feedforward.curvature_rate);
}

TEST(GovernorStage, RestartForgetsTheEnvelopesAndTheFarLaw) {
  Random random(case_seed(0) + 5);
  const ControllerParameters p = governed(random, 1);
  GovernorStage stage;
  stage.begin_period(p, {.speed_magnitude = 8.0, .period_s = 0.02, .step_length_m = 0.16});
  (void)stage.authority(p, 0.05);
  (void)stage.blend(p, {.lateral_error_m = 3.0, .relative_heading = 0.4}, true);
  EXPECT_GT(stage.far_share(), 0.0);
  EXPECT_GT(stage.heading_envelope(), 0.0);
  stage.restart(-0.02);
  EXPECT_EQ(stage.feedforward_envelope(), 0.02);
  EXPECT_EQ(stage.far_share(), 0.0);
  EXPECT_EQ(stage.heading_envelope(), 0.0);
  EXPECT_EQ(stage.rate_radps(), 0.0);
}

TEST(GovernorStage, AuthorityBlendAndClampKeepTheirBounds) {
  const int cases = property_cases(100);
  for (int index = 0; index < cases; ++index) {
    const auto seed = case_seed(index);
    Random random(seed + 907);
    const int order = random.coin() ? 2 : 1;
    const ControllerParameters p = governed(random, order);
    const double speed = random.uniform(0.5, 30.0), period = 0.02;
    const int steps = random.integer(1, 6);
    const double direction = random.coin() ? 1.0 : -1.0;
    std::ostringstream text;
    text << describe(p) << " v=" << speed << " steps=" << steps << " direction=" << direction;
    SCOPED_TRACE(seed_message(seed) + " " + text.str());
    GovernorStage stage;
    stage.restart(random.uniform(-1.0, 1.0) * p.feedforward_curvature_bound());
    const double step_length = speed * period / steps;
    stage.begin_period(p, {.speed_magnitude = speed,
                           .acceleration_mps2 = random.uniform(-3.0, 3.0),
                           .period_s = period,
                           .step_length_m = step_length});
    ASSERT_TRUE(stage.governed());
    const double near_bound =
        std::min(p.governor.near_law_switching_bound, p.switching_curvature_bound());
    const double lead_bound = p.chain.lead_curvature_bound;
    double rate = 0.0;
    for (int step = 0; step < steps; ++step) {
      const double feedforward = random.uniform(-1.0, 1.0) * p.feedforward_curvature_bound();
      const GovernorStage::Authority authority = stage.authority(p, feedforward);
      EXPECT_GE(authority.bound, near_bound);
      EXPECT_GE(stage.feedforward_envelope(), std::abs(feedforward));
      const double length = p.governor.fixed_law_length
                                ? p.governor.law_length_m
                                : governed_law_length(p, speed, stage.heading_envelope());
      EXPECT_DOUBLE_EQ(authority.layer, 0.5 * length * authority.bound);

      const double e = random.uniform(-3.0, 3.0), psi = random.uniform(-1.0, 1.0);
      const SwitchingResult far = dubins_switching_law(e, psi, authority.bound, authority.layer, p);
      const double blended = stage.blend(p,
                                         {.path_curvature = random.uniform(-0.05, 0.05),
                                          .lateral_error_m = e,
                                          .relative_heading = psi,
                                          .far_law_curvature = far.curvature},
                                         step == 0);
      EXPECT_GE(stage.far_share(), 0.0);
      EXPECT_LE(stage.far_share(), 1.0);
      EXPECT_GE(stage.heading_envelope(), std::abs(psi));
      // A convex combination of the far law and the near law (|kappa| <= its authority).
      EXPECT_LE(std::abs(blended), std::max(std::abs(far.curvature), near_bound) * (1 + 1e-12));
      if (stage.far_share() == 1.0) {
        EXPECT_EQ(blended, far.curvature);
      }

      const ChainAngles angles = random_angles(random, p);
      const double wanted = random.uniform(-2.0, 2.0) * lead_bound;
      const double clamped = stage.clamp(wanted, angles, p, direction);
      EXPECT_LE(std::abs(clamped), lead_bound);
      EXPECT_EQ(stage.clamp(clamped, angles, p, direction), clamped);
      stage.end_substep(angles, p, direction, clamped);
      rate = steering_derivatives(angles, p, direction, speed, 0.0, clamped).rate_radps;
    }
    stage.end_period();
    // n = 1 remembers the command's rate at the end of the period; n = 2 reads it from the state.
    EXPECT_EQ(stage.rate_radps(), order == 1 ? rate : 0.0);
  }
}

TEST(GovernorStage, AnErrorBeyondTheHandOverCallsTheFarLaw) {
  // With the near law's sliding variable kept inside its layer (a heading that points the lead
  // wheel back along the near law's own surface), the far law's share follows the lead wheel's
  // error alone: 0 within e_h = max(epsilon, share (K_f + K_r) v^2 / g), 1 from 2 e_h on, with
  // epsilon the certified layer on a gentle path and at most NearLawLayer::single_corner_layer
  // on a tight corner without a reversal.
  const int cases = property_cases(100);
  for (int index = 0; index < cases; ++index) {
    const auto seed = case_seed(index);
    Random random(seed + 1013);
    const ControllerParameters p = governed(random, random.coin() ? 2 : 1);
    const double speed = random.uniform(0.5, 30.0), slip_lag = random.uniform(0.0, 4.0);
    const bool tight_corner = random.coin();
    const double layer = tight_corner
                             ? std::min(p.law.boundary_layer, NearLawLayer::single_corner_layer)
                             : p.law.boundary_layer;
    const double handover = std::max(layer, SteeringGovernor::far_law_slip_lag_share * slip_lag);
    const double ratio = random.uniform(0.0, 3.0);
    const double e = (random.coin() ? 1.0 : -1.0) * ratio * handover;
    std::ostringstream text;
    text << describe(p) << " v=" << speed << " slip_lag=" << slip_lag << " e=" << e
         << " tight_corner=" << tight_corner;
    SCOPED_TRACE(seed_message(seed) + " " + text.str());
    GovernorStage stage;
    stage.restart(0.0);
    stage.begin_period(p,
                       {.speed_magnitude = speed, .period_s = 0.02, .step_length_m = 0.02 * speed});
    ASSERT_TRUE(stage.governed());
    // The heading that zeroes the near law's sliding variable at e: search it by bisection on
    // the sliding variable's sign (it falls as psi rises towards the path for e > 0).
    const double near_bound =
        std::min(p.governor.near_law_switching_bound, p.switching_curvature_bound());
    double low = -1.5, high = 1.5;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (low + high);
      const double sigma = dubins_switching_law(e, mid, near_bound, layer, p).sliding_variable;
      const double sigma_low = dubins_switching_law(e, low, near_bound, layer, p).sliding_variable;
      ((sigma > 0.0) == (sigma_low > 0.0) ? low : high) = mid;
    }
    const double psi = 0.5 * (low + high);
    const double sigma = dubins_switching_law(e, psi, near_bound, layer, p).sliding_variable;
    if (std::abs(sigma) > 0.5 * layer) continue;  // the surface has no such heading here
    (void)stage.blend(p,
                      {.lateral_error_m = e,
                       .relative_heading = psi,
                       .slip_lag_m = slip_lag,
                       .ahead = {.reversal = false, .gentle = !tight_corner}},
                      true);
    const double expected = std::clamp(ratio - 1.0, 0.0, 1.0);
    EXPECT_NEAR(stage.far_share(), expected, 1e-9);
  }
}

}  // namespace
}  // namespace smoothsteer
