// The readers of a scenario's sections but the simulation's (scenario_simulation.cpp): vehicle,
// actuator, speed, start, metrics, path and controller (docs/scenarios.md, "Schema").

#include <filesystem>
#include <limits>
#include <stdexcept>

#include "scenario_sections.hpp"
#include "smoothsteer/io/vehicle_file.hpp"
#include "smoothsteer/runner/controller_registry.hpp"
#include "smoothsteer/sim/gear_changes.hpp"

namespace smoothsteer::runner::detail {
using io::ConfigError;
using io::ConfigSection;
using io::Range;
using io::read_vehicle_section;
namespace {

//! Sets `entry` in `target`; a mapping over a mapping (a scenario's or --set's vehicle.front_tire
//! or vehicle.double_track keys over the vehicle file's group) is overlaid key by key, so that
//! the group's other keys stay the file's.
void overlay(YAML::Node& target, const std::pair<YAML::Node, YAML::Node>& entry) {
  const std::string key = entry.first.as<std::string>();
  YAML::Node existing = target[key];
  if (existing && existing.IsMap() && entry.second.IsMap()) {
    YAML::Node copy = YAML::Clone(existing);
    for (const auto& inner : entry.second) overlay(copy, {inner.first, inner.second});
    target[key] = copy;
  } else {
    target[key] = entry.second;
  }
}

}  // namespace

YAML::Node read_vehicle_block(const YAML::Node& node, const std::string& key,
                              const ScenarioSource& source, VehicleParameters& vehicle,
                              std::string& name, std::string& citation, std::string& label) {
  const std::string& file = source.file;
  const std::shared_ptr<std::set<std::string>>& overridden = source.overridden;
  YAML::Node merged(YAML::NodeType::Map);
  label = file;
  if (node && node["file"]) {
    ConfigSection vehicle_keys(node, key, file);
    vehicle_keys.set_overridden_keys(overridden);
    const std::string file_name = vehicle_keys.text("file", "");
    if (file_name.empty()) vehicle_keys.fail("file", "expected the name of a vehicle YAML file");
    std::filesystem::path vehicle_file(file_name);
    if (vehicle_file.is_relative())
      vehicle_file = std::filesystem::path(source.directory) / vehicle_file;
    YAML::Node from_file;
    try {
      from_file = source.read_yaml(vehicle_file.string());
    } catch (const ConfigError& error) {
      vehicle_keys.fail("file", error.what());  // names the key that gave the file
    }
    if (!from_file.IsMap()) throw ConfigError(vehicle_file.string() + ": expected a mapping");
    for (const auto& entry : from_file) merged[entry.first.as<std::string>()] = entry.second;
    label = file + " (vehicle file " + vehicle_file.string() + ")";
  }
  if (node && node.IsMap()) {
    for (const auto& entry : node) {
      if (entry.first.as<std::string>() != "file") overlay(merged, entry);
    }
  }
  ConfigSection section(merged, key, label);
  section.set_overridden_keys(overridden);
  YAML::Node resolved = read_vehicle_section(section, vehicle, name, citation);
  if (node && node["file"]) resolved["file"] = node["file"];
  return resolved;
}

YAML::Node read_vehicle(ConfigSection& c, const ScenarioSource& source, Scenario& s) {
  YAML::Node vehicle_node = c.raw("vehicle");
  if (vehicle_node && !vehicle_node.IsNull() && !vehicle_node.IsMap()) {
    c.fail("vehicle", "expected a mapping");
  }
  std::string vehicle_label;
  YAML::Node resolved_vehicle = read_vehicle_block(vehicle_node, "vehicle", source, s.vehicle,
                                                   s.vehicle_name, s.vehicle_source, vehicle_label);
  if (s.model == "double_track" && !s.vehicle.double_track) {
    throw ConfigError(vehicle_label +
                      ": key 'vehicle.double_track': is required by model: "
                      "double_track (tracks, roll inertia, roll stiffness and damping, drive and "
                      "brake shares; docs/scenarios.md)");
  }
  return resolved_vehicle;
}

YAML::Node read_actuator(ConfigSection& c, Scenario& s) {
  ConfigSection actuator = c.section("actuator");
  ActuatorParameters& a = s.actuator;
  a.ideal = actuator.boolean("ideal", false);
  a.bandwidth_hz = actuator.number("bandwidth_hz", a.bandwidth_hz, Range::positive());
  a.dead_time_s = actuator.number("dead_time_s", a.dead_time_s, {0.0, 10.0});
  a.max_angle_rad =
      actuator.number("max_angle_rad", s.vehicle.max_steering_angle_rad, Range::positive());
  a.max_rate_radps =
      actuator.number("max_rate_radps", s.vehicle.max_steering_rate_radps, Range::positive());
  actuator.finish();
  return actuator.resolved();
}

std::optional<CurvatureSpeedLimits> read_speed(ConfigSection& speed, Scenario& s) {
  // Limited by the path's curvature and by longitudinal acceleration:
  // curvature_speed_profile.hpp.
  std::optional<CurvatureSpeedLimits> curvature_limits;
  if (speed.text("profile", "ramp", {"ramp", "curvature"}) == "ramp") {
    s.speed.initial_speed_mps = speed.number("initial_mps", 10.0, {0.0, 100.0, true, false});
    s.speed.final_speed_mps =
        speed.number("final_mps", s.speed.initial_speed_mps, {0.0, 100.0, true, false});
    s.speed.acceleration_mps2 = speed.number("acceleration_mps2", 0.0, {0.0, 20.0});
    s.speed.start_time_s = speed.number("start_time_s", 0.0, Range::non_negative());
    speed.finish();
    check(speed, s.speed);
  } else {
    CurvatureSpeedLimits& l = curvature_limits.emplace();
    l.max_speed_mps = speed.required_number("max_mps", {0.0, 100.0, true, false});
    l.max_lateral_acceleration_mps2 =
        speed.required_number("max_lateral_acceleration_mps2", {0.0, 20.0, true, false});
    l.max_acceleration_mps2 =
        speed.number("max_acceleration_mps2", l.max_acceleration_mps2, {0.0, 20.0, true, false});
    l.max_deceleration_mps2 =
        speed.number("max_deceleration_mps2", l.max_deceleration_mps2, {0.0, 20.0, true, false});
    if (speed.has("initial_mps")) {
      l.initial_speed_mps = speed.required_number("initial_mps", {0.0, 100.0, true, false});
    }
    if (speed.has("cusp_rest_s")) {
      l.cusp_rest_s = speed.required_number("cusp_rest_s", {0.0, 60.0, true, false});
    }
    speed.finish();
    check(speed, l);
  }
  return curvature_limits;
}

YAML::Node read_start(ConfigSection& c, Scenario& s) {
  ConfigSection start = c.section("start");
  s.start.position.x = start.number("x_m", 0.0);
  s.start.position.y = start.number("y_m", 0.0);
  s.start.heading_rad = start.number("heading_rad", 0.0, {-10.0, 10.0});
  start.finish();
  return start.resolved();
}

YAML::Node read_metrics(ConfigSection& c, Scenario& s) {
  ConfigSection metrics = c.section("metrics");
  s.metrics.reaching_threshold_m = metrics.number("reaching_threshold_m", 0.1, Range::positive());
  // The vehicle's acceleration limit unless given; none: +inf internally, null in the resolved
  // parameters (JSON has no infinity; a huge finite stand-in would read like a real limit).
  if (metrics.has("steering_acceleration_limit_radps2")) {
    s.metrics.steering_acceleration_limit_radps2 =
        metrics.required_number("steering_acceleration_limit_radps2", Range::positive());
  } else if (std::isfinite(s.vehicle.max_steering_acceleration_radps2)) {
    s.metrics.steering_acceleration_limit_radps2 = s.vehicle.max_steering_acceleration_radps2;
  } else {
    s.metrics.steering_acceleration_limit_radps2 = std::numeric_limits<double>::infinity();
    metrics.store("steering_acceleration_limit_radps2", YAML::Node(YAML::NodeType::Null));
  }
  metrics.finish();
  s.metrics.steering_angle_limit_rad = s.vehicle.max_steering_angle_rad;
  s.metrics.steering_rate_limit_radps = s.vehicle.max_steering_rate_radps;
  s.metrics.friction_limit_mps2 = s.vehicle.friction_limit_mps2();
  return metrics.resolved();
}

YAML::Node read_path(ConfigSection& c, const ScenarioSource& source, ConfigSection& speed,
                     const std::optional<CurvatureSpeedLimits>& curvature_limits, Scenario& s) {
  // Required (docs/scenarios.md): a file with only `name:` must not run on defaults.
  if (!c.has("path")) c.fail("path", "is required (e.g. path: {type: straight})");
  const std::optional<std::string> reuse_key =
      source.built_paths ? BuiltPaths::key(c.raw("path"), source.directory) : std::nullopt;
  std::optional<BuiltPath> built = reuse_key ? source.built_paths->find(*reuse_key) : std::nullopt;
  ConfigSection path = c.section("path");
  if (!built) {
    s.path = make_path(path, source.directory, &s.plan);
    path.finish();
    built = BuiltPath{s.path, s.plan, path.resolved()};
    if (reuse_key) source.built_paths->keep(*reuse_key, *built);
  }
  s.path = built->path;
  s.plan = built->plan;
  if (s.plan && !curvature_limits) {
    speed.fail("profile",
               "must be 'curvature' on a path with gear changes (the car comes to "
               "rest at every cusp; docs/cusps.md)");
  }
  if (s.plan) {
    try {
      s.speed = curvature_speed_profile(*s.plan, *curvature_limits);
    } catch (const std::invalid_argument& error) {
      speed.fail("profile", error.what());
    }
    try {
      check_gear_changes(*s.plan, s.speed, s.simulation.control_period_s);
    } catch (const std::invalid_argument& error) {
      speed.fail("cusp_rest_s", error.what());
    }
    speed.store("cusp_rest_s", YAML::Node(curvature_limits->cusp_rest_s));
  } else if (curvature_limits) {
    try {
      s.speed = curvature_speed_profile(*s.path, *curvature_limits);
    } catch (const std::invalid_argument& error) {
      speed.fail("profile", error.what());
    }
  }
  return built->resolved;
}

YAML::Node read_controller(ConfigSection& c, const ScenarioSource& source, Scenario& s) {
  // Checked on the document's own node, whose marks give each key's line (a clone's are all
  // line 1); the clone is what the scenario keeps.
  s.controller = YAML::Clone(c.raw("controller"));
  YAML::Node resolved_controller;
  make_controller(c.raw("controller"), "controller", source.file, {s.path, s.vehicle, s.actuator},
                  &resolved_controller, source.overridden);
  return resolved_controller;
}

}  // namespace smoothsteer::runner::detail
