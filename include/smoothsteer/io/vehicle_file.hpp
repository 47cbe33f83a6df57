#pragma once
//! \file vehicle_file.hpp
//! A vehicle file (vehicles/*.yaml, schema in docs/scenarios.md) as VehicleParameters, checked
//! key by key as load_scenario() checks a scenario's vehicle.

#include <string>

#include "smoothsteer/vehicle/vehicle_parameters.hpp"

namespace smoothsteer::io {

//! Reads and checks the file (ConfigError naming the file and the key; unknown keys rejected).
VehicleParameters load_vehicle_file(const std::string& yaml_path);

}  // namespace smoothsteer::io
