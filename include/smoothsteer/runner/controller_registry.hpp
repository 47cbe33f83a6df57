#pragma once
//! \file controller_registry.hpp
//! Controllers by name, for scenario files (`controller: {type: lead_wheel, ...}`). Other
//! libraries (baselines) add their types with register_controller_type(). A factory reads its
//! keys through the ConfigSection (type, range and unknown-key checks come for free: the
//! registry calls finish() after the factory, so every key the factory did not read is
//! rejected). Thread-safe.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/io/config_section.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/tuning/scheduled_controller.hpp"
#include "smoothsteer/vehicle/steering_actuator.hpp"
#include "smoothsteer/vehicle/vehicle_parameters.hpp"

namespace smoothsteer::runner {

//! What a factory may read besides its own section: the scenario's path, vehicle file and
//! steering actuator (the derived compensation starts from the actuator's group delay).
struct ControllerContext {
  std::shared_ptr<const Path> path;
  VehicleParameters vehicle;
  ActuatorParameters actuator;
};

using ControllerFactory = std::function<std::unique_ptr<SteeringController>(
    io::ConfigSection& controller_section, const ControllerContext& context)>;

//! Adds or replaces a controller type. "lead_wheel" is built in.
void register_controller_type(const std::string& name, ControllerFactory factory);
//! Registered names, sorted.
std::vector<std::string> controller_types();

//! Builds the controller described by `section` (a mapping with `type`). `key_path` and `file`
//! name the section in error messages. If `resolved` is given, it receives the section with
//! every default filled in.
std::unique_ptr<SteeringController> make_controller(
    const YAML::Node& section, const std::string& key_path, const std::string& file,
    const ControllerContext& context, YAML::Node* resolved = nullptr,
    std::shared_ptr<const std::set<std::string>> overridden_keys = nullptr);

//! The built-in types as their own classes, for a caller that reads what the generic
//! SteeringController does not show (a fixed controller's certificate, a schedule's template):
//! built as make_controller() builds them, nullptr when the section's type is another one or
//! register_controller_type() replaced the built-in.
//! lead_wheel:
std::unique_ptr<LeadWheelController> make_lead_wheel_controller(const YAML::Node& section,
                                                                const std::string& key_path,
                                                                const std::string& file,
                                                                const ControllerContext& context);
//! scheduled_lead_wheel or steering_system:
std::unique_ptr<ScheduledController> make_scheduled_controller(const YAML::Node& section,
                                                               const std::string& key_path,
                                                               const std::string& file,
                                                               const ControllerContext& context);

}  // namespace smoothsteer::runner
