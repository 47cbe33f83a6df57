// The scenario keys of the plant-only model error and the imperfect sensors (docs/scenarios.md):
// --set reaches them, bad values are refused naming the file, the key and the rule, and the
// plant's vehicle is the truth while the controller keeps the scenario's vehicle.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "smoothsteer/runner/scenario.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer::runner {
namespace {

using testing::source_file;

const std::string lane_change = source_file("scenarios/lane_change_15.yaml");

std::string refusal(const std::string& file, const std::vector<std::string>& overrides) {
  try {
    load_scenario(file, overrides);
  } catch (const io::ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(PlantImperfectionKeys, SetOverridesReachEveryKey) {
  const Scenario s = load_scenario(
      lane_change,
      {"simulation.crossfall=0.02", "simulation.plant_scales.mass=1.3",
       "simulation.plant_scales.cg_position=-0.05",
       "simulation.plant_actuator_scales.dead_time=1.5",
       "simulation.plant_actuator_scales.bandwidth=0.5", "simulation.pose_latency_s=0.06",
       "simulation.pose_rate_hz=10", "simulation.steering_angle_sensor_offset_rad=0.01",
       "simulation.gyro_bias_radps=0.005", "simulation.side_force={force_n: 300, start_s: 2}"});
  const SimulationParameters& p = s.simulation;
  EXPECT_EQ(p.crossfall, 0.02);
  EXPECT_EQ(p.plant_scales.mass, 1.3);
  EXPECT_EQ(p.plant_scales.cg_position, -0.05);
  EXPECT_EQ(p.plant_actuator_scales.dead_time, 1.5);
  EXPECT_EQ(p.plant_actuator_scales.bandwidth, 0.5);
  EXPECT_EQ(p.pose_latency_s, 0.06);
  ASSERT_TRUE(p.pose_rate_hz.has_value());
  EXPECT_EQ(*p.pose_rate_hz, 10.0);
  EXPECT_EQ(p.steering_angle_sensor_offset_rad, 0.01);
  EXPECT_EQ(p.gyro_bias_radps, 0.005);
  EXPECT_EQ(p.side_force.force_n, 300.0);
  EXPECT_EQ(p.side_force.yaw_moment_nm, 0.0);
  EXPECT_EQ(p.side_force.start_s, 2.0);
  // The controller is told the scenario's vehicle and actuator, and the summary says what the
  // plant had.
  const Scenario nominal = load_scenario(lane_change);
  EXPECT_EQ(s.vehicle.mass_kg, nominal.vehicle.mass_kg);
  EXPECT_EQ(s.actuator.dead_time_s, nominal.actuator.dead_time_s);
  EXPECT_EQ(s.actuator.bandwidth_hz, nominal.actuator.bandwidth_hz);
  EXPECT_EQ(s.parameters["simulation"]["plant_scales"]["mass"], 1.3);
  EXPECT_EQ(nominal.parameters["simulation"]["crossfall"], 0.0);
  EXPECT_FALSE(nominal.simulation.pose_rate_hz.has_value());
}

TEST(PlantImperfectionKeys, BadValuesAreRefusedNamingFileKeyAndRule) {
  struct Bad {
    std::string override_;
    std::string key;
    std::string rule;
  };
  const Bad cases[] = {
      {"simulation.crossfall=0.2", "'simulation.crossfall'", "[-0.1, 0.1]"},
      {"simulation.plant_scales.mass=3", "'simulation.plant_scales.mass'", "[0.5, 2]"},
      {"simulation.plant_scales.friction=0", "'simulation.plant_scales.friction'", "[0.1, 1.5]"},
      {"simulation.plant_scales.stiffness=1", "'simulation.plant_scales.stiffness'", "unknown"},
      {"simulation.plant_actuator_scales.dead_time=1.6",
       "'simulation.plant_actuator_scales.dead_time'", "[0.5, 1.5]"},
      {"simulation.pose_latency_s=0.6", "'simulation.pose_latency_s'", "[0, 0.5]"},
      {"simulation.pose_rate_hz=100", "pose_rate_hz = 100", "1 / control_period_s"},
      {"simulation.steering_angle_sensor_offset_rad=.nan",
       "'simulation.steering_angle_sensor_offset_rad'", "expected a number"},
      {"simulation.gyro_bias_radps=1", "'simulation.gyro_bias_radps'", "[-0.5, 0.5]"},
      {"simulation.side_force.force_n=1e6", "'simulation.side_force.force_n'", "[-100000, 100000]"},
      {"simulation.side_force=3", "'simulation.side_force'", "mapping"},
  };
  for (const Bad& bad : cases) {
    const std::string error = refusal(lane_change, {bad.override_});
    EXPECT_NE(error.find(lane_change), std::string::npos) << bad.override_ << ": " << error;
    EXPECT_NE(error.find(bad.key), std::string::npos) << bad.override_ << ": " << error;
    EXPECT_NE(error.find(bad.rule), std::string::npos) << bad.override_ << ": " << error;
  }
}

TEST(PlantImperfectionKeys, TheKinematicPlantRefusesWhatActsThroughTires) {
  const std::string reaching = source_file("scenarios/reaching_0.yaml");
  ASSERT_EQ(load_scenario(reaching).model, "kinematic");
  for (const char* key : {"crossfall=0.01", "side_force.force_n=100", "plant_scales.mass=1.2"}) {
    const std::string error = refusal(reaching, {std::string("simulation.") + key});
    const std::string name = std::string(key).substr(0, std::string(key).find_first_of(".="));
    EXPECT_NE(error.find("'simulation." + name + "'"), std::string::npos) << error;
    EXPECT_NE(error.find("kinematic plant"), std::string::npos) << error;
  }
  // The sensor imperfections need no tires.
  EXPECT_NO_THROW(load_scenario(reaching, {"simulation.pose_latency_s=0.1"}));
}

TEST(PlantImperfectionKeys, TheCgShiftMayNotPassAnAxle) {
  // The passenger car's lf / L is 0.45: a shift of 0.25 L keeps both axles' distances > 0, so the
  // key's range admits it; a bigger car-specific limit is the vehicle's rule.
  EXPECT_NO_THROW(load_scenario(lane_change, {"simulation.plant_scales.cg_position=0.25"}));
  const std::string error =
      refusal(lane_change, {"simulation.plant_scales.cg_position=0.25",
                            "vehicle.cg_to_front_axle_m=0.5", "vehicle.cg_to_rear_axle_m=2.0"});
  EXPECT_NE(error.find("'simulation.plant_scales'"), std::string::npos) << error;
  EXPECT_NE(error.find("cg_position = 0.25"), std::string::npos) << error;
}

TEST(PlantVehicle, IsTheTruthWhileTheControllerKeepsTheScenariosVehicle) {
  const Scenario nominal = load_scenario(lane_change);
  // The same file as the truth: the same run, bit for bit (one wiring).
  const Scenario same = load_scenario(
      lane_change, {"simulation.plant_vehicle={file: ../vehicles/passenger_car.yaml}"});
  ASSERT_TRUE(same.plant_vehicle.has_value());
  const RunResult a = run_scenario(nominal);
  const RunResult b = run_scenario(same);
  ASSERT_EQ(a.simulation.trace.size(), b.simulation.trace.size());
  for (std::size_t k = 0; k < a.simulation.trace.size(); ++k) {
    ASSERT_EQ(a.simulation.trace[k].lateral_error_m, b.simulation.trace[k].lateral_error_m) << k;
  }
  // A heavier truth with its own tires (overlaid keys as in vehicle:): the plant differs, the
  // controller does not.
  const Scenario heavier =
      load_scenario(lane_change, {"simulation.plant_vehicle={file: ../vehicles/passenger_car.yaml, "
                                  "mass_kg: 1400, front_tire: {stiffness_factor_b: 12}}"});
  EXPECT_EQ(heavier.vehicle.mass_kg, nominal.vehicle.mass_kg);
  EXPECT_EQ(heavier.plant_vehicle->mass_kg, 1400.0);
  EXPECT_EQ(heavier.plant_vehicle->front_tire.stiffness_factor_b, 12.0);
  EXPECT_EQ(heavier.plant_vehicle->rear_tire.stiffness_factor_b, 15.47);
  EXPECT_EQ(make_vehicle_model(heavier)->parameters().mass_kg, 1400.0);
  EXPECT_EQ(heavier.parameters["simulation"]["plant_vehicle"]["mass_kg"], 1400.0);
  const RunResult c = run_scenario(heavier);
  EXPECT_NE(c.metrics.max_abs_rear_error_m, a.metrics.max_abs_rear_error_m);
  // A bad key of the truth names its own path.
  const std::string error =
      refusal(lane_change, {"simulation.plant_vehicle={file: ../vehicles/passenger_car.yaml, "
                            "mass_kg: -1}"});
  EXPECT_NE(error.find("'simulation.plant_vehicle.mass_kg'"), std::string::npos) << error;
  const std::string missing =
      refusal(lane_change, {"simulation.plant_vehicle={file: no_such_car.yaml}"});
  EXPECT_NE(missing.find("'simulation.plant_vehicle.file'"), std::string::npos) << missing;
}

}  // namespace
}  // namespace smoothsteer::runner
