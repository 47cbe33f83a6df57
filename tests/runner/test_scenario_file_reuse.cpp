// load_scenario_reusing_files() (a campaign's loads of one base) gives load_scenario()'s
// scenario and load_scenario()'s error messages, and sees a file that changed.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>

#include "../../src/runner/built_paths.hpp"
#include "../../src/runner/parsed_yaml_files.hpp"
#include "../../src/runner/path_demands.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "support/scratch_directory.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer::runner {
namespace {

namespace fs = std::filesystem;
using testing::source_dir;
using testing::source_file;

// The reason a failed load is repeated from the file: the parser's tree knows each key's line,
// a copy (the cache hands out copies) puts every key on line 1, and the messages quote the line.
TEST(ScenarioFileReuse, ACopyOfAParsedTreeLosesTheLines) {
  const YAML::Node parsed = YAML::Load("speed:\n  initial_mps: 500\n");
  const YAML::Node copy = YAML::Clone(parsed);
  EXPECT_EQ(parsed["speed"]["initial_mps"].Mark().line, 1);
  EXPECT_NE(copy["speed"]["initial_mps"].Mark().line, 1);
  EXPECT_EQ(copy["speed"]["initial_mps"].Scalar(), "500");
}

std::vector<fs::path> shipped_scenarios() {
  std::vector<fs::path> files;
  for (const char* folder : {"scenarios", "scenarios/roads"}) {
    for (const auto& entry : fs::directory_iterator(source_dir() / folder)) {
      if (entry.path().extension() == ".yaml") files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

void expect_same(const Scenario& expected, const Scenario& actual) {
  EXPECT_EQ(expected.parameters.dump(), actual.parameters.dump());
  EXPECT_EQ(YAML::Dump(expected.controller), YAML::Dump(actual.controller));
  EXPECT_EQ(expected.name, actual.name);
  EXPECT_EQ(expected.vehicle_name, actual.vehicle_name);
  EXPECT_EQ(expected.vehicle.wheelbase_m(), actual.vehicle.wheelbase_m());
  EXPECT_EQ(expected.plant_vehicle.has_value(), actual.plant_vehicle.has_value());
  ASSERT_EQ(expected.path->length(), actual.path->length());
  for (double s = 0.0; s <= expected.path->length(); s += expected.path->length() / 64.0) {
    EXPECT_EQ(expected.path->evaluate(s).curvature, actual.path->evaluate(s).curvature);
  }
}

TEST(ScenarioFileReuse, EveryShippedScenarioLoadsAsLoadScenarioLoadsIt) {
  const auto files = shipped_scenarios();
  ASSERT_GE(files.size(), 15u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const Scenario expected = load_scenario(file.string());
    expect_same(expected, load_scenario_reusing_files(file.string()));  // parses
    expect_same(expected, load_scenario_reusing_files(file.string()));  // from the copy
  }
}

TEST(ScenarioFileReuse, CasesOfOneBaseRunAsFromTheFile) {
  const std::string base = source_file("scenarios/lane_change_15.yaml");
  for (const std::vector<std::string>& overrides :
       {std::vector<std::string>{"speed.initial_mps=9.5", "start.y_m=0.1",
                                 "simulation.duration_s=4"},
        {"actuator.dead_time_s=0.02", "simulation.noise_seed=7", "simulation.duration_s=4",
         "vehicle.front_tire.friction_mu=0.8"},
        {"path.x_start_m=-35", "simulation.duration_s=4"},  // another path: built anew
        {"simulation.duration_s=4"}}) {
    const RunResult expected = run_scenario(load_scenario(base, overrides));
    const RunResult actual = run_scenario(load_scenario_reusing_files(base, overrides));
    ASSERT_EQ(expected.simulation.trace.size(), actual.simulation.trace.size());
    ASSERT_GT(expected.simulation.trace.size(), 100u);
    for (std::size_t i = 0; i < expected.simulation.trace.size(); ++i) {
      EXPECT_EQ(expected.simulation.trace[i].lateral_error_m,
                actual.simulation.trace[i].lateral_error_m)
          << i;
      EXPECT_EQ(expected.simulation.trace[i].steering_command_rad,
                actual.simulation.trace[i].steering_command_rad)
          << i;
    }
  }
}

TEST(ScenarioFileReuse, APathIsKeptByEveryKeyValueAndTagOfItsSection) {
  using detail::BuiltPaths;
  const auto key = [](const std::string& yaml, const std::string& directory = "scenarios") {
    return BuiltPaths::key(YAML::Load(yaml), directory);
  };
  const std::string section = "{type: straight, length_m: 5}";
  ASSERT_TRUE(key(section));
  EXPECT_EQ(key(section), key("type: straight\nlength_m: 5\n"));
  for (const std::string other :
       {"{type: straight, length_m: '5'}", "{type: straight, length_m: 5.0}",
        "{type: straight, length_m: [5]}", "{type: straight}", "{type: circle, length_m: 5}",
        "{type: straight, length_m: 5, heading_rad: 0}", "{type: straight, length_m: }"}) {
    EXPECT_NE(key(section), key(other)) << other;
  }
  EXPECT_NE(key(section), key(section, "scenarios/roads"));      // relative files
  EXPECT_FALSE(key("{type: waypoints_csv, file: points.csv}"));  // the file may change
}

TEST(ScenarioFileReuse, APathsDemandIsItsOwnAlsoAtAReusedAddress) {
  for (double radius = 5.0; radius < 50.0; radius *= 1.5) {
    const auto circle = std::make_shared<const Path>(Path::circle({0.0, 0.0}, radius, true, 0.0));
    const PathDemand expected = path_demand(*circle);
    EXPECT_EQ(detail::shared_path_demand(circle).max_curvature, expected.max_curvature);
    EXPECT_EQ(detail::shared_path_demand(circle).max_curvature, 1.0 / radius);
  }
}

class ScenarioFileReuseErrors : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    return scratch_.write(name, text);
  }
  testing::ScratchDirectory scratch_{"smoothsteer_reuse_"};
};

template <typename Load>
std::string error_of(Load load, const std::string& file, const std::vector<std::string>& set) {
  try {
    load(file, set);
  } catch (const io::ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST_F(ScenarioFileReuseErrors, AreLoadScenariosMessages) {
  const std::string vehicle = write("car.yaml", "wheelbase_m: 2.7\nmass_kg: -3\n");
  const std::string good = write("good.yaml",
                                 "name: t\npath: {type: straight}\n"
                                 "speed:\n  initial_mps: 5\ncontroller: {type: lead_wheel}\n");
  const std::string bad_key = write("bad_key.yaml",
                                    "name: t\npath: {type: straight}\n"
                                    "speed:\n  initial_mps: 500\ncontroller: {type: lead_wheel}\n");
  const std::string bad_vehicle =
      write("bad_vehicle.yaml", "path: {type: straight}\nvehicle: {file: car.yaml}\n");
  const std::string malformed = write("malformed.yaml", "path: {type: straight\n");
  const std::vector<std::pair<std::string, std::vector<std::string>>> loads{
      {good, {"speed.initial_mps=500"}},
      {good, {"speed.initial_mps"}},
      {good, {"speed.initial_mps=[1"}},
      {good, {"speed.unknown_key=1"}},
      {good, {"controller.k_rob=-1"}},
      {good, {"path.type=circle"}},
      {good, {"vehicle.file=missing.yaml"}},
      {good, {"path.length_m=-5"}},
      {bad_key, {}},
      {bad_key, {"start.y_m=0.1"}},
      {bad_vehicle, {}},
      {malformed, {}},
      {scratch_.file("missing.yaml"), {}}};
  for (const auto& [file, set] : loads) {
    for (int repeat = 0; repeat < 2; ++repeat) {  // parsed, then from the copy
      const std::string expected = error_of(load_scenario, file, set);
      SCOPED_TRACE(expected);
      ASSERT_FALSE(expected.empty());
      EXPECT_EQ(error_of(load_scenario_reusing_files, file, set), expected);
    }
  }
  // The case a copy alone would get wrong: the file's own key, whose line the message quotes.
  EXPECT_NE(error_of(load_scenario_reusing_files, bad_key, {}).find("(line 4)"), std::string::npos);
}

// A quoted waypoint coordinate is a string in summary.json's parameters: the kept path of the
// plain one must not serve it.
TEST_F(ScenarioFileReuseErrors, APathSectionThatDiffersOnlyInATagIsItsOwn) {
  const std::string file = write("waypoints.yaml",
                                 "path: {type: waypoints, points: [[0, 0], [10, 0], [20, 1]]}\n"
                                 "speed: {initial_mps: 5}\ncontroller: {type: lead_wheel}\n");
  for (const std::string first : {"0", "'0'", "0", "'0'"}) {
    SCOPED_TRACE(first);
    const std::vector<std::string> overrides{"path.points=[[" + first +
                                             ", 0], [10, 0], [20, 1], [30, 3]]"};
    expect_same(load_scenario(file, overrides), load_scenario_reusing_files(file, overrides));
  }
}

TEST_F(ScenarioFileReuseErrors, AChangedFileIsParsedAgain) {
  const std::string file = write("changing.yaml",
                                 "path: {type: straight}\ncontroller: {type: lead_wheel}\n"
                                 "speed: {initial_mps: 5}\n");
  detail::ParsedYamlFiles& files = detail::process_yaml_files();
  EXPECT_EQ(load_scenario_reusing_files(file).speed.initial_speed_mps, 5.0);
  const std::size_t parses = files.parses();
  EXPECT_EQ(load_scenario_reusing_files(file).speed.initial_speed_mps, 5.0);
  EXPECT_EQ(files.parses(), parses);  // the same bytes: not parsed again
  write("changing.yaml",              // the same size
        "path: {type: straight}\ncontroller: {type: lead_wheel}\nspeed: {initial_mps: 6}\n");
  EXPECT_EQ(load_scenario_reusing_files(file).speed.initial_speed_mps, 6.0);
  EXPECT_EQ(files.parses(), parses + 1);
}

TEST_F(ScenarioFileReuseErrors, TheCacheKeepsABoundedNumberOfFiles) {
  detail::ParsedYamlFiles files;
  std::vector<std::string> names;
  for (std::size_t i = 0; i <= detail::ParsedYamlFiles::max_files; ++i) {
    names.push_back(write("file_" + std::to_string(i) + ".yaml", "k: " + std::to_string(i)));
    EXPECT_EQ(files.copy(names.back())["k"].as<std::size_t>(), i);
  }
  const std::size_t parses = files.parses();
  files.copy(names.back());  // kept
  EXPECT_EQ(files.parses(), parses);
  files.copy(names.front());  // the oldest, dropped for the last
  EXPECT_EQ(files.parses(), parses + 1);
}

}  // namespace
}  // namespace smoothsteer::runner
