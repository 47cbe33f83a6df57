// Tight corners (tight_corners.hpp): the reference's speed, the speed override, no
// reference across a change of gear, and every controller at or above the reference where the
// steering rate binds.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "smoothsteer/evaluation/tight_corners.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "support/property.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer {
namespace {

TEST(TightCorners, TheReferenceHoldsTheSlowestMovingSpeed) {
  testing::Random random(testing::base_seed());
  for (int index = 0; index < testing::property_cases(50); ++index) {
    const double a = random.uniform(0.5, 30.0), b = random.uniform(0.5, 30.0);
    SCOPED_TRACE("seed " + std::to_string(testing::base_seed()) + " case " + std::to_string(index) +
                 " speeds " + std::to_string(a) + ", " + std::to_string(b));
    SpeedProfile constant;
    constant.initial_speed_mps = a;
    constant.final_speed_mps = b;  // ignored without a ramp
    EXPECT_DOUBLE_EQ(bound_speed_mps(constant), a);
    SpeedProfile ramp = constant;
    ramp.acceleration_mps2 = 1.0;
    EXPECT_DOUBLE_EQ(bound_speed_mps(ramp), std::min(a, b));
    SpeedProfile table;
    table.initial_speed_mps = a;
    // A stop and a reversing knot: the slowest moving |v| counts, the standstill does not.
    table.knots = std::make_shared<const std::vector<SpeedKnot>>(
        std::vector<SpeedKnot>{{0.0, a}, {3.0, 0.0}, {5.0, -b}, {9.0, 0.0}});
    EXPECT_DOUBLE_EQ(bound_speed_mps(table), std::min(a, b));
  }
}

TEST(TightCorners, EveryControllerAtOrAboveTheReferenceWhereTheRateBinds) {
  // The hairpin's 6 m clothoid at 15-16 m/s asks about 0.55 rad/s of the car's 0.4: the
  // reference is positive, and the kinetic plant's slip only adds to what the controllers lose.
  testing::Random random(testing::base_seed());
  TightCornerOptions options;
  const double speed = random.uniform(15.0, 16.0);
  SCOPED_TRACE("seed " + std::to_string(testing::base_seed()) + " speed " + std::to_string(speed));
  options.corners = {{testing::source_file("scenarios/hairpin.yaml"), speed},
                     {testing::source_file("scenarios/roads/parking_lot.yaml"), 0.0}};
  options.baselines = {"stanley"};
  const TightCornerResult result = run_tight_corner_study(options);
  ASSERT_EQ(result.cases.size(), 2u);

  const EngagementCase& hairpin = result.cases[0];
  EXPECT_TRUE(hairpin.speed_overridden);
  EXPECT_DOUBLE_EQ(hairpin.speed_mps, speed);
  EXPECT_DOUBLE_EQ(result.bound_speeds_mps[0], speed);
  ASSERT_TRUE(hairpin.bound_converged) << hairpin.bound.note;
  const double reference = hairpin.bound.max_abs_e_m;
  EXPECT_GT(reference, 0.005);
  EXPECT_LE(reference, hairpin.certified.max_abs_e_m);
  EXPECT_LE(reference, hairpin.baselines[0].max_abs_e_m);
  EXPECT_EQ(hairpin.certified.held_above_limits, 0);

  const EngagementCase& parking = result.cases[1];
  EXPECT_FALSE(parking.speed_overridden);
  EXPECT_TRUE(std::isnan(parking.bound.max_abs_e_m));
  EXPECT_NE(parking.bound.note.find("changes gear"), std::string::npos);
  EXPECT_LT(parking.certified.max_abs_e_m, 1.0);

  const ResultsTable summary = result.summary();
  ASSERT_EQ(summary.rows.size(), 2u);
  for (const auto& row : summary.rows) ASSERT_EQ(row.size(), summary.header.size());
  EXPECT_EQ(summary.header[9], "to_reference");
  EXPECT_EQ(summary.rows[1][9], "");  // no ratio to a reference that does not exist
  EXPECT_EQ(result.table().rows.size(), 2u * 4u);
  // The kinetic reference: positive here too, below every controller, none across the gears.
  ASSERT_EQ(result.kinetic_references.size(), 2u);
  EXPECT_FALSE(result.kinetic_references[0].diverged) << result.kinetic_references[0].note;
  EXPECT_GT(result.kinetic_references[0].max_abs_e_m, 0.005);
  EXPECT_LE(result.kinetic_references[0].max_abs_e_m, hairpin.certified.max_abs_e_m);
  EXPECT_LE(result.kinetic_references[0].max_abs_e_m, hairpin.baselines[0].max_abs_e_m);
  EXPECT_TRUE(std::isnan(result.kinetic_references[1].max_abs_e_m));
}

TEST(TightCorners, OptionsNameTheBrokenRule) {
  TightCornerOptions options;
  EXPECT_THROW(options.validate(), std::invalid_argument);  // no corner
  options.corners = {{"x.yaml", -1.0}};
  try {
    options.validate();
    FAIL() << "a negative speed accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("corners.speed_mps = -1"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace smoothsteer
