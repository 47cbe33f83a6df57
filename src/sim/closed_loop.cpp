// The closed loop of simulate() (simulation.hpp): the plant, the simulated sensors and the car's
// SteeringSystem, sampled with a zero-order hold. The sensors report what a car's buses and
// localization would: the rear-axle pose (with the configured noise), the speed, the yaw rate
// and lateral acceleration at the CG (with the configured noise), the road-wheel angle, and the
// true rear-axle slip for a system that reads a slip sensor.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "closed_loop.hpp"
#include "planner_window.hpp"
#include "plant_integration.hpp"
#include "pose_delay.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/sim/closed_loop_count.hpp"
#include "smoothsteer/sim/gear_changes.hpp"
#include "smoothsteer/sim/simulation.hpp"

namespace smoothsteer {
namespace {

bool finite(const VehicleState& s) {
  for (double v : s.to_array()) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

bool all_finite(const TraceSample& sample) {
  for (double v : trace_values(sample)) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

std::string text(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

//! "at t = T s: the controller returned S: <which input is out of range, and its bound>".
std::string controller_error_detail(Status status, const ControllerInput& input, double t) {
  std::string detail = "at t = " + text(t) + " s the controller returned " + to_string(status);
  if (const std::optional<InputRangeViolation> bad = first_input_range_violation(input)) {
    const std::string unit = std::string(" ") + bad->unit;
    const std::string range = bad->low == -bad->high
                                  ? "magnitude <= " + text(bad->high) + unit
                                  : std::string(bad->low_open ? "in (" : "in [") + text(bad->low) +
                                        ", " + text(bad->high) + "]" + unit;
    return detail + ": its input " + bad->field + " = " + text(bad->value) + unit +
           " is outside ControllerInputRange (" + range + ")";
  }
  if (status == Status::numerical_error) {
    return detail + ": a value inside the controller became non-finite";
  }
  return detail + " for an input within ControllerInputRange";
}

}  // namespace

namespace detail {

SimulationResult closed_loop(const Path& path, const PathPlan* plan, const VehicleModel& told,
                             const ActuatorParameters& actuator_parameters,
                             const SpeedProfile& speed, const SimulationParameters& parameters,
                             const Pose2& start, SteeringSystem& system,
                             const TraceObserver& observer) {
  parameters.validate();
  speed.validate();
  std::vector<GearChange> gear_switches;
  if (plan) {
    check_gear_changes(*plan, speed, parameters.control_period_s);
    gear_switches = gear_changes(speed);
  }
  // The plant: the given model and actuator, or copies with the plant-only scales.
  std::unique_ptr<VehicleModel> scaled_vehicle;
  const VehicleModel& vehicle = plant_model(told, parameters.plant_scales, scaled_vehicle);
  if (dynamic_cast<const KinematicVehicleModel*>(&vehicle) &&
      (parameters.crossfall != 0.0 || parameters.side_force.active())) {
    throw std::invalid_argument(
        "SimulationParameters: crossfall and side_force act through the tires' lateral forces, "
        "which the kinematic plant has not (its rear axle rolls without slip); use the dynamic "
        "or double_track plant, or plant_curvature_disturbance");
  }
  SteeringActuator actuator(
      parameters.plant_actuator_scales.identity()
          ? actuator_parameters
          : scaled_plant_actuator(actuator_parameters, parameters.plant_actuator_scales,
                                  parameters.substep_s),
      parameters.substep_s);
  detail::count_closed_loop();
  const VehicleParameters& car = vehicle.parameters();
  actuator.reset(0.0);
  const int substeps =
      static_cast<int>(std::lround(parameters.control_period_s / parameters.substep_s));
  const long steps =
      static_cast<long>(std::ceil(parameters.duration_s / parameters.control_period_s - 1e-9));

  SimulationResult result;
  std::vector<double> input_buffer(static_cast<std::size_t>(substeps));
  VehicleState state = state_from_rear_axle(start, speed.speed(0.0), car);
  vehicle.constrain(state, 0.0);
  (void)system.reset(0.0);  // 0 is always accepted
  // The active piece of a plan (docs/cusps.md); a plain path is one forward piece.
  std::size_t piece = 0;
  const Path* active = &path;
  double travel_offset = 0.0;  // + pi on a reverse piece: the heading error is the travel's
  if (plan) {
    if (system.set_path(plan->piece(0).path) != Status::ok) {
      throw std::invalid_argument(std::string(system.controller().name()) +
                                  " does not support set_path(), which a PathPlan needs");
    }
    travel_offset = plan->piece(0).gear == Gear::reverse ? pi : 0.0;
  }
  // Matched disturbance: into the controller's chain where it has one, else into the plant.
  const double plant_disturbance = parameters.plant_curvature_disturbance +
                                   (system.set_matched_disturbance(parameters.matched_disturbance)
                                        ? 0.0
                                        : parameters.matched_disturbance);
  const detail::PlantContext plant{
      vehicle,
      speed,
      actuator,
      plant_disturbance,
      parameters.substep_s,
      substeps,
      parameters.integrator,
      parameters.integrator_tolerance,
      &result.model_evaluations,
      &result.plant_fallback_periods,
      input_buffer.data(),
      parameters.steering_offset_rad,
      crossfall_lateral_acceleration(parameters.crossfall, car.gravity_mps2),
      parameters.side_force};
  PoseDelay pose_delay(parameters.pose_latency_s, parameters.pose_rate_hz,
                       parameters.control_period_s, start, speed.speed(0.0));

  // Stack mode: a window of the active piece every planner period (from step 0 on), jittered by a
  // generator of its own so that the sensors' noise sequence stays the run's.
  const PlannerWindows& planner = parameters.planner;
  const long planner_steps =
      planner.active() ? std::lround(planner.period_s / parameters.control_period_s) : 0;
  std::mt19937_64 planner_engine(parameters.noise_seed ^ 0x9e3779b97f4a7c15ULL);
  WaypointConditioner conditioner;
  ProjectionHint planner_hint;

  std::mt19937_64 engine(parameters.noise_seed);
  std::normal_distribution<double> unit_normal(0.0, 1.0);
  const SideSlipEstimation& sensors = parameters.side_slip;
  // Only the observer reads the gyro and the accelerometer; their noise is drawn for it alone,
  // so that a run's noise sequence does not depend on sensors nobody reads.
  const bool observed = system.parameters().slip_input == SlipInput::observer;
  ProjectionHint rear_hint, front_hint;
  SteeringSystemOutput output;
  double distance = 0.0;
  double previous_command = 0.0, previous_rate = 0.0;
  double delayed_input = 0.0;
  result.stop_reason = "duration";

  for (long k = 0; k <= steps; ++k) {
    const double t = static_cast<double>(k) * parameters.control_period_s;
    bool new_piece = false;
    if (piece < gear_switches.size() && t >= gear_switches[piece].stop_time_s - 1e-9) {
      ++piece;  // at rest on the cusp: on to the next piece
      active = plan->piece(piece).path.get();
      travel_offset = plan->piece(piece).gear == Gear::reverse ? pi : 0.0;
      rear_hint = {};
      front_hint = {};
      planner_hint = {};
      new_piece = true;
      state.vx_mps = 0.0;  // the profile's exact 0 (the integration leaves rounding)
      if (const Status status = system.set_path(plan->piece(piece).path); status != Status::ok) {
        result.status = status;
        result.stop_reason = "controller_error";
        result.stop_detail = "at t = " + text(t) + " s set_path() of piece " +
                             std::to_string(piece) + " returned " + to_string(status);
        break;
      }
    }
    const Pose2 rear = rear_axle_pose(state, car);
    if (planner_steps > 0 && (k % planner_steps == 0 || new_piece)) {
      const double center = active->project(rear.position, planner_hint).arc_length_m;
      std::shared_ptr<const Path> window;
      try {
        window = planner_window(*active, center, planner, planner_engine, conditioner);
      } catch (const std::exception& error) {
        throw std::invalid_argument("SimulationParameters.planner: the window at t = " + text(t) +
                                    " s cannot be fitted: " + error.what());
      }
      if (const Status status = system.set_path(std::move(window)); status != Status::ok) {
        result.status = status;
        result.stop_reason = "controller_error";
        result.stop_detail = "at t = " + text(t) + " s set_path() of the planner's window " +
                             "returned " + to_string(status);
        break;
      }
    }
    SteeringSystemInput input;
    const Pose2 localized = pose_delay.deliver(k, rear);
    input.rear_axle_position = localized.position;
    input.heading_rad = localized.heading_rad;
    if (parameters.pose_age_known && pose_delay.active()) {
      input.pose_age_s = std::max(0.0, t - pose_delay.sampled_time(k));
    }
    input.speed_mps = state.vx_mps;
    input.acceleration_mps2 = speed.acceleration(t);
    input.period_s = parameters.control_period_s;
    if (parameters.position_noise_std_m > 0.0 || parameters.heading_noise_std_rad > 0.0) {
      input.rear_axle_position.x += parameters.position_noise_std_m * unit_normal(engine);
      input.rear_axle_position.y += parameters.position_noise_std_m * unit_normal(engine);
      input.heading_rad += parameters.heading_noise_std_rad * unit_normal(engine);
    }
    const double true_rear_slip = rear_axle_side_slip_angle(state, car);
    input.rear_axle_side_slip_rad = true_rear_slip;
    input.steering_angle_rad = actuator.angle();
    if (parameters.steering_angle_sensor_offset_rad != 0.0) {
      input.steering_angle_rad = actuator.angle() + parameters.steering_angle_sensor_offset_rad;
    }
    // The gyro and the accelerometer (the specific force: the crossfall's gravity is not in it,
    // a side force is) on time, whoever reads them; their noise only for the observer.
    input.yaw_rate_radps = state.yaw_rate_radps;
    if (parameters.gyro_bias_radps != 0.0) input.yaw_rate_radps += parameters.gyro_bias_radps;
    // The accelerometer reads the plant: its wheels steer with the rack offset.
    const VehicleState rates = vehicle.derivative(
        state, detail::plant_steering_angle(plant, actuator.angle()), input.acceleration_mps2);
    input.lateral_acceleration_mps2 = rates.vy_mps + state.vx_mps * state.yaw_rate_radps;
    if (parameters.side_force.active()) {
      input.lateral_acceleration_mps2 += detail::body_acceleration(plant, state, t, false).lateral;
    }
    if (observed) {
      if (sensors.yaw_rate_noise_std_radps > 0.0) {
        input.yaw_rate_radps += sensors.yaw_rate_noise_std_radps * unit_normal(engine);
      }
      if (sensors.lateral_acceleration_noise_std_mps2 > 0.0) {
        input.lateral_acceleration_mps2 +=
            sensors.lateral_acceleration_noise_std_mps2 * unit_normal(engine);
      }
    }
    const Status status = system.update(input, output);
    if (status != Status::ok) {
      result.status = status;
      result.stop_reason = "controller_error";
      result.stop_detail = controller_error_detail(status, system.controller_input(), t);
      break;
    }
    const double command = output.steering_angle_rad;
    TraceSample sample;
    sample.time_s = t;
    sample.distance_m = distance;
    sample.rear_axle = rear;
    sample.speed_mps = state.vx_mps;
    sample.acceleration_mps2 = input.acceleration_mps2;
    const PathProjection rear_projection = active->project(rear.position, rear_hint);
    const PathProjection front_projection =
        active->project(front_axle_position(state, car), front_hint);
    sample.path_arc_length_m = rear_projection.arc_length_m;
    sample.path_curvature = rear_projection.curvature;
    sample.lateral_error_m = rear_projection.lateral_error_m;
    sample.heading_error_rad =
        wrap_angle(rear.heading_rad + travel_offset - rear_projection.heading_rad);
    sample.front_lateral_error_m = front_projection.lateral_error_m;
    record_controller_report(sample, output.tracking);
    sample.steering_command_rad = command;
    const double difference_rate =
        k > 0 ? (command - previous_command) / parameters.control_period_s : 0.0;
    sample.steering_command_rate_radps =
        output.derivatives_available >= 1 ? output.steering_rate_radps : difference_rate;
    sample.steering_command_acceleration_radps2 =
        output.derivatives_available >= 2
            ? output.steering_acceleration_radps2
            : (k > 0 ? (sample.steering_command_rate_radps - previous_rate) /
                           parameters.control_period_s
                     : 0.0);
    previous_command = command;
    previous_rate = sample.steering_command_rate_radps;
    sample.steering_actual_rad = actuator.angle();
    sample.steering_actual_rate_radps = actuator.rate(delayed_input);
    sample.steering_actual_acceleration_radps2 = actuator.acceleration(delayed_input);
    sample.side_slip_rad = side_slip_angle(state);
    sample.rear_side_slip_rad = true_rear_slip;
    sample.rear_side_slip_input_rad = output.side_slip.rear_axle_side_slip_rad;
    sample.slip_error = output.side_slip.slip_error;
    sample.course_bias_rad = output.side_slip.course_bias_rad;
    sample.lateral_velocity_mps = state.vy_mps;
    sample.yaw_rate_radps = state.yaw_rate_radps;
    if (!all_finite(sample)) {
      result.non_finite = true;
      result.stop_reason = "non_finite";
      result.stop_detail = "at t = " + text(t) + " s a trace value became non-finite";
      break;
    }
    observer(sample);

    const bool last_piece = !plan || piece + 1 == plan->piece_count();
    if (parameters.stop_at_path_end && !active->is_closed() && last_piece &&
        (rear_projection.arc_length_m > active->length() + parameters.stop_beyond_path_end_m ||
         (plan && speed.knots->back().speed_mps == 0.0 && t >= speed.knots->back().time_s))) {
      result.stop_reason = "path_end";
      break;
    }
    if (k == steps) break;
    // Zero-order hold of the command over the control period (src/sim/plant_integration.hpp).
    delayed_input = detail::advance_plant(plant, t, command, state, distance);
    if (!finite(state)) {
      result.non_finite = true;
      result.stop_reason = "non_finite";
      result.stop_detail = "after t = " + text(t) + " s the plant state became non-finite";
      break;
    }
  }
  result.final_state = state;
  return result;
}

}  // namespace detail
}  // namespace smoothsteer
