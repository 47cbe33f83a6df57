#include "smoothsteer/evaluation/certified_route.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "smoothsteer/tuning/path_demand.hpp"
#include "smoothsteer/tuning/scheduled_controller.hpp"

namespace smoothsteer {

namespace {

constexpr double speed_step_mps = 0.5;  // the step of the committed schedules (scenarios/*.yaml)
constexpr double gravity_mps2 = 9.81;   // as load_vehicle_limits

//! What the certified route takes from the scenario's own controller: the options of its
//! committed schedule (the template `base`, the order and the feedforward headroom: the largest
//! kbar_ff over the path's curvature bound; the CSV does not store the headroom, `tune
//! --feedforward-headroom`) and its delay and catch-up over speed (derived_compensation).
struct OwnSchedule {
  TuningOptions options;
  std::optional<SpeedCompensation> compensation;
};

OwnSchedule own_schedule(const runner::Scenario& scenario) {
  const std::unique_ptr<ScheduledController> scheduled =
      runner::make_scheduled_controller(scenario);
  if (scheduled == nullptr) {
    throw std::invalid_argument(scenario.file + ": key 'controller.type': the certified route " +
                                "needs a scheduled_lead_wheel, not '" +
                                runner::make_controller(scenario)->name() + "'");
  }
  TuningOptions options = scheduled->schedule().options();
  apply_path_demand(options, scenario.path);
  double largest_feedforward_bound = 0.0;
  for (const ScheduleEntry& e : scheduled->schedule().entries()) {
    largest_feedforward_bound = std::max(largest_feedforward_bound, e.feedforward_curvature_bound);
  }
  if (options.path_curvature_bound > 0.0 && largest_feedforward_bound > 0.0) {
    constexpr double resolution = 1e6;  // the CSV's 12 digits leave the ratio off by ~1e-11
    const double ratio = largest_feedforward_bound / options.path_curvature_bound;
    options.feedforward_headroom =
        std::clamp(std::round(ratio * resolution) / resolution, 1.0, 3.0);
  }
  return {options, scheduled->compensation()};
}

}  // namespace

VehicleLimits vehicle_limits_of(const runner::Scenario& scenario) {
  const VehicleParameters& v = scenario.vehicle;
  VehicleLimits limits;
  limits.wheelbase_m = v.wheelbase_m();
  limits.max_steering_angle_rad = v.max_steering_angle_rad;
  limits.max_steering_rate_radps = v.max_steering_rate_radps;
  limits.max_steering_acceleration_radps2 = v.max_steering_acceleration_radps2;
  limits.max_lateral_acceleration_mps2 =
      std::min(v.front_tire.friction_mu, v.rear_tire.friction_mu) * gravity_mps2;
  return limits;
}

std::vector<double> certified_speed_grid(const runner::Scenario& scenario) {
  const double top =
      std::max(scenario.speed.initial_speed_mps,
               scenario.speed.acceleration_mps2 > 0.0 ? scenario.speed.final_speed_mps : 0.0);
  // One step beyond: parameters_at() blends each interval's upper entry with the next one.
  const double last = std::ceil(top / speed_step_mps) * speed_step_mps + speed_step_mps;
  return speed_grid(speed_step_mps, last, speed_step_mps);
}

namespace {

TuningOptions route_options(const runner::Scenario& scenario, const TuningOptions& committed,
                            const std::vector<std::pair<std::string, double>>& knobs) {
  TuningOptions options;
  options.certificate = Certificate::feedforward;
  options.base = committed.base;
  options.order = committed.order;
  options.feedforward_headroom = committed.feedforward_headroom;
  apply_path_demand(options, scenario.path);
  if (scenario.speed.acceleration_mps2 > 0.0 &&
      scenario.speed.final_speed_mps != scenario.speed.initial_speed_mps) {
    options.max_longitudinal_acceleration_mps2 = scenario.speed.acceleration_mps2;
  }
  for (const auto& [key, value] : knobs) {
    if (key == "feedforward_rate_share") {
      options.feedforward_rate_share = value;
    } else if (key == "k_rob_floor") {
      options.k_rob_floor = value;
    } else if (key == "switching_floor_share") {
      options.switching_floor_share = value;
    } else if (key == "feedforward_rate_margin") {
      options.feedforward_rate_margin = value;
    } else if (key == "boundary_layer") {
      options.base.law.boundary_layer = value;
    } else {
      throw std::invalid_argument("certified_route_options: '" + key +
                                  "' is not a knob of the certified route (docs/baselines.md)");
    }
  }
  options.validate();
  return options;
}

}  // namespace

TuningOptions certified_route_options(const runner::Scenario& scenario,
                                      const std::vector<std::pair<std::string, double>>& knobs) {
  return route_options(scenario, own_schedule(scenario).options, knobs);
}

std::unique_ptr<SteeringController> make_certified_controller(
    const runner::Scenario& scenario, const std::vector<std::pair<std::string, double>>& knobs) {
  const OwnSchedule own = own_schedule(scenario);
  const TuningOptions options = route_options(scenario, own.options, knobs);
  GainSchedule schedule = compute_feedforward_schedule(vehicle_limits_of(scenario), options,
                                                       certified_speed_grid(scenario));
  // The delay and the catch-up over speed as the scenario's own controller has them, so that
  // the route differs from the file only in its schedule.
  return std::make_unique<ScheduledController>(std::move(schedule), scenario.path,
                                               own.compensation);
}

}  // namespace smoothsteer
