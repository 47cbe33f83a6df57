#pragma once
//! \file vehicle_file.hpp
//! The vehicle schema of scenario and vehicle files (vehicles/*.yaml, docs/scenarios.md): mass,
//! inertia, axle distances, tires, steering limits, model switching and the optional
//! double-track group. Every key is checked for type and range, unknown keys are rejected and
//! VehicleParameters' own rules are applied; errors are ConfigError naming file and key.

#include <yaml-cpp/yaml.h>

#include <set>
#include <string>

#include "smoothsteer/io/config_section.hpp"
#include "smoothsteer/vehicle/vehicle_parameters.hpp"

namespace smoothsteer::io {

//! Reads a vehicle mapping (a vehicle file's keys, overlaid with a scenario's own keys) into
//! `vehicle`, `name` (default "unnamed") and `source` (the parameter set's citation); returns
//! the mapping with every default filled in.
YAML::Node read_vehicle_section(ConfigSection& section, VehicleParameters& vehicle,
                                std::string& name, std::string& source);

//! Checks a vehicle mapping (a vehicle file's root) against the simulation's vehicle schema
//! exactly as load_scenario() does, and returns its parameters; the keys in `skipped` are left
//! out (the tuner's `wheelbase_m`). Throws ConfigError naming `file` and the key.
VehicleParameters check_vehicle_mapping(const YAML::Node& vehicle, const std::string& file,
                                        const std::set<std::string>& skipped = {});

//! Reads and checks a vehicle file (ConfigError naming the file and the key; unknown keys
//! rejected), as check_vehicle_mapping() on the file's root; an empty file or one whose root
//! is not a mapping is refused ("<file>: expected a mapping of vehicle keys ..."), as the
//! scenario loader refuses it.
VehicleParameters load_vehicle_file(const std::string& yaml_path);

}  // namespace smoothsteer::io
