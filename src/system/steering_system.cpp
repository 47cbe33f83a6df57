#include "smoothsteer/system/steering_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/math/angles.hpp"

namespace smoothsteer {
namespace {

//! The lead-wheel controller for the constructor that builds one: its wheelbase must be the car's.
std::unique_ptr<SteeringController> lead_wheel_for(const VehicleParameters& vehicle,
                                                   const ControllerParameters& controller,
                                                   std::shared_ptr<const Path> path) {
  vehicle.validate();
  const double wheelbase = vehicle.wheelbase_m();
  if (!(std::abs(controller.chain.vehicle_wheelbase_m - wheelbase) <= 1e-9 * wheelbase)) {
    throw std::invalid_argument(describe(Violation{
        "ControllerParameters", "", "vehicle_wheelbase_m", controller.chain.vehicle_wheelbase_m,
        "must be the vehicle's wheelbase lf + lr =", wheelbase}));
  }
  if (!path) throw std::invalid_argument("SteeringSystem: path is null; a path is required");
  return std::make_unique<LeadWheelController>(controller, std::move(path));
}

}  // namespace

SteeringSystemParameters SteeringSystemParameters::from_vehicle(const VehicleParameters& vehicle,
                                                                ObserverTireModel tire_model) {
  SteeringSystemParameters parameters;
  parameters.observer = SideSlipObserverParameters::from_vehicle(vehicle, 1.0, 1.0, tire_model);
  return parameters;
}

std::optional<Violation> SteeringSystemParameters::first_violation() const noexcept {
  RuleChecker check("SteeringSystemParameters");
  const int source = static_cast<int>(slip_input);
  check.require(source >= 0 && source <= static_cast<int>(SlipInput::observer), "slip_input",
                source, "must be 0 (kinematic), 1 (sensor) or 2 (observer)");
  if (slip_input == SlipInput::observer) {
    check.include_member(observer.first_violation(), "observer.");
  }
  if (course_error) check.include_member(course_error->first_violation(), "course_error.");
  if (domain) check.include_member(domain->first_violation(), "domain.");
  if (actuator) {
    // The controller's model of the actuator: the simulator's sub-step rules do not apply to it.
    check.require(
        actuator->ideal || (std::isfinite(actuator->bandwidth_hz) && actuator->bandwidth_hz > 0.0),
        "actuator.bandwidth_hz", actuator->bandwidth_hz, "must be finite and > 0");
    check.require(actuator->dead_time_s >= 0.0 && actuator->dead_time_s <= 10.0,
                  "actuator.dead_time_s", actuator->dead_time_s, "must be in [0, 10] s");
  }
  check.require(certified_max_speed_mps > 0.0, "certified_max_speed_mps", certified_max_speed_mps,
                "must be > 0 (+inf: certified at every speed)");
  return check.first();
}

std::string SteeringSystemParameters::validation_error() const {
  return describe(first_violation());
}

void SteeringSystemParameters::validate() const {
  throw_if_violated(first_violation());
}

SteeringSystem::SteeringSystem(std::unique_ptr<SteeringController> controller,
                               const SteeringSystemParameters& parameters)
    : owned_(std::move(controller)) {
  if (!owned_) {
    throw std::invalid_argument("SteeringSystem: controller is null; a controller is required");
  }
  controller_ = owned_.get();
  set_up(parameters);
}

SteeringSystem::SteeringSystem(SteeringController& controller,
                               const SteeringSystemParameters& parameters)
    : controller_(&controller) {
  set_up(parameters);
}

SteeringSystem::SteeringSystem(const VehicleParameters& vehicle,
                               const ControllerParameters& controller,
                               std::shared_ptr<const Path> path, SlipInput slip_input)
    : owned_(lead_wheel_for(vehicle, controller, std::move(path))) {
  controller_ = owned_.get();
  SteeringSystemParameters parameters = SteeringSystemParameters::from_vehicle(vehicle);
  parameters.slip_input = slip_input;
  set_up(parameters);
}

void SteeringSystem::set_up(const SteeringSystemParameters& parameters) {
  parameters.validate();
  parameters_ = parameters;
  if (parameters_.slip_input == SlipInput::observer) {
    observer_.emplace(parameters_.observer);
    pending_observer_.emplace(parameters_.observer);
  }
  // The compensation holds the command to the car's limits the controller was given.
  const std::optional<SteeringLimits> limits = controller_->car_steering_limits();
  if (parameters_.compensate_steering_offset && parameters_.actuator && observer_ && limits &&
      parameters_.observer.max_steering_offset_rad > 0.0) {
    if (limits->is_valid() && std::isfinite(limits->rate_radps)) {
      compensation_.emplace(SteeringOffsetCompensationParameters{
          .actuator = *parameters_.actuator,
          .limits = *limits,
          .max_offset_rad = parameters_.observer.max_steering_offset_rad});
    }
  }
}

void SteeringSystem::forget_course_error() noexcept {
  course_error_.reset();
}

void SteeringSystem::forget_steering_offset() noexcept {
  if (observer_) observer_->forget_steering_offset();
  if (compensation_) compensation_->forget();
}

Status SteeringSystem::reset(double measured_steering_angle_rad) noexcept {
  // With the compensation the controller's chain starts where the road wheels are.
  double chain_angle = measured_steering_angle_rad;
  if (compensation_ && std::isfinite(measured_steering_angle_rad)) {
    const double bound = compensation_->parameters().limits.angle_rad;
    chain_angle = compensation_->wheels_from_measured(measured_steering_angle_rad);
    if (std::abs(measured_steering_angle_rad) <= bound) {
      chain_angle = std::clamp(chain_angle, -bound, bound);
    }
  }
  const Status status = controller_->reset(chain_angle);
  if (status != Status::ok) return status;
  if (compensation_) compensation_->reset(measured_steering_angle_rad);
  if (observer_) observer_->reset();
  pose_latency_.restart();
  course_error_.restart();
  controller_output_ = {};
  last_command_rad_ = measured_steering_angle_rad;
  return Status::ok;
}

Status SteeringSystem::set_path(std::shared_ptr<const Path> path) noexcept {
  const PathCurvatureDemand demand =
      path && parameters_.domain ? curvature_demand(*path) : PathCurvatureDemand{};
  const Status status = controller_->set_path(std::move(path));
  if (status == Status::ok) path_demand_ = demand;
  return status;
}

Status SteeringSystem::set_waypoints(const std::vector<Vec2>& waypoints) {
  return set_path(std::make_shared<const Path>(conditioner_.fit(waypoints)));
}

bool SteeringSystem::valid_input(const SteeringSystemInput& input) const noexcept {
  if (!input_in_range(controller_input_)) return false;
  // The wheel's angle is measured or absent (std::nullopt), never NaN or beyond a half turn.
  if (input.steering_angle_rad && !(std::abs(*input.steering_angle_rad) <= pi)) return false;
  if (parameters_.slip_input == SlipInput::sensor) {
    // As measured: beyond ControllerInput::max_side_slip_rad the controller would reject it.
    return std::abs(input.rear_axle_side_slip_rad.value_or(0.0)) <=
           ControllerInput::max_side_slip_rad;
  }
  return true;
}

double SteeringSystem::rear_axle_side_slip(const SteeringSystemInput& input,
                                           SideSlipDiagnostics& slip) noexcept {
  switch (parameters_.slip_input) {
    case SlipInput::kinematic:
      return 0.0;
    case SlipInput::sensor:
      return input.rear_axle_side_slip_rad.value_or(0.0);
    case SlipInput::observer:
      break;
  }
  // The observer steps on a copy, committed only when the controller accepts the period: an
  // update() that fails changes no state.
  SideSlipObserver& next = *pending_observer_;
  next = *observer_;
  SideSlipMeasurement measurement;
  measurement.speed_mps = input.speed_mps;
  measurement.yaw_rate_radps = input.yaw_rate_radps;
  measurement.lateral_acceleration_mps2 = input.lateral_acceleration_mps2;
  measurement.steering_angle_rad = input.steering_angle_rad.value_or(last_command_rad_);
  slip.observer_status = next.update(measurement, input.period_s);
  slip.side_slip_rad = next.side_slip_rad();
  slip.lateral_velocity_mps = next.lateral_velocity_mps();
  slip.yaw_rate_radps = next.yaw_rate_radps();
  slip.steering_offset_rad = next.steering_offset_rad();
  slip.steering_offset_std_rad = next.steering_offset_std_rad();
  slip.sensors = next.health();
  slip.estimate_trusted = slip.observer_status == Status::ok && slip.sensors.trusted;
  // Not trusted (saturated, or the model's prediction alone): the kinematic assumption.
  if (!slip.estimate_trusted) return 0.0;
  // The estimate is clamped to what the controller accepts (docs/vehicle_dynamics.md).
  return std::clamp(next.rear_axle_side_slip_rad(), -ControllerInput::max_side_slip_rad,
                    ControllerInput::max_side_slip_rad);
}

Status SteeringSystem::update(const SteeringSystemInput& input,
                              SteeringSystemOutput& output) noexcept {
  SideSlipDiagnostics slip;
  controller_input_ = {input.rear_axle_position, input.heading_rad, input.speed_mps,
                       input.acceleration_mps2, input.period_s};
  controller_input_.pose_age_s = input.pose_age_s;
  // Every input is checked before any stage takes it: an error changes no state.
  if (!valid_input(input)) return Status::invalid_input;
  controller_input_.rear_axle_side_slip_rad = rear_axle_side_slip(input, slip);
  // The pose's age where the input does not give it (pose_latency_estimator.hpp), on a copy
  // committed with the observer; from the gyro samples the observer's gates let through.
  // A pose that differs from the last one in any value is a new one (a pose at 10 Hz repeats).
  const bool new_pose =
      !(input.rear_axle_position.x == last_position_.x &&
        input.rear_axle_position.y == last_position_.y && input.heading_rad == last_heading_rad_);
  PoseLatencyEstimator latency = pose_latency_;
  if (parameters_.estimate_pose_age) {
    constexpr std::uint32_t gyro_faults =
        fault_yaw_rate_dropped | fault_yaw_rate_implausible | fault_yaw_rate_innovation;
    const bool gyro_usable = observer_ ? (slip.sensors.last_period & gyro_faults) == 0
                                       : std::isfinite(input.yaw_rate_radps);
    const double estimate = latency.update(
        input.heading_rad, new_pose,
        gyro_usable ? input.yaw_rate_radps : std::numeric_limits<double>::quiet_NaN(),
        input.period_s, ControllerInput::max_pose_age_s);
    if (input.pose_age_s == 0.0) controller_input_.pose_age_s = estimate;
  }
  // What the slip estimate gets wrong about the course, from the pose's steps
  // (course_error_estimator.hpp), on a copy committed with the observer.
  CourseErrorEstimator course_error = course_error_;
  if (parameters_.course_error) {
    // The yaw rate the observer filtered, else the gyro's (NaN when dropped: no bound).
    const double yaw_rate = observer_ ? slip.yaw_rate_radps : input.yaw_rate_radps;
    const double correction =
        course_error.update(*parameters_.course_error,
                            {.position = input.rear_axle_position,
                             .heading_rad = input.heading_rad,
                             .new_pose = new_pose,
                             .rear_axle_side_slip_rad = controller_input_.rear_axle_side_slip_rad,
                             .speed_mps = input.speed_mps,
                             .lateral_acceleration_mps2 = input.speed_mps * yaw_rate,
                             .period_s = input.period_s,
                             .pose_age_s = controller_input_.pose_age_s});
    controller_input_.rear_axle_side_slip_rad =
        std::clamp(controller_input_.rear_axle_side_slip_rad + correction,
                   -ControllerInput::max_side_slip_rad, ControllerInput::max_side_slip_rad);
    controller_input_.slip_gradient_scale = 1.0 + course_error.slip_error();
    slip.slip_error = course_error.slip_error();
    slip.course_bias_rad = course_error.course_bias_rad();
  }
  slip.rear_axle_side_slip_rad = controller_input_.rear_axle_side_slip_rad;
  const Status status = controller_->update(controller_input_, controller_output_);
  if (status != Status::ok) return status;
  if (observer_) std::swap(*observer_, *pending_observer_);
  pose_latency_ = latency;
  course_error_ = course_error;
  last_position_ = input.rear_axle_position;
  last_heading_rad_ = input.heading_rad;
  const ControllerOutput& command = controller_output_;
  output.steering_angle_rad = command.steering_angle_rad;
  output.steering_rate_radps = command.steering_rate_radps;
  output.steering_acceleration_radps2 = command.steering_acceleration_radps2;
  output.derivatives_available = command.derivatives_available;
  if (compensation_) {
    output.steering_angle_rad = compensation_->update(
        command.steering_angle_rad, input.steering_angle_rad, slip.steering_offset_rad,
        slip.steering_offset_std_rad, input.period_s, output.steering_rate_radps,
        output.steering_acceleration_radps2);
    output.derivatives_available = 2;
    output.applied_steering_offset_rad = compensation_->applied_offset_rad();
    output.steering_angle_sensor_bias_rad = compensation_->sensor_bias_rad();
  }
  last_command_rad_ = output.steering_angle_rad;
  output.pose_age_s = controller_input_.pose_age_s;
  output.tracking = command.diagnostics;
  output.side_slip = slip;
  const double speed = std::abs(input.speed_mps);
  output.active_limits = controller_->active_limits(command, speed);
  if (parameters_.domain && path_demand_.beyond(*parameters_.domain, speed)) {
    output.active_limits |= limit_path_beyond_domain;
  }
  if (speed > parameters_.certified_max_speed_mps) {
    output.active_limits |= limit_beyond_certified_speed;
  }
  return Status::ok;
}

}  // namespace smoothsteer
