// The robustness comparison (docs/results/robustness.md) on a small case: the 10 m/s lane change
// with the passenger car, the certified route and Stanley, nominal and with a rack offset of
// 0.01 rad either way. The offset acts on the plant only: it moves every controller's figure,
// the nominal column repeats the run without it, and the summary compares the certified route
// with the best baseline.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "smoothsteer/evaluation/robustness_comparison.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer {
namespace {

RobustnessOptions small_case() {
  RobustnessOptions options;
  options.scenarios = {{(testing::source_dir() / "scenarios/lane_change_10.yaml").string(), 0.0}};
  options.vehicle_files = {(testing::source_dir() / "vehicles/passenger_car.yaml").string()};
  options.controllers = {"certified", "stanley"};
  options.imperfections = {{"rack +0.01", "disturbance", {"simulation.steering_offset_rad=0.01"}},
                           {"rack -0.01", "disturbance", {"simulation.steering_offset_rad=-0.01"}}};
  options.threads = 2;
  return options;
}

TEST(RobustnessComparison, TheImperfectionActsOnThePlantAndTheSummaryNamesTheBest) {
  const RobustnessResult result = run_robustness_comparison(small_case());
  // 2 controllers x (nominal + 2 imperfections).
  ASSERT_EQ(result.runs.rows.size(), 6u);
  const runner::Scenario plain =
      runner::load_scenario((testing::source_dir() / "scenarios/lane_change_10.yaml").string());
  const double shipped = runner::run_scenario(plain).metrics.max_abs_rear_error_m;
  for (const auto& row : result.runs.rows) {
    SCOPED_TRACE(row[5] + " / " + row[3]);
    EXPECT_EQ(row[0], "lane_change_10");
    EXPECT_EQ(row[2], "single-track");
    EXPECT_EQ(row[8], "0");  // every row holds the car's limits
    const double max_e = std::stod(row[6]), nominal = std::stod(row[7]);
    if (row[3] == "nominal") {
      EXPECT_EQ(max_e, nominal);
      if (row[5] == "certified") {
        EXPECT_NEAR(max_e, shipped, 5e-4);  // the file's own run
      }
    } else {
      EXPECT_GT(max_e, nominal + 0.005);  // 0.01 rad of rack offset moves every controller
    }
  }
  ASSERT_EQ(result.summary.rows.size(), 2u);  // certified x 2 imperfections
  for (const auto& row : result.summary.rows) {
    EXPECT_EQ(row[7], "stanley");
    const bool beats = std::stod(row[4]) <= std::stod(row[8]);
    EXPECT_EQ(row[9], beats ? "yes" : "no");
    const bool within = std::stod(row[4]) <= 1.2 * std::stod(row[5]) + 0.02;
    EXPECT_EQ(row[6], within ? "yes" : "no");
  }
}

TEST(RobustnessComparison, OptionsAreValidatedNamingTheField) {
  auto message = [](RobustnessOptions options) {
    try {
      options.validate();
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  EXPECT_EQ(message(small_case()), "");
  RobustnessOptions bad = small_case();
  bad.models = {"kinematic"};
  EXPECT_NE(message(bad).find("models contains 'kinematic'"), std::string::npos);
  bad = small_case();
  bad.controllers = {"stanly"};
  EXPECT_NE(message(bad).find("controllers contains 'stanly'"), std::string::npos);
  bad = small_case();
  bad.imperfections = {{"rack", "disturbance", {}}};
  EXPECT_NE(message(bad).find("imperfection 'rack' has no overrides"), std::string::npos);
  bad = small_case();
  bad.imperfections = {{"nominal", "disturbance", {"simulation.steering_offset_rad=0.01"}}};
  EXPECT_NE(message(bad).find("other than 'nominal'"), std::string::npos);
  bad = small_case();
  bad.scenarios[0].settle_time_s = -1.0;
  EXPECT_NE(message(bad).find("settle_time_s = -1"), std::string::npos);
  bad = small_case();
  bad.threads = 0;
  EXPECT_NE(message(bad).find("threads = 0"), std::string::npos);
  bad = small_case();
  bad.scenarios.clear();
  EXPECT_NE(message(bad).find("scenarios is empty"), std::string::npos);
  // A bad override is the scenario loader's error, with the case named.
  bad = small_case();
  bad.imperfections = {{"rack", "disturbance", {"simulation.steering_offset_rad=0.5"}}};
  bad.controllers = {"stanley"};
  try {
    run_robustness_comparison(bad);
    ADD_FAILURE() << "an offset of 0.5 rad was accepted";
  } catch (const std::runtime_error& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("robustness comparison"), std::string::npos) << text;
    EXPECT_NE(text.find("steering_offset_rad"), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace smoothsteer
