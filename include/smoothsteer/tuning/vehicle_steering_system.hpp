#pragma once
//! \file vehicle_steering_system.hpp
//! A car's SteeringSystem from its description (the vehicle file and the steering actuator's
//! model) and a path, built once at set-up: the certified gain schedule over speed from the car's
//! limits and the path's demand (compute_feedforward_schedule, docs/tuning.md), driving the
//! lead-wheel controller; the slip gradients of the single-track inversion, the friction guard
//! and the governor's limits from the vehicle file; the Smith predictor's delay from the
//! actuator; and the side-slip observer on the vehicle's mass, inertia and tires.

#include <memory>
#include <optional>
#include <string>

#include "smoothsteer/controller/controller_parameters.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/system/driving_domain.hpp"
#include "smoothsteer/system/steering_system.hpp"
#include "smoothsteer/tuning/path_demand.hpp"
#include "smoothsteer/tuning/scheduled_controller.hpp"
#include "smoothsteer/tuning/speed_compensation.hpp"
#include "smoothsteer/tuning/vehicle_limits.hpp"
#include "smoothsteer/validation.hpp"
#include "smoothsteer/vehicle/steering_actuator.hpp"
#include "smoothsteer/vehicle/vehicle_parameters.hpp"

namespace smoothsteer {

//! What is known about the car: the vehicle file (wheelbase, steering limits, tires, mass) and
//! the model of its steering actuator (dead time and low-pass).
struct VehicleDescription {
  VehicleParameters vehicle;
  ActuatorParameters actuator;

  //! The vehicle's first violation (VehicleParameters), else the actuator's: bandwidth_hz
  //! finite and > 0 (unless ideal), dead_time_s in [0, ControllerParameters::max_actuator_delay_s]
  //! (the plant sub-step is the simulator's business, ActuatorParameters::first_violation).
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  std::string validation_error() const { return describe(first_violation()); }
  void validate() const { throw_if_violated(first_violation()); }
};

//! The template of the lead-wheel controller that make_steering_system() starts from: the
//! exact rear-axle target with planned curvature jumps, the steering governor, boundary layer
//! 0.03 (the block of scenarios/lane_change_15.yaml).
ControllerParameters default_steering_system_controller();

struct SteeringSystemOptions {
  //! The schedule covers |v| up to this [m/s] (grid speed_step_mps, speed_step_mps, ..., one
  //! step beyond the first multiple at or above it); above it the last entry holds, uncertified.
  double max_speed_mps = 20.0;
  double speed_step_mps = 0.5;  //!< [m/s]
  //! TuningOptions::feedforward_headroom: kbar_ff over the path's largest curvature, in [1, 3].
  double feedforward_headroom = 1.2;
  //! |dv/dt| the schedule covers [m/s^2] (TuningOptions::max_longitudinal_acceleration_mps2).
  double max_longitudinal_acceleration_mps2 = 0.0;
  //! Every field the car does not determine (order, cornering target, preview, boundary layer,
  //! governor.enabled ...). vehicle_wheelbase_m, the slip gradients, the friction guard, the
  //! governor's limits and actuator_delay_s are set from the description as below.
  ControllerParameters controller = default_steering_system_controller();
  //! Single-track inversion with the vehicle's slip gradients K_f, K_r (docs/vehicle_dynamics.md).
  bool slip_preview = true;
  //! Friction guard at the tires' mu g (FrictionGuard::max_lateral_acceleration_mps2).
  bool friction_guard = false;
  //! The Smith predictor's delay [s]; absent: it follows the speed from the actuator's dead time
  //! plus the group delay of its low-pass at low frequency, 3 / w_p (none for an ideal
  //! actuator), the tires and the path, and so does the feedforward's catch-up
  //! (speed_compensation.hpp; controller.feedforward_catch_up is then not used).
  std::optional<double> actuator_delay_s;
  SlipInput slip_input = SlipInput::observer;
  ObserverTireModel observer_tire_model = ObserverTireModel::magic_formula;
  //! The paths the car-alone overload of make_steering_system() certifies for; absent:
  //! DrivingDomain::for_vehicle(car.vehicle). The path overload does not use it.
  std::optional<DrivingDomain> domain;

  //! The first rule broken (validation.hpp); is_valid(), validation_error(), validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  std::string validation_error() const { return describe(first_violation()); }
  void validate() const { throw_if_violated(first_violation()); }
};

//! The tuner's view of the car: lf + lr, the steering limits and mu g of its tires.
VehicleLimits vehicle_limits(const VehicleParameters& vehicle);

//! The Smith predictor's delay of the actuator: dead time + 3 / w_p (0 + dead time if ideal).
double actuator_group_delay_s(const ActuatorParameters& actuator) noexcept;

//! The vehicle's slip gradients as the single-track inversion uses them: K_f, K_r of the vehicle
//! file, each at most ControllerParameters::max_slip_gradient_s2pm.
struct InversionSlipGradients {
  double front_s2pm = 0.0;  //!< K_f [s^2/m]
  double rear_s2pm = 0.0;   //!< K_r [s^2/m]
};
InversionSlipGradients inversion_slip_gradients(const VehicleParameters& vehicle) noexcept;

//! The load transfer coefficients the single-track inversion scales its slip gradients with
//! (SingleTrackInversion): t_f = h / (g lr) and t_r = h / (g lf) of the vehicle file, each at
//! most 1 s^2/m.
struct LoadTransfer {
  double front_s2pm = 0.0;  //!< t_f [s^2/m]
  double rear_s2pm = 0.0;   //!< t_r [s^2/m]
};
LoadTransfer inversion_load_transfer(const VehicleParameters& vehicle) noexcept;

//! The delay and catch-up over speed (speed_compensation.hpp) of `vehicle` on a path of demand
//! `path` (path_demand.hpp): t_act = `actuator_group_delay_s`, the inversion's slip gradients,
//! the path's largest curvature as kappa_d and the tires' mu g.
SpeedCompensation speed_compensation(const VehicleParameters& vehicle,
                                     double actuator_group_delay_s, const PathDemand& path);

//! speed_compensation() of the car: its vehicle and its actuator's group delay.
SpeedCompensation car_speed_compensation(const VehicleDescription& car, const PathDemand& path);

//! The controller parameters of `options.controller` with what the car determines: the vehicle
//! wheelbase, the slip gradients (options.slip_preview), the friction guard at mu g
//! (options.friction_guard), the governor's limits (while it is enabled) and the Smith predictor's
//! delay (options.actuator_delay_s, else the actuator's group delay). The one derivation from the
//! car: make_steering_system() gives it the schedule as its template, and the scenario runner's
//! controller types build their parameters with it.
ControllerParameters steering_system_controller(const VehicleDescription& car,
                                                const SteeringSystemOptions& options);

//! Builds the car's steering system on `path`, its schedule certified for the path's demand
//! with a switching authority of at least min_switching_authority_per_m. Where a grid speed is
//! out of reach the schedule ends below it instead of refusing to be built: above
//! parameters().certified_max_speed_mps its last entry holds and update() sets
//! limit_beyond_certified_speed (the governor still holds the car's limits on the command).
//! Throws std::invalid_argument naming the field (vehicle, actuator, options, a null path) and
//! InfeasibleLimits only when the lowest grid speed cannot be certified.
SteeringSystem make_steering_system(const VehicleDescription& car, std::shared_ptr<const Path> path,
                                    const SteeringSystemOptions& options = {});

//! Builds the car's steering system from the car alone, for a driving stack that hands over its
//! paths later by set_path() (update() returns not_configured until the first). The schedule is
//! certified at each grid speed for every path of the domain there (options.domain, else
//! DrivingDomain::for_vehicle; compute_domain_schedule), and ends below a speed out of reach as
//! the path overload's does. A path beyond the domain at the current speed sets
//! limit_path_beyond_domain. The compensation's design curvature follows each path set_path()
//! accepts. Errors as the path overload's.
SteeringSystem make_steering_system(const VehicleDescription& car,
                                    const SteeringSystemOptions& options = {});
//! The controller make_steering_system(car, options) runs: the schedule over the domain, the
//! compensation's design curvature following each path it is given. With `path` it starts on
//! it (the scenario runner's controller type steering_system); without, update() returns
//! not_configured until set_path(). Errors as make_steering_system's.
std::unique_ptr<ScheduledController> make_car_controller(
    const VehicleDescription& car, const SteeringSystemOptions& options = {},
    std::shared_ptr<const Path> path = nullptr);

//! The car's schedule's least switching authority kbar_sw [1/m] (the tuner's default,
//! TuningOptions::min_lead_curvature_bound, is 1e-3): at motorway speeds the steering rate
//! limit leaves a passenger car less than 1e-3 1/m (9.9e-4 at 24 m/s), which still steers the
//! residual the feedforward leaves.
inline constexpr double min_switching_authority_per_m = 1e-4;

}  // namespace smoothsteer
