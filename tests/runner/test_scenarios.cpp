// Every scenario file loads, runs, and yields a complete summary; overrides; atomic outputs.

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "smoothsteer/runner/controller_registry.hpp"
#include "smoothsteer/runner/run_output.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "smoothsteer/runner/sweep.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer::runner {
namespace {

namespace fs = std::filesystem;

using testing::source_dir;

std::vector<fs::path> scenario_files() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(source_dir() / "scenarios")) {
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(Scenarios, EveryFileRunsAndItsSummaryHasEveryMetric) {
  const auto files = scenario_files();
  ASSERT_GE(files.size(), 9u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const Scenario scenario = load_scenario(file.string());
    const RunResult result = run_scenario(scenario);
    EXPECT_EQ(result.simulation.status, Status::ok);
    EXPECT_FALSE(result.simulation.non_finite);
    EXPECT_EQ(result.metrics.non_finite_values, 0);
    EXPECT_TRUE(result.metrics.reached);
    const nlohmann::json summary = summary_json(scenario, result);
    for (const auto& [name, value] : metric_values(result.metrics)) {
      ASSERT_TRUE(summary.at("metrics").contains(name)) << name;
      EXPECT_FALSE(summary.at("metrics").at(name).is_null()) << name;
    }
    EXPECT_TRUE(summary.at("parameters").at("controller").contains("k_rob"));
    EXPECT_TRUE(summary.at("parameters").at("vehicle").contains("mass_kg"));
  }
}

TEST(Scenarios, OverridesReachTheResolvedParametersAndTheRun) {
  const std::string file = (source_dir() / "scenarios/lane_change_10.yaml").string();
  const Scenario base = load_scenario(file);
  const Scenario changed = load_scenario(file, {"controller.k_rob=0.2", "speed.initial_mps=12",
                                                "vehicle.mass_kg=1500", "simulation.duration_s=3"});
  EXPECT_DOUBLE_EQ(changed.parameters["controller"]["k_rob"].get<double>(), 0.2);
  EXPECT_DOUBLE_EQ(changed.speed.initial_speed_mps, 12.0);
  EXPECT_DOUBLE_EQ(changed.vehicle.mass_kg, 1500.0);
  EXPECT_DOUBLE_EQ(base.vehicle.mass_kg, 1093.3);
  const RunResult run = run_scenario(changed);
  EXPECT_NEAR(run.metrics.duration_s, 3.0, 1e-9);
}

TEST(Scenarios, RunOutputsAreCompleteAndNoTemporaryFileRemains) {
  const fs::path out =
      fs::temp_directory_path() / ("smoothsteer_io_test_" + std::to_string(::getpid()));
  fs::remove_all(out);
  const Scenario scenario = load_scenario((source_dir() / "scenarios/reaching_0.yaml").string(),
                                          {"simulation.duration_s=2"});
  const RunResult result = run_scenario(scenario);
  write_run_outputs(out.string(), scenario, result);
  std::ifstream trace(out / "trace.csv");
  std::string header, line;
  std::getline(trace, header);
  EXPECT_EQ(header.substr(0, 12), "t,s,x,y,psi,");
  int rows = 0;
  while (std::getline(trace, line)) ++rows;
  EXPECT_EQ(rows, result.metrics.steps);
  std::ifstream summary_file(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  EXPECT_EQ(summary.at("scenario"), "reaching_0");
  for (const auto& entry : fs::directory_iterator(out)) {
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
  }
  fs::remove_all(out);
}

TEST(Registry, OtherLibrariesCanAddControllerTypes) {
  class Straight final : public SteeringController {
   public:
    explicit Straight(double angle) : angle_(angle) {}
    Status compute_command(const ControllerInput&, ControllerOutput& out) noexcept override {
      out = {};
      out.steering_angle_rad = angle_;
      return Status::ok;
    }
    Status reset(double) noexcept override { return Status::ok; }
    const char* name() const noexcept override { return "test_fixed"; }

   private:
    double angle_;
  };
  register_controller_type("test_fixed", [](io::ConfigSection& c, const ControllerContext&) {
    return std::make_unique<Straight>(c.number("angle_rad", 0.0, {-0.5, 0.5}));
  });
  const std::string file = (source_dir() / "scenarios/reaching_0.yaml").string();
  const Scenario s =
      load_scenario(file, {"controller={type: test_fixed, angle_rad: 0.0}",
                           "simulation.duration_s=1", "metrics.reaching_threshold_m=1"});
  const RunResult r = run_scenario(s);
  EXPECT_EQ(r.controller_name, "test_fixed");
  EXPECT_NEAR(r.metrics.max_abs_rear_error_m, 0.5, 1e-9);  // drives straight, parallel to the path
  try {
    load_scenario(file, {"controller={type: test_fixed, angle: 0.1}"});
    FAIL() << "unknown key accepted";
  } catch (const io::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("controller.angle'"), std::string::npos)
        << error.what();
  }
}

TEST(Scenarios, TheConcreteFactoriesBuildTheirOwnTypeAndNoOther) {
  const Scenario fixed = load_scenario((source_dir() / "scenarios/reaching_p02pi.yaml").string());
  const Scenario scheduled =
      load_scenario((source_dir() / "scenarios/lane_change_15.yaml").string());
  const Scenario car = load_scenario((source_dir() / "scenarios/lane_change_15.yaml").string(),
                                     {"controller={type: steering_system}"});
  const std::unique_ptr<LeadWheelController> lead_wheel = make_lead_wheel_controller(fixed);
  ASSERT_NE(lead_wheel, nullptr);
  EXPECT_STREQ(lead_wheel->name(), make_controller(fixed)->name());
  EXPECT_EQ(make_scheduled_controller(fixed), nullptr);
  EXPECT_EQ(make_lead_wheel_controller(scheduled), nullptr);
  EXPECT_NE(make_scheduled_controller(scheduled), nullptr);
  EXPECT_NE(make_scheduled_controller(car), nullptr);
  EXPECT_EQ(make_lead_wheel_controller(car), nullptr);
  // The same key checks as make_controller(): an unknown key is refused.
  EXPECT_THROW(
      make_lead_wheel_controller(YAML::Load("{type: lead_wheel, no_such_key: 1}"), "controller",
                                 fixed.file, {fixed.path, fixed.vehicle, fixed.actuator}),
      io::ConfigError);
}

TEST(Sweep, GridPaperVariationsAndParallelRunsAgreeWithSequentialRuns) {
  const auto grid = sweep_grid({parse_sweep_axis("a=1,2,3"), parse_sweep_axis("b.c=x,y")});
  ASSERT_EQ(grid.size(), 6u);
  EXPECT_EQ(grid[5], (std::vector<std::string>{"a=3", "b.c=y"}));
  EXPECT_THROW(parse_sweep_axis("novalues"), io::ConfigError);

  const std::string file = (source_dir() / "scenarios/lane_change_10.yaml").string();
  // The paper's variations (Sec. IV-A) vary a fixed lead-wheel controller, not a schedule.
  const std::vector<std::string> base{
      "simulation.duration_s=4",
      "controller={type: lead_wheel, order: 2, lead_wheelbase_m: 0.5, lead_curvature_bound: 0.2}"};
  const Scenario scenario = load_scenario(file, base);
  const auto variations = paper_variations(scenario);
  ASSERT_EQ(variations.size(), 4u);
  EXPECT_EQ(variations[1][0], "controller.lead_curvature_bound=0.1");
  EXPECT_EQ(variations[2][0], "controller.lead_wheelbase_m=2");
  const auto rows = run_sweep(file, base, variations, 2);
  ASSERT_EQ(rows.size(), 4u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_TRUE(rows[i].ok) << rows[i].error;
    std::vector<std::string> overrides = base;
    overrides.insert(overrides.end(), variations[i].begin(), variations[i].end());
    const RunResult sequential = run_scenario(load_scenario(file, overrides));
    EXPECT_EQ(rows[i].metrics.max_abs_rear_error_m, sequential.metrics.max_abs_rear_error_m);
  }
  const std::string csv = sweep_csv(rows);
  EXPECT_EQ(csv.substr(0, csv.find(',')), "controller.lead_curvature_bound");
}

}  // namespace
}  // namespace smoothsteer::runner
