#include "smoothsteer/runner/controller_registry.hpp"

#include <algorithm>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "controller_keys.hpp"
#include "path_demands.hpp"
#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/controller/steering_certificate.hpp"
#include "smoothsteer/io/schedule_files.hpp"
#include "smoothsteer/tuning/scheduled_controller.hpp"
#include "smoothsteer/tuning/vehicle_steering_system.hpp"

namespace smoothsteer::runner {
using detail::lead_wheel_options;
using detail::read_controller_keys;
using io::ConfigError;
using io::ConfigSection;
using io::Range;
using io::read_schedule_csv;
namespace {

//! The paper's wheelbases unless `wheelbases_m` lists them: n = 1 -> lambda = lambda_veh
//! (eq. ext1); n = 2 -> lambda = sqrt(lambda_veh^2 - lambda_l^2) (eq. cornering_constr) for the
//! lead wheelbase `lead_wheelbase_m`.
void read_wheelbases(ConfigSection& c, ChainParameters& chain, double vehicle_wheelbase_m) {
  const auto count = static_cast<std::size_t>(std::max(chain.order, 1));
  if (c.has("wheelbases_m")) {
    const auto list =
        c.numbers("wheelbases_m", {}, count, count, detail::key_range("wheelbases_m"));
    for (std::size_t i = 0; i < list.size(); ++i) chain.wheelbases_m[i] = list[i];
    if (c.has("lead_wheelbase_m"))
      c.fail("lead_wheelbase_m", "give either wheelbases_m or lead_wheelbase_m");
    return;
  }
  const double lead = c.number("lead_wheelbase_m", 1.0, {0.0, vehicle_wheelbase_m, true, true});
  if (chain.order == 2) {
    chain.wheelbases_m[0] = cornering_front_wheelbase(vehicle_wheelbase_m, lead * lead);
    chain.wheelbases_m[1] = lead;
  } else if (chain.order == 1) {
    chain.wheelbases_m[0] = vehicle_wheelbase_m;
  } else if (chain.order > 2) {
    c.fail("wheelbases_m", "is required for order " + std::to_string(chain.order));
  }
  YAML::Node list(YAML::NodeType::Sequence);
  for (int i = 0; i < chain.order; ++i)
    list.push_back(chain.wheelbases_m[static_cast<std::size_t>(i)]);
  c.store("wheelbases_m", list);
}

//! The paper's controller (Sec. II-III) with ControllerParameters' defaults (n = 2, k_rob = 0.3,
//! the rear axle on curved paths) and the wheelbases of Sec. IV-A.
std::unique_ptr<LeadWheelController> make_lead_wheel(ConfigSection& c,
                                                     const ControllerContext& context) {
  SteeringSystemOptions options = lead_wheel_options();
  read_controller_keys(c, options, context.vehicle, {});
  read_wheelbases(c, options.controller.chain, context.vehicle.wheelbase_m());
  const ControllerParameters p =
      steering_system_controller({context.vehicle, context.actuator}, options);
  if (const std::string error = p.validation_error(); !error.empty()) {
    throw ConfigError(c.file() + ": key '" + c.full_key("") + "': " + error);
  }
  return std::make_unique<LeadWheelController>(p, context.path);
}

//! The lead-wheel controller with a gain schedule from `smoothsteer tune` (docs/tuning.md):
//! `schedule` is the CSV, relative to the scenario file; lambda, lambda_l and kbar_l follow |v|.
std::unique_ptr<ScheduledController> make_scheduled_lead_wheel(ConfigSection& c,
                                                               const ControllerContext& context) {
  const VehicleDescription car{context.vehicle, context.actuator};
  const std::shared_ptr<const Path>& path = context.path;
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
  SteeringSystemOptions options = lead_wheel_options();
  read_controller_keys(c, options, car.vehicle, {.chain_shape = false});
  // The car's block estimates the plant's disturbance unless the file says otherwise
  // (DisturbanceEstimation::car_length_m; 0 turns it off).
  if (derived && !c.has("disturbance_estimation_length_m")) {
    options.controller.disturbance_estimation = {.enabled = true,
                                                 .length_m = DisturbanceEstimation::car_length_m};
  }
  std::optional<SpeedCompensation> compensation;
  if (derived) {
    if (!path) c.fail("derived_compensation", "needs the path (its largest curvature)");
    compensation = car_speed_compensation(car, detail::shared_path_demand(path));
  }
  std::filesystem::path schedule_file = c.required_text("schedule");
  if (schedule_file.is_relative()) {
    schedule_file = std::filesystem::path(c.file()).parent_path() / schedule_file;
  }
  try {
    return std::make_unique<ScheduledController>(
        read_schedule_csv(schedule_file.string(), steering_system_controller(car, options)), path,
        compensation);
  } catch (const std::invalid_argument& error) {
    c.fail("schedule", error.what());  // [[noreturn]]
  }
}

//! The paths the car's system is certified for: `domain`, each absent key the car's
//! (DrivingDomain::for_vehicle).
DrivingDomain read_domain(ConfigSection& c, const VehicleParameters& vehicle) {
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
  return domain;
}

//! The car's own system (make_car_controller, docs/steering_system.md): the schedule certified
//! over a driving domain from the vehicle file and the actuator, no schedule CSV. Every law key
//! of lead_wheel, with the car's block (default_steering_system_controller()) as the default;
//! max_speed_mps (40), feedforward_headroom (1.2), and `domain`.
std::unique_ptr<ScheduledController> make_car_system(ConfigSection& c,
                                                     const ControllerContext& context) {
  SteeringSystemOptions options;
  options.max_speed_mps = c.number("max_speed_mps", 40.0, {1.0, 100.0});
  options.feedforward_headroom =
      c.number("feedforward_headroom", options.feedforward_headroom, {1.0, 3.0});
  read_controller_keys(c, options, context.vehicle,
                       {.chain_shape = false, .delay_from_actuator = true});
  options.domain = read_domain(c, context.vehicle);
  try {
    return make_car_controller({context.vehicle, context.actuator}, options, context.path);
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
  //! The names whose factory is still the built-in one (make_lead_wheel_controller() and
  //! make_scheduled_controller() build only these).
  std::set<std::string> built_in{"lead_wheel", "scheduled_lead_wheel", "steering_system"};
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
  r.built_in.erase(name);
}

std::vector<std::string> controller_types() {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  std::vector<std::string> names;
  for (const auto& entry : r.factories) names.push_back(entry.first);
  return names;
}

namespace {

//! The section's `type`; without one (or without the section) the car's own system: one front
//! door, built from the scenario's vehicle and actuator alone.
std::string controller_type(ConfigSection& c) {
  return c.text("type", "steering_system", controller_types());
}

//! Builds a built-in type with its own factory as make_controller() would, or nullptr when the
//! section's type is none of `types`.
template <class Concrete>
std::unique_ptr<Concrete> make_built_in(
    const YAML::Node& section, const std::string& key_path, const std::string& file,
    const ControllerContext& context,
    std::initializer_list<std::pair<
        const char*, std::unique_ptr<Concrete> (*)(ConfigSection&, const ControllerContext&)>>
        types) {
  ConfigSection c(section, key_path, file);
  const std::string type = controller_type(c);
  {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    if (!r.built_in.contains(type)) return nullptr;
  }
  for (const auto& [name, factory] : types) {
    if (type != name) continue;
    std::unique_ptr<Concrete> controller = factory(c, context);
    c.finish();
    return controller;
  }
  return nullptr;
}

}  // namespace

std::unique_ptr<SteeringController> make_controller(
    const YAML::Node& section, const std::string& key_path, const std::string& file,
    const ControllerContext& context, YAML::Node* resolved,
    std::shared_ptr<const std::set<std::string>> overridden_keys) {
  ConfigSection c(section, key_path, file);
  c.set_overridden_keys(std::move(overridden_keys));
  const std::string type = controller_type(c);
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

std::unique_ptr<LeadWheelController> make_lead_wheel_controller(const YAML::Node& section,
                                                                const std::string& key_path,
                                                                const std::string& file,
                                                                const ControllerContext& context) {
  return make_built_in<LeadWheelController>(section, key_path, file, context,
                                            {{"lead_wheel", make_lead_wheel}});
}

std::unique_ptr<ScheduledController> make_scheduled_controller(const YAML::Node& section,
                                                               const std::string& key_path,
                                                               const std::string& file,
                                                               const ControllerContext& context) {
  return make_built_in<ScheduledController>(
      section, key_path, file, context,
      {{"scheduled_lead_wheel", make_scheduled_lead_wheel}, {"steering_system", make_car_system}});
}

}  // namespace smoothsteer::runner
