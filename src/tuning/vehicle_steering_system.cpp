#include "smoothsteer/tuning/vehicle_steering_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "smoothsteer/tuning/gain_schedule.hpp"
#include "smoothsteer/tuning/path_demand.hpp"
#include "smoothsteer/tuning/scheduled_controller.hpp"

namespace smoothsteer {

std::optional<Violation> VehicleDescription::first_violation() const noexcept {
  RuleChecker check("VehicleDescription");
  check.include(vehicle.first_violation());
  if (!actuator.ideal) {
    check.require(std::isfinite(actuator.bandwidth_hz) && actuator.bandwidth_hz > 0.0,
                  "actuator.bandwidth_hz", actuator.bandwidth_hz, "must be finite and > 0");
  }
  check.require(actuator.dead_time_s >= 0.0 &&
                    actuator.dead_time_s <= ControllerParameters::max_actuator_delay_s,
                "actuator.dead_time_s", actuator.dead_time_s,
                "must be in [0, ControllerParameters::max_actuator_delay_s =",
                ControllerParameters::max_actuator_delay_s);
  return check.first();
}

std::optional<Violation> SteeringSystemOptions::first_violation() const noexcept {
  RuleChecker check("SteeringSystemOptions");
  check.require(std::isfinite(max_speed_mps) && max_speed_mps > 0.0 && max_speed_mps <= 100.0,
                "max_speed_mps", max_speed_mps, "must be in (0, 100] m/s");
  check.require(
      std::isfinite(speed_step_mps) && speed_step_mps >= 0.01 && speed_step_mps <= max_speed_mps,
      "speed_step_mps", speed_step_mps, "must be in [0.01, max_speed_mps] m/s");
  check.require(feedforward_headroom >= 1.0 && feedforward_headroom <= 3.0, "feedforward_headroom",
                feedforward_headroom, "must be in [1, 3]");
  check.require(
      max_longitudinal_acceleration_mps2 >= 0.0 && max_longitudinal_acceleration_mps2 <= 50.0,
      "max_longitudinal_acceleration_mps2", max_longitudinal_acceleration_mps2,
      "must be in [0, 50] m/s^2");
  if (actuator_delay_s) {
    check.require(
        *actuator_delay_s >= 0.0 && *actuator_delay_s <= ControllerParameters::max_actuator_delay_s,
        "actuator_delay_s", *actuator_delay_s,
        "must be in [0, max_actuator_delay_s =", ControllerParameters::max_actuator_delay_s);
  }
  const int source = static_cast<int>(slip_input);
  check.require(source >= 0 && source <= static_cast<int>(SlipInput::observer), "slip_input",
                source, "must be 0 (kinematic), 1 (sensor) or 2 (observer)");
  const int tire = static_cast<int>(observer_tire_model);
  check.require(tire >= 0 && tire <= static_cast<int>(ObserverTireModel::magic_formula),
                "observer_tire_model", tire, "must be 0 (linear) or 1 (magic_formula)");
  return check.first();
}

namespace {

//! What the template may not say: the gain schedule sets k_rob and the feedforward share per
//! speed, so a value given here would be dropped without a word; and the boundary layer, which
//! the tuner does not check (a NaN one came back as InfeasibleLimits).
void check_schedule_template(const ControllerParameters& controller) {
  const ControllerParameters defaults = default_steering_system_controller();
  const double epsilon = controller.law.boundary_layer;
  if (!(std::isfinite(epsilon) && epsilon >= 0.0)) {
    throw std::invalid_argument("SteeringSystemOptions: controller.law.boundary_layer = " +
                                exact_number(epsilon) + " must be finite and >= 0");
  }
  const auto scheduled = [](const char* field, double value, double default_value) {
    throw std::invalid_argument(
        std::string("SteeringSystemOptions: controller.") + field + " = " + exact_number(value) +
        " is set per speed by the gain schedule, which would override it; leave it at " +
        exact_number(default_value) +
        " (for a fixed value, build a LeadWheelController, or a ScheduledController from your "
        "own GainSchedule)");
  };
  if (!(controller.law.k_rob == defaults.law.k_rob)) {
    scheduled("law.k_rob", controller.law.k_rob, defaults.law.k_rob);
  }
  if (!(controller.feedforward.share == defaults.feedforward.share)) {
    scheduled("feedforward.share", controller.feedforward.share, defaults.feedforward.share);
  }
}

//! The tuner's options for the car's schedule, without the path's demand.
TuningOptions schedule_tuning(const VehicleDescription& car, const SteeringSystemOptions& options) {
  options.validate();
  check_schedule_template(options.controller);
  car.validate();
  TuningOptions tuning;
  tuning.certificate = Certificate::feedforward;
  tuning.base = steering_system_controller(car, options);
  tuning.order = tuning.base.chain.order;
  tuning.feedforward_headroom = options.feedforward_headroom;
  tuning.max_longitudinal_acceleration_mps2 = options.max_longitudinal_acceleration_mps2;
  return tuning;
}

//! The schedule's speeds: one step beyond the top speed, since parameters_at() blends each
//! interval's upper entry with the next one.
std::vector<double> schedule_speeds(const SteeringSystemOptions& options) {
  const double step = options.speed_step_mps;
  const double last = std::ceil(options.max_speed_mps / step - 1e-9) * step + step;
  return speed_grid(step, last, step);
}

//! compute(speeds) over the options' grid; where a speed is out of reach (InfeasibleLimits),
//! over the speeds below it instead of refusing: the system then flags the speeds above its
//! certified_max_speed_mps. Refuses only when the lowest speed is out of reach.
template <class Compute>
GainSchedule schedule_degrading_above_reach(const SteeringSystemOptions& options,
                                            Compute&& compute) {
  std::vector<double> speeds = schedule_speeds(options);
  try {
    return compute(speeds);
  } catch (const InfeasibleLimits& error) {
    std::erase_if(speeds, [&](double v) { return v >= error.speed_mps(); });
    if (speeds.empty()) throw;
    return compute(speeds);
  }
}

//! The domain the car-alone schedule is certified for.
DrivingDomain car_domain(const VehicleDescription& car, const SteeringSystemOptions& options) {
  return options.domain.value_or(DrivingDomain::for_vehicle(car.vehicle));
}

SteeringSystemParameters system_parameters(const VehicleDescription& car,
                                           const SteeringSystemOptions& options) {
  SteeringSystemParameters system =
      SteeringSystemParameters::from_vehicle(car.vehicle, options.observer_tire_model);
  system.slip_input = options.slip_input;
  system.actuator = car.actuator;
  return system;
}

}  // namespace

SteeringSystem make_steering_system(const VehicleDescription& car, std::shared_ptr<const Path> path,
                                    const SteeringSystemOptions& options) {
  TuningOptions tuning = schedule_tuning(car, options);
  if (!path) throw std::invalid_argument("make_steering_system: path is null; a path is required");
  tuning.min_lead_curvature_bound = min_switching_authority_per_m;
  const PathDemand demand = apply_path_demand(tuning, path);
  const VehicleLimits limits = vehicle_limits(car.vehicle);
  GainSchedule schedule =
      schedule_degrading_above_reach(options, [&](const std::vector<double>& speeds) {
        return compute_feedforward_schedule(limits, tuning, speeds);
      });
  SteeringSystemParameters system = system_parameters(car, options);
  system.certified_max_speed_mps = schedule.max_speed_mps();
  // Without a delay of the caller's, the delay and the catch-up follow the speed
  // (speed_compensation.hpp), as the shipped scenarios' derived_compensation.
  std::optional<SpeedCompensation> compensation;
  if (!options.actuator_delay_s) {
    compensation = car_speed_compensation(car, demand);
  }
  return SteeringSystem(
      std::make_unique<ScheduledController>(std::move(schedule), std::move(path), compensation),
      system);
}

std::unique_ptr<ScheduledController> make_car_controller(const VehicleDescription& car,
                                                         const SteeringSystemOptions& options,
                                                         std::shared_ptr<const Path> path) {
  TuningOptions tuning = schedule_tuning(car, options);
  tuning.min_lead_curvature_bound = min_switching_authority_per_m;
  const DrivingDomain domain = car_domain(car, options);
  const VehicleLimits limits = vehicle_limits(car.vehicle);
  GainSchedule schedule =
      schedule_degrading_above_reach(options, [&](const std::vector<double>& speeds) {
        return compute_domain_schedule(limits, tuning, domain, speeds);
      });
  std::optional<SpeedCompensation> compensation;
  if (!options.actuator_delay_s) {
    // The design curvature follows each path set_path() accepts (ScheduledController).
    compensation = car_speed_compensation(car, {});
  }
  auto controller =
      std::make_unique<ScheduledController>(std::move(schedule), PathLater{}, compensation);
  if (path && controller->set_path(std::move(path)) != Status::ok) {
    throw std::invalid_argument("make_car_controller: the path was refused");
  }
  return controller;
}

SteeringSystem make_steering_system(const VehicleDescription& car,
                                    const SteeringSystemOptions& options) {
  std::unique_ptr<ScheduledController> controller = make_car_controller(car, options);
  SteeringSystemParameters system = system_parameters(car, options);
  system.domain = car_domain(car, options);
  system.certified_max_speed_mps = controller->schedule().max_speed_mps();
  return SteeringSystem(std::move(controller), system);
}

}  // namespace smoothsteer
