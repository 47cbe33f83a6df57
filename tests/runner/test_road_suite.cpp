// The road suite (scenarios/roads/*.yaml) and the hairpin: every file loads, its path is built
// of lines, arcs and clothoids with no curvature jump (C1 with continuous curvature), each
// clothoid's parameter lies in [R/3, R] of its arc (the guideline rule the files follow), the
// speed profile keeps its lateral and longitudinal limits, and the run reaches the path's end.
// Also the validation of the clothoid pieces and of the curvature speed profile's keys.

#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "smoothsteer/sim/gear_changes.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer::runner {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> road_files() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(testing::source_dir() / "scenarios/roads")) {
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  files.push_back(testing::source_dir() / "scenarios/hairpin.yaml");
  return files;
}

TEST(RoadSuite, EveryRoadIsC1WithContinuousCurvatureAndClothoidsWithinTheGuideline) {
  const auto files = road_files();
  ASSERT_GE(files.size(), 6u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const Scenario scenario = load_scenario(file.string());
    int clothoids = 0;
    // A path with gear changes (parking_lot): every piece of its plan.
    const std::size_t pieces = scenario.plan ? scenario.plan->piece_count() : 1;
    for (std::size_t p = 0; p < pieces; ++p) {
      const Path& path = scenario.plan ? *scenario.plan->piece(p).path : *scenario.path;
      EXPECT_TRUE(path.curvature_jumps().empty());
      const auto& segments = path.segments();
      for (std::size_t i = 0; i < segments.size(); ++i) {
        const PathSegment& segment = segments[i];
        if (i > 0) {  // position, heading and curvature continuous across the joint
          const PathPoint before = segments[i - 1].evaluate_at(segments[i - 1].length);
          const PathPoint after = segment.evaluate_at(0.0);
          EXPECT_LT(norm(after.position - before.position), 1e-9) << "joint " << i;
          EXPECT_LT(std::abs(wrap_angle(after.heading_rad - before.heading_rad)), 1e-9);
          EXPECT_LT(std::abs(after.curvature - before.curvature), 1e-12) << "joint " << i;
        }
        if (segment.kind != PathSegment::Kind::clothoid) continue;
        ++clothoids;
        // RAL 2012 / RAA 2008: R / 3 <= A <= R, A^2 = L / |delta kappa|, R the tighter end.
        const double parameter =
            std::sqrt(segment.length / std::abs(segment.end_curvature() - segment.curvature));
        const double radius =
            1.0 / std::max(std::abs(segment.curvature), std::abs(segment.end_curvature()));
        EXPECT_GE(parameter, radius / 3.0 - 1e-9) << "segment " << i;
        EXPECT_LE(parameter, radius + 1e-9) << "segment " << i;
      }
    }
    EXPECT_GE(clothoids, 2);
  }
}

TEST(RoadSuite, SpeedProfilesKeepTheirLimitsAndEveryRoadRunsToItsEnd) {
  for (const fs::path& file : road_files()) {
    SCOPED_TRACE(file.string());
    const Scenario scenario = load_scenario(file.string());
    const nlohmann::json& speed = scenario.parameters.at("speed");
    if (scenario.plan) {  // signed and at rest at each cusp (tests/sim/test_plan_simulation.cpp)
      ASSERT_TRUE(scenario.speed.signed_speeds);
      EXPECT_EQ(scenario.plan->cusp_count(), 2u);
      EXPECT_EQ(gear_changes(scenario.speed).size(), 2u);
      for (const SpeedKnot& knot : *scenario.speed.knots) {
        EXPECT_LE(std::abs(knot.speed_mps), speed.at("max_mps").get<double>());
      }
    } else if (speed.value("profile", "ramp") == "curvature") {
      ASSERT_TRUE(scenario.speed.knots);
      const double v_max = speed.at("max_mps").get<double>();
      const double a_lat = speed.at("max_lateral_acceleration_mps2").get<double>();
      const double a_up = speed.at("max_acceleration_mps2").get<double>();
      const double a_down = speed.at("max_deceleration_mps2").get<double>();
      // Along the path at the profile's own time: s(t) integrated from the knots.
      const auto& knots = *scenario.speed.knots;
      double s = 0.0;
      for (std::size_t i = 0; i < knots.size(); ++i) {
        if (i > 0) {
          const double dt = knots[i].time_s - knots[i - 1].time_s;
          const double a = (knots[i].speed_mps - knots[i - 1].speed_mps) / dt;
          ASSERT_LE(a, a_up * (1 + 1e-9)) << "knot " << i;
          ASSERT_GE(a, -a_down * (1 + 1e-9)) << "knot " << i;
          s += 0.5 * (knots[i].speed_mps + knots[i - 1].speed_mps) * dt;
        }
        const double v = knots[i].speed_mps;
        ASSERT_LE(v, v_max * (1 + 1e-12));
        ASSERT_LE(v * v * std::abs(scenario.path->evaluate(s).curvature), a_lat * (1 + 1e-9))
            << "knot " << i << " s " << s;
      }
      EXPECT_NEAR(s, scenario.path->length(), 1e-6);
    }
    const RunResult result = run_scenario(scenario);
    EXPECT_EQ(result.simulation.status, Status::ok);
    EXPECT_FALSE(result.simulation.non_finite);
    EXPECT_EQ(result.simulation.stop_reason, "path_end");
    if (scenario.plan) {  // ends on the plan's last piece, at rest near its end
      const Pose2 end = result.simulation.trace.back().rear_axle;
      EXPECT_LT(norm(end.position - scenario.plan->final_position()), 0.5);
      EXPECT_NEAR(result.simulation.trace.back().speed_mps, 0.0, 1e-9);
    }
    std::printf("%-24s max |e| rear %.3f m, RMS %.3f m\n", scenario.name.c_str(),
                result.metrics.max_abs_rear_error_m, result.metrics.rms_rear_error_m);
  }
}

class RoadErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::temp_directory_path() / ("smoothsteer_roads_" + std::to_string(::getpid()));
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }
  //! The error of a file with these pieces and speed section ("" if it loaded).
  std::string error_of(const std::string& pieces,
                       const std::string& speed = "{initial_mps: 5}") const {
    const fs::path file = directory_ / "road.yaml";
    std::ofstream(file) << "name: t\npath: {type: segments, pieces: [" << pieces
                        << "]}\nspeed: " << speed << "\ncontroller: {type: lead_wheel}\n";
    try {
      load_scenario(file.string());
    } catch (const io::ConfigError& error) {
      return error.what();
    }
    return "";
  }
  fs::path directory_;
};

void expect_contains(const std::string& message, std::initializer_list<std::string> parts) {
  ASSERT_FALSE(message.empty()) << "expected an error";
  for (const std::string& part : parts) {
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' missing in: " << message;
  }
}

TEST_F(RoadErrors, ClothoidPiecesAreValidatedByKey) {
  EXPECT_EQ(error_of("{line_m: 10}, {clothoid_m: 5, end_curvature_per_m: 0.1}, "
                     "{arc_radius_m: 10, arc_angle_rad: 1}, "
                     "{clothoid_parameter_m: 5, end_curvature_per_m: 0}"),
            "");
  expect_contains(error_of("{clothoid_m: 5}"), {"path.pieces[0].end_curvature_per_m", "required"});
  expect_contains(error_of("{clothoid_m: -5, end_curvature_per_m: 0.1}"),
                  {"path.pieces[0].clothoid_m"});
  expect_contains(error_of("{clothoid_m: 5, clothoid_parameter_m: 3, end_curvature_per_m: 0.1}"),
                  {"path.pieces[0].clothoid_parameter_m", "not both"});
  expect_contains(error_of("{line_m: 3}, {clothoid_m: 5, end_curvature_per_m: 0}"),
                  {"path.pieces[1].end_curvature_per_m", "must differ", "0 1/m"});
  expect_contains(error_of("{clothoid_parameter_m: 100, end_curvature_per_m: 1}"),
                  {"path.pieces[0].clothoid_parameter_m", "two full turns"});
  expect_contains(error_of("{clothoid_m: 5, end_curvature_per_m: 0.1, radius: 3}"),
                  {"path.pieces[0].radius"});
}

TEST_F(RoadErrors, GearKeysAreValidatedByKey) {
  const std::string speed =
      "{profile: curvature, max_mps: 1.5, max_lateral_acceleration_mps2: 1, "
      "max_deceleration_mps2: 0.5}";
  EXPECT_EQ(error_of("{line_m: 10}, {line_m: 6, gear: reverse}, {line_m: 5, gear: forward}", speed),
            "");
  EXPECT_EQ(error_of("{line_m: 10, gear: reverse}", speed), "");  // reversing throughout
  expect_contains(error_of("{line_m: 10}, {line_m: 6, gear: neutral}", speed),
                  {"path.pieces[1].gear", "neutral"});
  expect_contains(error_of("{line_m: 10}, {line_m: 6, gear: reverse}"),
                  {"speed.profile", "gear changes"});
  expect_contains(error_of("{line_m: 10}, {line_m: 6, gear: reverse}",
                           "{profile: curvature, max_mps: 1.5, max_lateral_acceleration_mps2: 1, "
                           "cusp_rest_s: 0}"),
                  {"speed.cusp_rest_s"});
  expect_contains(error_of("{line_m: 10}, {line_m: 6, gear: reverse}",
                           "{profile: curvature, max_mps: 1.5, max_lateral_acceleration_mps2: 1, "
                           "cusp_rest_s: 0.005}"),
                  {"speed.cusp_rest_s", "control period"});
  expect_contains(error_of("{line_m: 10}, {line_m: 0.6, gear: reverse}", speed),
                  {"speed.profile", "pieces[1]"});
}

TEST_F(RoadErrors, CurvatureSpeedProfileKeysAreValidated) {
  const std::string line = "{line_m: 10}";
  EXPECT_EQ(error_of(line, "{profile: curvature, max_mps: 10, max_lateral_acceleration_mps2: 2}"),
            "");
  expect_contains(error_of(line, "{profile: curvature, max_lateral_acceleration_mps2: 2}"),
                  {"speed.max_mps", "required"});
  expect_contains(error_of(line, "{profile: curvature, max_mps: 10}"),
                  {"speed.max_lateral_acceleration_mps2"});
  expect_contains(error_of(line,
                           "{profile: curvature, max_mps: 10, "
                           "max_lateral_acceleration_mps2: 2, max_deceleration_mps2: 0}"),
                  {"speed.max_deceleration_mps2"});
  expect_contains(error_of(line,
                           "{profile: curvature, max_mps: 10, "
                           "max_lateral_acceleration_mps2: 2, final_mps: 3}"),
                  {"speed.final_mps"});
  expect_contains(error_of(line, "{profile: curvy}"), {"speed.profile", "curvy"});
}

}  // namespace
}  // namespace smoothsteer::runner
