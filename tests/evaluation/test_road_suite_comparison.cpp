// The road-suite comparison (docs/results/road_suite.md) on a small case: the parking lot (two
// cusps) with one car, both plants, the certified route and pure pursuit; one row per run, the
// summary's totals, and the option checks naming the field.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "smoothsteer/evaluation/road_suite_comparison.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer {
namespace {

RoadSuiteOptions small_case() {
  RoadSuiteOptions options;
  options.road_files = {(testing::source_dir() / "scenarios/roads/parking_lot.yaml").string()};
  options.vehicle_files = {(testing::source_dir() / "vehicles/ford_escort.yaml").string()};
  options.controllers = {"certified", "pure_pursuit"};
  return options;
}

TEST(RoadSuiteComparison, OneRowPerRunAndTotalsPerPlantAndController) {
  const RoadSuiteResult result = run_road_suite_comparison(small_case());
  ASSERT_EQ(result.runs.rows.size(), 4u);
  ASSERT_EQ(result.summary.rows.size(), 4u);
  int best = 0;
  for (const auto& row : result.runs.rows) {
    SCOPED_TRACE(row[3] + " on " + row[2]);
    EXPECT_EQ(row[0], "parking_lot");
    EXPECT_EQ(row[1], "ford_escort");
    EXPECT_EQ(row[9], "path_end");  // every run reaches its end, through both cusps
    const double max_e = std::stod(row[4]);
    EXPECT_GT(max_e, 0.0);
    EXPECT_LT(max_e, 1.0);  // neither runs wide here
    EXPECT_EQ(row[7], "");
    EXPECT_LE(std::stod(row[5]), max_e);
  }
  for (const auto& row : result.summary.rows) {
    EXPECT_EQ(row[2], "1");
    best += std::stoi(row[9]);
  }
  EXPECT_EQ(best, 2);  // one best controller per road x car on each plant
}

TEST(RoadSuiteComparison, OptionsAreValidatedNamingTheField) {
  auto message = [](RoadSuiteOptions options) {
    try {
      options.validate();
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  EXPECT_EQ(message(small_case()), "");
  RoadSuiteOptions bad = small_case();
  bad.models = {"bicycle"};
  EXPECT_NE(message(bad).find("models contains 'bicycle'"), std::string::npos);
  bad = small_case();
  bad.controllers = {"certified", "stanly"};
  EXPECT_NE(message(bad).find("controllers contains 'stanly'"), std::string::npos);
  bad = small_case();
  bad.threads = 0;
  EXPECT_NE(message(bad).find("threads = 0"), std::string::npos);
  bad = small_case();
  bad.road_files.clear();
  EXPECT_NE(message(bad).find("road_files"), std::string::npos);
  bad = small_case();
  bad.vehicle_files.clear();
  EXPECT_NE(message(bad).find("vehicle_files"), std::string::npos);
}

// A broken --vehicles file is named with its own error, not as a missing schedule.
TEST(RoadSuiteComparison, ABrokenVehicleFileIsNamedWithItsError) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "smoothsteer_road_suite_broken_car.yaml";
  std::ofstream(file) << "mass_kg: -5\n";
  RoadSuiteOptions options = small_case();
  options.vehicle_files.push_back(file.string());
  try {
    options.validate();
    FAIL() << "a broken vehicle file was accepted";
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("vehicle_files (--vehicles) " + file.string()), std::string::npos)
        << message;
    EXPECT_NE(message.find("mass_kg"), std::string::npos) << message;
    EXPECT_EQ(message.find("schedule"), std::string::npos) << message;
  }
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace smoothsteer
