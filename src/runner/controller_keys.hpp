#pragma once
// The scenario keys of the lead-wheel controller types (docs/scenarios.md, "controller"): each
// key of ControllerParameters is a row of the field table (parameter_fields.hpp), read as the
// row says, so that a key, its field, its range and its default cannot disagree. What the car
// determines is left to steering_system_controller(), the one place that derives it.

#include <string_view>

#include "smoothsteer/io/config_section.hpp"
#include "smoothsteer/tuning/vehicle_steering_system.hpp"
#include "smoothsteer/vehicle/vehicle_parameters.hpp"

namespace smoothsteer::runner::detail {

//! Which keys a controller type reads besides the rows every type shares.
struct ControllerKeys {
  //! `order` and `lead_curvature_bound`: a gain schedule gives them otherwise.
  bool chain_shape = true;
  //! An absent `actuator_delay_s` leaves the delay to the actuator (and the speed), as
  //! SteeringSystemOptions::actuator_delay_s does; otherwise the key's value (0: off) holds.
  bool delay_from_actuator = false;
};

//! The options of the lead-wheel types: ControllerParameters' defaults, the car's groups (slip
//! preview, friction guard) off unless their keys say otherwise.
SteeringSystemOptions lead_wheel_options();

//! The range a scenario key of the field table's row `name` accepts: the row's, with the value
//! that switches its group off.
io::Range key_range(std::string_view name);

//! Reads the controller keys into `options`: every direct row of the field table into
//! options.controller (its value on entry is the key's default), the switches `slip_preview` and
//! `friction_guard`, and the `governor` section. `vehicle` is needed only to refuse a governor
//! the vehicle file gives no acceleration limit.
void read_controller_keys(io::ConfigSection& c, SteeringSystemOptions& options,
                          const VehicleParameters& vehicle, ControllerKeys keys);

}  // namespace smoothsteer::runner::detail
