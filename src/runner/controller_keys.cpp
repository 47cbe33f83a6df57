#include "controller_keys.hpp"

#include <cmath>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "smoothsteer/controller/parameter_fields.hpp"

namespace smoothsteer::runner::detail {
using io::ConfigSection;
using io::Range;
namespace {

//! A row's range as a scenario key accepts it: with the value that switches its group off.
Range key_range(const ParameterField& field) {
  return field.range.hull();
}

std::vector<std::string> choice_names(const ParameterField& field) {
  std::vector<std::string> names;
  std::istringstream words{std::string(field.choices)};
  for (std::string word; words >> word;) names.push_back(word);
  return names;
}

//! Reads `key` into the row's member of `p`, as the row's kind says; the member's value on entry
//! is the default.
void read_field(ConfigSection& c, const std::string& key, const ParameterField& field,
                ControllerParameters& p) {
  const double fallback = field.get(p);
  const Range range = key_range(field);
  switch (field.kind) {
    case FieldKind::integer:
      field.set(p, c.integer(key, static_cast<int>(fallback), static_cast<int>(range.min),
                             static_cast<int>(range.max)));
      break;
    case FieldKind::boolean:
      field.set(p, c.boolean(key, fallback != 0.0) ? 1.0 : 0.0);
      break;
    case FieldKind::choice: {
      const std::vector<std::string> names = choice_names(field);
      const std::string chosen = c.text(key, names[static_cast<std::size_t>(fallback)], names);
      for (std::size_t k = 0; k < names.size(); ++k) {
        if (names[k] == chosen) field.set(p, static_cast<double>(k));
      }
      break;
    }
    default:
      if (std::isinf(fallback) && !c.has(key)) {
        // Absent: the C++ default, +inf (null in the resolved parameters).
        field.set(p, fallback);
        c.store(key, YAML::Node(YAML::NodeType::Null));
      } else {
        field.set(p, c.number(key, fallback, range));
      }
  }
}

//! A row the scenario sets as it is, at the top of the controller section. The wheelbases have
//! keys of their own (the registry's lead_wheel); the governor's rows sit in its section.
bool top_level_key(const ParameterField& field, ControllerKeys keys) {
  if (field.scenario != ScenarioKey::direct || field.group == ParameterGroup::governor ||
      field.kind == FieldKind::wheelbases) {
    return false;
  }
  return keys.chain_shape || (field.name != "order" && field.name != "lead_curvature_bound");
}

//! The steering governor (docs/governor.md): its own keys in `governor`; the limits it holds are
//! the vehicle file's (steering_system_controller).
void read_governor_keys(ConfigSection& c, ControllerParameters& p,
                        const VehicleParameters& vehicle) {
  ConfigSection governor = c.section("governor");
  constexpr std::string_view prefix = "governor.";
  for (const ParameterField& field : controller_parameter_fields()) {
    if (field.group != ParameterGroup::governor || field.scenario != ScenarioKey::direct) continue;
    read_field(governor, std::string(field.name.substr(prefix.size())), field, p);
  }
  if (group_enabled(p, ParameterGroup::governor) &&
      !std::isfinite(vehicle.max_steering_acceleration_radps2)) {
    governor.fail("enabled", "needs the vehicle file's max_steering_acceleration_radps2");
  }
  governor.finish();
  c.store("governor", governor.resolved());
}

}  // namespace

Range key_range(std::string_view name) {
  return key_range(*find_parameter_field(name));
}

SteeringSystemOptions lead_wheel_options() {
  SteeringSystemOptions options;
  options.controller = ControllerParameters{};
  options.slip_preview = false;
  options.friction_guard = false;
  return options;
}

void read_controller_keys(ConfigSection& c, SteeringSystemOptions& options,
                          const VehicleParameters& vehicle, ControllerKeys keys) {
  ControllerParameters& p = options.controller;
  for (const ParameterField& field : controller_parameter_fields()) {
    if (top_level_key(field, keys)) read_field(c, std::string(field.name), field, p);
  }
  if (!keys.delay_from_actuator || c.has("actuator_delay_s")) {
    options.actuator_delay_s = find_parameter_field("actuator_delay_s")->get(p);
  }
  // slip_preview: the feedforward inverts the single-track model's lateral dynamics with the
  // vehicle file's K_f and K_r; friction_guard: never ask more than its tires' mu g.
  options.slip_preview = c.boolean("slip_preview", options.slip_preview);
  options.friction_guard = c.boolean("friction_guard", options.friction_guard);
  read_governor_keys(c, p, vehicle);
}

}  // namespace smoothsteer::runner::detail
