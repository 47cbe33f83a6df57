// Scenario loading (docs/scenarios.md) and running. Each section has its reader
// (scenario_sections.hpp); load_scenario() calls them in the file's order.

#include "smoothsteer/runner/scenario.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>

#include "parsed_yaml_files.hpp"
#include "scenario_sections.hpp"
#include "smoothsteer/runner/controller_registry.hpp"

namespace smoothsteer::runner {
using io::ConfigError;
using io::ConfigSection;
using io::load_yaml_file;
using io::parse_number;
using io::parse_yaml_text;

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

namespace {

//! load_scenario() with its YAML files read by `read_yaml` and its path from `built_paths`
//! where it was built before.
Scenario load_scenario_from(const std::string& file, const std::vector<std::string>& overrides,
                            const std::function<YAML::Node(const std::string&)>& read_yaml,
                            detail::BuiltPaths* built_paths) {
  YAML::Node root = read_yaml(file);
  if (!root.IsMap()) throw ConfigError(file + ": expected a mapping at the top level");
  apply_overrides(root, overrides, file);
  const detail::ScenarioSource source{file, std::filesystem::path(file).parent_path().string(),
                                      std::make_shared<std::set<std::string>>(), read_yaml,
                                      built_paths};
  for (const std::string& o : overrides) source.overridden->insert(o.substr(0, o.find('=')));
  Scenario s;
  s.file = file;
  s.overrides = overrides;
  ConfigSection c(root, "", file);
  c.set_overridden_keys(source.overridden);
  s.name = c.text("name", std::filesystem::path(file).stem().string());
  s.description = c.text("description", "");
  s.model = c.text("model", "dynamic", {"dynamic", "kinematic", "double_track"});
  const YAML::Node vehicle = detail::read_vehicle(c, source, s);
  const YAML::Node actuator = detail::read_actuator(c, s);
  ConfigSection speed = c.section("speed");
  const std::optional<CurvatureSpeedLimits> curvature_limits = detail::read_speed(speed, s);
  const YAML::Node simulation = detail::read_simulation(c, source, s);
  const YAML::Node start = detail::read_start(c, s);
  const YAML::Node metrics = detail::read_metrics(c, s);
  const YAML::Node path = detail::read_path(c, source, speed, curvature_limits, s);
  const YAML::Node controller = detail::read_controller(c, source, s);
  c.finish();

  YAML::Node all = c.resolved();
  all["vehicle"] = vehicle;
  all["actuator"] = actuator;
  all["speed"] = speed.resolved();
  all["simulation"] = simulation;
  all["start"] = start;
  all["metrics"] = metrics;
  all["path"] = path;
  all["controller"] = controller;
  s.parameters = to_json(all);
  return s;
}

}  // namespace

Scenario load_scenario(const std::string& file, const std::vector<std::string>& overrides) {
  return load_scenario_from(file, overrides, load_yaml_file, nullptr);
}

Scenario load_scenario_reusing_files(const std::string& file,
                                     const std::vector<std::string>& overrides) {
  try {
    return load_scenario_from(
        file, overrides,
        [](const std::string& yaml_file) { return detail::process_yaml_files().copy(yaml_file); },
        &detail::process_paths());
  } catch (...) {
    // The copies have no marks, so the message may lack the line; the files' own trees have
    // them, and errors are rare enough to read the files again.
    return load_scenario(file, overrides);
  }
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

std::unique_ptr<LeadWheelController> make_lead_wheel_controller(const Scenario& s) {
  return make_lead_wheel_controller(s.controller, "controller", s.file,
                                    {s.path, s.vehicle, s.actuator});
}

std::unique_ptr<ScheduledController> make_scheduled_controller(const Scenario& s) {
  return make_scheduled_controller(s.controller, "controller", s.file,
                                   {s.path, s.vehicle, s.actuator});
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
