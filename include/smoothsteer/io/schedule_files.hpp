#pragma once
//! \file schedule_files.hpp
//! Files of the tuner (io owns every file format): the vehicle YAML it reads and the schedule CSV
//! it writes (docs/tuning.md).

#include <string>

#include "smoothsteer/tuning/gain_schedule.hpp"

namespace smoothsteer::io {

//! Reads wheelbase and steering limits from a vehicle YAML (vehicles/*.yaml). The wheelbase is
//! `wheelbase_m`, or `cg_to_front_axle_m + cg_to_rear_axle_m`; the steering limits are
//! `max_steering_angle_rad`, `max_steering_rate_radps` and the optional
//! `max_steering_acceleration_radps2`. Keys of the simulation schema are not used but checked as
//! load_scenario() checks them; any other key, a missing key or a bad value throws
//! std::invalid_argument naming file and key. The file is read by load_yaml_file().
VehicleLimits load_vehicle_limits(const std::string& yaml_path);

//! Writes one row per grid speed (columns in docs/tuning.md) via a temporary file and rename.
void write_schedule_csv(const GainSchedule& schedule, const std::string& csv_path);

//! Reads a CSV written by write_schedule_csv() back into a schedule usable by
//! ScheduledController. The order follows from lead_wheelbase_m (0 -> n = 1); `base` supplies
//! the other controller fields. Throws std::invalid_argument naming file, line and column.
GainSchedule read_schedule_csv(const std::string& csv_path, const ControllerParameters& base = {});

}  // namespace smoothsteer::io
