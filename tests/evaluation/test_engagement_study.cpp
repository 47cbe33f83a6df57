// The engagement family (engagement_study.hpp): the table holds every case and controller, the
// lower bound is below every controller's max |e|, and the rear-axle reaching distance follows its
// definition.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "smoothsteer/evaluation/engagement_study.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer {
namespace {

TEST(EngagementStudy, ReachingDistanceIsTheTravelUntilTheErrorStaysBelow) {
  std::vector<TraceSample> trace(5);
  const double errors[5] = {0.5, 0.05, 0.2, 0.09, -0.05};
  for (std::size_t k = 0; k < trace.size(); ++k) {
    trace[k].distance_m = 10.0 + 2.0 * static_cast<double>(k);
    trace[k].lateral_error_m = errors[k];
  }
  EXPECT_DOUBLE_EQ(rear_reaching_distance(trace, 0.1), 6.0);  // from row 3 on
  EXPECT_DOUBLE_EQ(rear_reaching_distance(trace, 1.0), 0.0);  // never above
  trace.back().lateral_error_m = 0.3;
  EXPECT_DOUBLE_EQ(rear_reaching_distance(trace, 0.1), -1.0);  // the last row is above
  EXPECT_DOUBLE_EQ(rear_reaching_distance({}, 0.1), -1.0);
}

TEST(EngagementStudy, TwoCasesAtOneSpeed) {
  EngagementStudyOptions options;
  options.scenario_files = {testing::source_file("scenarios/lane_change_15.yaml")};
  options.offsets_m = {-0.5};
  options.headings_rad = {0.0, -0.1};
  const EngagementStudyResult result = run_engagement_study(options);
  ASSERT_EQ(result.cases.size(), 2u);
  const std::size_t baselines = result.options.baselines.size();
  EXPECT_EQ(baselines, 7u);  // every real-time baseline of the tuning study

  const ResultsTable table = result.table();
  ASSERT_EQ(table.rows.size(), 2 * (baselines + 2));
  for (const auto& row : table.rows) ASSERT_EQ(row.size(), table.header.size());
  EXPECT_EQ(table.header[4], "controller");
  EXPECT_EQ(table.rows[0][4], "scenario (scheduled_lead_wheel)");
  EXPECT_EQ(table.rows[baselines + 1][4], "lower_bound");
  EXPECT_EQ(table.rows[0][2], "-0.50");
  EXPECT_EQ(table.rows[baselines + 2][3], "-0.10");

  for (const EngagementCase& c : result.cases) {
    SCOPED_TRACE("heading " + std::to_string(c.heading_rad));
    EXPECT_DOUBLE_EQ(c.speed_mps, 15.0);
    ASSERT_TRUE(c.bound_converged) << c.bound.note;
    ASSERT_EQ(c.baselines.size(), baselines);
    const double bound = c.bound.max_abs_e_m;
    // No controller beats the lower bound (on the kinetic model, the dynamics the bound leaves out
    // cost the controllers more than they could give), nor starts below |e(0)|.
    EXPECT_GE(bound, std::abs(c.offset_m) - 1e-6);
    EXPECT_LE(bound, c.certified.max_abs_e_m) << c.certified.controller;
    for (const EngagementRun& run : c.baselines)
      EXPECT_LE(bound, run.max_abs_e_m) << run.controller;
    EXPECT_NEAR(c.bound_check.max_abs_lateral_error_m, bound, std::max(0.01, 0.02 * bound));
    EXPECT_EQ(c.certified.held_above_limits, 0);
    EXPECT_GE(c.certified.reaching_distance_m, 0.0);
    EXPECT_DOUBLE_EQ(c.ratio_to_bound(), c.certified.max_abs_e_m / bound);
    EXPECT_DOUBLE_EQ(c.ratio_to_best_baseline(),
                     c.certified.max_abs_e_m / c.baselines[c.best_baseline()].max_abs_e_m);
  }
  const std::string summary = result.summary_markdown();
  EXPECT_NE(summary.find("| 15.0 | 2 | 2 |"), std::string::npos) << summary;
  EXPECT_NE(summary.find("cases_within_1.1x_baseline"), std::string::npos);
  EXPECT_NE(summary.find("lower_bound"), std::string::npos);
}

TEST(EngagementStudy, OptionsNameTheBrokenRule) {
  EngagementStudyOptions options;
  options.scenario_files = {"x.yaml"};
  options.threads = 0;
  try {
    options.validate();
    FAIL() << "threads = 0 accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("EngagementStudyOptions: threads = 0"),
              std::string::npos)
        << error.what();
  }
  options.threads = 2;
  options.baselines = {"no_such_controller"};
  EXPECT_THROW(options.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace smoothsteer
