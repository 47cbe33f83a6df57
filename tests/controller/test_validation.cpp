// Every invalid parameter and input gets its own error that names the field, the value and the
// rule; update() never emits NaN.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

std::shared_ptr<const Path> line() {
  return std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 100.0));
}

void expect_rejected(const ControllerParameters& parameters, const std::string& field,
                     const std::string& rule) {
  try {
    LeadWheelController controller(parameters, line());
    FAIL() << "accepted invalid parameters; expected an error about " << field;
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(field), std::string::npos) << message;
    EXPECT_NE(message.find(rule), std::string::npos) << message;
  }
}

TEST(ParameterValidation, DefaultsAreValid) {
  EXPECT_NO_THROW(ControllerParameters{}.validate());
}

TEST(ParameterValidation, RejectsEachInvalidField) {
  ControllerParameters p;
  p.chain.order = -1;
  expect_rejected(p, "order = -1", "[0, 8]");
  p = {};
  p.chain.order = 9;
  expect_rejected(p, "order = 9", "[0, 8]");
  p = {};
  p.chain.vehicle_wheelbase_m = 0.0;
  expect_rejected(p, "vehicle_wheelbase_m = 0", "[0.01, 100] m");
  p = {};
  p.chain.vehicle_wheelbase_m = nan;
  expect_rejected(p, "vehicle_wheelbase_m = nan", "[0.01, 100] m");
  p = {};
  p.chain.wheelbases_m[0] = -2.5;
  expect_rejected(p, "wheelbases_m[0] (lambda_1) = -2.5", "> 0");
  p = {};
  p.chain.wheelbases_m[1] = 2.7;
  expect_rejected(p, "wheelbases_m[1] (lambda_2) = 2.7", "lambda_l < lambda_veh");
  p = {};
  p.chain.lead_curvature_bound = -0.1;
  expect_rejected(p, "lead_curvature_bound = -0.1", "> 0");
  p = {};
  p.law.k_rob = 1.0;
  expect_rejected(p, "k_rob = 1", "[0, 1)");
  p = {};
  p.law.k_rob = 3.0;  // the paper's printed value (paper_notes §5)
  expect_rejected(p, "k_rob = 3", "[0, 1)");
  p = {};
  p.law.k_rob = -0.1;
  expect_rejected(p, "k_rob = -0.1", "[0, 1)");
  p = {};
  p.delay_compensation.actuator_delay_s = -0.1;
  expect_rejected(p, "actuator_delay_s = -0.1", "[0, 1] s");
  p = {};
  p.delay_compensation.actuator_delay_s = 2.0;
  expect_rejected(p, "actuator_delay_s = 2", "[0, 1] s");
  p = {};
  p.feedforward.catch_up = 1.5;
  expect_rejected(p, "feedforward_catch_up = 1.5", "[0, 1]");
  p = {};
  p.feedforward.catch_up = std::numeric_limits<double>::quiet_NaN();
  expect_rejected(p, "feedforward_catch_up = nan", "[0, 1]");
  p = {};
  p.feedforward.curvature_preview = CurvaturePreview::planned_jumps;  // default target rear_axle
  expect_rejected(p, "curvature_preview (1 = planned_jumps) = 1",
                  "cornering_target rear_axle_exact");
  p.feedforward.cornering_target = CorneringTarget::rear_axle_exact;
  p.chain.order = 3;
  expect_rejected(p, "curvature_preview (1 = planned_jumps) = 1", "order 1 or 2");
  p.chain.order = 2;
  p.feedforward.curvature_rate = inf;
  expect_rejected(p, "curvature_preview (1 = planned_jumps) = 1",
                  "finite feedforward_curvature_rate > 0");
  p = {};
  p.law.boundary_layer = -0.01;
  expect_rejected(p, "boundary_layer = -0.01", ">= 0");
  p = {};
  p.law.approach_angle_rad = 2.0;
  expect_rejected(p, "approach_angle_rad = 2", "(0, pi/2]");
  p = {};
  p.chain.lead_curvature_bound = 1.5;  // kbar_2 lambda_2 = 1.5 >= 1
  expect_rejected(p, "kbar_2 * lambda_2 = 1.5", "must be < 1");
  p = {};
  p.chain.lead_curvature_bound = 0.9;  // kbar_2 lambda_2 = 0.9, kbar_1 = 2.06, kbar_1 lambda_1 > 1
  expect_rejected(p, "kbar_1 * lambda_1", "must be < 1");
}

// Values that overflowed the sub-step count (a float-to-int conversion in update()) or that
// name no enumerator were accepted.
TEST(ParameterValidation, RejectsValuesThatBreakTheArithmetic) {
  ControllerParameters p;
  p.chain.wheelbases_m[0] = 1e-308;
  expect_rejected(p, "wheelbases_m[0] (lambda_1) = 1e-308", "[0.01, 100] m");
  p = {};
  p.chain.wheelbases_m[1] = 1e-308;
  expect_rejected(p, "wheelbases_m[1] (lambda_2) = 1e-308", "[0.01, 100] m");
  p = {};
  p.chain.max_substep_fraction = 1e-308;
  expect_rejected(p, "max_substep_fraction = 1e-308", "min_substep_m = 0.001 m");
  p = {};
  p.chain.max_substep_fraction = 0.005;  // 0.005 * lambda_2 = 0.005 m: fine
  EXPECT_NO_THROW(p.validate());
  p.chain.wheelbases_m[1] = 0.1;  // 0.0005 m
  expect_rejected(p, "max_substep_fraction = 0.005", "shortest wheelbase 0.1");
  p = {};
  p.chain.vehicle_wheelbase_m = 1e308;
  expect_rejected(p, "vehicle_wheelbase_m = 1e+308", "[0.01, 100] m");
  p = {};
  p.law.surface = static_cast<SlidingSurface>(7);
  expect_rejected(p, "surface = 7", "0 (global) or 1 (paper)");
  p = {};
  p.feedforward.cornering_target = static_cast<CorneringTarget>(-3);
  expect_rejected(p, "cornering_target = -3", "2 (lead_wheel)");
  p = {};
  p.feedforward.curvature_preview = static_cast<CurvaturePreview>(2);
  expect_rejected(p, "curvature_preview = 2", "1 (planned_jumps)");
}

// The shortest legal sub-step at the fastest, longest legal period: the count fits an int.
TEST(InputValidation, LongestPeriodAtTheShortestSubStepIsFinite) {
  ControllerParameters p;
  p.chain.wheelbases_m[1] = 0.01;      // ControllerParameters::min_wheelbase_m
  p.chain.max_substep_fraction = 0.1;  // 0.001 m: ControllerParameters::min_substep_m
  LeadWheelController controller(p, line());
  ControllerOutput output;
  const ControllerInput fastest{{0.0, 3.0},
                                0.0,
                                ControllerInputRange::max_abs_speed_mps,
                                0.0,
                                ControllerInputRange::max_period_s};
  EXPECT_EQ(controller.update(fastest, output), Status::ok);
  EXPECT_TRUE(all_finite(output));
}

TEST(MatchedDisturbance, RefusesValuesBeyondItsBound) {
  LeadWheelController controller(ControllerParameters{}, line());
  EXPECT_FALSE(controller.set_matched_disturbance(1e308));
  EXPECT_FALSE(controller.set_matched_disturbance(-1.5));
  EXPECT_FALSE(controller.set_matched_disturbance(nan));
  EXPECT_TRUE(controller.set_matched_disturbance(0.01));
  EXPECT_TRUE(controller.set_matched_disturbance(-1.0));  // max_matched_disturbance_per_m
  ControllerOutput output;
  EXPECT_EQ(controller.update({{0.0, 3.0}, 0.0, 5.0, 0.0, 0.02}, output), Status::ok);
  EXPECT_TRUE(all_finite(output));
}

TEST(ParameterValidation, RejectsNullPath) {
  EXPECT_THROW(LeadWheelController(ControllerParameters{}, nullptr), std::invalid_argument);
}

TEST(InputValidation, InvalidInputReturnsErrorAndKeepsOutput) {
  LeadWheelController controller(ControllerParameters{}, line());
  ControllerOutput output;
  ASSERT_EQ(controller.update({{0.0, 3.0}, 0.0, 5.0, 0.0, 0.02}, output), Status::ok);
  const ControllerOutput before = output;
  const ControllerInput bad_inputs[] = {
      {{nan, 0.0}, 0.0, 5.0, 0.0, 0.02}, {{0.0, inf}, 0.0, 5.0, 0.0, 0.02},
      {{0.0, 0.0}, nan, 5.0, 0.0, 0.02}, {{0.0, 0.0}, 0.0, nan, 0.0, 0.02},
      {{0.0, 0.0}, 0.0, inf, 0.0, 0.02}, {{0.0, 0.0}, 0.0, 5.0, nan, 0.02},
      {{0.0, 0.0}, 0.0, 5.0, 0.0, 0.0},  {{0.0, 0.0}, 0.0, 5.0, 0.0, -0.02},
      {{0.0, 0.0}, 0.0, 5.0, 0.0, nan},
  };
  for (const ControllerInput& input : bad_inputs) {
    EXPECT_EQ(controller.update(input, output), Status::invalid_input);
    EXPECT_EQ(output.steering_angle_rad, before.steering_angle_rad);
    EXPECT_TRUE(std::isfinite(output.steering_angle_rad));
  }
  // The controller keeps working afterwards.
  EXPECT_EQ(controller.update({{0.0, 3.0}, 0.0, 5.0, 0.0, 0.02}, output), Status::ok);
}

TEST(InputValidation, ZeroSpeedFreezesTheChain) {
  LeadWheelController controller(ControllerParameters{}, line());
  ControllerOutput output;
  for (int k = 0; k < 20; ++k) controller.update({{0.0, 3.0}, 0.0, 5.0, 0.0, 0.02}, output);
  const ChainAngles frozen = controller.chain_angles();
  for (int k = 0; k < 20; ++k) {
    ASSERT_EQ(controller.update({{0.0, 3.0}, 0.0, 0.0, 0.0, 0.02}, output), Status::ok);
  }
  EXPECT_EQ(controller.chain_angles(), frozen);
  EXPECT_EQ(output.steering_rate_radps, 0.0);
}

TEST(Reset, InitialisesFromMeasuredSteeringAngleInsideTheBound) {
  LeadWheelController controller(ControllerParameters{}, line());
  EXPECT_EQ(controller.reset(0.1), Status::ok);
  EXPECT_NEAR(controller.vehicle_steering_angle(controller.chain_angles()[0]), 0.1, 1e-12);
  // Beyond the bound: the chain starts at the invariant set's edge (the command approaches it).
  EXPECT_EQ(controller.reset(1.4), Status::ok);
  EXPECT_LE(std::abs(controller.vehicle_steering_angle(controller.chain_angles()[0])),
            controller.bounds().steering_angle_rad + 1e-12);
  // NaN is refused and changes nothing.
  const ChainAngles kept = controller.chain_angles();
  EXPECT_EQ(controller.reset(nan), Status::invalid_input);
  EXPECT_EQ(controller.chain_angles(), kept);
}

TEST(RuleChecker, FieldListsReportTheFirstBrokenFieldInOrder) {
  // The list rules check in the order given and keep the first violation, as single rules do.
  RuleChecker check("Owner");
  check.require_positive({{"a", 1.0}, {"b", 0.0}, {"c", nan}});
  check.require_non_negative({{"d", -1.0}});
  ASSERT_TRUE(check.first());
  EXPECT_EQ(describe(check.first()), "Owner: b = 0 must be finite and > 0");
  RuleChecker non_negative("Owner");
  non_negative.require_non_negative({{"zero", 0.0}, {"infinite", inf}, {"negative", -1.0}});
  EXPECT_EQ(describe(non_negative.first()), "Owner: infinite = inf must be finite and >= 0");
  RuleChecker fine("Owner");
  fine.require_positive({{"a", 1e-300}});
  fine.require_non_negative({{"b", 0.0}});
  EXPECT_FALSE(fine.first());
}

}  // namespace
}  // namespace smoothsteer
