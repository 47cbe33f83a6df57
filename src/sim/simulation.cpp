#include "smoothsteer/sim/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "closed_loop.hpp"

namespace smoothsteer {
namespace {

//! A broken rule of SimulationParameters: its field, value, rule and reference value.
std::optional<Violation> bad(const char* field, double value, const char* rule,
                             double reference = std::numeric_limits<double>::quiet_NaN()) {
  return Violation{"SimulationParameters", "", field, value, rule, reference};
}

//! The rules of the plant-only imperfections (plant_imperfections.hpp).
std::optional<Violation> imperfection_violation(const SimulationParameters& p) noexcept {
  auto within = [](double value, double lo, double hi) { return value >= lo && value <= hi; };
  const PlantScales& scales = p.plant_scales;
  if (!within(scales.mass, 0.5, 2.0)) {
    return bad("plant_scales.mass", scales.mass, "must be in [0.5, 2]");
  }
  if (!within(scales.yaw_inertia, 0.5, 2.0)) {
    return bad("plant_scales.yaw_inertia", scales.yaw_inertia, "must be in [0.5, 2]");
  }
  if (!within(scales.cornering_stiffness, 0.5, 2.0)) {
    return bad("plant_scales.cornering_stiffness", scales.cornering_stiffness,
               "must be in [0.5, 2]");
  }
  if (!within(scales.friction, 0.1, 1.5)) {
    return bad("plant_scales.friction", scales.friction, "must be in [0.1, 1.5]");
  }
  if (!within(scales.cg_position, -0.25, 0.25)) {
    return bad("plant_scales.cg_position", scales.cg_position,
               "must be in [-0.25, 0.25] (a fraction of the wheelbase)");
  }
  if (!within(p.plant_actuator_scales.dead_time, 0.5, 1.5)) {
    return bad("plant_actuator_scales.dead_time", p.plant_actuator_scales.dead_time,
               "must be in [0.5, 1.5]");
  }
  if (!within(p.plant_actuator_scales.bandwidth, 0.5, 1.5)) {
    return bad("plant_actuator_scales.bandwidth", p.plant_actuator_scales.bandwidth,
               "must be in [0.5, 1.5]");
  }
  if (!within(p.crossfall, -0.1, 0.1)) {
    return bad("crossfall", p.crossfall, "must be in [-0.1, 0.1] (a grade, tan of the angle)");
  }
  if (!within(p.side_force.force_n, -1e5, 1e5)) {
    return bad("side_force.force_n", p.side_force.force_n, "must be in [-1e5, 1e5] N");
  }
  if (!within(p.side_force.yaw_moment_nm, -1e6, 1e6)) {
    return bad("side_force.yaw_moment_nm", p.side_force.yaw_moment_nm,
               "must be in [-1e6, 1e6] N m");
  }
  if (!within(p.side_force.start_s, 0.0, 3600.0)) {
    return bad("side_force.start_s", p.side_force.start_s, "must be in [0, 3600] s");
  }
  if (!within(p.pose_latency_s, 0.0, SimulationParameters::max_pose_latency_s)) {
    return bad("pose_latency_s", p.pose_latency_s, "must be in [0, 0.5] s");
  }
  if (p.pose_rate_hz && !within(*p.pose_rate_hz, SimulationParameters::min_pose_rate_hz,
                                (1.0 + 1e-9) / p.control_period_s)) {
    return bad("pose_rate_hz", *p.pose_rate_hz,
               "must be in [1, 1 / control_period_s] Hz; 1 / control_period_s =",
               1.0 / p.control_period_s);
  }
  if (p.pose_age_known) {
    const double oldest = p.pose_latency_s + (p.pose_rate_hz ? 1.0 / *p.pose_rate_hz : 0.0);
    if (!(oldest <= ControllerInput::max_pose_age_s)) {
      return bad("pose_age_known", oldest,
                 "needs pose_latency_s + 1 / pose_rate_hz (the oldest pose's age) <= "
                 "ControllerInput::max_pose_age_s =",
                 ControllerInput::max_pose_age_s);
    }
  }
  if (!within(p.steering_angle_sensor_offset_rad, -0.1, 0.1)) {
    return bad("steering_angle_sensor_offset_rad", p.steering_angle_sensor_offset_rad,
               "must be in [-0.1, 0.1] rad");
  }
  if (!within(p.gyro_bias_radps, -0.5, 0.5)) {
    return bad("gyro_bias_radps", p.gyro_bias_radps, "must be in [-0.5, 0.5] rad/s");
  }
  return std::nullopt;
}

//! The rules of the planner's windows (planner_windows.hpp).
std::optional<Violation> planner_violation(const SimulationParameters& p) noexcept {
  auto within = [](double value, double lo, double hi) { return value >= lo && value <= hi; };
  const PlannerWindows& w = p.planner;
  if (!within(w.period_s, 0.0, 10.0)) {
    return bad("planner.period_s", w.period_s, "must be in [0, 10] s (0: off)");
  }
  const double periods = w.period_s / p.control_period_s;
  if (w.active() && (periods < 1.0 - 1e-9 || std::abs(periods - std::round(periods)) > 1e-6)) {
    return bad("planner.period_s", w.period_s,
               "must be a whole multiple of control_period_s =", p.control_period_s);
  }
  if (!within(w.behind_m, 0.0, 1000.0)) {
    return bad("planner.behind_m", w.behind_m, "must be in [0, 1000] m");
  }
  if (!within(w.spacing_m, 0.05, 50.0)) {
    return bad("planner.spacing_m", w.spacing_m, "must be in [0.05, 50] m");
  }
  if (!within(w.ahead_m, 2.0 * w.spacing_m, 10000.0)) {
    return bad("planner.ahead_m", w.ahead_m,
               "must be in [2 spacing_m, 10000] m; 2 spacing_m =", 2.0 * w.spacing_m);
  }
  if (!within(w.jitter_std_m, 0.0, 1.0)) {
    return bad("planner.jitter_std_m", w.jitter_std_m, "must be in [0, 1] m");
  }
  if (w.smoothing_tolerance_m && !within(*w.smoothing_tolerance_m, 0.0, 10.0)) {
    return bad("planner.smoothing_tolerance_m", *w.smoothing_tolerance_m, "must be in [0, 10] m");
  }
  return std::nullopt;
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
  if (const auto violation = imperfection_violation(*this)) return violation;
  if (const auto violation = planner_violation(*this)) return violation;
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
  // The observer's own bounds (the rule texts state them).
  using Observer = SideSlipObserverParameters;
  if (!(side_slip.max_steering_offset_rad >= 0.0 &&
        side_slip.max_steering_offset_rad <= Observer::max_steering_offset_bound_rad)) {
    return bad("side_slip.max_steering_offset_rad", side_slip.max_steering_offset_rad,
               "must be in [0, 0.2] rad");
  }
  if (!(side_slip.steering_offset_process_std_radps >= 0.0 &&
        side_slip.steering_offset_process_std_radps <=
            Observer::max_steering_offset_process_std_radps)) {
    return bad("side_slip.steering_offset_process_std_radps",
               side_slip.steering_offset_process_std_radps, "must be in [0, 0.1] rad/sqrt(s)");
  }
  return std::nullopt;
}

std::string SimulationParameters::validation_error() const {
  return describe(first_violation());
}

void SimulationParameters::validate() const {
  throw_if_violated(first_violation());
}

SteeringSystemParameters steering_system_parameters(const SideSlipEstimation& slip,
                                                    const VehicleParameters& vehicle,
                                                    const ActuatorParameters& actuator) {
  SteeringSystemParameters system;
  system.actuator = actuator;
  system.compensate_steering_offset = slip.compensate_steering_offset;
  if (!slip.estimate_course_error) system.course_error.reset();
  system.slip_input = slip.source == SideSlipSource::none    ? SlipInput::kinematic
                      : slip.source == SideSlipSource::truth ? SlipInput::sensor
                                                             : SlipInput::observer;
  if (system.slip_input != SlipInput::observer) return system;
  system.observer = SideSlipObserverParameters::from_vehicle(
      vehicle, slip.cornering_stiffness_scale, slip.mass_scale, slip.tire_model);
  // The observer trusts its sensors as much as their simulated noise says (at least its
  // defaults: a noise-free sensor would make the filter over-confident in the model's error).
  system.observer.yaw_rate_noise_std_radps =
      std::max(system.observer.yaw_rate_noise_std_radps, slip.yaw_rate_noise_std_radps);
  system.observer.lateral_acceleration_noise_std_mps2 =
      std::max(system.observer.lateral_acceleration_noise_std_mps2,
               slip.lateral_acceleration_noise_std_mps2);
  system.observer.max_steering_offset_rad = slip.max_steering_offset_rad;
  system.observer.steering_offset_process_std_radps = slip.steering_offset_process_std_radps;
  return system;
}

namespace {

//! Streams to `observer`, or without one collects the trace in memory (`capacity` reserved).
template <typename Run>
SimulationResult stream_or_store(const TraceObserver& observer, std::size_t capacity, Run&& run) {
  if (observer) return run(observer);
  std::vector<TraceSample> trace;
  trace.reserve(capacity);
  SimulationResult result = run([&trace](const TraceSample& sample) { trace.push_back(sample); });
  result.trace = std::move(trace);
  return result;
}

//! The samples a run on a path emits at most (validated first: the count needs finite values).
std::size_t path_trace_capacity(const SimulationParameters& parameters) {
  parameters.validate();
  return static_cast<std::size_t>(
      std::min(std::ceil(parameters.duration_s / parameters.control_period_s) + 1.0,
               SimulationParameters::max_control_steps + 1.0));
}

//! The controller overloads: the car's steering system around `controller`, then its overload.
template <typename Track>
SimulationResult drive_with_system(const Track& track, const VehicleModel& vehicle,
                                   const ActuatorParameters& actuator, const SpeedProfile& speed,
                                   const SimulationParameters& parameters, const Pose2& start,
                                   SteeringController& controller, const TraceObserver& observer) {
  parameters.validate();
  SteeringSystem system(
      controller, steering_system_parameters(parameters.side_slip, vehicle.parameters(), actuator));
  return simulate(track, vehicle, actuator, speed, parameters, start, system, observer);
}

}  // namespace

SimulationResult simulate(const Path& path, const VehicleModel& vehicle,
                          const ActuatorParameters& actuator, const SpeedProfile& speed,
                          const SimulationParameters& parameters, const Pose2& start,
                          SteeringSystem& system, const TraceObserver& observer) {
  const std::size_t capacity = observer ? 0 : path_trace_capacity(parameters);
  return stream_or_store(observer, capacity, [&](const TraceObserver& sink) {
    return detail::closed_loop(path, nullptr, vehicle, actuator, speed, parameters, start, system,
                               sink);
  });
}

SimulationResult simulate(const PathPlan& plan, const VehicleModel& vehicle,
                          const ActuatorParameters& actuator, const SpeedProfile& speed,
                          const SimulationParameters& parameters, const Pose2& start,
                          SteeringSystem& system, const TraceObserver& observer) {
  // No reserve: a plan's duration is the profile's, not parameters.duration_s.
  return stream_or_store(observer, 0, [&](const TraceObserver& sink) {
    return detail::closed_loop(*plan.piece(0).path, &plan, vehicle, actuator, speed, parameters,
                               start, system, sink);
  });
}

SimulationResult simulate(const Path& path, const VehicleModel& vehicle,
                          const ActuatorParameters& actuator, const SpeedProfile& speed,
                          const SimulationParameters& parameters, const Pose2& start,
                          SteeringController& controller, const TraceObserver& observer) {
  return drive_with_system(path, vehicle, actuator, speed, parameters, start, controller, observer);
}

SimulationResult simulate(const PathPlan& plan, const VehicleModel& vehicle,
                          const ActuatorParameters& actuator, const SpeedProfile& speed,
                          const SimulationParameters& parameters, const Pose2& start,
                          SteeringController& controller, const TraceObserver& observer) {
  return drive_with_system(plan, vehicle, actuator, speed, parameters, start, controller, observer);
}

}  // namespace smoothsteer
