// The shipped kinetic scenarios at the car's own actuator (0.4 rad/s) hold the figures that
// docs/vehicle_dynamics.md section 7 reports: no held sample of the command above the vehicle
// file's limits, no spin, and the rear axle's error below a pinned bound. The bounds are the
// issue's targets where the file meets them and the reported figure plus a small margin where it
// does not yet (lane_change_15, circle_sections), so that a change that makes a figure worse
// fails here. The observer's stiffness and mass off by +-20 % must degrade gracefully: within a
// pinned bound at most about twice the nominal one, still without spin or a held sample above
// the limits.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "smoothsteer/runner/controller_registry.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer::runner {
namespace {

using testing::source_dir;

struct ShippedCase {
  std::string file;
  double settle_time_s;     //!< the error is measured from here on (the start offset settles)
  double max_rear_error_m;  //!< pinned bound on the rear axle's |e|
  double max_rear_error_observer_off_m;  //!< the same with the observer's parameters off 20 %
};

// At each file's own noise seed (over other seeds the figures spread by a few per cent,
// docs/vehicle_dynamics.md section 7), with the steering governor of docs/governor.md as the files
// ship it: 0.025 / 0.030 / 0.264 m on the lane changes and 0.122 m on circle_sections after 8 s
// (0.024 / 0.031 / 0.233 / 0.097 m without it). With the observer off by 20 %: 0.032-0.044 /
// 0.053-0.074 / 0.237-0.406 / 0.145-0.169 m (without the governor 0.031-0.043 / 0.056-0.074 /
// 0.266-0.281 / 0.147-0.171 m). The bounds are those figures plus 5-10 %.
const std::vector<ShippedCase> shipped_cases = {
    {"lane_change_10.yaml", 0.0, 0.03, 0.05},
    {"lane_change_15.yaml", 0.0, 0.033, 0.08},
    {"lane_change_19.yaml", 0.0, 0.28, 0.43},
    {"circle_sections.yaml", 8.0, 0.13, 0.19},
    // A rack misaligned by 0.01 rad and a plant curvature of 0.002 1/m from t = 0 at 15 m/s: the
    // estimate of docs/feedforward.md section 7 leaves 1.6-3.7 mm from 10 s on over noise seeds
    // 1-5. With the observer's model off by 20 % its biased side slip leaves 8-10 cm.
    {"disturbances_15.yaml", 10.0, 0.01, 0.12},
};

struct RunFigures {
  double max_rear_error_m = 0.0;
  double max_abs_heading_error_rad = 0.0;
  int held_samples_above_limits = 0;
};

RunFigures run_figures(const ShippedCase& shipped, const std::vector<std::string>& overrides) {
  const Scenario scenario =
      load_scenario((source_dir() / "scenarios" / shipped.file).string(), overrides);
  const RunResult result = run_scenario(scenario);
  EXPECT_EQ(result.simulation.status, Status::ok);
  EXPECT_EQ(result.metrics.non_finite_values, 0);
  RunFigures figures;
  for (const auto& sample : result.simulation.trace) {
    figures.max_abs_heading_error_rad =
        std::max(figures.max_abs_heading_error_rad, std::abs(sample.heading_error_rad));
    if (sample.time_s >= shipped.settle_time_s) {
      figures.max_rear_error_m =
          std::max(figures.max_rear_error_m, std::abs(sample.lateral_error_m));
    }
  }
  figures.held_samples_above_limits = result.metrics.held_rate_violations +
                                      result.metrics.held_acceleration_violations +
                                      result.metrics.angle_violations;
  // The scenario's limits are the vehicle file's: the 0.4 rad/s actuator, not a faster demo one.
  EXPECT_NEAR(scenario.metrics.steering_rate_limit_radps, 0.4, 1e-12);
  return figures;
}

// A spin shows as a heading error far beyond any tracking transient.
constexpr double spin_heading_error_rad = 1.0;

TEST(ShippedKineticScenarios, MeetTheirPinnedFiguresAtTheCarsActuator) {
  for (const ShippedCase& shipped : shipped_cases) {
    SCOPED_TRACE(shipped.file);
    const RunFigures figures = run_figures(shipped, {});
    EXPECT_EQ(figures.held_samples_above_limits, 0);
    EXPECT_LT(figures.max_abs_heading_error_rad, spin_heading_error_rad);
    EXPECT_LE(figures.max_rear_error_m, shipped.max_rear_error_m);
  }
}

TEST(ShippedKineticScenarios, SteeringOffsetAndPlantDisturbanceLeaveNoSteadyOffset) {
  // Either sign, each alone: within 2 cm from 10 s on (the rack alone 1.8-1.9 cm over noise
  // seeds, the slower case: its smaller drift leaves the recovery to the certified near law);
  // without the estimate 2.6 m.
  const ShippedCase disturbed{"disturbances_15.yaml", 10.0, 0.02, 0.0};
  const std::vector<std::vector<std::string>> variants = {
      {"simulation.steering_offset_rad=-0.01", "simulation.plant_curvature_disturbance=-0.002"},
      {"simulation.plant_curvature_disturbance=0"},
      {"simulation.steering_offset_rad=0"},
  };
  for (const auto& variant : variants) {
    SCOPED_TRACE(variant.front());
    const RunFigures figures = run_figures(disturbed, variant);
    EXPECT_EQ(figures.held_samples_above_limits, 0);
    EXPECT_LE(figures.max_rear_error_m, disturbed.max_rear_error_m);
  }
  const RunFigures without =
      run_figures(disturbed, {"controller.disturbance_estimation_length_m=0"});
  EXPECT_GT(without.max_rear_error_m, 1.0);
}

TEST(ShippedKineticScenarios, DegradeGracefullyWithTheObserverOffByTwentyPercent) {
  const std::vector<std::string> variants = {
      "simulation.side_slip.cornering_stiffness_scale=0.8",
      "simulation.side_slip.cornering_stiffness_scale=1.2",
      "simulation.side_slip.mass_scale=0.8",
      "simulation.side_slip.mass_scale=1.2",
  };
  for (const ShippedCase& shipped : shipped_cases) {
    for (const std::string& variant : variants) {
      SCOPED_TRACE(shipped.file + " with " + variant);
      const RunFigures figures = run_figures(shipped, {variant});
      EXPECT_EQ(figures.held_samples_above_limits, 0);
      EXPECT_LT(figures.max_abs_heading_error_rad, spin_heading_error_rad);
      EXPECT_LE(figures.max_rear_error_m, shipped.max_rear_error_observer_off_m);
    }
  }
}

}  // namespace
}  // namespace smoothsteer::runner
