#pragma once
// The readers of a scenario file's sections (docs/scenarios.md, "Schema"), one each, which
// load_scenario() calls in the file's order. Each reads its keys through a ConfigSection (the
// range, type and unknown-key checks and the messages that name file and key are its) into the
// Scenario and returns the section's resolved mapping for summary.json's parameters.

#include <yaml-cpp/yaml.h>

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "built_paths.hpp"
#include "smoothsteer/io/config_section.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "smoothsteer/sim/curvature_speed_profile.hpp"

namespace smoothsteer::runner::detail {

//! Where the scenario came from: its file (error messages), the folder relative references are
//! resolved against, the keys --set gave (errors say so), how its YAML files (the vehicle
//! files it names) are read: io::load_yaml_file, or a copy of a tree parsed before
//! (parsed_yaml_files.hpp), and the paths built before for the same section, if any
//! (built_paths.hpp).
struct ScenarioSource {
  std::string file;
  std::string directory;
  std::shared_ptr<std::set<std::string>> overridden;
  std::function<YAML::Node(const std::string&)> read_yaml = io::load_yaml_file;
  BuiltPaths* built_paths = nullptr;
};

//! Throws the value's validation error (validation.hpp) as a ConfigError naming the section.
template <typename Validated>
void check(const io::ConfigSection& c, const Validated& value) {
  if (const std::string error = value.validation_error(); !error.empty()) {
    throw io::ConfigError(c.file() + ": key '" + c.full_key("") + "': " + error);
  }
}

//! Reads a vehicle block (`key`: the vehicle file's keys under `file:`, overlaid with the
//! block's own keys) into `vehicle`; returns the resolved mapping, `label` names where it came
//! from in error messages.
YAML::Node read_vehicle_block(const YAML::Node& node, const std::string& key,
                              const ScenarioSource& source, VehicleParameters& vehicle,
                              std::string& name, std::string& citation, std::string& label);

//! `vehicle`: the vehicle file's keys overlaid with the scenario's own (model: double_track
//! needs the file's double_track group).
YAML::Node read_vehicle(io::ConfigSection& c, const ScenarioSource& source, Scenario& s);
//! `actuator`: the steering actuator's model; its limits default to the vehicle's.
YAML::Node read_actuator(io::ConfigSection& c, Scenario& s);
//! `speed` (the caller's section, which the path's speed profile still needs): a ramp in time,
//! or with `profile: curvature` the limits returned, the profile computed once the path is built.
std::optional<CurvatureSpeedLimits> read_speed(io::ConfigSection& speed, Scenario& s);
//! `simulation` (scenario_simulation.cpp), then the actuator against its sub-step.
YAML::Node read_simulation(io::ConfigSection& c, const ScenarioSource& source, Scenario& s);
//! `start`: the rear axle's pose.
YAML::Node read_start(io::ConfigSection& c, Scenario& s);
//! `metrics`: the thresholds and the limits the metrics count against.
YAML::Node read_metrics(io::ConfigSection& c, Scenario& s);
//! `path` (required), then the speed profile that follows from it.
YAML::Node read_path(io::ConfigSection& c, const ScenarioSource& source, io::ConfigSection& speed,
                     const std::optional<CurvatureSpeedLimits>& curvature_limits, Scenario& s);
//! `controller`, built once through the registry to check it.
YAML::Node read_controller(io::ConfigSection& c, const ScenarioSource& source, Scenario& s);

}  // namespace smoothsteer::runner::detail
