#include "smoothsteer/runner/controller_registry.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <optional>

#include <filesystem>
#include <stdexcept>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
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
void read_law_options(ConfigSection& c, ControllerParameters& p, const VehicleParameters& vehicle) {
  // Defaults come from the C++ struct: a scenario key and its field cannot disagree.
  const ControllerParameters defaults;
  p.k_rob = c.number("k_rob", defaults.k_rob, {0.0, 1.0, false, true});
  p.boundary_layer = c.number("boundary_layer", defaults.boundary_layer, Range::non_negative());
  p.feedforward_share =
      c.number("feedforward_share", defaults.feedforward_share, {0.0, 1.0, false, true});
  // Absent: the C++ default, no rate limit (+inf, null in the resolved parameters).
  if (c.has("feedforward_curvature_rate")) {
    p.feedforward_curvature_rate =
        c.required_number("feedforward_curvature_rate", Range::non_negative());
  } else {
    p.feedforward_curvature_rate = defaults.feedforward_curvature_rate;
    c.store("feedforward_curvature_rate", YAML::Node(YAML::NodeType::Null));
  }
  p.feedforward_catch_up =
      c.number("feedforward_catch_up", defaults.feedforward_catch_up, {0.0, 1.0});
  p.actuator_delay_s = c.number("actuator_delay_s", defaults.actuator_delay_s,
                                {0.0, ControllerParameters::max_actuator_delay_s});
  p.disturbance_estimation_length_m = c.number(
      "disturbance_estimation_length_m", defaults.disturbance_estimation_length_m, {0.0, 1000.0});
  p.preview_time_s = c.number("preview_time_s", defaults.preview_time_s,
                              {0.0, ControllerParameters::max_actuator_delay_s});
  // slip_preview: the feedforward inverts the single-track model's lateral dynamics, with K_r
  // and K_f from the vehicle file.
  const bool slip_preview = c.boolean("slip_preview", defaults.rear_slip_gradient_s2pm > 0.0);
  const double most = ControllerParameters::max_slip_gradient_s2pm;
  p.rear_slip_gradient_s2pm = slip_preview ? std::min(vehicle.rear_slip_gradient(), most) : 0.0;
  p.front_slip_gradient_s2pm = slip_preview ? std::min(vehicle.front_slip_gradient(), most) : 0.0;
  p.slip_preview_second_order =
      c.boolean("slip_preview_second_order", defaults.slip_preview_second_order);
  // friction_guard: never ask more than the tires' mu g (vehicle file) of lateral acceleration.
  p.max_lateral_acceleration_mps2 =
      c.boolean("friction_guard", std::isfinite(defaults.max_lateral_acceleration_mps2))
          ? vehicle.friction_limit_mps2()
          : std::numeric_limits<double>::infinity();
  p.actuator_time_constant_s =
      c.number("actuator_time_constant_s", defaults.actuator_time_constant_s, {0.0, 0.5});
  p.actuator_lag_count = c.integer("actuator_lag_count", defaults.actuator_lag_count, 1, 3);
  p.approach_angle_rad = c.number("approach_angle_rad", defaults.approach_angle_rad,
                                  {0.0, std::numbers::pi / 2.0, true, false});
  const bool paper_surface = defaults.surface == SlidingSurface::paper;
  const std::string surface =
      c.text("surface", paper_surface ? "paper" : "global", {"global", "paper"});
  p.surface = surface == "paper" ? SlidingSurface::paper : SlidingSurface::global;
  const char* names[] = {"rear_axle", "rear_axle_exact", "lead_wheel"};
  const CorneringTarget kinds[] = {CorneringTarget::rear_axle, CorneringTarget::rear_axle_exact,
                                   CorneringTarget::lead_wheel};
  std::string fallback = names[0];
  for (std::size_t k = 0; k < 3; ++k) {
    if (kinds[k] == defaults.cornering_target) fallback = names[k];
  }
  const std::string target =
      c.text("cornering_target", fallback, {"lead_wheel", "rear_axle", "rear_axle_exact"});
  for (std::size_t k = 0; k < 3; ++k) {
    if (target == names[k]) p.cornering_target = kinds[k];
  }
  const bool planned = defaults.curvature_preview == CurvaturePreview::planned_jumps;
  p.curvature_preview = c.text("curvature_preview", planned ? "planned_jumps" : "centred_ramp",
                               {"centred_ramp", "planned_jumps"}) == "planned_jumps"
                            ? CurvaturePreview::planned_jumps
                            : CurvaturePreview::centred_ramp;
  // The steering governor (docs/governor.md) holds the vehicle file's rate and acceleration
  // limits on the held command and draws its authority from its angle and friction limits.
  ConfigSection governor = c.section("governor");
  SteeringGovernor& g = p.governor;
  g.enabled = governor.boolean("enabled", defaults.governor.enabled);
  g.law_length_m = governor.number("law_length_m", defaults.governor.law_length_m, {0.0, 1000.0});
  g.max_longitudinal_acceleration_mps2 =
      governor.number("max_longitudinal_acceleration_mps2",
                      defaults.governor.max_longitudinal_acceleration_mps2, {0.0, 50.0});
  g.margin = governor.number("margin", defaults.governor.margin, {0.0, 0.5, true, false});
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
  p.max_substep_fraction =
      c.number("max_substep_fraction", defaults.max_substep_fraction, {0.0, 1.0, true, false});
  p.max_substeps = c.integer("max_substeps", defaults.max_substeps, 1, 10000);
}

std::unique_ptr<SteeringController> make_lead_wheel(ConfigSection& c,
                                                    std::shared_ptr<const Path> path,
                                                    const VehicleParameters& vehicle) {
  ControllerParameters p;
  const double wheelbase = vehicle.wheelbase_m();
  p.vehicle_wheelbase_m = wheelbase;
  const ControllerParameters defaults;
  p.order = c.integer("order", defaults.order, 0, ControllerParameters::max_order);
  p.lead_curvature_bound =
      c.number("lead_curvature_bound", defaults.lead_curvature_bound, Range::positive());
  read_law_options(c, p, vehicle);
  // Wheelbases: explicit list, or the paper's choice: n = 1 -> lambda = lambda_veh (eq. ext1);
  // n = 2 -> lambda = sqrt(lambda_veh^2 - lambda_l^2) (eq. cornering_constr).
  if (c.has("wheelbases_m")) {
    const auto list = c.numbers("wheelbases_m", {}, static_cast<std::size_t>(std::max(p.order, 1)),
                                static_cast<std::size_t>(std::max(p.order, 1)), Range::positive());
    for (std::size_t i = 0; i < list.size(); ++i) p.wheelbases_m[i] = list[i];
    if (c.has("lead_wheelbase_m"))
      c.fail("lead_wheelbase_m", "give either wheelbases_m or lead_wheelbase_m");
  } else {
    const double lead = c.number("lead_wheelbase_m", 1.0, {0.0, wheelbase, true, true});
    if (p.order == 2) {
      p.wheelbases_m[0] = cornering_front_wheelbase(wheelbase, lead * lead);
      p.wheelbases_m[1] = lead;
    } else if (p.order == 1) {
      p.wheelbases_m[0] = wheelbase;
    } else if (p.order > 2) {
      c.fail("wheelbases_m", "is required for order " + std::to_string(p.order));
    }
    YAML::Node list(YAML::NodeType::Sequence);
    for (int i = 0; i < p.order; ++i) list.push_back(p.wheelbases_m[static_cast<std::size_t>(i)]);
    c.store("wheelbases_m", list);
  }
  if (const std::string error = p.validation_error(); !error.empty()) {
    throw ConfigError(c.file() + ": key '" + c.full_key("") + "': " + error);
  }
  return std::make_unique<LeadWheelController>(p, std::move(path));
}

//! The lead-wheel controller with a gain schedule from `smoothsteer tune` (docs/tuning.md):
//! `schedule` is the CSV, relative to the scenario file; lambda, lambda_l and kbar_l follow |v|.
std::unique_ptr<SteeringController> make_scheduled_lead_wheel(ConfigSection& c,
                                                              std::shared_ptr<const Path> path,
                                                              const VehicleParameters& vehicle) {
  ControllerParameters base;
  base.vehicle_wheelbase_m = vehicle.wheelbase_m();
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
  std::optional<SpeedCompensation> compensation;
  if (derived) {
    if (!path) c.fail("derived_compensation", "needs the path (its largest curvature)");
    // The scenario loader fills actuator_group_delay_s from the actuator block.
    const double group_delay = c.required_number("actuator_group_delay_s",
                                                 {0.0, ControllerParameters::max_actuator_delay_s});
    compensation = speed_compensation(vehicle, group_delay, *path);
  }
  std::filesystem::path schedule_file = c.required_text("schedule");
  if (schedule_file.is_relative()) {
    schedule_file = std::filesystem::path(c.file()).parent_path() / schedule_file;
  }
  try {
    return std::make_unique<ScheduledController>(read_schedule_csv(schedule_file.string(), base),
                                                 std::move(path), compensation);
  } catch (const std::invalid_argument& error) {
    c.fail("schedule", error.what());  // [[noreturn]]
  }
}

struct Registry {
  std::mutex mutex;
  std::map<std::string, ControllerFactory> factories{
      {"lead_wheel", make_lead_wheel}, {"scheduled_lead_wheel", make_scheduled_lead_wheel}};
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
    std::shared_ptr<const Path> path, const VehicleParameters& vehicle, YAML::Node* resolved,
    std::shared_ptr<const std::set<std::string>> overridden_keys) {
  ConfigSection c(section, key_path, file);
  c.set_overridden_keys(std::move(overridden_keys));
  const std::vector<std::string> types = controller_types();
  if (!c.has("type")) c.fail("type", "is required (e.g. controller: {type: lead_wheel})");
  const std::string type = c.text("type", "lead_wheel", types);
  ControllerFactory factory;
  {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    factory = r.factories.at(type);
  }
  std::unique_ptr<SteeringController> controller = factory(c, std::move(path), vehicle);
  c.finish();
  if (resolved) *resolved = c.resolved();
  return controller;
}

}  // namespace smoothsteer::runner
