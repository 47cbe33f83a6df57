// The car's block rejects a steady disturbance of its documented class (docs/feedforward.md,
// section 7) without being told of it: a rack offset up to 0.01 rad, a plant curvature up to
// 0.001 1/m or a crossfall up to 3 %, either sign, acting on the plant only from t = 0 on a
// straight road at 8-19 m/s. From 15 s on the rear axle stays within 2 cm, the held command
// within the car's limits and the estimate within the feedforward's bound. Without the estimate
// and the steering offset compensation (steering_offset_compensation.hpp) at least a third of the
// same cases stand off by more than 2 cm (up to 0.8 m: the near law, stiff on the straight, holds
// part of the disturbance itself).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "smoothsteer/runner/scenario.hpp"
#include "support/property.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer::runner {
namespace {

struct Outcome {
  double settled_error_m = 0.0;  //!< max |e| from 15 s on
  double largest_estimate = 0.0;
  long above_limits = 0;
};

Outcome run(const std::vector<std::string>& overrides) {
  const Scenario scenario =
      load_scenario((testing::source_dir() / "scenarios/lane_change_15.yaml").string(), overrides);
  const RunResult result = run_scenario(scenario);
  EXPECT_EQ(result.simulation.status, Status::ok);
  Outcome outcome;
  for (const TraceSample& sample : result.simulation.trace) {
    if (sample.time_s >= 15.0) {
      outcome.settled_error_m = std::max(outcome.settled_error_m, std::abs(sample.lateral_error_m));
    }
    outcome.largest_estimate =
        std::max(outcome.largest_estimate, std::abs(sample.disturbance_curvature));
  }
  outcome.above_limits = static_cast<long>(result.metrics.angle_violations) +
                         result.metrics.held_rate_violations +
                         result.metrics.held_acceleration_violations;
  return outcome;
}

TEST(DisturbanceRejection, TheCarsBlockRemovesASteadyDisturbanceOfItsClass) {
  const int cases = testing::property_cases(6);
  int stood_off = 0;
  for (int index = 0; index < cases; ++index) {
    const auto seed = testing::case_seed(index);
    testing::Random random(seed + 53);
    const double speed = random.uniform(8.0, 19.0);
    const double sign = random.coin() ? 1.0 : -1.0;
    std::string disturbance;
    switch (random.integer(0, 2)) {
      case 0:
        disturbance =
            "simulation.steering_offset_rad=" + std::to_string(sign * random.uniform(0.002, 0.01));
        break;
      case 1:
        disturbance = "simulation.plant_curvature_disturbance=" +
                      std::to_string(sign * random.uniform(2e-4, 1e-3));
        break;
      default:
        disturbance = "simulation.crossfall=" + std::to_string(sign * random.uniform(0.01, 0.03));
    }
    SCOPED_TRACE(testing::seed_message(seed) + " v=" + std::to_string(speed) + " " + disturbance);
    const std::vector<std::string> overrides{
        "path={type: straight, start: [-40.0, 0.0], heading_rad: 0.0, length_m: 800.0}",
        "speed.initial_mps=" + std::to_string(speed), "simulation.duration_s=30",
        "simulation.noise_seed=" + std::to_string(index + 1), disturbance};
    const Outcome outcome = run(overrides);
    EXPECT_LE(outcome.settled_error_m, 0.02);
    EXPECT_EQ(outcome.above_limits, 0);
    // |kappa_d| <= 0.01 rad / 2.578 m + 0.001 1/m plus the settling: far inside kbar_ff.
    EXPECT_LE(outcome.largest_estimate, 0.008);
    std::vector<std::string> without = overrides;
    without.push_back("controller.disturbance_estimation_length_m=0");
    without.push_back("simulation.side_slip.compensate_steering_offset=false");
    if (run(without).settled_error_m > 0.02) ++stood_off;
  }
  // The check can fail: without the estimate many of these cases stand beside the path (the
  // crossfall's are the exception: the tires take it, docs/simulation.md).
  EXPECT_GE(stood_off, cases / 3);
}

// A cold start: the rack misaligned by up to 0.3 deg from t = 0, which the estimate has not
// learned yet, on a straight road at 8-12 m/s. The near law is stiff on steady stretches
// (near_law_layer.hpp), so the transient stays within a few centimetres (measured at most
// 0.055 m at 12 m/s; with the certified layer throughout, 0.15 m at 10 m/s). Above 15 m/s the
// certified authority kbar_sw is about the disturbance itself and the peak grows (0.10 m at
// 15 m/s, 0.22 m at 19 m/s, docs/governor.md).
TEST(DisturbanceRejection, AColdStartRackOffsetStaysWithinCentimetres) {
  const int cases = testing::property_cases(6);
  for (int index = 0; index < cases; ++index) {
    const auto seed = testing::case_seed(index);
    testing::Random random(seed + 71);
    const double speed = random.uniform(8.0, 12.0);
    const double offset = (random.coin() ? 1.0 : -1.0) * random.uniform(0.002, 0.005);
    SCOPED_TRACE(testing::seed_message(seed) + " v=" + std::to_string(speed) +
                 " offset=" + std::to_string(offset));
    const Scenario scenario = load_scenario(
        (testing::source_dir() / "scenarios/lane_change_15.yaml").string(),
        {"path={type: straight, start: [-40.0, 0.0], heading_rad: 0.0, length_m: 400.0}",
         "speed.initial_mps=" + std::to_string(speed), "simulation.duration_s=12",
         "simulation.noise_seed=" + std::to_string(index + 1),
         "simulation.steering_offset_rad=" + std::to_string(offset)});
    const RunResult result = run_scenario(scenario);
    ASSERT_EQ(result.simulation.status, Status::ok);
    EXPECT_LE(result.metrics.max_abs_rear_error_m, 0.07);
    EXPECT_EQ(result.metrics.held_rate_violations + result.metrics.held_acceleration_violations +
                  result.metrics.angle_violations,
              0);
  }
}

}  // namespace
}  // namespace smoothsteer::runner
