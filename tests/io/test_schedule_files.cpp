// The schedule CSV reader (docs/tuning.md): every cell is checked before use, and an error names
// the file, the line and the column or parameter.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "smoothsteer/io/schedule_files.hpp"

namespace smoothsteer {
namespace {

namespace fs = std::filesystem;

const char* kHeader =
    "speed_mps,region,fictive_wheelbase_m,lead_wheelbase_m,lead_curvature_bound_per_m,"
    "lead_radius_m,k_rob,max_steering_angle_rad,max_steering_rate_radps,"
    "max_steering_acceleration_radps2,feedforward_curvature_bound_per_m,"
    "feedforward_curvature_rate_per_m2\n";
const char* kRow1 = "1,5,2.57,0.1,0.1,10,0.3,0.25,0.4,4,0.02,0.01\n";
const char* kRow3 = "3,5,2.57,0.1,0.05,20,0.3,0.13,0.4,7,0.02,0.01\n";

//! The reader's error message for a schedule whose middle row is `row`.
std::string error_for(const std::string& row) {
  const fs::path file = fs::temp_directory_path() / "smoothsteer_schedule_test.csv";
  std::ofstream(file) << kHeader << kRow1 << row << kRow3;
  try {
    io::read_schedule_csv(file.string(), ControllerParameters{});
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(ScheduleFiles, RejectBadCellsNamingLineAndColumn) {
  EXPECT_EQ(error_for("2,5,2.57,0.1,0.08,12.5,0.3,0.2,0.4,5,0.02,0.01\n"), "");
  const std::string region = error_for("2,1e300,2.57,0.1,0.08,12.5,0.3,0.2,0.4,5,0.02,0.01\n");
  EXPECT_NE(region.find("line 3: column region"), std::string::npos) << region;
  const std::string garbage = error_for("2,5,2.57,0.1,0.08garbage,12.5,0.3,0.2,0.4,5,0.02,0.01\n");
  EXPECT_NE(garbage.find("line 3: column lead_curvature_bound_per_m"), std::string::npos)
      << garbage;
  const std::string k_rob = error_for("2,5,2.57,0.1,0.08,12.5,5,0.2,0.4,5,0.02,0.01\n");
  EXPECT_NE(k_rob.find("line 3"), std::string::npos) << k_rob;
  EXPECT_NE(k_rob.find("k_rob"), std::string::npos) << k_rob;
  const std::string speed = error_for("inf,5,2.57,0.1,0.08,12.5,0.3,0.2,0.4,5,0.02,0.01\n");
  EXPECT_NE(speed.find("line 3: column speed_mps"), std::string::npos) << speed;
  const std::string bound = error_for("2,5,2.57,0.1,-0.08,12.5,0.3,0.2,0.4,5,0.02,0.01\n");
  EXPECT_NE(bound.find("line 3"), std::string::npos) << bound;
  const std::string extra = error_for("2,5,2.57,0.1,0.08,12.5,0.3,0.2,0.4,5,0.02,0.01,7\n");
  EXPECT_NE(extra.find("more than 12 columns"), std::string::npos) << extra;
}

}  // namespace
}  // namespace smoothsteer
