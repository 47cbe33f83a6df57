// The shipped kinetic scenarios at the car's own actuator (0.4 rad/s) hold the figures that
// docs/vehicle_dynamics.md section 7 reports, with the passenger car's one controller block
// (derived_compensation: the Smith delay and the catch-up over speed from the car): no held
// sample of the command above the vehicle file's limits, no spin, and the rear axle's error below
// a pinned bound, as the median and the largest over 20 noise seeds. The bounds are the targets
// where the block meets them and the reported figure plus a small margin where it does not
// (lane_change_19, circle_sections), so that a change that makes a figure worse fails here. The
// observer's stiffness and mass off by +-20 % must degrade gracefully, still without spin or a
// held sample above the limits. Every kinetic scenario of the passenger car carries the same
// controller block.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "smoothsteer/io/config_section.hpp"
#include "smoothsteer/runner/controller_registry.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer::runner {
namespace {

using testing::source_dir;

struct ShippedCase {
  std::string file;
  double settle_time_s;        //!< the error is measured from here on (the start offset settles)
  double median_rear_error_m;  //!< pinned bound on the median over the seeds of max |e|
  double max_rear_error_m;     //!< pinned bound on max |e| at every seed
  //! max |e| with the car 20 % off its vehicle file (mass or cornering stiffness of the plant)
  double max_rear_error_model_off_m;
};

// Over noise seeds 1-20 (median, min-max), with the car's disturbance estimate (80 m memory):
// 0.0081 (0.0059-0.0100), 0.0351 (0.0298-0.0404), 0.278 (0.263-0.302) m on the lane changes,
// 0.079 (0.070-0.088) m on circle_sections after 8 s and 0.086 (0.085-0.087) m on the hairpin.
// With the car's mass or cornering stiffness 20 % off its vehicle file (seed 1), the course
// error estimator learning the slip's scale: the lane changes 0.015-0.030 / 0.063-0.078 /
// 0.23-0.49 m, circle_sections 0.073-0.097 m after 8 s, the hairpin 0.019-0.127 m; disturbances_15
// 0.002-0.012 m from 10 s on (the observer alone 20 % off left 7-10 cm there before the course
// error estimator). The bounds are the targets (0.03 m) or those figures plus 5-10 %.
const std::vector<ShippedCase> shipped_cases = {
    {"lane_change_10.yaml", 0.0, 0.03, 0.03, 0.04},
    {"lane_change_15.yaml", 0.0, 0.036, 0.045, 0.09},
    {"lane_change_19.yaml", 0.0, 0.30, 0.33, 0.54},
    {"circle_sections.yaml", 8.0, 0.09, 0.10, 0.11},
    // A 12 m hairpin entered through a 6 m clothoid at 6 m/s^2: the feedforward moves at the
    // car's rate limit (docs/governor.md, eq. governed_feedforward_rate) and the clothoid's
    // joints are planned kinks (docs/feedforward.md, section 2b).
    {"hairpin.yaml", 0.0, 0.095, 0.10, 0.14},
    // A rack misaligned by 0.01 rad and a plant curvature of 0.002 1/m from t = 0 at 15 m/s: the
    // estimate of docs/feedforward.md section 7 leaves 3-4 mm from 10 s on.
    {"disturbances_15.yaml", 10.0, 0.01, 0.01, 0.02},
};

constexpr int noise_seeds = 20;

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

TEST(ShippedKineticScenarios, MeetTheirPinnedFiguresAtTheCarsActuatorOverNoiseSeeds) {
  for (const ShippedCase& shipped : shipped_cases) {
    std::vector<double> errors;
    for (int seed = 1; seed <= noise_seeds; ++seed) {
      SCOPED_TRACE(shipped.file + " at simulation.noise_seed=" + std::to_string(seed));
      const RunFigures figures =
          run_figures(shipped, {"simulation.noise_seed=" + std::to_string(seed)});
      EXPECT_EQ(figures.held_samples_above_limits, 0);
      EXPECT_LT(figures.max_abs_heading_error_rad, spin_heading_error_rad);
      EXPECT_LE(figures.max_rear_error_m, shipped.max_rear_error_m);
      errors.push_back(figures.max_rear_error_m);
    }
    std::sort(errors.begin(), errors.end());
    const double median = 0.5 * (errors[noise_seeds / 2 - 1] + errors[noise_seeds / 2]);
    EXPECT_LE(median, shipped.median_rear_error_m) << shipped.file;
  }
}

// The controller block as written in a scenario file, key by key (in any order), with the
// schedule's path reduced to its file name (the road suite's files sit one folder deeper).
std::map<std::string, std::string> controller_block(const std::string& file) {
  const YAML::Node block =
      io::load_yaml_file((source_dir() / "scenarios" / file).string())["controller"];
  std::map<std::string, std::string> keys;
  for (const auto& entry : block) keys[entry.first.as<std::string>()] = YAML::Dump(entry.second);
  keys["schedule"] = std::filesystem::path(keys["schedule"]).filename().string();
  return keys;
}

TEST(ShippedKineticScenarios, ShareOneControllerBlock) {
  const auto reference = controller_block("lane_change_15.yaml");
  for (const char* file :
       {"lane_change_10.yaml", "lane_change_19.yaml", "circle_sections.yaml", "hairpin.yaml",
        "roads/rural_80.yaml", "roads/motorway_exit.yaml", "roads/roundabout.yaml",
        "roads/urban_turn.yaml", "roads/mountain_hairpins.yaml"}) {
    EXPECT_EQ(controller_block(file), reference) << file;
  }
  // disturbances_15 adds the disturbance estimate, and nothing else.
  auto disturbed = controller_block("disturbances_15.yaml");
  EXPECT_EQ(disturbed.erase("disturbance_estimation_length_m"), 1U);
  EXPECT_EQ(disturbed, reference);
}

TEST(ShippedKineticScenarios, SteeringOffsetAndPlantDisturbanceLeaveNoSteadyOffset) {
  // Either sign, each alone: within 2 cm from 10 s on (each alone 1.4-1.6 cm, the slower cases:
  // the smaller drift leaves the recovery to the certified near law); without the estimate and
  // the steering offset compensation over
  // 0.3 m (0.39 m: the near law, stiff on the straight, and the far law, which takes over from
  // the error, hold some of it themselves).
  const ShippedCase disturbed{"disturbances_15.yaml", 10.0, 0.02, 0.02, 0.0};
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
      run_figures(disturbed, {"controller.disturbance_estimation_length_m=0",
                              "simulation.side_slip.compensate_steering_offset=false"});
  EXPECT_GT(without.max_rear_error_m, 0.3);
}

// The car is not its vehicle file: the plant's mass or tires 20 % off what the observer and the
// feedforward are told (a loaded car, worn or new tires).
TEST(ShippedKineticScenarios, DegradeGracefullyWithTheCarTwentyPercentOffItsFile) {
  const std::vector<std::string> variants = {
      "simulation.plant_scales.cornering_stiffness=0.8",
      "simulation.plant_scales.cornering_stiffness=1.2",
      "simulation.plant_scales.mass=0.8",
      "simulation.plant_scales.mass=1.2",
  };
  for (const ShippedCase& shipped : shipped_cases) {
    for (const std::string& variant : variants) {
      SCOPED_TRACE(shipped.file + " with " + variant);
      const RunFigures figures = run_figures(shipped, {variant});
      EXPECT_EQ(figures.held_samples_above_limits, 0);
      EXPECT_LT(figures.max_abs_heading_error_rad, spin_heading_error_rad);
      EXPECT_LE(figures.max_rear_error_m, shipped.max_rear_error_model_off_m);
    }
  }
}

}  // namespace
}  // namespace smoothsteer::runner
