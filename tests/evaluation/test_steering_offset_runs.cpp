// The car's block on the lane changes with the rack misaligned or the angle sensor reading off
// from t = 0, acting on the plant only: the side-slip observer learns the offset and the held
// command makes up for the rack's (steering_offset_compensation.hpp), not for the sensor's.
// Without the compensation the 10 m/s lane change ran 0.12 / 0.27 m with a 0.01 / 0.02 rad rack
// (Stanley, same limiter, 0.07-0.08 / 0.12-0.13 m).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "smoothsteer/evaluation/controller_registration.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "support/property.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer {
namespace {

runner::RunResult run(const std::string& file, std::vector<std::string> overrides) {
  const runner::RunResult result = runner::run_scenario(
      runner::load_scenario(testing::source_file("scenarios/" + file), overrides));
  EXPECT_EQ(result.simulation.status, Status::ok);
  EXPECT_EQ(result.metrics.angle_violations + result.metrics.held_rate_violations +
                result.metrics.held_acceleration_violations,
            0);
  return result;
}

TEST(SteeringOffsetRuns, TheRackIsMadeUpForAndTheSensorIsNot) {
  register_comparison_controllers();  // Stanley, the comparison
  const int cases = testing::property_cases(4);
  for (int index = 0; index < cases; ++index) {
    const auto seed = testing::case_seed(index);
    testing::Random random(seed + 97);
    const double offset = (random.coin() ? 1.0 : -1.0) * random.uniform(0.005, 0.02);
    const bool rack = random.coin();
    const std::string noise = "simulation.noise_seed=" + std::to_string(random.integer(1, 100));
    const std::string key =
        rack ? "simulation.steering_offset_rad=" : "simulation.steering_angle_sensor_offset_rad=";
    const std::string imperfection = key + std::to_string(offset);
    SCOPED_TRACE(testing::seed_message(seed) + " " + imperfection + " " + noise);
    const double nominal = run("lane_change_10.yaml", {noise}).metrics.max_abs_rear_error_m;
    const double disturbed =
        run("lane_change_10.yaml", {noise, imperfection}).metrics.max_abs_rear_error_m;
    if (rack) {
      // Measured: 0.013-0.015 m at 0.005 rad, 0.021 m at 0.01 rad, 0.057 m at 0.02 rad.
      EXPECT_LE(disturbed, nominal + 3.0 * std::abs(offset));
      const double stanley =
          run("lane_change_10.yaml", {noise, imperfection, "controller={type: stanley}"})
              .metrics.max_abs_rear_error_m;
      EXPECT_LE(disturbed, stanley);
      // And without the compensation it is worse: the check can fail.
      const double without =
          run("lane_change_10.yaml",
              {noise, imperfection, "simulation.side_slip.compensate_steering_offset=false"})
              .metrics.max_abs_rear_error_m;
      EXPECT_LT(disturbed, without);
    } else {
      // The sensor's offset is not made up for: the nominal figure (0.008 m), within 5 mm.
      EXPECT_LE(disturbed, nominal + 0.005);
    }
  }
}

}  // namespace
}  // namespace smoothsteer
