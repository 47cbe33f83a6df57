// Malformed files, unknown keys, wrong types and out-of-range values name file, key and reason.

#include <gtest/gtest.h>

#include <cstdlib>

#include "smoothsteer/runner/scenario.hpp"
#include "support/scratch_directory.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer::runner {
namespace {

class ScenarioErrors : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    return scratch_.write(name, text);
  }
  //! Loads and returns the error message ("" if it loaded).
  std::string error_of(const std::string& file, const std::vector<std::string>& overrides = {}) {
    try {
      load_scenario(file, overrides);
    } catch (const io::ConfigError& error) {
      return error.what();
    }
    return "";
  }
  static constexpr const char* valid =
      "name: t\npath: {type: straight}\nspeed: {initial_mps: 5}\ncontroller: {type: lead_wheel}\n";

  testing::ScratchDirectory scratch_{"smoothsteer_errors_"};
};

void expect_contains(const std::string& message, std::initializer_list<std::string> parts) {
  ASSERT_FALSE(message.empty()) << "expected an error";
  for (const std::string& part : parts) {
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' missing in: " << message;
  }
}

TEST_F(ScenarioErrors, ValidFileLoads) {
  EXPECT_EQ(error_of(write("ok.yaml", valid)), "");
}

TEST_F(ScenarioErrors, DerivedCompensationConflictsWithTheKeysItSets) {
  const std::string shipped =
      (smoothsteer::testing::source_dir() / "scenarios" / "lane_change_15.yaml").string();
  for (const char* key : {"actuator_delay_s", "feedforward_catch_up"}) {
    expect_contains(error_of(shipped, {std::string("controller.") + key + "=0.03"}),
                    {shipped, std::string("'controller.") + key + "'", "(from --set)",
                     "conflicts with derived_compensation: true"});
  }
  // Every spelling of true that the key accepts gets the actuator block's group delay.
  EXPECT_EQ(error_of(shipped, {"controller.derived_compensation=yes"}), "");
  // The actuator's group delay comes from the scenario's actuator block, not from a key of the
  // controller section.
  expect_contains(error_of(shipped, {"controller.actuator_group_delay_s=0.02"}),
                  {shipped, "'controller.actuator_group_delay_s'", "unknown"});
}

TEST_F(ScenarioErrors, MalformedYamlNamesFileAndLine) {
  const std::string file = write("bad.yaml", "name: t\npath: {type: straight\nspeed: [1, 2\n");
  expect_contains(error_of(file), {file, "malformed YAML", "line"});
}

TEST_F(ScenarioErrors, MissingFile) {
  expect_contains(error_of(scratch_.file("nope.yaml")), {"nope.yaml", "cannot open"});
}

TEST_F(ScenarioErrors, UnknownKeysAnywhere) {
  const std::string file = write("u.yaml", std::string(valid) + "simulaton: {duration_s: 3}\n");
  expect_contains(error_of(file), {file, "unknown key", "'simulaton'"});
  const std::string nested = write("n.yaml", std::string(valid) + "simulation: {duraton_s: 3}\n");
  expect_contains(error_of(nested), {nested, "'simulation.duraton_s'"});
  const std::string controller =
      write("c.yaml", "path: {type: straight}\ncontroller: {type: lead_wheel, krob: 0.3}\n");
  expect_contains(error_of(controller), {controller, "'controller.krob'"});
  expect_contains(error_of(write("o.yaml", valid), {"vehicle.front_tire.Bee=3"}),
                  {"'vehicle.front_tire.Bee'", "unknown key"});
}

TEST_F(ScenarioErrors, WrongTypes) {
  const std::string file = write("t.yaml", std::string(valid) + "simulation: {duration_s: long}\n");
  expect_contains(error_of(file), {file, "'simulation.duration_s'", "expected a number", "'long'"});
  const std::string list = write("l.yaml", std::string(valid) + "start: [1, 2]\n");
  expect_contains(error_of(list), {list, "'start'", "expected a mapping"});
  expect_contains(error_of(write("b.yaml", valid), {"simulation.stop_at_path_end=maybe"}),
                  {"'simulation.stop_at_path_end'", "true or false"});
}

TEST_F(ScenarioErrors, OutOfRangeValues) {
  const std::string file = write("r.yaml", valid);
  expect_contains(error_of(file, {"controller.k_rob=1.5"}),
                  {file, "'controller.k_rob'", "1.5", "[0, 1)"});
  expect_contains(error_of(file, {"speed.initial_mps=-2"}),
                  {"'speed.initial_mps'", "-2", "out of range"});
  expect_contains(error_of(file, {"vehicle.mass_kg=0"}), {"'vehicle.mass_kg'", "out of range"});
  expect_contains(error_of(file, {"controller.feedforward_catch_up=2"}),
                  {file, "'controller.feedforward_catch_up'", "2", "[0, 1]"});
  // wheelbases_m is read as a list, in the field table's range.
  expect_contains(error_of(file, {"controller.wheelbases_m=[2.0, 0.005]"}),
                  {"'controller.wheelbases_m'", "element 1 = 0.005", "[0.01, 100]"});
  expect_contains(error_of(file, {"controller.order=9"}), {"'controller.order'", "[0, 8]"});
  expect_contains(error_of(file, {"simulation.control_period_s=0.0125"}),
                  {"'simulation'", "control_period_s", "whole multiple"});
  expect_contains(error_of(file, {"controller.lead_curvature_bound=0.9"}),
                  {"'controller'", "must be < 1"});
  expect_contains(error_of(file, {"simulation.side_slip.tire_model=pacejka"}),
                  {file, "'simulation.side_slip.tire_model'", "pacejka", "must be one of"});
  expect_contains(error_of(file, {"controller.type=stanley_typo"}),
                  {"'controller.type'", "stanley_typo", "must be one of"});
  expect_contains(error_of(file, {"controller.curvature_preview=planned"}),
                  {file, "'controller.curvature_preview'", "planned", "must be one of"});
  // planned_jumps on the default rear_axle target: the parameters' rule, named.
  expect_contains(error_of(file, {"controller.curvature_preview=planned_jumps"}),
                  {"'controller'", "curvature_preview", "rear_axle_exact"});
  EXPECT_EQ(error_of(file, {"controller.curvature_preview=planned_jumps",
                            "controller.cornering_target=rear_axle_exact",
                            "controller.feedforward_curvature_rate=0.02"}),
            "");
}

// The steering-offset compensation acts on the observer's learned offset: where there is none,
// the key is refused naming what makes it inert.
TEST_F(ScenarioErrors, AnInertSteeringOffsetCompensationIsRefused) {
  const std::string file = write("o.yaml", valid);
  const std::string key = "simulation.side_slip.compensate_steering_offset";
  expect_contains(error_of(file, {key + "=false"}),
                  {file, "'" + key + "'", "no effect with side_slip.source = none"});
  expect_contains(error_of(file, {key + "=true", "simulation.side_slip.source=truth"}),
                  {"'" + key + "'", "side_slip.source = truth"});
  expect_contains(error_of(file, {key + "=true", "simulation.side_slip.source=observer",
                                  "simulation.side_slip.max_steering_offset_rad=0"}),
                  {"'" + key + "'", "side_slip.max_steering_offset_rad = 0"});
  EXPECT_EQ(error_of(file, {key + "=false", "simulation.side_slip.source=observer"}), "");
}

TEST_F(ScenarioErrors, BadOverridesAndWaypointFiles) {
  const std::string file = write("w.yaml", valid);
  expect_contains(error_of(file, {"no_equals_sign"}), {"no_equals_sign", "key.path=value"});
  expect_contains(error_of(file, {"name.x=3"}), {"'name'", "not a mapping"});
  write("pts.csv", "x,y\n0,0\n1,oops\n");
  const std::string csv = write(
      "csv.yaml", "path: {type: waypoints_csv, file: pts.csv}\ncontroller: {type: lead_wheel}\n");
  expect_contains(error_of(csv), {"pts.csv", "line 3", "two finite numbers"});
  const std::string missing = write("m.yaml", "path: {type: waypoints_csv, file: none.csv}\n");
  expect_contains(error_of(missing), {"none.csv", "cannot open"});
  write("good.csv", "x,y\n0,0\n10,0.01\n20,-0.01\n30,0\n");
  const std::string smoothed =
      write("s.yaml",
            "path: {type: waypoints_csv, file: good.csv, smoothing_tolerance_m: 0.01}\n"
            "controller: {type: lead_wheel}\n");
  EXPECT_EQ(error_of(smoothed), "");
  expect_contains(error_of(smoothed, {"path.smoothing_tolerance_m=-1"}),
                  {"'path.smoothing_tolerance_m'", "-1", "out of range"});
  EXPECT_EQ(error_of(smoothed, {"path.estimate_jitter=true"}), "");
  expect_contains(error_of(smoothed, {"path.estimate_jitter=maybe"}),
                  {"'path.estimate_jitter'", "expected true or false", "maybe"});
  EXPECT_EQ(error_of(smoothed, {"path.restore_corners=false"}), "");
  expect_contains(error_of(smoothed, {"path.restore_corners=2"}),
                  {"'path.restore_corners'", "expected true or false", "2"});
  const std::string vehicle =
      write("v.yaml", "vehicle: {file: missing_car.yaml}\npath: {type: straight}\n");
  expect_contains(error_of(vehicle), {"missing_car.yaml", "cannot open"});
}

}  // namespace
}  // namespace smoothsteer::runner
