// The tuning rule (tuning_rule.hpp): every tuned controller gets exactly the same number of
// configurations, the rule is deterministic, and it reports on the held-out scenarios only.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "smoothsteer/evaluation/certified_route.hpp"
#include "smoothsteer/evaluation/controller_registration.hpp"
#include "smoothsteer/evaluation/tuning_rule.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer {
namespace {

std::string scenario_file(const std::string& name) {
  return testing::source_file("scenarios/" + name + ".yaml");
}

TEST(TuningRule, EveryGridHasExactlyTheBudget) {
  for (int budget : {8, 16, 64, 1024}) {
    for (std::size_t axes = 1; axes <= 3; ++axes) {
      const std::vector<int> shape = grid_shape(budget, axes);
      int product = 1;
      for (int count : shape) {
        EXPECT_GE(count, 2);
        product *= count;
      }
      EXPECT_EQ(product, budget) << "budget " << budget << " axes " << axes;
    }
  }
  for (int budget : {0, 3, 12, 4, 8192}) {
    try {
      grid_shape(budget, 3);
      FAIL() << "budget " << budget << " accepted";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("TuningRuleOptions: budget = "), std::string::npos)
          << error.what();
    }
  }
}

TEST(TuningRule, EveryAxisKeyIsAGainOfItsController) {
  for (const std::string& name : comparison_controller_names()) {
    for (const GainAxis& axis : gain_axes(name)) {
      EXPECT_LT(axis.low, axis.high) << name << " " << axis.key;
      ComparisonSetup setup;
      EXPECT_NO_THROW(apply_gain(name, axis.key, axis.low, setup)) << name << " " << axis.key;
    }
  }
  ComparisonSetup setup;
  EXPECT_THROW(apply_gain("stanley", "weight_lateral", 1.0, setup), std::invalid_argument);
  EXPECT_TRUE(gain_axes("proposed_c1").empty());
  // The certified controller's axes are knobs of its route, and every study controller has a
  // grid (the same budget for all).
  const runner::Scenario scenario = runner::load_scenario(scenario_file("lane_change_15"));
  for (const GainAxis& axis : gain_axes(certified_controller_name)) {
    EXPECT_NO_THROW(certified_route_options(scenario, {{axis.key, axis.low}})) << axis.key;
  }
  for (const std::string& name : study_controller_names()) {
    EXPECT_FALSE(gain_axes(name).empty()) << name;
  }
}

TEST(TuningRule, IsDeterministicAndReportsOnHeldOutScenariosOnly) {
  register_comparison_controllers();
  const std::vector<std::string> short_run{"simulation.duration_s=4"};
  const std::vector<runner::Scenario> training{
      runner::load_scenario(scenario_file("lane_change_10"), short_run)};
  const std::vector<runner::Scenario> held_out{
      runner::load_scenario(scenario_file("lane_change_15"), short_run)};
  TuningRuleOptions options;
  options.budget = 4;
  options.controllers = {"certified", "stanley", "pure_pursuit", "proposed_c1"};
  const TuningRuleResult first = run_tuning_rule(training, held_out, options);
  const TuningRuleResult second = run_tuning_rule(training, held_out, options);
  EXPECT_EQ(first.table().to_csv(), second.table().to_csv());
  ASSERT_EQ(first.controllers.size(), 4u);
  for (const TunedController& tuned : first.controllers) {
    const std::vector<GainAxis> axes = gain_axes(tuned.controller);
    EXPECT_EQ(tuned.configurations, axes.empty() ? 1 : 4) << tuned.controller;
    ASSERT_EQ(tuned.gains.size(), axes.size());
    for (std::size_t a = 0; a < axes.size(); ++a) {
      EXPECT_EQ(tuned.gains[a].first, axes[a].key);
      EXPECT_GE(tuned.gains[a].second, axes[a].low * (1 - 1e-12));
      EXPECT_LE(tuned.gains[a].second, axes[a].high * (1 + 1e-12));
    }
    ASSERT_EQ(tuned.held_out.size(), 1u);
    EXPECT_EQ(tuned.held_out[0].scenario, held_out[0].name);
  }
  EXPECT_THROW(run_tuning_rule(training, {}, options), std::invalid_argument);
  // One row per (held-out scenario, controller), and no wall-clock figure in the table.
  EXPECT_EQ(first.table().rows.size(), 4u);
  EXPECT_EQ(first.table().to_csv().find("update_us"), std::string::npos);
  EXPECT_EQ(first.timings_table().rows.size(), 4u);
}

TEST(TuningRule, AdmissibleMeansNoHeldSampleAboveTheLimitsAndNoDivergence) {
  ScenarioScore score;
  EXPECT_TRUE(score.admissible());
  score.clamped_updates = 3;  // cut to the limits: counted, allowed
  EXPECT_TRUE(score.admissible());
  score.metrics.held_acceleration_violations = 1;
  EXPECT_EQ(score.held_above_limits(), 1);
  EXPECT_FALSE(score.admissible());
  score.metrics.held_acceleration_violations = 0;
  score.diverged = true;
  EXPECT_FALSE(score.admissible());
  score.diverged = false;
  score.infeasible = true;
  EXPECT_FALSE(score.admissible());
}

TEST(TuningRule, RejectsAnUnknownController) {
  TuningRuleOptions options;
  options.controllers = {"certified", "no_such_controller"};
  try {
    options.validate();
    FAIL() << "unknown controller accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("no_such_controller"), std::string::npos);
  }
}

}  // namespace
}  // namespace smoothsteer
