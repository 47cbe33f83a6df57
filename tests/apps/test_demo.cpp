// The demo (scripts/demo.sh, apps/demo.cpp): the car's SteeringSystem on the kinetic model prints
// each of the car's three steering limits beside the held command's maximum, every maximum at or
// below its limit, and scripts/plot_trace.py draws the PNG beside the CSV.

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <regex>
#include <string>

#include "apps/cli_process.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer::testing {
namespace {

namespace fs = std::filesystem;

#ifndef SMOOTHSTEER_DEMO
#define SMOOTHSTEER_DEMO ""
#endif

TEST(Demo, HeldCommandWithinTheCarsLimitsAndAPicture) {
  if (std::string(SMOOTHSTEER_DEMO).empty()) GTEST_SKIP() << "apps not built";
  const fs::path directory =
      fs::temp_directory_path() / ("smoothsteer_demo_" + std::to_string(::getpid()));
  fs::remove_all(directory);
  fs::create_directories(directory);
  const ProcessResult demo = run_process({SMOOTHSTEER_DEMO, "demo_trace.csv"}, directory);
  ASSERT_EQ(demo.exit_code, 0) << demo.out << demo.err;

  // "  steering rate              : max 0.2100 rad/s    limit 0.4000 rad/s"
  const std::regex line(
      R"(steering (angle|rate|acceleration) +: max ([0-9.]+) (\S+) +limit ([0-9.]+) (\S+))");
  int checked = 0;
  for (auto it = std::sregex_iterator(demo.out.begin(), demo.out.end(), line);
       it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    EXPECT_EQ(m[3], m[5]) << m[0];  // the same unit
    EXPECT_LE(std::stod(m[2]), std::stod(m[4])) << m[0];
    ++checked;
  }
  EXPECT_EQ(checked, 3) << demo.out;  // angle, rate and acceleration, each with its limit

  const ProcessResult plot =
      run_process({"/usr/bin/python3", (source_dir() / "scripts/plot_trace.py").string(),
                   "demo_trace.csv", "demo_trace.png"},
                  directory);
  ASSERT_EQ(plot.exit_code, 0) << plot.out << plot.err;
  const std::string png = read_text(directory / "demo_trace.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  fs::remove_all(directory);
}

}  // namespace
}  // namespace smoothsteer::testing
