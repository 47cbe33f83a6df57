// Every row of the lane-change comparison holds the car's angle, rate and acceleration limits
// on the held command: the baselines through the second-order limiter (docs/baselines.md, "The
// limiter"), the certified controller by construction. At 19 m/s the first-order clamp let
// Stanley, HOSM, the MPCs and the Dubins SMC reach 11-40 rad/s^2 against the car's 8.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "smoothsteer/evaluation/scenario_comparison.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer {
namespace {

std::size_t column(const ResultsTable& table, const std::string& name) {
  const auto found = std::find(table.header.begin(), table.header.end(), name);
  EXPECT_NE(found, table.header.end()) << name;
  return static_cast<std::size_t>(found - table.header.begin());
}

TEST(LimitedBaselines, EveryLaneChangeRowHoldsTheCarsLimits) {
  const ResultsTable table =
      run_lane_change_comparison({testing::source_file("scenarios/lane_change_19.yaml")});
  const std::size_t controller = column(table, "controller");
  const std::size_t above = column(table, "held_above_limits");
  const std::size_t acceleration = column(table, "held_accel_max_radps2");
  const std::size_t rate = column(table, "held_rate_max_radps");
  ASSERT_EQ(table.rows.size(), 11U);  // the scenario's controller and the ten of the comparison
  for (const std::vector<std::string>& row : table.rows) {
    EXPECT_EQ(row[above], "0") << row[controller];
    EXPECT_LE(std::stod(row[acceleration]), 8.0) << row[controller];
    EXPECT_LE(std::stod(row[rate]), 0.4) << row[controller];
  }
}

}  // namespace
}  // namespace smoothsteer
