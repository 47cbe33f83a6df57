// The three CommonRoad cars (vehicles/ford_escort.yaml, bmw_320i.yaml, vw_vanagon.yaml) on both
// kinetic models, and the vehicle files' double_track keys: validated with a message naming the
// key, non-physical values rejected, overrides of one key keeping the group's others.

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>

#include "smoothsteer/io/schedule_files.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer::runner {
namespace {

namespace fs = std::filesystem;

std::string scenario(const std::string& name) {
  return (fs::path(smoothsteer::testing::source_dir()) / "scenarios" / (name + ".yaml")).string();
}

std::string error_of(const std::string& file, const std::vector<std::string>& overrides) {
  try {
    load_scenario(file, overrides);
  } catch (const io::ConfigError& error) {
    return error.what();
  }
  return "";
}

// Each car runs the 10 m/s lane change with the shipped controller on the single-track and the
// double-track plant: finite, on the path within 0.2 m, and the double-track group read.
TEST(DoubleTrackVehicles, PublishedCarsRunOnBothModels) {
  for (const char* car : {"ford_escort", "bmw_320i", "vw_vanagon"}) {
    for (const char* model : {"dynamic", "double_track"}) {
      SCOPED_TRACE(std::string(car) + " on " + model);
      const Scenario s = load_scenario(scenario("lane_change_10"),
                                       {std::string("vehicle.file=../vehicles/") + car + ".yaml",
                                        std::string("model=") + model});
      ASSERT_TRUE(s.vehicle.double_track.has_value());
      EXPECT_EQ(s.parameters["vehicle"]["double_track"]["drive_share_front"].get<double>(),
                std::string(car) == "ford_escort" ? 1.0 : 0.0);
      const RunResult run = run_scenario(s);
      EXPECT_FALSE(run.simulation.non_finite);
      EXPECT_LT(run.metrics.max_abs_rear_error_m, 0.2);
    }
  }
}

TEST(DoubleTrackVehicles, SteeringLimitsArePublishedOnes) {
  const std::vector<std::pair<std::string, double>> limits{
      {"ford_escort", 0.910}, {"bmw_320i", 1.066}, {"vw_vanagon", 1.023}};
  for (const auto& [car, angle] : limits) {
    const Scenario s =
        load_scenario(scenario("lane_change_10"), {"vehicle.file=../vehicles/" + car + ".yaml"});
    EXPECT_DOUBLE_EQ(s.vehicle.max_steering_angle_rad, angle) << car;
    EXPECT_DOUBLE_EQ(s.vehicle.max_steering_rate_radps, 0.4) << car;
  }
}

// `smoothsteer tune` reads the same files (it ignores the simulation-only keys).
TEST(DoubleTrackVehicles, TunerReadsTheCars) {
  for (const char* car : {"passenger_car", "ford_escort", "bmw_320i", "vw_vanagon"}) {
    const VehicleLimits limits = io::load_vehicle_limits(
        (fs::path(smoothsteer::testing::source_dir()) / "vehicles" / (std::string(car) + ".yaml"))
            .string());
    EXPECT_DOUBLE_EQ(limits.max_steering_rate_radps, 0.4) << car;
  }
}

TEST(DoubleTrackVehicles, NonPhysicalValuesAreRejectedByKey) {
  const std::string file = scenario("lane_change_10");
  auto expect = [&](const std::vector<std::string>& overrides, const std::string& part) {
    const std::string message = error_of(file, overrides);
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' missing in: " << message;
  };
  expect({"model=double_track", "vehicle.double_track.roll_inertia_kgm2=-3"},
         "'vehicle.double_track.roll_inertia_kgm2'");
  expect({"model=double_track", "vehicle.double_track.front_track_m=.nan"},
         "'vehicle.double_track.front_track_m'");
  expect({"model=double_track", "vehicle.mass_kg=0"}, "'vehicle.mass_kg'");
  expect({"vehicle.yaw_inertia_kgm2=-1"}, "'vehicle.yaw_inertia_kgm2'");
  expect({"vehicle.double_track.front_roll_stiffness_nmprad=100",
          "vehicle.double_track.rear_roll_stiffness_nmprad=100"},
         "tips over");
  expect({"vehicle.double_track.ackermann_share=2"}, "'vehicle.double_track.ackermann_share'");
  expect({"vehicle.double_track.rolling=1"}, "'vehicle.double_track.rolling'");
  expect({"model=bicycle"}, "'model'");
}

TEST(DoubleTrackVehicles, ModelNeedsTheGroup) {
  const fs::path directory =
      fs::temp_directory_path() / ("smoothsteer_dt_" + std::to_string(::getpid()));
  fs::create_directories(directory);
  const std::string file = (directory / "s.yaml").string();
  std::ofstream(file) << "name: t\nmodel: double_track\npath: {type: straight}\n"
                         "controller: {type: lead_wheel}\n";
  const std::string message = error_of(file, {});
  fs::remove_all(directory);
  EXPECT_NE(message.find("'vehicle.double_track'"), std::string::npos) << message;
  EXPECT_NE(message.find("required by model: double_track"), std::string::npos) << message;
}

// An override of one key of a vehicle file's group keeps the group's other keys.
TEST(DoubleTrackVehicles, OverrideOfOneGroupKeyKeepsTheOthers) {
  const Scenario s =
      load_scenario(scenario("lane_change_10"),
                    {"model=double_track", "vehicle.double_track.friction_load_sensitivity=0",
                     "vehicle.front_tire.friction_mu=0.8"});
  EXPECT_EQ(s.vehicle.double_track->friction_load_sensitivity, 0.0);
  EXPECT_DOUBLE_EQ(s.vehicle.double_track->front_roll_stiffness_nmprad, 25361.0);
  EXPECT_DOUBLE_EQ(s.vehicle.front_tire.friction_mu, 0.8);
  EXPECT_DOUBLE_EQ(s.vehicle.front_tire.curvature_factor_e, -0.0074722);
}

}  // namespace
}  // namespace smoothsteer::runner
