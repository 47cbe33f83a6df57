// The reader of a scenario's `simulation` section (docs/scenarios.md, "Schema"): the loop's
// timing and integrator, the disturbances, the plant-only model error and imperfect sensors,
// the side-slip estimation and the planner's windows.

#include <array>
#include <stdexcept>

#include "scenario_sections.hpp"

namespace smoothsteer::runner::detail {
using io::ConfigError;
using io::ConfigSection;
using io::Range;
namespace {

//! `integrator`: the plant's integrator by name; `current` is the default.
PlantIntegrator read_integrator(ConfigSection& sim, PlantIntegrator current) {
  constexpr std::array<const char*, 3> integrator_names{"fixed_rk4", "rkf78", "dopri5"};
  const std::string integrator =
      sim.text("integrator", integrator_names[static_cast<std::size_t>(current)],
               {"fixed_rk4", "rkf78", "dopri5"});
  return integrator == "fixed_rk4" ? PlantIntegrator::fixed_rk4
         : integrator == "dopri5"  ? PlantIntegrator::dopri5
                                   : PlantIntegrator::rkf78;
}

//! The simulation keys of the plant-only model error and the imperfect sensors
//! (plant_imperfections.hpp): the truth's vehicle block, scales, crossfall, side force, the
//! pose's latency and rate, sensor offsets. Ranges as SimulationParameters::first_violation.
void read_imperfections(ConfigSection& sim, Scenario& s, const ScenarioSource& source) {
  SimulationParameters& p = s.simulation;
  if (sim.has("plant_vehicle")) {
    YAML::Node node = sim.raw("plant_vehicle");
    if (!node.IsMap()) sim.fail("plant_vehicle", "expected a mapping (e.g. {file: ...})");
    VehicleParameters& truth = s.plant_vehicle.emplace();
    std::string label, citation;
    sim.store("plant_vehicle", read_vehicle_block(node, sim.full_key("plant_vehicle"), source,
                                                  truth, s.plant_vehicle_name, citation, label));
    if (s.model == "double_track" && !truth.double_track) {
      throw ConfigError(label + ": key '" + sim.full_key("plant_vehicle") +
                        ".double_track': is required by model: double_track");
    }
  }
  ConfigSection scales = sim.section("plant_scales");
  p.plant_scales.mass = scales.number("mass", 1.0, {0.5, 2.0});
  p.plant_scales.yaw_inertia = scales.number("yaw_inertia", 1.0, {0.5, 2.0});
  p.plant_scales.cornering_stiffness = scales.number("cornering_stiffness", 1.0, {0.5, 2.0});
  p.plant_scales.friction = scales.number("friction", 1.0, {0.1, 1.5});
  p.plant_scales.cg_position = scales.number("cg_position", 0.0, {-0.25, 0.25});
  scales.finish();
  sim.store("plant_scales", scales.resolved());
  ConfigSection actuator = sim.section("plant_actuator_scales");
  p.plant_actuator_scales.dead_time = actuator.number("dead_time", 1.0, {0.5, 1.5});
  p.plant_actuator_scales.bandwidth = actuator.number("bandwidth", 1.0, {0.5, 1.5});
  actuator.finish();
  sim.store("plant_actuator_scales", actuator.resolved());
  p.crossfall = sim.number("crossfall", 0.0, {-0.1, 0.1});
  ConfigSection side = sim.section("side_force");
  p.side_force.force_n = side.number("force_n", 0.0, {-1e5, 1e5});
  p.side_force.yaw_moment_nm = side.number("yaw_moment_nm", 0.0, {-1e6, 1e6});
  p.side_force.start_s = side.number("start_s", 0.0, {0.0, 3600.0});
  side.finish();
  sim.store("side_force", side.resolved());
  p.pose_latency_s =
      sim.number("pose_latency_s", 0.0, {0.0, SimulationParameters::max_pose_latency_s});
  if (sim.has("pose_rate_hz")) {
    p.pose_rate_hz =
        sim.required_number("pose_rate_hz", {SimulationParameters::min_pose_rate_hz, 1000.0});
  }
  p.pose_age_known = sim.boolean("pose_age_known", false);
  p.steering_angle_sensor_offset_rad =
      sim.number("steering_angle_sensor_offset_rad", 0.0, {-0.1, 0.1});
  p.gyro_bias_radps = sim.number("gyro_bias_radps", 0.0, {-0.5, 0.5});

  // What acts through tire forces needs a plant that has them (model: dynamic or double_track).
  if (s.model == "kinematic") {
    const char* why =
        "acts through the tires' lateral forces, which the kinematic plant has not (its rear "
        "axle rolls without slip): use model: dynamic or double_track, or "
        "plant_curvature_disturbance";
    if (p.crossfall != 0.0) sim.fail("crossfall", why);
    if (p.side_force.active()) sim.fail("side_force", why);
    if (!p.plant_scales.identity()) sim.fail("plant_scales", why);
  }
  try {
    (void)scaled_plant_vehicle(s.plant_vehicle.value_or(s.vehicle), p.plant_scales);
  } catch (const std::invalid_argument& error) {
    sim.fail("plant_scales", error.what());
  }
}

//! simulation.side_slip: where the controller's rear-axle side slip comes from, and the observer's
//! model error and sensor noise.
void read_side_slip(ConfigSection& sim, SideSlipEstimation& estimation) {
  ConfigSection slip = sim.section("side_slip");
  const std::string source = slip.text("source", "none", {"none", "truth", "observer"});
  estimation.source = source == "none"    ? SideSlipSource::none
                      : source == "truth" ? SideSlipSource::truth
                                          : SideSlipSource::observer;
  estimation.cornering_stiffness_scale = slip.number("cornering_stiffness_scale", 1.0, {0.2, 5.0});
  estimation.mass_scale = slip.number("mass_scale", 1.0, {0.2, 5.0});
  estimation.tire_model = slip.text("tire_model", "linear", {"linear", "magic_formula"}) == "linear"
                              ? ObserverTireModel::linear
                              : ObserverTireModel::magic_formula;
  estimation.yaw_rate_noise_std_radps = slip.number("yaw_rate_noise_std_radps", 0.0, {0.0, 1.0});
  estimation.lateral_acceleration_noise_std_mps2 =
      slip.number("lateral_acceleration_noise_std_mps2", 0.0, {0.0, 10.0});
  using Observer = SideSlipObserverParameters;
  estimation.max_steering_offset_rad =
      slip.number("max_steering_offset_rad", estimation.max_steering_offset_rad,
                  {0.0, Observer::max_steering_offset_bound_rad});
  estimation.steering_offset_process_std_radps =
      slip.number("steering_offset_process_std_radps", estimation.steering_offset_process_std_radps,
                  {0.0, Observer::max_steering_offset_process_std_radps});
  estimation.compensate_steering_offset =
      slip.boolean("compensate_steering_offset", estimation.compensate_steering_offset);
  // The compensation makes up for the observer's learned offset: without that state the key
  // would do nothing, silently.
  if (slip.has("compensate_steering_offset")) {
    if (estimation.source != SideSlipSource::observer) {
      slip.fail("compensate_steering_offset",
                "has no effect with side_slip.source = " + source +
                    " (it makes up for the observer's learned steering offset)");
    }
    if (estimation.max_steering_offset_rad == 0.0) {
      slip.fail("compensate_steering_offset",
                "has no effect with side_slip.max_steering_offset_rad = 0 (the observer then "
                "learns no steering offset)");
    }
  }
  estimation.estimate_course_error =
      slip.boolean("estimate_course_error", estimation.estimate_course_error);
  slip.finish();
  sim.store("side_slip", slip.resolved());
}

//! Stack mode (planner_windows.hpp): simulation.planner. The rule that ties period_s to the
//! control period is SimulationParameters' (check() names the key).
void read_planner(ConfigSection& sim, PlannerWindows& windows) {
  ConfigSection planner = sim.section("planner");
  windows.period_s = planner.number("period_s", windows.period_s, {0.0, 10.0});
  windows.behind_m = planner.number("behind_m", windows.behind_m, {0.0, 1000.0});
  windows.spacing_m = planner.number("spacing_m", windows.spacing_m, {0.05, 50.0});
  windows.ahead_m = planner.number("ahead_m", windows.ahead_m, {2.0 * windows.spacing_m, 1e4});
  windows.jitter_std_m = planner.number("jitter_std_m", windows.jitter_std_m, {0.0, 1.0});
  if (planner.has("smoothing_tolerance_m")) {
    windows.smoothing_tolerance_m = planner.required_number("smoothing_tolerance_m", {0.0, 10.0});
  }
  planner.finish();
  sim.store("planner", planner.resolved());
}

}  // namespace

YAML::Node read_simulation(ConfigSection& c, const ScenarioSource& source, Scenario& s) {
  ConfigSection sim = c.section("simulation");
  SimulationParameters& p = s.simulation;
  p.control_period_s = sim.number("control_period_s", p.control_period_s, {0.0, 1.0, true, false});
  p.substep_s = sim.number("substep_s", p.substep_s, {0.0, 0.01, true, false});
  p.duration_s = sim.number("duration_s", p.duration_s, {0.0, 3600.0, true, false});
  p.integrator = read_integrator(sim, p.integrator);
  p.integrator_tolerance =
      sim.number("integrator_tolerance", p.integrator_tolerance, {1e-14, 1e-3});
  p.stop_at_path_end = sim.boolean("stop_at_path_end", p.stop_at_path_end);
  p.stop_beyond_path_end_m = sim.number("stop_beyond_path_end_m", p.stop_beyond_path_end_m);
  p.matched_disturbance = sim.number("matched_disturbance", 0.0, {-1.0, 1.0});
  p.plant_curvature_disturbance = sim.number("plant_curvature_disturbance", 0.0, {-1.0, 1.0});
  p.steering_offset_rad = sim.number("steering_offset_rad", 0.0, {-0.1, 0.1});
  read_imperfections(sim, s, source);
  p.position_noise_std_m = sim.number("position_noise_std_m", 0.0, Range::non_negative());
  p.heading_noise_std_rad = sim.number("heading_noise_std_rad", 0.0, Range::non_negative());
  p.noise_seed = static_cast<std::uint64_t>(sim.integer("noise_seed", 1, 0, 2147483647));
  read_side_slip(sim, p.side_slip);
  read_planner(sim, p.planner);
  sim.finish();
  check(sim, p);
  if (const std::string error = s.actuator.validation_error(p.substep_s); !error.empty()) {
    throw ConfigError(source.file + ": key 'actuator': " + error);
  }
  return sim.resolved();
}

}  // namespace smoothsteer::runner::detail
