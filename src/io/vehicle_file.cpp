// Vehicle mappings of scenario and vehicle files (include/smoothsteer/io/vehicle_file.hpp,
// docs/scenarios.md).

#include "smoothsteer/io/vehicle_file.hpp"

#include <optional>

#include "smoothsteer/validation.hpp"

namespace smoothsteer::io {
namespace {

YAML::Node read_tire(ConfigSection c, TireParameters& tire) {
  tire.stiffness_factor_b =
      c.number("stiffness_factor_b", tire.stiffness_factor_b, Range::positive());
  tire.shape_factor_c = c.number("shape_factor_c", tire.shape_factor_c, {0.0, 2.0, true, true});
  tire.friction_mu = c.number("friction_mu", tire.friction_mu, Range::positive());
  tire.curvature_factor_e = c.number("curvature_factor_e", tire.curvature_factor_e, {-100.0, 1.0});
  c.finish();
  return c.resolved();
}

//! The double-track group of a vehicle (double_track_parameters.hpp); ranges here, the physical
//! rules (the body must not tip over on its springs, damping > 0) in its validation.
YAML::Node read_double_track(ConfigSection c, DoubleTrackParameters& d) {
  d.front_track_m = c.required_number("front_track_m", {0.0, 5.0, true, false});
  d.rear_track_m = c.required_number("rear_track_m", {0.0, 5.0, true, false});
  d.roll_inertia_kgm2 = c.required_number("roll_inertia_kgm2", Range::positive());
  d.front_roll_stiffness_nmprad =
      c.required_number("front_roll_stiffness_nmprad", Range::non_negative());
  d.rear_roll_stiffness_nmprad =
      c.required_number("rear_roll_stiffness_nmprad", Range::non_negative());
  d.front_roll_damping_nmsprad =
      c.required_number("front_roll_damping_nmsprad", Range::non_negative());
  d.rear_roll_damping_nmsprad =
      c.required_number("rear_roll_damping_nmsprad", Range::non_negative());
  d.drive_share_front = c.required_number("drive_share_front", {0.0, 1.0});
  d.brake_share_front = c.required_number("brake_share_front", {0.0, 1.0});
  d.longitudinal_friction_mu =
      c.number("longitudinal_friction_mu", d.longitudinal_friction_mu, {0.0, 3.0, true, false});
  d.friction_load_sensitivity =
      c.number("friction_load_sensitivity", d.friction_load_sensitivity, {-0.5, 0.5, true, false});
  d.ackermann_share = c.number("ackermann_share", d.ackermann_share, {0.0, 1.0});
  c.finish();
  return c.resolved();
}

}  // namespace

YAML::Node read_vehicle_section(ConfigSection& c, VehicleParameters& v, std::string& name,
                                std::string& source) {
  name = c.text("name", "unnamed");
  source = c.text("source", "");
  v.mass_kg = c.number("mass_kg", v.mass_kg, Range::positive());
  v.yaw_inertia_kgm2 = c.number("yaw_inertia_kgm2", v.yaw_inertia_kgm2, Range::positive());
  v.cg_to_front_axle_m = c.number("cg_to_front_axle_m", v.cg_to_front_axle_m, Range::positive());
  v.cg_to_rear_axle_m = c.number("cg_to_rear_axle_m", v.cg_to_rear_axle_m, Range::positive());
  v.cg_height_m = c.number("cg_height_m", v.cg_height_m, Range::non_negative());
  v.gravity_mps2 = c.number("gravity_mps2", v.gravity_mps2, Range::positive());
  const YAML::Node front = read_tire(c.section("front_tire"), v.front_tire);
  const YAML::Node rear = read_tire(c.section("rear_tire"), v.rear_tire);
  v.max_steering_angle_rad =
      c.number("max_steering_angle_rad", v.max_steering_angle_rad, {0.0, 1.5, true, true});
  v.max_steering_rate_radps =
      c.number("max_steering_rate_radps", v.max_steering_rate_radps, Range::positive());
  if (c.has("max_steering_acceleration_radps2")) {
    v.max_steering_acceleration_radps2 =
        c.required_number("max_steering_acceleration_radps2", Range::positive());
  }
  v.kinematic_below_mps = c.number("kinematic_below_mps", v.kinematic_below_mps, {0.1, 50.0});
  v.kinetic_above_mps = c.number("kinetic_above_mps", v.kinetic_above_mps, {0.1, 50.0});
  v.kinematic_relaxation_s =
      c.number("kinematic_relaxation_s", v.kinematic_relaxation_s, Range::positive());
  YAML::Node double_track;
  if (c.has("double_track")) {
    v.double_track.emplace();
    double_track = read_double_track(c.section("double_track"), *v.double_track);
  }
  c.finish();
  // Named by its key: "key 'vehicle.mass_kg' (from --set): VehicleParameters: mass_kg = ...".
  if (const std::optional<Violation> violation = v.first_violation()) {
    c.fail(std::string(violation->prefix) + violation->field, describe(*violation));
  }
  YAML::Node resolved = c.resolved();
  resolved["front_tire"] = front;
  resolved["rear_tire"] = rear;
  if (v.double_track) resolved["double_track"] = double_track;
  return resolved;
}

VehicleParameters check_vehicle_mapping(const YAML::Node& vehicle, const std::string& file,
                                        const std::set<std::string>& skipped) {
  YAML::Node kept(YAML::NodeType::Map);
  if (vehicle.IsMap()) {
    for (const auto& entry : vehicle) {
      if (!skipped.count(entry.first.Scalar())) kept[entry.first.Scalar()] = entry.second;
    }
  }
  ConfigSection c(vehicle.IsMap() ? kept : vehicle, "", file);
  VehicleParameters v;
  std::string name;
  std::string source;
  read_vehicle_section(c, v, name, source);
  return v;
}

VehicleParameters load_vehicle_file(const std::string& yaml_path) {
  const YAML::Node root = load_yaml_file(yaml_path);
  // As the scenario loader refuses it: an empty file is no car, not the default one.
  if (!root.IsMap()) {
    throw ConfigError(yaml_path + ": expected a mapping of vehicle keys (mass_kg, ...), got " +
                      (root.IsNull() ? "an empty file" : "a list or a scalar"));
  }
  return check_vehicle_mapping(root, yaml_path);
}

}  // namespace smoothsteer::io
