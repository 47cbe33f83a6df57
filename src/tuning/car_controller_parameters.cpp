// What the car determines in the lead-wheel controller's parameters: the one derivation from
// the vehicle file and the actuator that make_steering_system() and the scenario runner's
// controller types share (docs/steering_system.md, "Construction").

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "smoothsteer/tuning/vehicle_steering_system.hpp"

namespace smoothsteer {

ControllerParameters default_steering_system_controller() {
  ControllerParameters p;
  p.feedforward.cornering_target = CorneringTarget::rear_axle_exact;
  p.feedforward.curvature_preview = CurvaturePreview::planned_jumps;
  p.law.boundary_layer = 0.03;
  p.governor.enabled = true;
  p.disturbance_estimation = {.enabled = true, .length_m = DisturbanceEstimation::car_length_m};
  return p;
}

VehicleLimits vehicle_limits(const VehicleParameters& vehicle) {
  VehicleLimits limits;
  limits.wheelbase_m = vehicle.wheelbase_m();
  limits.max_steering_angle_rad = vehicle.max_steering_angle_rad;
  limits.max_steering_rate_radps = vehicle.max_steering_rate_radps;
  limits.max_steering_acceleration_radps2 = vehicle.max_steering_acceleration_radps2;
  limits.max_lateral_acceleration_mps2 = vehicle.friction_limit_mps2();
  return limits;
}

double actuator_group_delay_s(const ActuatorParameters& actuator) noexcept {
  // Three equal lags 1 / (1 + s / w_p): each delays a slow signal by 1 / w_p.
  return actuator.dead_time_s + (actuator.ideal ? 0.0 : 3.0 / actuator.pole_radps());
}

InversionSlipGradients inversion_slip_gradients(const VehicleParameters& vehicle) noexcept {
  const double most = ControllerParameters::max_slip_gradient_s2pm;
  return {std::min(vehicle.front_slip_gradient(), most),
          std::min(vehicle.rear_slip_gradient(), most)};
}

LoadTransfer inversion_load_transfer(const VehicleParameters& vehicle) noexcept {
  // Fz_f = m (g lr - a_x h) / L = Fz_f0 (1 - a_x h / (g lr)); Fz_r likewise with + and lf
  // (VehicleParameters::front_axle_load_n).
  const double height_per_g = vehicle.cg_height_m / vehicle.gravity_mps2;
  return {std::min(height_per_g / vehicle.cg_to_rear_axle_m, 1.0),
          std::min(height_per_g / vehicle.cg_to_front_axle_m, 1.0)};
}

SpeedCompensation speed_compensation(const VehicleParameters& vehicle,
                                     double actuator_group_delay_s, const PathDemand& path) {
  const InversionSlipGradients gradients = inversion_slip_gradients(vehicle);
  SpeedCompensation compensation;
  compensation.actuator_group_delay_s = actuator_group_delay_s;
  compensation.slip_gradient_sum_s2pm = gradients.front_s2pm + gradients.rear_s2pm;
  compensation.design_curvature_per_m = path.max_curvature;
  compensation.friction_limit_mps2 = vehicle.friction_limit_mps2();
  return compensation;
}

SpeedCompensation car_speed_compensation(const VehicleDescription& car, const PathDemand& path) {
  return speed_compensation(car.vehicle, actuator_group_delay_s(car.actuator), path);
}

ControllerParameters steering_system_controller(const VehicleDescription& car,
                                                const SteeringSystemOptions& options) {
  const VehicleParameters& vehicle = car.vehicle;
  ControllerParameters p = options.controller;
  p.chain.vehicle_wheelbase_m = vehicle.wheelbase_m();
  // As the scenario files' keys slip_preview and friction_guard (docs/scenarios.md).
  const InversionSlipGradients gradients = inversion_slip_gradients(vehicle);
  p.single_track.rear_slip_gradient_s2pm = options.slip_preview ? gradients.rear_s2pm : 0.0;
  p.single_track.front_slip_gradient_s2pm = options.slip_preview ? gradients.front_s2pm : 0.0;
  const LoadTransfer transfer = inversion_load_transfer(vehicle);
  p.single_track.front_load_transfer_s2pm = options.slip_preview ? transfer.front_s2pm : 0.0;
  p.single_track.rear_load_transfer_s2pm = options.slip_preview ? transfer.rear_s2pm : 0.0;
  p.friction_guard.max_lateral_acceleration_mps2 = options.friction_guard
                                                       ? vehicle.friction_limit_mps2()
                                                       : std::numeric_limits<double>::infinity();
  p.single_track.enabled = p.single_track.rear_slip_gradient_s2pm != 0.0 ||
                           p.single_track.front_slip_gradient_s2pm != 0.0;
  p.friction_guard.enabled = std::isfinite(p.friction_guard.max_lateral_acceleration_mps2);
  if (p.governor.enabled) {
    if (!std::isfinite(vehicle.max_steering_acceleration_radps2)) {
      throw std::invalid_argument(
          "SteeringSystemOptions: controller.governor.enabled needs the vehicle's "
          "max_steering_acceleration_radps2 (VehicleParameters), which is +inf");
    }
    p.governor.max_steering_rate_radps = vehicle.max_steering_rate_radps;
    p.governor.max_steering_acceleration_radps2 = vehicle.max_steering_acceleration_radps2;
    p.governor.max_steering_angle_rad = vehicle.max_steering_angle_rad;
    p.governor.max_lateral_acceleration_mps2 = vehicle.friction_limit_mps2();
  }
  p.delay_compensation.actuator_delay_s =
      options.actuator_delay_s.value_or(actuator_group_delay_s(car.actuator));
  p.delay_compensation.enabled = p.delay_compensation.actuator_delay_s != 0.0;
  return p;
}

}  // namespace smoothsteer
