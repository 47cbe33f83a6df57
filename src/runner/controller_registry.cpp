#include "smoothsteer/runner/controller_registry.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <filesystem>
#include <stdexcept>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/controller/parameter_fields.hpp"
#include "smoothsteer/controller/steering_certificate.hpp"
#include "smoothsteer/io/schedule_files.hpp"
#include "smoothsteer/tuning/scheduled_controller.hpp"
#include "smoothsteer/tuning/vehicle_steering_system.hpp"

namespace smoothsteer::runner {
using io::ConfigError;
using io::ConfigSection;
using io::Range;
using io::read_schedule_csv;
namespace {

//! The paper's controller (Sec. II-III). Defaults are ControllerParameters' (n = 2, k_rob = 0.3,
//! the rear axle on curved paths); the wheelbases follow Sec. IV-A: the fictive wheelbase of
//! eq. (cornering_constr).
//! Keys shared by the fixed and the scheduled lead-wheel controller.
void read_law_options(ConfigSection& c, ControllerParameters& p, const VehicleParameters& vehicle,
                      const ControllerParameters& defaults = ControllerParameters{}) {
  // Defaults come from the C++ struct: a scenario key and its field cannot disagree. The direct
  // keys are the field table's (parameter_fields.hpp), each read as its row says; the chain's
  // order, bound and wheelbases are make_lead_wheel's (a schedule gives them otherwise), the
  // slip gradients, the friction guard and the governor follow from the vehicle file below.
  for (const ParameterField& field : controller_parameter_fields()) {
    if (field.scenario != ScenarioKey::direct || field.group == ParameterGroup::governor ||
        field.kind == FieldKind::wheelbases || field.member == "chain.order" ||
        field.member == "chain.lead_curvature_bound") {
      continue;
    }
    const std::string key(field.name);
    const double fallback = field.get(defaults);
    const FieldRange r = field.range.hull();
    switch (field.kind) {
      case FieldKind::integer:
        field.set(p, c.integer(key, static_cast<int>(fallback), static_cast<int>(r.min),
                               static_cast<int>(r.max)));
        break;
      case FieldKind::boolean:
        field.set(p, c.boolean(key, fallback != 0.0) ? 1.0 : 0.0);
        break;
      case FieldKind::choice: {
        std::vector<std::string> names;
        std::istringstream words{std::string(field.choices)};
        for (std::string word; words >> word;) names.push_back(word);
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
          field.set(p, c.number(key, fallback, {r.min, r.max, r.min_open, r.max_open}));
        }
    }
  }
  // slip_preview: the feedforward inverts the single-track model's lateral dynamics, with K_r
  // and K_f from the vehicle file.
  const bool slip_preview = c.boolean("slip_preview", defaults.single_track.enabled);
  const InversionSlipGradients gradients = inversion_slip_gradients(vehicle);
  find_parameter_field("rear_slip_gradient_s2pm")->set(p, slip_preview ? gradients.rear_s2pm : 0.0);
  find_parameter_field("front_slip_gradient_s2pm")
      ->set(p, slip_preview ? gradients.front_s2pm : 0.0);
  // friction_guard: never ask more than the tires' mu g (vehicle file) of lateral acceleration.
  find_parameter_field("max_lateral_acceleration_mps2")
      ->set(p, c.boolean("friction_guard", defaults.friction_guard.enabled)
                   ? vehicle.friction_limit_mps2()
                   : std::numeric_limits<double>::infinity());
  // The steering governor (docs/governor.md) holds the vehicle file's rate and acceleration
  // limits on the held command and draws its authority from its angle and friction limits.
  ConfigSection governor = c.section("governor");
  SteeringGovernor& g = p.governor;
  g.enabled = governor.boolean("enabled", defaults.governor.enabled);
  // The numbers' ranges are the field table's (parameter_fields.cpp): one statement of each rule.
  const auto table_number = [&governor](const std::string& key, double fallback) {
    const FieldRange r = find_parameter_field("governor." + key)->range;
    return governor.number(key, fallback, Range{r.min, r.max, r.min_open, r.max_open});
  };
  g.law_length_m = table_number("law_length_m", defaults.governor.law_length_m);
  g.max_longitudinal_acceleration_mps2 = table_number(
      "max_longitudinal_acceleration_mps2", defaults.governor.max_longitudinal_acceleration_mps2);
  g.margin = table_number("margin", defaults.governor.margin);
  if (g.enabled) {
    g.max_steering_rate_radps = vehicle.max_steering_rate_radps;
    g.max_steering_acceleration_radps2 = vehicle.max_steering_acceleration_radps2;
    g.max_steering_angle_rad = vehicle.max_steering_angle_rad;
    g.max_lateral_acceleration_mps2 = vehicle.friction_limit_mps2();
    if (!std::isfinite(g.max_steering_acceleration_radps2)) {
      governor.fail("enabled", "needs the vehicle file's max_steering_acceleration_radps2");
    }
  }
  governor.finish();
  c.store("governor", governor.resolved());
}

std::unique_ptr<SteeringController> make_lead_wheel(ConfigSection& c,
                                                    const ControllerContext& context) {
  const VehicleParameters& vehicle = context.vehicle;
  ControllerParameters p;
  const double wheelbase = vehicle.wheelbase_m();
  p.chain.vehicle_wheelbase_m = wheelbase;
  const ControllerParameters defaults;
  p.chain.order = c.integer("order", defaults.chain.order, 0, ControllerParameters::max_order);
  p.chain.lead_curvature_bound =
      c.number("lead_curvature_bound", defaults.chain.lead_curvature_bound, Range::positive());
  read_law_options(c, p, vehicle);
  // Wheelbases: explicit list, or the paper's choice: n = 1 -> lambda = lambda_veh (eq. ext1);
  // n = 2 -> lambda = sqrt(lambda_veh^2 - lambda_l^2) (eq. cornering_constr).
  if (c.has("wheelbases_m")) {
    const auto list =
        c.numbers("wheelbases_m", {}, static_cast<std::size_t>(std::max(p.chain.order, 1)),
                  static_cast<std::size_t>(std::max(p.chain.order, 1)), Range::positive());
    for (std::size_t i = 0; i < list.size(); ++i) p.chain.wheelbases_m[i] = list[i];
    if (c.has("lead_wheelbase_m"))
      c.fail("lead_wheelbase_m", "give either wheelbases_m or lead_wheelbase_m");
  } else {
    const double lead = c.number("lead_wheelbase_m", 1.0, {0.0, wheelbase, true, true});
    if (p.chain.order == 2) {
      p.chain.wheelbases_m[0] = cornering_front_wheelbase(wheelbase, lead * lead);
      p.chain.wheelbases_m[1] = lead;
    } else if (p.chain.order == 1) {
      p.chain.wheelbases_m[0] = wheelbase;
    } else if (p.chain.order > 2) {
      c.fail("wheelbases_m", "is required for order " + std::to_string(p.chain.order));
    }
    YAML::Node list(YAML::NodeType::Sequence);
    for (int i = 0; i < p.chain.order; ++i)
      list.push_back(p.chain.wheelbases_m[static_cast<std::size_t>(i)]);
    c.store("wheelbases_m", list);
  }
  if (const std::string error = p.validation_error(); !error.empty()) {
    throw ConfigError(c.file() + ": key '" + c.full_key("") + "': " + error);
  }
  return std::make_unique<LeadWheelController>(p, context.path);
}

//! The lead-wheel controller with a gain schedule from `smoothsteer tune` (docs/tuning.md):
//! `schedule` is the CSV, relative to the scenario file; lambda, lambda_l and kbar_l follow |v|.
std::unique_ptr<SteeringController> make_scheduled_lead_wheel(ConfigSection& c,
                                                              const ControllerContext& context) {
  const VehicleParameters& vehicle = context.vehicle;
  const std::shared_ptr<const Path>& path = context.path;
  ControllerParameters base;
  base.chain.vehicle_wheelbase_m = vehicle.wheelbase_m();
  // The Smith predictor's delay and the catch-up over speed from the car (speed_compensation.hpp)
  // or, without it, the keys actuator_delay_s and feedforward_catch_up as set.
  const bool derived = c.boolean("derived_compensation", false);
  if (derived) {
    for (const char* key : {"actuator_delay_s", "feedforward_catch_up"}) {
      if (c.has(key)) {
        c.fail(key,
               "conflicts with derived_compensation: true, which sets it over speed; give "
               "one or the other");
      }
    }
  }
  read_law_options(c, base, vehicle);
  // The car's block estimates the plant's disturbance unless the file says otherwise
  // (DisturbanceEstimation::car_length_m; 0 turns it off).
  if (derived && !c.has("disturbance_estimation_length_m")) {
    base.disturbance_estimation = {.enabled = true,
                                   .length_m = DisturbanceEstimation::car_length_m};
  }
  std::optional<SpeedCompensation> compensation;
  if (derived) {
    if (!path) c.fail("derived_compensation", "needs the path (its largest curvature)");
    compensation =
        speed_compensation(vehicle, actuator_group_delay_s(context.actuator), path_demand(*path));
  }
  std::filesystem::path schedule_file = c.required_text("schedule");
  if (schedule_file.is_relative()) {
    schedule_file = std::filesystem::path(c.file()).parent_path() / schedule_file;
  }
  try {
    return std::make_unique<ScheduledController>(read_schedule_csv(schedule_file.string(), base),
                                                 path, compensation);
  } catch (const std::invalid_argument& error) {
    c.fail("schedule", error.what());  // [[noreturn]]
  }
}

//! The car's own system (make_car_controller, docs/steering_system.md): the schedule certified
//! over a driving domain from the vehicle file and the actuator, no schedule CSV. Every law key
//! of lead_wheel, with the car's block (default_steering_system_controller()) as the default;
//! max_speed_mps (40), feedforward_headroom (1.2), and `domain` (absent keys: the car's,
//! DrivingDomain::for_vehicle).
std::unique_ptr<SteeringController> make_car_system(ConfigSection& c,
                                                    const ControllerContext& context) {
  const VehicleParameters& vehicle = context.vehicle;
  SteeringSystemOptions options;
  options.max_speed_mps = c.number("max_speed_mps", 40.0, {1.0, 100.0});
  options.feedforward_headroom =
      c.number("feedforward_headroom", options.feedforward_headroom, {1.0, 3.0});
  ControllerParameters defaults = default_steering_system_controller();
  // The template leaves the car's groups off (make_car_controller sets them from the vehicle
  // file); their keys default to what make_steering_system does.
  defaults.single_track.enabled = options.slip_preview;
  defaults.friction_guard.enabled = options.friction_guard;
  ControllerParameters base = default_steering_system_controller();
  base.chain.vehicle_wheelbase_m = vehicle.wheelbase_m();
  read_law_options(c, base, vehicle, defaults);
  options.slip_preview = base.single_track.rear_slip_gradient_s2pm != 0.0 ||
                         base.single_track.front_slip_gradient_s2pm != 0.0;
  options.friction_guard = std::isfinite(base.friction_guard.max_lateral_acceleration_mps2);
  if (c.has("actuator_delay_s")) {
    options.actuator_delay_s = base.delay_compensation.actuator_delay_s;
  }
  options.controller = base;
  ConfigSection domain_keys = c.section("domain");
  DrivingDomain domain = DrivingDomain::for_vehicle(vehicle);
  for (auto [key, field] :
       {std::pair{"max_curvature_per_m", &domain.max_curvature_per_m},
        {"max_lateral_acceleration_mps2", &domain.max_lateral_acceleration_mps2},
        {"max_curvature_rate_per_m2", &domain.max_curvature_rate_per_m2},
        {"max_lateral_jerk_mps3", &domain.max_lateral_jerk_mps3}}) {
    *field = domain_keys.number(key, *field, {0.0, 1e6, true, false});
  }
  domain_keys.finish();
  c.store("domain", domain_keys.resolved());
  options.domain = domain;
  try {
    return make_car_controller({vehicle, context.actuator}, options, context.path);
  } catch (const std::invalid_argument& error) {
    throw ConfigError(c.file() + ": key '" + c.full_key("") + "': " + error.what());
  }
}

struct Registry {
  std::mutex mutex;
  std::map<std::string, ControllerFactory> factories{
      {"lead_wheel", make_lead_wheel},
      {"scheduled_lead_wheel", make_scheduled_lead_wheel},
      {"steering_system", make_car_system}};
};

Registry& registry() {
  static Registry instance;
  return instance;
}

}  // namespace

void register_controller_type(const std::string& name, ControllerFactory factory) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  r.factories[name] = std::move(factory);
}

std::vector<std::string> controller_types() {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  std::vector<std::string> names;
  for (const auto& entry : r.factories) names.push_back(entry.first);
  return names;
}

std::unique_ptr<SteeringController> make_controller(
    const YAML::Node& section, const std::string& key_path, const std::string& file,
    const ControllerContext& context, YAML::Node* resolved,
    std::shared_ptr<const std::set<std::string>> overridden_keys) {
  ConfigSection c(section, key_path, file);
  c.set_overridden_keys(std::move(overridden_keys));
  const std::vector<std::string> types = controller_types();
  // Without a type (or without the section) the car's own system: one front door, built from
  // the scenario's vehicle and actuator alone.
  const std::string type = c.text("type", "steering_system", types);
  ControllerFactory factory;
  {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    factory = r.factories.at(type);
  }
  std::unique_ptr<SteeringController> controller = factory(c, context);
  c.finish();
  if (resolved) *resolved = c.resolved();
  return controller;
}

}  // namespace smoothsteer::runner
