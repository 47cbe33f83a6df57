// Scenario loading (docs/scenarios.md) and running.

#include "smoothsteer/runner/scenario.hpp"

#include <array>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "smoothsteer/io/vehicle_file.hpp"
#include "smoothsteer/runner/controller_registry.hpp"
#include "smoothsteer/sim/curvature_speed_profile.hpp"
#include "smoothsteer/sim/gear_changes.hpp"

namespace smoothsteer::runner {
using io::ConfigError;
using io::ConfigSection;
using io::load_yaml_file;
using io::parse_number;
using io::parse_yaml_text;
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

template <typename Validated>
void check(const ConfigSection& c, const Validated& value) {
  if (const std::string error = value.validation_error(); !error.empty()) {
    throw ConfigError(c.file() + ": key '" + c.full_key("") + "': " + error);
  }
}

//! Reads a vehicle block (`key`: the vehicle file's keys under `file:`, overlaid with the
//! block's own keys) into `vehicle`; returns the resolved mapping, `label` names where it came
//! from in error messages.
YAML::Node read_vehicle_block(const YAML::Node& node, const std::string& key,
                              const std::string& file, const std::string& directory,
                              const std::shared_ptr<std::set<std::string>>& overridden,
                              VehicleParameters& vehicle, std::string& name, std::string& source,
                              std::string& label) {
  YAML::Node merged(YAML::NodeType::Map);
  label = file;
  if (node && node["file"]) {
    ConfigSection vehicle_keys(node, key, file);
    vehicle_keys.set_overridden_keys(overridden);
    const std::string file_name = vehicle_keys.text("file", "");
    if (file_name.empty()) vehicle_keys.fail("file", "expected the name of a vehicle YAML file");
    std::filesystem::path vehicle_file(file_name);
    if (vehicle_file.is_relative()) vehicle_file = std::filesystem::path(directory) / vehicle_file;
    YAML::Node from_file;
    try {
      from_file = load_yaml_file(vehicle_file.string());
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
  YAML::Node resolved = read_vehicle_section(section, vehicle, name, source);
  if (node && node["file"]) resolved["file"] = node["file"];
  return resolved;
}

//! The simulation keys of the plant-only model error and the imperfect sensors
//! (plant_imperfections.hpp): the truth's vehicle block, scales, crossfall, side force, the
//! pose's latency and rate, sensor offsets. Ranges as SimulationParameters::first_violation.
void read_imperfections(ConfigSection& sim, Scenario& s, const std::string& file,
                        const std::string& directory,
                        const std::shared_ptr<std::set<std::string>>& overridden) {
  SimulationParameters& p = s.simulation;
  if (sim.has("plant_vehicle")) {
    YAML::Node node = sim.raw("plant_vehicle");
    if (!node.IsMap()) sim.fail("plant_vehicle", "expected a mapping (e.g. {file: ...})");
    VehicleParameters& truth = s.plant_vehicle.emplace();
    std::string label, source;
    sim.store("plant_vehicle",
              read_vehicle_block(node, sim.full_key("plant_vehicle"), file, directory, overridden,
                                 truth, s.plant_vehicle_name, source, label));
    if (s.model == "double_track" && !truth.double_track) {
      throw ConfigError(label + ": key '" + sim.full_key("plant_vehicle") +
                        ".double_track': is required by model: double_track");
    }
  }
  ConfigSection scales = sim.section("plant_scales");
  p.plant_scales.mass = scales.number("mass", 1.0, {0.5, 2.0});
  p.plant_scales.yaw_inertia = scales.number("yaw_inertia", 1.0, {0.5, 2.0});
  p.plant_scales.cornering_stiffness = scales.number("cornering_stiffness", 1.0, {0.5, 2.0});
  p.plant_scales.friction = scales.number("friction", 1.0, {0.1, 1.5});
  p.plant_scales.cg_position = scales.number("cg_position", 0.0, {-0.25, 0.25});
  scales.finish();
  sim.store("plant_scales", scales.resolved());
  ConfigSection actuator = sim.section("plant_actuator_scales");
  p.plant_actuator_scales.dead_time = actuator.number("dead_time", 1.0, {0.5, 1.5});
  p.plant_actuator_scales.bandwidth = actuator.number("bandwidth", 1.0, {0.5, 1.5});
  actuator.finish();
  sim.store("plant_actuator_scales", actuator.resolved());
  p.crossfall = sim.number("crossfall", 0.0, {-0.1, 0.1});
  ConfigSection side = sim.section("side_force");
  p.side_force.force_n = side.number("force_n", 0.0, {-1e5, 1e5});
  p.side_force.yaw_moment_nm = side.number("yaw_moment_nm", 0.0, {-1e6, 1e6});
  p.side_force.start_s = side.number("start_s", 0.0, {0.0, 3600.0});
  side.finish();
  sim.store("side_force", side.resolved());
  p.pose_latency_s =
      sim.number("pose_latency_s", 0.0, {0.0, SimulationParameters::max_pose_latency_s});
  if (sim.has("pose_rate_hz")) {
    p.pose_rate_hz =
        sim.required_number("pose_rate_hz", {SimulationParameters::min_pose_rate_hz, 1000.0});
  }
  p.pose_age_known = sim.boolean("pose_age_known", false);
  p.steering_angle_sensor_offset_rad =
      sim.number("steering_angle_sensor_offset_rad", 0.0, {-0.1, 0.1});
  p.gyro_bias_radps = sim.number("gyro_bias_radps", 0.0, {-0.5, 0.5});

  // What acts through tire forces needs a plant that has them (model: dynamic or double_track).
  if (s.model == "kinematic") {
    const char* why =
        "acts through the tires' lateral forces, which the kinematic plant has not (its rear "
        "axle rolls without slip): use model: dynamic or double_track, or "
        "plant_curvature_disturbance";
    if (p.crossfall != 0.0) sim.fail("crossfall", why);
    if (p.side_force.active()) sim.fail("side_force", why);
    if (!p.plant_scales.identity()) sim.fail("plant_scales", why);
  }
  try {
    (void)scaled_plant_vehicle(s.plant_vehicle.value_or(s.vehicle), p.plant_scales);
  } catch (const std::invalid_argument& error) {
    sim.fail("plant_scales", error.what());
  }
}

//! Stack mode (planner_windows.hpp): simulation.planner. The rule that ties period_s to the
//! control period is SimulationParameters' (check() names the key).
void read_planner(ConfigSection& sim, PlannerWindows& windows) {
  ConfigSection planner = sim.section("planner");
  windows.period_s = planner.number("period_s", windows.period_s, {0.0, 10.0});
  windows.behind_m = planner.number("behind_m", windows.behind_m, {0.0, 1000.0});
  windows.spacing_m = planner.number("spacing_m", windows.spacing_m, {0.05, 50.0});
  windows.ahead_m = planner.number("ahead_m", windows.ahead_m, {2.0 * windows.spacing_m, 1e4});
  windows.jitter_std_m = planner.number("jitter_std_m", windows.jitter_std_m, {0.0, 1.0});
  if (planner.has("smoothing_tolerance_m")) {
    windows.smoothing_tolerance_m = planner.required_number("smoothing_tolerance_m", {0.0, 10.0});
  }
  planner.finish();
  sim.store("planner", planner.resolved());
}

}  // namespace

void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides,
                     const std::string& file) {
  for (const std::string& entry : overrides) {
    const std::size_t equals = entry.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw ConfigError(file + ": override '" + entry + "': expected key.path=value");
    }
    const std::string key = entry.substr(0, equals);
    const YAML::Node value =
        parse_yaml_text(entry.substr(equals + 1), file + ": override '" + entry + "': value");
    std::vector<std::string> parts;
    std::size_t begin = 0;
    while (true) {
      const std::size_t dot = key.find('.', begin);
      parts.push_back(key.substr(begin, dot - begin));
      if (dot == std::string::npos) break;
      begin = dot + 1;
    }
    YAML::Node node = root;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      if (parts[i].empty()) throw ConfigError(file + ": override '" + entry + "': empty key part");
      YAML::Node child = node[parts[i]];
      if (child && !child.IsNull() && !child.IsMap()) {
        throw ConfigError(file + ": override '" + entry + "': key '" + parts[i] +
                          "' is not a mapping");
      }
      if (!child || child.IsNull()) node[parts[i]] = YAML::Node(YAML::NodeType::Map);
      node.reset(node[parts[i]]);
    }
    if (parts.back().empty())
      throw ConfigError(file + ": override '" + entry + "': empty key part");
    node[parts.back()] = value;
  }
}

Scenario load_scenario(const std::string& file, const std::vector<std::string>& overrides) {
  YAML::Node root = load_yaml_file(file);
  if (!root.IsMap()) throw ConfigError(file + ": expected a mapping at the top level");
  apply_overrides(root, overrides, file);
  const std::string directory = std::filesystem::path(file).parent_path().string();
  Scenario s;
  s.file = file;
  s.overrides = overrides;
  auto overridden = std::make_shared<std::set<std::string>>();
  for (const std::string& o : overrides) overridden->insert(o.substr(0, o.find('=')));
  ConfigSection c(root, "", file);
  c.set_overridden_keys(overridden);
  s.name = c.text("name", std::filesystem::path(file).stem().string());
  s.description = c.text("description", "");
  s.model = c.text("model", "dynamic", {"dynamic", "kinematic", "double_track"});

  // Vehicle: the file's keys, overlaid with the scenario's own keys.
  YAML::Node vehicle_node = c.raw("vehicle");
  if (vehicle_node && !vehicle_node.IsNull() && !vehicle_node.IsMap()) {
    c.fail("vehicle", "expected a mapping");
  }
  std::string vehicle_label;
  YAML::Node resolved_vehicle =
      read_vehicle_block(vehicle_node, "vehicle", file, directory, overridden, s.vehicle,
                         s.vehicle_name, s.vehicle_source, vehicle_label);
  if (s.model == "double_track" && !s.vehicle.double_track) {
    throw ConfigError(vehicle_label +
                      ": key 'vehicle.double_track': is required by model: "
                      "double_track (tracks, roll inertia, roll stiffness and damping, drive and "
                      "brake shares; docs/scenarios.md)");
  }

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

  // Speed: a ramp in time (default), or limited by the path's curvature and by longitudinal
  // acceleration (curvature_speed_profile.hpp), computed once the path is built.
  ConfigSection speed = c.section("speed");
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

  ConfigSection sim = c.section("simulation");
  SimulationParameters& p = s.simulation;
  p.control_period_s = sim.number("control_period_s", p.control_period_s, {0.0, 1.0, true, false});
  p.substep_s = sim.number("substep_s", p.substep_s, {0.0, 0.01, true, false});
  p.duration_s = sim.number("duration_s", p.duration_s, {0.0, 3600.0, true, false});
  constexpr std::array<const char*, 3> integrator_names{"fixed_rk4", "rkf78", "dopri5"};
  const std::string integrator =
      sim.text("integrator", integrator_names[static_cast<std::size_t>(p.integrator)],
               {"fixed_rk4", "rkf78", "dopri5"});
  p.integrator = integrator == "fixed_rk4" ? PlantIntegrator::fixed_rk4
                 : integrator == "dopri5"  ? PlantIntegrator::dopri5
                                           : PlantIntegrator::rkf78;
  p.integrator_tolerance =
      sim.number("integrator_tolerance", p.integrator_tolerance, {1e-14, 1e-3});
  p.stop_at_path_end = sim.boolean("stop_at_path_end", p.stop_at_path_end);
  p.stop_beyond_path_end_m = sim.number("stop_beyond_path_end_m", p.stop_beyond_path_end_m);
  p.matched_disturbance = sim.number("matched_disturbance", 0.0, {-1.0, 1.0});
  p.plant_curvature_disturbance = sim.number("plant_curvature_disturbance", 0.0, {-1.0, 1.0});
  p.steering_offset_rad = sim.number("steering_offset_rad", 0.0, {-0.1, 0.1});
  read_imperfections(sim, s, file, directory, overridden);
  p.position_noise_std_m = sim.number("position_noise_std_m", 0.0, Range::non_negative());
  p.heading_noise_std_rad = sim.number("heading_noise_std_rad", 0.0, Range::non_negative());
  p.noise_seed = static_cast<std::uint64_t>(sim.integer("noise_seed", 1, 0, 2147483647));
  ConfigSection slip = sim.section("side_slip");
  SideSlipEstimation& estimation = p.side_slip;
  const std::string source = slip.text("source", "none", {"none", "truth", "observer"});
  estimation.source = source == "none"    ? SideSlipSource::none
                      : source == "truth" ? SideSlipSource::truth
                                          : SideSlipSource::observer;
  estimation.cornering_stiffness_scale = slip.number("cornering_stiffness_scale", 1.0, {0.2, 5.0});
  estimation.mass_scale = slip.number("mass_scale", 1.0, {0.2, 5.0});
  estimation.tire_model = slip.text("tire_model", "linear", {"linear", "magic_formula"}) == "linear"
                              ? ObserverTireModel::linear
                              : ObserverTireModel::magic_formula;
  estimation.yaw_rate_noise_std_radps = slip.number("yaw_rate_noise_std_radps", 0.0, {0.0, 1.0});
  estimation.lateral_acceleration_noise_std_mps2 =
      slip.number("lateral_acceleration_noise_std_mps2", 0.0, {0.0, 10.0});
  using Observer = SideSlipObserverParameters;
  estimation.max_steering_offset_rad =
      slip.number("max_steering_offset_rad", estimation.max_steering_offset_rad,
                  {0.0, Observer::max_steering_offset_bound_rad});
  estimation.steering_offset_process_std_radps =
      slip.number("steering_offset_process_std_radps", estimation.steering_offset_process_std_radps,
                  {0.0, Observer::max_steering_offset_process_std_radps});
  estimation.compensate_steering_offset =
      slip.boolean("compensate_steering_offset", estimation.compensate_steering_offset);
  slip.finish();
  sim.store("side_slip", slip.resolved());
  read_planner(sim, p.planner);
  sim.finish();
  check(sim, p);
  if (const std::string error = a.validation_error(p.substep_s); !error.empty()) {
    throw ConfigError(file + ": key 'actuator': " + error);
  }

  ConfigSection start = c.section("start");
  s.start.position.x = start.number("x_m", 0.0);
  s.start.position.y = start.number("y_m", 0.0);
  s.start.heading_rad = start.number("heading_rad", 0.0, {-10.0, 10.0});
  start.finish();

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

  // Required (docs/scenarios.md): a file with only `name:` must not run on defaults.
  if (!c.has("path")) c.fail("path", "is required (e.g. path: {type: straight})");
  ConfigSection path = c.section("path");
  s.path = make_path(path, directory, &s.plan);
  path.finish();
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

  // Checked on the document's own node, whose marks give each key's line (a clone's are all
  // line 1); the clone is what the scenario keeps.
  s.controller = YAML::Clone(c.raw("controller"));
  YAML::Node resolved_controller;
  make_controller(c.raw("controller"), "controller", file, {s.path, s.vehicle, s.actuator},
                  &resolved_controller, overridden);
  c.finish();

  YAML::Node all = c.resolved();
  all["vehicle"] = resolved_vehicle;
  all["actuator"] = actuator.resolved();
  all["speed"] = speed.resolved();
  all["simulation"] = sim.resolved();
  all["start"] = start.resolved();
  all["metrics"] = metrics.resolved();
  all["path"] = path.resolved();
  all["controller"] = resolved_controller;
  s.parameters = to_json(all);
  return s;
}

std::unique_ptr<VehicleModel> make_vehicle_model(const Scenario& s) {
  const VehicleParameters& truth = s.plant_vehicle.value_or(s.vehicle);
  if (s.model == "kinematic") return std::make_unique<KinematicVehicleModel>(truth);
  if (s.model == "double_track") return std::make_unique<DoubleTrack>(truth);
  return std::make_unique<DynamicSingleTrack>(truth);
}

std::unique_ptr<SteeringController> make_controller(const Scenario& s) {
  return make_controller(s.controller, "controller", s.file, {s.path, s.vehicle, s.actuator});
}

SimulationResult simulate_scenario(const Scenario& s, SteeringController& controller,
                                   const TraceObserver& observer) {
  const std::unique_ptr<VehicleModel> model = make_vehicle_model(s);
  // The side-slip observer believes the scenario's vehicle, not the plant's.
  s.simulation.validate();
  SteeringSystem system(controller,
                        steering_system_parameters(s.simulation.side_slip, s.vehicle, s.actuator));
  return s.plan ? simulate(*s.plan, *model, s.actuator, s.speed, s.simulation, s.start, system,
                           observer)
                : simulate(*s.path, *model, s.actuator, s.speed, s.simulation, s.start, system,
                           observer);
}

RunResult run_scenario(const Scenario& s, SteeringController& controller) {
  RunResult result;
  result.simulation = simulate_scenario(s, controller);
  result.metrics = compute_metrics(result.simulation.trace, s.metrics);
  result.controller_name = controller.name();
  return result;
}

RunResult run_scenario(const Scenario& s) {
  const std::unique_ptr<SteeringController> controller = make_controller(s);
  return run_scenario(s, *controller);
}

nlohmann::json to_json(const YAML::Node& node) {
  if (!node || node.IsNull()) return nullptr;
  if (node.IsSequence()) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& item : node) list.push_back(to_json(item));
    return list;
  }
  if (node.IsMap()) {
    nlohmann::json object = nlohmann::json::object();
    for (const auto& entry : node) object[entry.first.as<std::string>()] = to_json(entry.second);
    return object;
  }
  const std::string& text = node.Scalar();
  if (node.Tag() != "!") {  // plain (unquoted) scalars may be numbers or booleans
    bool flag = false;
    if (text == "true" || text == "false") {
      YAML::convert<bool>::decode(node, flag);
      return flag;
    }
    if (const std::optional<double> number = parse_number(text)) return *number;
  }
  return text;
}

}  // namespace smoothsteer::runner
