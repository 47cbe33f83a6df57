#include "smoothsteer/sim/simulation.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <random>
#include <stdexcept>

#include "plant_integration.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/sim/closed_loop_count.hpp"
#include "smoothsteer/sim/gear_changes.hpp"
#include "smoothsteer/vehicle/side_slip_observer.hpp"

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

//! One observer step on what a car's sensors would report now (with the configured noise);
//! returns its beta_r estimate, clamped to what the controller accepts.
template <typename Noise>
double observe_rear_axle_side_slip(SideSlipObserver& observer, const VehicleModel& vehicle,
                                   const VehicleState& state, double steering_angle,
                                   double longitudinal_acceleration, double period,
                                   const SideSlipEstimation& slip, Noise&& noise) {
  const VehicleState rates = vehicle.derivative(state, steering_angle, longitudinal_acceleration);
  SideSlipMeasurement measurement;
  measurement.speed_mps = state.vx_mps;
  measurement.yaw_rate_radps = state.yaw_rate_radps;
  measurement.lateral_acceleration_mps2 = rates.vy_mps + state.vx_mps * state.yaw_rate_radps;
  measurement.steering_angle_rad = steering_angle;
  if (slip.yaw_rate_noise_std_radps > 0.0) {
    measurement.yaw_rate_radps += slip.yaw_rate_noise_std_radps * noise();
  }
  if (slip.lateral_acceleration_noise_std_mps2 > 0.0) {
    measurement.lateral_acceleration_mps2 += slip.lateral_acceleration_noise_std_mps2 * noise();
  }
  if (observer.update(measurement, period) != Status::ok) return 0.0;
  return std::clamp(observer.rear_axle_side_slip_rad(), -ControllerInput::max_side_slip_rad,
                    ControllerInput::max_side_slip_rad);
}

std::string text(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

//! "at t = T s: the controller returned S: <which input is out of range, and its bound>".
std::string controller_error_detail(Status status, const ControllerInput& input, double t) {
  using R = ControllerInputRange;
  std::string detail = "at t = " + text(t) + " s the controller returned " + to_string(status);
  const struct {
    const char* name;
    double value;
    double bound;
    const char* unit;
  } checks[] = {
      {"rear axle x", input.rear_axle_position.x, R::max_abs_coordinate_m, "m"},
      {"rear axle y", input.rear_axle_position.y, R::max_abs_coordinate_m, "m"},
      {"heading", input.heading_rad, R::max_abs_heading_rad, "rad"},
      {"speed", input.speed_mps, R::max_abs_speed_mps, "m/s"},
      {"acceleration", input.acceleration_mps2, R::max_abs_acceleration_mps2, "m/s^2"},
      {"rear-axle side slip", input.rear_axle_side_slip_rad, ControllerInput::max_side_slip_rad,
       "rad"},
  };
  for (const auto& check : checks) {
    if (!(std::abs(check.value) <= check.bound)) {
      return detail + ": its input " + check.name + " = " + text(check.value) + " " + check.unit +
             " is outside ControllerInputRange (magnitude <= " + text(check.bound) + " " +
             check.unit + ")";
    }
  }
  if (status == Status::numerical_error) {
    return detail + ": a value inside the controller became non-finite";
  }
  return detail + " for an input within ControllerInputRange";
}

}  // namespace

PlantIntegrator default_plant_integrator() noexcept {
#if SMOOTHSTEER_HAS_ODEINT
  return PlantIntegrator::dopri5;
#else
  return PlantIntegrator::fixed_rk4;
#endif
}

std::optional<Violation> SimulationParameters::first_violation() const noexcept {
  auto bad = [](const char* field, double value, const char* rule,
                double reference = std::numeric_limits<double>::quiet_NaN()) {
    return Violation{"SimulationParameters", "", field, value, rule, reference};
  };
  if (!std::isfinite(substep_s) || substep_s <= 0.0 || substep_s > 0.01) {
    return bad("substep_s", substep_s, "must be in (0, 0.01]");
  }
  if (!std::isfinite(control_period_s) || control_period_s < substep_s || control_period_s > 1.0) {
    return bad("control_period_s", control_period_s, "must be in [substep_s, 1]");
  }
  const double ratio = control_period_s / substep_s;
  if (std::abs(ratio - std::round(ratio)) > 1e-6) {
    return bad("control_period_s", control_period_s,
               "must be a whole multiple of substep_s =", substep_s);
  }
  if (!std::isfinite(duration_s) || duration_s <= 0.0 || duration_s > 3600.0) {
    return bad("duration_s", duration_s, "must be in (0, 3600]");
  }
  if (duration_s / control_period_s > max_control_steps) {
    return bad("duration_s", duration_s,
               "gives more control steps (duration_s / control_period_s) than allowed:",
               max_control_steps);
  }
  if (duration_s / substep_s > max_substeps) {
    return bad("duration_s", duration_s,
               "gives more plant sub-steps (duration_s / substep_s) than allowed:", max_substeps);
  }
#if !SMOOTHSTEER_HAS_ODEINT
  if (integrator != PlantIntegrator::fixed_rk4) {
    return bad("integrator", static_cast<double>(integrator),
               "needs Boost.Odeint, absent from this build: only fixed_rk4 (0) is available");
  }
#endif
  if (!(integrator_tolerance >= 1e-14 && integrator_tolerance <= 1e-3)) {
    return bad("integrator_tolerance", integrator_tolerance, "must be in [1e-14, 1e-3]");
  }
  if (!std::isfinite(stop_beyond_path_end_m)) {
    return bad("stop_beyond_path_end_m", stop_beyond_path_end_m, "must be finite");
  }
  if (!std::isfinite(matched_disturbance) || std::abs(matched_disturbance) > 1.0) {
    return bad("matched_disturbance", matched_disturbance, "must be in [-1, 1] 1/m");
  }
  if (!std::isfinite(plant_curvature_disturbance) || std::abs(plant_curvature_disturbance) > 1.0) {
    return bad("plant_curvature_disturbance", plant_curvature_disturbance,
               "must be in [-1, 1] 1/m");
  }
  if (!std::isfinite(steering_offset_rad) || std::abs(steering_offset_rad) > 0.1) {
    return bad("steering_offset_rad", steering_offset_rad, "must be in [-0.1, 0.1] rad");
  }
  if (!std::isfinite(position_noise_std_m) || position_noise_std_m < 0.0) {
    return bad("position_noise_std_m", position_noise_std_m, "must be finite and >= 0");
  }
  if (!std::isfinite(heading_noise_std_rad) || heading_noise_std_rad < 0.0) {
    return bad("heading_noise_std_rad", heading_noise_std_rad, "must be finite and >= 0");
  }
  const int source = static_cast<int>(side_slip.source);
  if (source < 0 || source > static_cast<int>(SideSlipSource::observer)) {
    return bad("side_slip.source", source, "must be 0 (none), 1 (truth) or 2 (observer)");
  }
  const int tire_model = static_cast<int>(side_slip.tire_model);
  if (tire_model < 0 || tire_model > static_cast<int>(ObserverTireModel::magic_formula)) {
    return bad("side_slip.tire_model", tire_model, "must be 0 (linear) or 1 (magic_formula)");
  }
  if (!(side_slip.cornering_stiffness_scale >= 0.2 && side_slip.cornering_stiffness_scale <= 5.0)) {
    return bad("side_slip.cornering_stiffness_scale", side_slip.cornering_stiffness_scale,
               "must be in [0.2, 5]");
  }
  if (!(side_slip.mass_scale >= 0.2 && side_slip.mass_scale <= 5.0)) {
    return bad("side_slip.mass_scale", side_slip.mass_scale, "must be in [0.2, 5]");
  }
  if (!(side_slip.yaw_rate_noise_std_radps >= 0.0 && side_slip.yaw_rate_noise_std_radps <= 1.0)) {
    return bad("side_slip.yaw_rate_noise_std_radps", side_slip.yaw_rate_noise_std_radps,
               "must be in [0, 1] rad/s");
  }
  if (!(side_slip.lateral_acceleration_noise_std_mps2 >= 0.0 &&
        side_slip.lateral_acceleration_noise_std_mps2 <= 10.0)) {
    return bad("side_slip.lateral_acceleration_noise_std_mps2",
               side_slip.lateral_acceleration_noise_std_mps2, "must be in [0, 10] m/s^2");
  }
  return std::nullopt;
}

std::string SimulationParameters::validation_error() const {
  return describe(first_violation());
}

void SimulationParameters::validate() const {
  throw_if_violated(first_violation());
}

SimulationResult simulate(const Path& path, const VehicleModel& vehicle,
                          const ActuatorParameters& actuator, const SpeedProfile& speed,
                          const SimulationParameters& parameters, const Pose2& start,
                          SteeringController& controller) {
  std::vector<TraceSample> trace;
  trace.reserve(static_cast<std::size_t>(
      std::min(std::ceil(parameters.duration_s / parameters.control_period_s) + 1.0,
               SimulationParameters::max_control_steps + 1.0)));
  SimulationResult result =
      simulate(path, vehicle, actuator, speed, parameters, start, controller,
               [&trace](const TraceSample& sample) { trace.push_back(sample); });
  result.trace = std::move(trace);
  return result;
}

namespace {

//! The closed loop on `path`, or on the pieces of `plan` (then `path` is its piece 0).
SimulationResult closed_loop(const Path& path, const PathPlan* plan, const VehicleModel& vehicle,
                             const ActuatorParameters& actuator_parameters,
                             const SpeedProfile& speed, const SimulationParameters& parameters,
                             const Pose2& start, SteeringController& controller,
                             const TraceObserver& observer) {
  parameters.validate();
  speed.validate();
  std::vector<GearChange> gear_switches;
  if (plan) {
    check_gear_changes(*plan, speed, parameters.control_period_s);
    gear_switches = gear_changes(speed);
  }
  detail::count_closed_loop();
  const VehicleParameters& car = vehicle.parameters();
  SteeringActuator actuator(actuator_parameters, parameters.substep_s);
  actuator.reset(0.0);
  const int substeps =
      static_cast<int>(std::lround(parameters.control_period_s / parameters.substep_s));
  const long steps =
      static_cast<long>(std::ceil(parameters.duration_s / parameters.control_period_s - 1e-9));

  SimulationResult result;
  std::vector<double> input_buffer(static_cast<std::size_t>(substeps));
  VehicleState state = state_from_rear_axle(start, speed.speed(0.0), car);
  vehicle.constrain(state, 0.0);
  controller.reset(0.0);
  // The active piece of a plan (docs/cusps.md); a plain path is one forward piece.
  std::size_t piece = 0;
  const Path* active = &path;
  double travel_offset = 0.0;  // + pi on a reverse piece: the heading error is the travel's
  if (plan) {
    if (controller.set_path(plan->piece(0).path) != Status::ok) {
      throw std::invalid_argument(std::string(controller.name()) +
                                  " does not support set_path(), which a PathPlan needs");
    }
    travel_offset = plan->piece(0).gear == Gear::reverse ? pi : 0.0;
  }
  // Matched disturbance: into the controller's chain where it has one, else into the plant.
  const double plant_disturbance =
      parameters.plant_curvature_disturbance +
      (controller.set_matched_disturbance(parameters.matched_disturbance)
           ? 0.0
           : parameters.matched_disturbance);
  const detail::PlantContext plant{vehicle,
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
                                   parameters.steering_offset_rad};

  std::mt19937_64 engine(parameters.noise_seed);
  std::normal_distribution<double> unit_normal(0.0, 1.0);
  const SideSlipEstimation& slip = parameters.side_slip;
  SideSlipObserverParameters observer_parameters = SideSlipObserverParameters::from_vehicle(
      car, slip.cornering_stiffness_scale, slip.mass_scale, slip.tire_model);
  // The observer trusts its sensors as much as their simulated noise says (at least its
  // defaults: a noise-free sensor would make the filter over-confident in the model's error).
  observer_parameters.yaw_rate_noise_std_radps =
      std::max(observer_parameters.yaw_rate_noise_std_radps, slip.yaw_rate_noise_std_radps);
  observer_parameters.lateral_acceleration_noise_std_mps2 =
      std::max(observer_parameters.lateral_acceleration_noise_std_mps2,
               slip.lateral_acceleration_noise_std_mps2);
  SideSlipObserver slip_observer(observer_parameters);
  ProjectionHint rear_hint, front_hint;
  ControllerOutput output;
  double distance = 0.0;
  double previous_command = 0.0, previous_rate = 0.0;
  double delayed_input = 0.0;
  result.stop_reason = "duration";

  for (long k = 0; k <= steps; ++k) {
    const double t = static_cast<double>(k) * parameters.control_period_s;
    if (piece < gear_switches.size() && t >= gear_switches[piece].stop_time_s - 1e-9) {
      ++piece;  // at rest on the cusp: on to the next piece
      active = plan->piece(piece).path.get();
      travel_offset = plan->piece(piece).gear == Gear::reverse ? pi : 0.0;
      rear_hint = {};
      front_hint = {};
      state.vx_mps = 0.0;  // the profile's exact 0 (the integration leaves rounding)
      if (const Status status = controller.set_path(plan->piece(piece).path);
          status != Status::ok) {
        result.status = status;
        result.stop_reason = "controller_error";
        result.stop_detail = "at t = " + text(t) + " s set_path() of piece " +
                             std::to_string(piece) + " returned " + to_string(status);
        break;
      }
    }
    const Pose2 rear = rear_axle_pose(state, car);
    ControllerInput input{rear.position, rear.heading_rad, state.vx_mps, speed.acceleration(t),
                          parameters.control_period_s};
    if (parameters.position_noise_std_m > 0.0 || parameters.heading_noise_std_rad > 0.0) {
      input.rear_axle_position.x += parameters.position_noise_std_m * unit_normal(engine);
      input.rear_axle_position.y += parameters.position_noise_std_m * unit_normal(engine);
      input.heading_rad += parameters.heading_noise_std_rad * unit_normal(engine);
    }
    const double true_rear_slip = rear_axle_side_slip_angle(state, car);
    if (slip.source == SideSlipSource::truth) {
      input.rear_axle_side_slip_rad = true_rear_slip;
    } else if (slip.source == SideSlipSource::observer) {
      input.rear_axle_side_slip_rad = observe_rear_axle_side_slip(
          slip_observer, vehicle, state, actuator.angle(), input.acceleration_mps2,
          parameters.control_period_s, slip, [&] { return unit_normal(engine); });
    }
    const Status status = controller.update(input, output);
    if (status != Status::ok) {
      result.status = status;
      result.stop_reason = "controller_error";
      result.stop_detail = controller_error_detail(status, input, t);
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
    sample.lead_lateral_error_m = output.diagnostics.lead_lateral_error_m;
    sample.measured_lateral_error_m = output.diagnostics.lateral_error_m;
    sample.sliding_variable = output.diagnostics.sliding_variable;
    sample.lead_curvature = output.diagnostics.lead_curvature;
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
    sample.rear_side_slip_input_rad = input.rear_axle_side_slip_rad;
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

}  // namespace

SimulationResult simulate(const Path& path, const VehicleModel& vehicle,
                          const ActuatorParameters& actuator, const SpeedProfile& speed,
                          const SimulationParameters& parameters, const Pose2& start,
                          SteeringController& controller, const TraceObserver& observer) {
  return closed_loop(path, nullptr, vehicle, actuator, speed, parameters, start, controller,
                     observer);
}

SimulationResult simulate(const PathPlan& plan, const VehicleModel& vehicle,
                          const ActuatorParameters& actuator, const SpeedProfile& speed,
                          const SimulationParameters& parameters, const Pose2& start,
                          SteeringController& controller, const TraceObserver& observer) {
  return closed_loop(*plan.piece(0).path, &plan, vehicle, actuator, speed, parameters, start,
                     controller, observer);
}

SimulationResult simulate(const PathPlan& plan, const VehicleModel& vehicle,
                          const ActuatorParameters& actuator, const SpeedProfile& speed,
                          const SimulationParameters& parameters, const Pose2& start,
                          SteeringController& controller) {
  std::vector<TraceSample> trace;
  SimulationResult result =
      simulate(plan, vehicle, actuator, speed, parameters, start, controller,
               [&trace](const TraceSample& sample) { trace.push_back(sample); });
  result.trace = std::move(trace);
  return result;
}

}  // namespace smoothsteer
