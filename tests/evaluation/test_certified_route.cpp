// The certified route of the study (certified_route.hpp) is the route of `smoothsteer tune`:
// with the knobs of a committed schedule's command it gives that schedule, and every command
// of the resulting controller stays within the car's limits (tracking is not certified: at
// feedforward_rate_share 0.2 the 15 m/s lane change diverges, docs/baselines.md).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "smoothsteer/evaluation/certified_route.hpp"
#include "smoothsteer/evaluation/tuning_rule.hpp"
#include "smoothsteer/io/schedule_files.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer {
namespace {

using testing::source_file;

TEST(CertifiedRoute, ReproducesTheCommittedCircleSectionsSchedule) {
  // tune --speeds 0.5:13:0.5 --max-longitudinal-acceleration 0.5 --feedforward-rate-share 0.5
  // --path scenarios/circle_sections.yaml --feedforward-headroom 1.8 (the file itself now runs
  // the car's one schedule, passenger_car_lane_change.csv).
  const runner::Scenario scenario =
      runner::load_scenario(source_file("scenarios/circle_sections.yaml"),
                            {"controller.schedule=schedules/passenger_car_circle_sections.csv"});
  const TuningOptions options =
      certified_route_options(scenario, {{"feedforward_rate_share", 0.5}});
  const GainSchedule computed = compute_feedforward_schedule(vehicle_limits_of(scenario), options,
                                                             certified_speed_grid(scenario));
  const GainSchedule committed = io::read_schedule_csv(
      source_file("scenarios/schedules/passenger_car_circle_sections.csv"), options.base);
  ASSERT_EQ(computed.entries().size(), committed.entries().size())
      << "the speed grid differs from the committed command's 0.5:13:0.5";
  for (std::size_t k = 0; k < computed.entries().size(); ++k) {
    const ScheduleEntry& a = computed.entries()[k];
    const ScheduleEntry& b = committed.entries()[k];
    EXPECT_NEAR(a.speed_mps, b.speed_mps, 1e-9);
    EXPECT_NEAR(a.lead_curvature_bound, b.lead_curvature_bound, 1e-9 * b.lead_curvature_bound)
        << "speed " << a.speed_mps;
    EXPECT_NEAR(a.lead_wheelbase_m, b.lead_wheelbase_m, 1e-9) << "speed " << a.speed_mps;
    EXPECT_NEAR(a.feedforward_curvature_rate, b.feedforward_curvature_rate,
                1e-9 * b.feedforward_curvature_rate)
        << "speed " << a.speed_mps;
  }
}

TEST(CertifiedRoute, RejectsAnUnknownKnobAndAScenarioWithoutSchedule) {
  const runner::Scenario scenario =
      runner::load_scenario(source_file("scenarios/lane_change_15.yaml"));
  try {
    certified_route_options(scenario, {{"gain_per_s", 1.0}});
    FAIL() << "unknown knob accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("'gain_per_s'"), std::string::npos) << error.what();
  }
  const runner::Scenario fixed = runner::load_scenario(source_file("scenarios/lane_change_15.yaml"),
                                                       {"controller={type: lead_wheel}"});
  EXPECT_THROW(make_certified_controller(fixed), std::invalid_argument);
}

TEST(CertifiedRoute, EveryKnobCornerStaysWithinTheCarsLimitsOnTheLaneChange) {
  const runner::Scenario scenario = runner::load_scenario(
      source_file("scenarios/lane_change_15.yaml"), {"simulation.duration_s=12"});
  for (const GainAxis& share : std::vector<GainAxis>{gain_axes(certified_controller_name)[0]}) {
    for (const double value : {share.low, share.high}) {
      const ScenarioScore score =
          score_configuration(scenario, certified_controller_name, {{share.key, value}}, 5.0);
      EXPECT_FALSE(score.infeasible) << share.key << " = " << value;
      EXPECT_EQ(score.held_above_limits(), 0) << share.key << " = " << value;
      EXPECT_EQ(score.clamped_updates, 0) << share.key << " = " << value;
    }
  }
}

}  // namespace
}  // namespace smoothsteer
