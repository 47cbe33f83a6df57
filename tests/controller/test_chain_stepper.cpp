// The chain stepper of the control step (chain_stepper.hpp): the period splits into at most
// max_substeps sub-steps, none longer than the largest one allowed unless that cap binds; a
// chain in stationary cornering stays there while the rear axle's predicted pose turns by the
// chain's curvature plus the disturbance over the distance travelled; a straight chain drives
// straight.

#include "smoothsteer/controller/chain_stepper.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "smoothsteer/controller/steering_certificate.hpp"
#include "smoothsteer/math/angles.hpp"
#include "support/property.hpp"
#include "support/random_setup.hpp"

namespace smoothsteer {
namespace {

using namespace smoothsteer::testing;

TEST(ChainStepper, SubstepsCoverThePeriodWithinTheLargestLength) {
  const int cases = property_cases(200);
  for (int index = 0; index < cases; ++index) {
    const auto seed = case_seed(index);
    Random random(seed + 613);
    const double distance = random.coin() ? random.uniform(0.0, 2.0) : 0.0;
    const double largest = random.uniform(0.001, 0.5);
    const int max_substeps = random.integer(1, 64);
    const int order = random.integer(0, 3);
    std::ostringstream text;
    text << "distance=" << distance << " largest=" << largest << " max=" << max_substeps
         << " order=" << order;
    SCOPED_TRACE(seed_message(seed) + " " + text.str());
    ChainStepper stepper;
    stepper.begin_period({1.0, -2.0}, 0.3, distance, largest, max_substeps, order);
    const int steps = stepper.steps();
    EXPECT_EQ(steps, ChainStepper::substep_count(distance, largest, max_substeps, order));
    EXPECT_GE(steps, 1);
    EXPECT_LE(steps, max_substeps);
    if (order == 0 || distance == 0.0) {
      EXPECT_EQ(steps, 1);
    }
    EXPECT_NEAR(steps * stepper.step_length(), distance, 1e-12 * (1.0 + distance));
    if (steps < max_substeps && order > 0) {
      EXPECT_LE(stepper.step_length(), largest * (1.0 + 1e-12));
    }
    // One sub-step fewer would have been too long.
    if (steps > 1 && order > 0) {
      EXPECT_GT(distance / (steps - 1), largest);
    }
    EXPECT_EQ(stepper.position().x, 1.0);
    EXPECT_EQ(stepper.heading(), 0.3);
  }
}

TEST(ChainStepper, StationaryCorneringTurnsByTheChainsCurvature) {
  const int cases = property_cases(100);
  for (int index = 0; index < cases; ++index) {
    const auto seed = case_seed(index);
    Random random(seed + 617);
    const int order = random.integer(1, 3);
    const ControllerParameters p = random_parameters(random, order, random.uniform(0.2, 0.6));
    const ChainBounds bounds = compute_chain_bounds(p);
    const double* wheelbases = p.chain.wheelbases_m.data();
    const double front = random.uniform(-0.9, 0.9) * bounds.angle[0];
    const double disturbance = random.coin() ? random.uniform(-0.01, 0.01) : 0.0;
    const double distance = random.uniform(0.05, 1.0);
    const Vec2 start{random.uniform(-50.0, 50.0), random.uniform(-50.0, 50.0)};
    const double heading = random.uniform(-pi, pi);
    std::ostringstream text;
    text << describe(p) << " delta_1=" << front << " kappa_d=" << disturbance
         << " distance=" << distance;
    SCOPED_TRACE(seed_message(seed) + " " + text.str());
    ChainAngles angles{};
    stationary_chain(front, wheelbases, order, angles);
    const ChainAngles before = angles;
    double length_squared = 0.0;
    for (int i = 0; i < order; ++i) length_squared += wheelbases[i] * wheelbases[i];
    const double rear = std::tan(front) / wheelbases[0];
    const double lead = stationary_lead_curvature(rear, length_squared);
    ChainStepper stepper;
    stepper.begin_period(start, heading, distance, 0.05, 100, order);
    for (int step = 0; step < stepper.steps(); ++step) {
      stepper.advance(angles, wheelbases, order, lead, lead, bounds.angle, disturbance);
    }
    for (int i = 0; i < order; ++i) {
      const auto k = static_cast<std::size_t>(i);
      EXPECT_NEAR(angles[k], before[k], 1e-9) << "delta_" << i + 1;
    }
    const double turn = (rear + disturbance) * distance;
    EXPECT_NEAR(stepper.heading() - heading, turn, 1e-9);
    // Exactly on the arc of curvature c through the start, up to the midpoint rule: each
    // sub-step moves h along the arc's chord direction instead of the chord 2 sin(c h / 2) / c.
    const double c = rear + disturbance;
    const double h = stepper.step_length();
    auto chord = [c](double s) {
      return std::abs(c) > 1e-12 ? 2.0 * std::sin(0.5 * c * s) / c : s;
    };
    const Vec2 exact = start + chord(distance) * unit_from_heading(heading + 0.5 * turn);
    const Vec2 miss = stepper.position() - exact;
    EXPECT_LE(std::hypot(miss.x, miss.y), stepper.steps() * (h - chord(h)) + 1e-9 * distance);
  }
}

TEST(ChainStepper, StraightChainDrivesStraight) {
  ControllerParameters p;
  const ChainBounds bounds = compute_chain_bounds(p);
  ChainAngles angles{};
  ChainStepper stepper;
  stepper.begin_period({0.0, 0.0}, 0.5 * pi, 0.4, 0.1, 10, p.chain.order);
  ASSERT_EQ(stepper.steps(), 4);
  for (int step = 0; step < stepper.steps(); ++step) {
    stepper.advance(angles, p.chain.wheelbases_m.data(), p.chain.order, 0.0, 0.0, bounds.angle,
                    0.0);
  }
  EXPECT_EQ(stepper.heading(), 0.5 * pi);
  EXPECT_NEAR(stepper.position().x, 0.0, 1e-15);
  EXPECT_NEAR(stepper.position().y, 0.4, 1e-15);
  for (double angle : angles) EXPECT_EQ(angle, 0.0);
}

}  // namespace
}  // namespace smoothsteer
