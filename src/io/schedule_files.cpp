#include "smoothsteer/io/schedule_files.hpp"

#include <yaml-cpp/yaml.h>

#include "smoothsteer/io/atomic_output.hpp"
#include "smoothsteer/io/bounded_file.hpp"
#include "smoothsteer/io/text_checks.hpp"
#include "smoothsteer/io/vehicle_file.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace smoothsteer::io {
namespace {

// The last two columns (the feedforward route) are optional when reading: a file without them is
// a box-route schedule (no feedforward).
constexpr std::size_t kLegacyColumns = 10;
constexpr std::array<const char*, 12> kColumns{"speed_mps",
                                               "region",
                                               "fictive_wheelbase_m",
                                               "lead_wheelbase_m",
                                               "lead_curvature_bound_per_m",
                                               "lead_radius_m",
                                               "k_rob",
                                               "max_steering_angle_rad",
                                               "max_steering_rate_radps",
                                               "max_steering_acceleration_radps2",
                                               "feedforward_curvature_bound_per_m",
                                               "feedforward_curvature_rate_per_m2"};

// Keys of the simulation's vehicle schema (vehicles/*.yaml, docs/scenarios.md) that the tuner
// does not need.
const std::set<std::string>& ignored_keys() {
  static const std::set<std::string> keys{"name",
                                          "source",
                                          "mass_kg",
                                          "yaw_inertia_kgm2",
                                          "cg_height_m",
                                          "front_tire",
                                          "rear_tire",
                                          "kinematic_below_mps",
                                          "kinetic_above_mps",
                                          "double_track"};
  return keys;
}

[[noreturn]] void fail(const std::string& file, const std::string& key, const std::string& why) {
  throw std::invalid_argument(file + ": " + key + ": " + why);
}

double number(const YAML::Node& root, const std::string& file, const std::string& key) {
  const YAML::Node node = root[key];
  if (!node) fail(file, key, "missing (required)");
  // The scenario reader's number syntax: ".nan", ".inf" and "0.3garbage" are not numbers.
  const std::optional<double> value = node.IsScalar() ? parse_number(node.Scalar()) : std::nullopt;
  if (!value) fail(file, key, "must be a finite number");
  return *value;
}

}  // namespace

VehicleLimits load_vehicle_limits(const std::string& yaml_path) {
  YAML::Node root;
  try {
    // Regular files only, bounded size and alias expansion, UTF-8, plain and unique keys.
    root = load_yaml_file(yaml_path);
  } catch (const ConfigError& error) {
    throw std::invalid_argument(error.what());
  }
  if (!root.IsMap()) throw std::invalid_argument(yaml_path + ": a vehicle file must be a map");
  static const std::set<std::string> used{"wheelbase_m",
                                          "cg_to_front_axle_m",
                                          "cg_to_rear_axle_m",
                                          "max_steering_angle_rad",
                                          "max_steering_rate_radps",
                                          "max_steering_acceleration_radps2"};
  for (const auto& item : root) {
    const std::string key = item.first.Scalar();
    if (!used.count(key) && !ignored_keys().count(key)) {
      fail(yaml_path, key, "unknown key (docs/tuning.md lists the vehicle schema)");
    }
  }
  // The keys of the simulation's schema are checked as `run` checks them, even those the tuner
  // does not use: a file tune accepts is one run accepts.
  try {
    check_vehicle_mapping(root, yaml_path, {"wheelbase_m"});
  } catch (const ConfigError& error) {
    throw std::invalid_argument(error.what());
  }
  VehicleLimits limits;
  if (root["wheelbase_m"]) {
    limits.wheelbase_m = number(root, yaml_path, "wheelbase_m");
  } else if (root["cg_to_front_axle_m"] || root["cg_to_rear_axle_m"]) {
    limits.wheelbase_m = number(root, yaml_path, "cg_to_front_axle_m") +
                         number(root, yaml_path, "cg_to_rear_axle_m");
  } else {
    fail(yaml_path, "wheelbase_m", "missing (or give cg_to_front_axle_m and cg_to_rear_axle_m)");
  }
  limits.max_steering_angle_rad = number(root, yaml_path, "max_steering_angle_rad");
  limits.max_steering_rate_radps = number(root, yaml_path, "max_steering_rate_radps");
  if (root["max_steering_acceleration_radps2"]) {
    limits.max_steering_acceleration_radps2 =
        number(root, yaml_path, "max_steering_acceleration_radps2");
  }
  // Friction limit mu g from the tires (the smaller mu of the two axles), if the file has them.
  constexpr double gravity = 9.81;
  for (const char* tire : {"front_tire", "rear_tire"}) {
    const YAML::Node node = root[tire];
    if (!node || !node.IsMap() || !node["friction_mu"]) continue;
    const double mu = number(node, yaml_path, "friction_mu");
    if (!(mu > 0.0) || !std::isfinite(mu)) {
      fail(yaml_path, std::string(tire) + ".friction_mu", "must be finite and > 0");
    }
    limits.max_lateral_acceleration_mps2 =
        std::min(limits.max_lateral_acceleration_mps2, mu * gravity);
  }
  const std::string error = limits.validation_error();
  if (!error.empty()) throw std::invalid_argument(yaml_path + ": " + error);
  return limits;
}

void write_schedule_csv(const GainSchedule& schedule, const std::string& csv_path) {
  std::ostringstream out;
  out.precision(12);
  for (std::size_t c = 0; c < kColumns.size(); ++c) out << (c ? "," : "") << kColumns[c];
  out << '\n';
  for (const ScheduleEntry& e : schedule.entries()) {
    out << e.speed_mps << ',' << static_cast<int>(e.region) << ',' << e.fictive_wheelbase_m << ','
        << e.lead_wheelbase_m << ',' << e.lead_curvature_bound << ','
        << 1.0 / e.lead_curvature_bound << ',' << e.k_rob << ',' << e.max_steering_angle_rad << ','
        << e.max_steering_rate_radps << ',' << e.max_steering_acceleration_radps2 << ','
        << e.feedforward_curvature_bound << ',' << e.feedforward_curvature_rate << '\n';
  }
  write_file_atomically(csv_path, out.str(), "--out");  // no half-written file is left behind
}

GainSchedule read_schedule_csv(const std::string& csv_path, const ControllerParameters& base) {
  std::istringstream in;
  try {
    in.str(read_bounded_file(csv_path, max_schedule_file_bytes, "schedule file"));
  } catch (const FileReadError& error) {
    throw std::invalid_argument(error.what());
  }
  std::string line;
  std::getline(in, line);
  std::string expected, legacy;
  for (std::size_t c = 0; c < kColumns.size(); ++c) {
    if (c > 0) expected.push_back(',');
    expected.append(kColumns[c]);
    if (c + 1 == kLegacyColumns) legacy = expected;
  }
  if (line != expected && line != legacy)
    throw std::invalid_argument(csv_path + ": line 1: header must be " + expected);
  const std::size_t columns = line == expected ? kColumns.size() : kLegacyColumns;
  std::vector<ScheduleEntry> entries;
  VehicleLimits vehicle;
  vehicle.max_steering_angle_rad = vehicle.max_steering_rate_radps = 0.0;
  vehicle.max_steering_acceleration_radps2 = 0.0;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    std::array<double, kColumns.size()> v{};
    std::istringstream row(line);
    std::string cell;
    for (std::size_t c = 0; c < columns; ++c) {
      if (!std::getline(row, cell, ',')) {
        throw std::invalid_argument(csv_path + ": line " + std::to_string(number) + ": column " +
                                    kColumns[c] + " missing");
      }
      char* end = nullptr;
      v[c] = std::strtod(cell.c_str(), &end);
      // The whole cell is the number; only the certified acceleration (no limit) and the
      // feedforward rate (no rate limit) may be +inf.
      const bool may_be_infinite = c == 9 || c == 11;
      if (end == cell.c_str() || *end != '\0' || std::isnan(v[c]) ||
          (!may_be_infinite && std::isinf(v[c]))) {
        throw std::invalid_argument(csv_path + ": line " + std::to_string(number) + ": column " +
                                    kColumns[c] + " = '" + cell + "' is not a finite number");
      }
    }
    if (std::getline(row, cell, ',')) {
      throw std::invalid_argument(csv_path + ": line " + std::to_string(number) + ": more than " +
                                  std::to_string(columns) + " columns");
    }
    // Region labels 1-5 (VelocityRegion); checked before the conversion to int.
    if (!(v[1] >= 1.0 && v[1] <= 5.0 && v[1] == std::floor(v[1]))) {
      throw std::invalid_argument(csv_path + ": line " + std::to_string(number) +
                                  ": column region = " + std::to_string(v[1]) +
                                  " must be an integer in [1, 5]");
    }
    ScheduleEntry e;
    e.speed_mps = v[0];
    e.region = static_cast<VelocityRegion>(static_cast<int>(v[1]));
    e.fictive_wheelbase_m = v[2];
    e.lead_wheelbase_m = v[3];
    e.lead_curvature_bound = v[4];
    e.k_rob = v[6];
    e.max_steering_angle_rad = v[7];
    e.max_steering_rate_radps = v[8];
    e.max_steering_acceleration_radps2 = v[9];
    e.feedforward_curvature_bound = v[10];
    e.feedforward_curvature_rate = v[11];
    if (!entries.empty() && !(e.speed_mps > entries.back().speed_mps)) {
      throw std::invalid_argument(csv_path + ": line " + std::to_string(number) +
                                  ": speed_mps must increase");
    }
    vehicle.wheelbase_m = std::hypot(e.fictive_wheelbase_m, e.lead_wheelbase_m);
    TuningOptions row_options;
    row_options.base = base;
    row_options.order = e.lead_wheelbase_m > 0.0 ? 2 : 1;
    const ControllerParameters p = schedule_entry_parameters(row_options, vehicle.wheelbase_m, e);
    if (!std::isfinite(e.speed_mps) || e.speed_mps <= 0.0 || !p.is_valid()) {
      throw std::invalid_argument(
          csv_path + ": line " + std::to_string(number) + ": " +
          (p.is_valid() ? "speed_mps must be finite and > 0" : p.validation_error()));
    }
    vehicle.max_steering_angle_rad =
        std::max(vehicle.max_steering_angle_rad, e.max_steering_angle_rad);
    vehicle.max_steering_rate_radps =
        std::max(vehicle.max_steering_rate_radps, e.max_steering_rate_radps);
    vehicle.max_steering_acceleration_radps2 =
        std::max(vehicle.max_steering_acceleration_radps2, e.max_steering_acceleration_radps2);
    entries.push_back(e);
  }
  if (entries.empty()) throw std::invalid_argument(csv_path + ": no schedule rows");
  TuningOptions options;
  options.base = base;
  options.order = entries.front().lead_wheelbase_m > 0.0 ? 2 : 1;
  GainSchedule schedule(vehicle, options, std::move(entries));
  for (const double v : {0.0, schedule.max_speed_mps()}) {
    const ControllerParameters p = schedule.parameters_at(v);
    if (!p.is_valid()) throw std::invalid_argument(csv_path + ": " + p.validation_error());
  }
  return schedule;
}

}  // namespace smoothsteer::io
