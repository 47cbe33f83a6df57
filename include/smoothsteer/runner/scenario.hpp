#pragma once
//! \file scenario.hpp
//! Scenario files (YAML, schema in docs/scenarios.md): path, vehicle, actuator, speed profile,
//! start pose, controller and simulation settings. load_scenario() checks every key, type and
//! range and rejects unknown keys; errors are ConfigError naming the file, the key and the
//! reason. run_scenario() simulates and computes the metrics.

#include <yaml-cpp/yaml.h>
#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/io/config_section.hpp"
#include "smoothsteer/io/vehicle_file.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_plan.hpp"
#include "smoothsteer/sim/metrics.hpp"
#include "smoothsteer/sim/simulation.hpp"
#include "smoothsteer/tuning/scheduled_controller.hpp"
#include "smoothsteer/vehicle/double_track.hpp"

namespace smoothsteer::runner {

struct Scenario {
  std::string name;
  std::string description;
  std::string file;               //!< the scenario file as given
  std::string model = "dynamic";  //!< "dynamic", "kinematic" or "double_track"
  VehicleParameters vehicle;
  std::string vehicle_name;
  std::string vehicle_source;  //!< citation of the parameter set
  ActuatorParameters actuator;
  SpeedProfile speed;
  SimulationParameters simulation;
  //! The plant's own vehicle (simulation.plant_vehicle: the truth), absent: the plant is
  //! `vehicle`, which the controller is told in either case.
  std::optional<VehicleParameters> plant_vehicle;
  std::string plant_vehicle_name;
  MetricsParameters metrics;
  Pose2 start;                       //!< rear-axle start pose
  std::shared_ptr<const Path> path;  //!< the path; with gear changes, the plan's piece 0
  //! A `segments` path with gear changes (`gear: reverse`, docs/cusps.md), else null.
  std::shared_ptr<const PathPlan> plan;
  YAML::Node controller;               //!< the controller section (type + parameters)
  std::vector<std::string> overrides;  //!< the --set overrides applied
  nlohmann::json parameters;           //!< full resolved parameter set (defaults filled in)
};

//! Applies "key.path=value" overrides to a YAML tree (value parsed as YAML, so lists work).
//! Throws ConfigError on a malformed override.
void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides,
                     const std::string& file);

//! Loads, overrides, validates. Relative file references (vehicle file, waypoint CSV) are
//! resolved against the scenario's directory.
Scenario load_scenario(const std::string& file, const std::vector<std::string>& overrides = {});
//! load_scenario() for many loads of one file with other overrides (a campaign's cases): the
//! scenario file and the vehicle files it names are parsed once per process, each load works on
//! a copy, and a file whose bytes changed is parsed again; a path section seen before (every key
//! and value the same) reuses its built path. Same result, same errors: a load that fails is
//! repeated by load_scenario(), whose messages quote the lines (docs/campaigns.md).
Scenario load_scenario_reusing_files(const std::string& file,
                                     const std::vector<std::string>& overrides = {});

//! Builds the path of a `path:` section (used by load_scenario; public for tests and tools).
//! A `segments` path with gear changes also sets *plan (and returns its piece 0); without
//! `plan` a gear change is rejected with a message naming the piece's `gear` key.
std::shared_ptr<const Path> make_path(io::ConfigSection& path_section,
                                      const std::string& base_directory,
                                      std::shared_ptr<const PathPlan>* plan = nullptr);

//! The plant's model: simulation.plant_vehicle, else the scenario's vehicle (the plant-only
//! scales are applied by simulate()).
std::unique_ptr<VehicleModel> make_vehicle_model(const Scenario& scenario);
//! Builds the scenario's controller through the registry.
std::unique_ptr<SteeringController> make_controller(const Scenario& scenario);
//! The scenario's controller as its own class (controller_registry.hpp), nullptr for other types.
std::unique_ptr<LeadWheelController> make_lead_wheel_controller(const Scenario& scenario);
std::unique_ptr<ScheduledController> make_scheduled_controller(const Scenario& scenario);

//! Simulates the scenario with `controller` (the one wiring of the CLI, run_scenario() and
//! Python): the plant from make_vehicle_model(), the car's steering system believing the
//! scenario's vehicle. With an observer the samples stream to it (simulate()).
SimulationResult simulate_scenario(const Scenario& scenario, SteeringController& controller,
                                   const TraceObserver& observer = {});

struct RunResult {
  SimulationResult simulation;
  Metrics metrics;
  std::string controller_name;
};
//! Simulates with the scenario's controller (thread-safe: every call builds its own objects).
RunResult run_scenario(const Scenario& scenario);
//! Simulates with a caller-provided controller (e.g. a baseline not in the registry).
RunResult run_scenario(const Scenario& scenario, SteeringController& controller);

//! YAML -> JSON (numbers, booleans, strings, lists, mappings).
nlohmann::json to_json(const YAML::Node& node);

}  // namespace smoothsteer::runner
