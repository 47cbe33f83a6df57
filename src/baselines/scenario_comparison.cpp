#include "smoothsteer/baselines/scenario_comparison.hpp"

#ifdef SMOOTHSTEER_HAS_io

#include <cmath>
#include <stdexcept>

#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/io/controller_registry.hpp"
#include "smoothsteer/io/scenario.hpp"

namespace smoothsteer {

namespace {

ComparisonSetup setup_for(std::shared_ptr<const Path> path, double wheelbase_m, double speed,
                          SteeringLimits limits) {
  ComparisonSetup setup;
  setup.path = std::move(path);
  setup.wheelbase_m = wheelbase_m;
  setup.nominal_speed_mps = speed;
  setup.limits = limits;
  return setup;
}

}  // namespace

namespace {

//! The gains of one baseline as keys of its controller section; the keys are the parameter
//! fields, so a validate() message ("LqrParameters: weight_lateral = ...") names the key.
void read_baseline_gains(const std::string& name, io::ConfigSection& section,
                         ComparisonSetup& setup) {
  const io::Range positive = io::Range::positive(), non_negative = io::Range::non_negative();
  if (name == "stanley") {
    StanleyParameters& p = setup.stanley;
    p.gain_per_s = section.number("gain_per_s", p.gain_per_s, positive);
    p.softening_mps = section.number("softening_mps", p.softening_mps, positive);
  } else if (name == "pure_pursuit") {
    PurePursuitParameters& p = setup.pure_pursuit;
    p.min_lookahead_m = section.number("min_lookahead_m", p.min_lookahead_m, positive);
    p.lookahead_time_s = section.number("lookahead_time_s", p.lookahead_time_s, non_negative);
    p.max_lookahead_m = section.number("max_lookahead_m", p.max_lookahead_m, positive);
  } else if (name == "lqr") {
    LqrParameters& p = setup.lqr;
    p.weight_lateral = section.number("weight_lateral", p.weight_lateral, positive);
    p.weight_heading = section.number("weight_heading", p.weight_heading, non_negative);
    p.weight_steering = section.number("weight_steering", p.weight_steering, positive);
    p.curvature_feedforward = section.boolean("curvature_feedforward", p.curvature_feedforward);
  } else if (name == "newton_raphson") {
    NewtonRaphsonParameters& p = setup.newton_raphson;
    p.horizon_s = section.number("horizon_s", p.horizon_s, positive);
    p.gain_per_s = section.number("gain_per_s", p.gain_per_s, positive);
  } else if (name == "mpc" || name == "mpc_constrained") {
    MpcParameters& p = setup.mpc;
    p.steering_time_constant_s =
        section.number("steering_time_constant_s", p.steering_time_constant_s, positive);
    p.horizon_steps = section.integer("horizon_steps", p.horizon_steps, 2, 200);
    p.prediction_step_s = section.number("prediction_step_s", p.prediction_step_s, positive);
    const auto weight = [&](const char* key, double& value) {
      value = section.number(key, value, non_negative);
    };
    weight("weight_lateral_error", p.weight_lateral_error);
    weight("weight_heading_error", p.weight_heading_error);
    weight("weight_heading_error_squared_speed", p.weight_heading_error_squared_speed);
    p.weight_steering_input =
        section.number("weight_steering_input", p.weight_steering_input, positive);
    weight("weight_steering_input_squared_speed", p.weight_steering_input_squared_speed);
    weight("weight_steering_rate", p.weight_steering_rate);
    weight("weight_steering_acceleration", p.weight_steering_acceleration);
    weight("weight_terminal_lateral_error", p.weight_terminal_lateral_error);
    weight("weight_terminal_heading_error", p.weight_terminal_heading_error);
    weight("zero_feedforward_angle_rad", p.zero_feedforward_angle_rad);
  }
}

}  // namespace

void register_comparison_controllers() {
  for (const std::string& name : comparison_controller_names()) {
    io::register_controller_type(
        name,
        [name](io::ConfigSection& section, std::shared_ptr<const Path> path,
               const VehicleParameters& vehicle) -> std::unique_ptr<SteeringController> {
          // Limits C1 and C2: the vehicle's, unless the section sets the rate limit (e.g. to
          // the scenario actuator's max_rate_radps).
          const SteeringLimits limits{
              vehicle.max_steering_angle_rad,
              section.number("max_steering_rate_radps", vehicle.max_steering_rate_radps,
                             io::Range::positive())};
          ComparisonSetup setup =
              setup_for(std::move(path), vehicle.wheelbase_m(),
                        section.number("nominal_speed_mps", 10.0, io::Range::positive()), limits);
          setup.k_rob = section.number("k_rob", setup.k_rob, {0.0, 1.0, false, true});
          setup.hosm_heading_bound_rad = section.number(
              "hosm_heading_bound_rad", setup.hosm_heading_bound_rad, io::Range::positive());
          setup.lead_wheelbase_m =
              section.number("lead_wheelbase_m", setup.lead_wheelbase_m, io::Range::positive());
          read_baseline_gains(name, section, setup);
          try {
            return make_comparison_controller(name, setup);
          } catch (const std::invalid_argument& error) {
            throw io::ConfigError(section.file() + ": key '" + section.full_key("") +
                                  "': " + error.what());
          }
        });
  }
}

ResultsTable run_lane_change_comparison(const std::vector<std::string>& scenario_files) {
  ResultsTable table;
  table.title = "Lane change (Falcone et al. 2007) on the kinetic model with actuator";
  table.header = {"speed_mps",         "controller",       "max_abs_e_m",
                  "std_rate_radps",    "max_accel_radps2", "angle_hits",
                  "rate_hits",         "limited_fraction", "max_rate_excess_radps",
                  "max_side_slip_rad", "paper_max_e_m"};
  for (const std::string& file : scenario_files) {
    const io::Scenario scenario = io::load_scenario(file);
    const double speed = scenario.speed.initial_speed_mps;
    const double paper = std::abs(speed - 10.0) < 0.5   ? 0.012
                         : std::abs(speed - 15.0) < 0.5 ? 0.39
                         : std::abs(speed - 19.0) < 0.5 ? 0.99
                                                        : std::nan("");
    // The scenario's own controller is the proposed one (lead_wheel, paper parameters).
    {
      const io::RunResult run = io::run_scenario(scenario);
      const Metrics& m = run.metrics;
      table.rows.push_back({ResultsTable::number(speed, 1), "proposed (scenario)",
                            ResultsTable::number(m.max_abs_rear_error_m),
                            ResultsTable::number(m.command_rate_std_radps),
                            ResultsTable::number(m.command_acceleration_max_radps2, 2),
                            std::to_string(m.angle_violations), std::to_string(m.rate_violations),
                            "", "", ResultsTable::number(m.max_abs_side_slip_rad),
                            ResultsTable::number(paper)});
    }
    for (const std::string& name : comparison_controller_names()) {
      // Every controller gets the limits the simulated actuator enforces, so that all rows are
      // compared under the same C1 and C2.
      const SteeringLimits limits{scenario.actuator.max_angle_rad,
                                  scenario.actuator.max_rate_radps};
      auto controller = make_comparison_controller(
          name, setup_for(scenario.path, scenario.vehicle.wheelbase_m(), speed, limits));
      const io::RunResult run = io::run_scenario(scenario, *controller);
      const Metrics& m = run.metrics;
      const SaturationStatistics& s = controller->saturation();
      table.rows.push_back({ResultsTable::number(speed, 1), name,
                            ResultsTable::number(m.max_abs_rear_error_m),
                            ResultsTable::number(m.command_rate_std_radps),
                            ResultsTable::number(m.command_acceleration_max_radps2, 2),
                            std::to_string(s.angle_limited), std::to_string(s.rate_limited),
                            ResultsTable::number(s.limited_fraction()),
                            ResultsTable::number(s.max_rate_excess_radps),
                            ResultsTable::number(m.max_abs_side_slip_rad), ""});
    }
  }
  table.notes = {
      "max_abs_e_m: rear-axle lateral error over the run. std_rate / max_accel: of the steering "
      "command. Every controller is limited to the scenario actuator's angle and rate "
      "(max_angle_rad, max_rate_radps); proposed_c0/c1 are sized so that their worst case fits "
      "them at the scenario speed. angle_hits / rate_hits: updates in which the saturation "
      "clamped the raw command; for the scenario row: metric violations of the vehicle file's "
      "limits (0.4 rad/s). Paper (Sec. IV-C, proposed, C^1): 0.012 / 0.39 / 0.99 m at 10 / 15 / 19 "
      "m/s; "
      "Newton-Raphson flow of Shivam et al. with a slip model: 0.07 m at 10 m/s, 0.25 m at 19 "
      "m/s."};
  return table;
}

ResultsTable run_parameter_comparison(const std::string& scenario_file) {
  struct Setting {
    const char* name;
    std::vector<std::string> overrides;
  };
  const io::Scenario base = io::load_scenario(scenario_file);
  const double kbar = base.controller["lead_curvature_bound"].as<double>(0.2);
  const double lead = base.controller["lead_wheelbase_m"].as<double>(0.5);
  const double k_rob = base.controller["k_rob"].as<double>(0.3);
  auto set = [](const char* key, double value) {
    return std::string("controller.") + key + "=" + ResultsTable::number(value, 6);
  };
  const std::vector<Setting> settings{{"base", {}},
                                      {"kbar_l -50%", {set("lead_curvature_bound", 0.5 * kbar)}},
                                      {"lambda_l +300%", {set("lead_wheelbase_m", 4.0 * lead)}},
                                      {"k_rob -33%", {set("k_rob", k_rob * 2.0 / 3.0)}}};
  ResultsTable table;
  table.title = "circle_sections: parameter settings of Sec. IV-A (Fig. parameter_radar)";
  table.header = {"setting",        "kbar_l",          "lambda_l_m",
                  "k_rob",          "reaching_time_s", "max_abs_e_lead_after_reaching_m",
                  "std_rate_radps", "std_accel_radps2"};
  for (const Setting& setting : settings) {
    const io::Scenario scenario = io::load_scenario(scenario_file, setting.overrides);
    const io::RunResult run = io::run_scenario(scenario);
    const Metrics& m = run.metrics;
    table.rows.push_back(
        {setting.name,
         ResultsTable::number(scenario.controller["lead_curvature_bound"].as<double>(kbar), 3),
         ResultsTable::number(scenario.controller["lead_wheelbase_m"].as<double>(lead), 2),
         ResultsTable::number(scenario.controller["k_rob"].as<double>(k_rob), 3),
         ResultsTable::number(m.reaching_time_s, 2),
         ResultsTable::number(m.max_abs_lead_error_after_reaching_m, 4),
         ResultsTable::number(m.command_rate_std_radps, 4),
         ResultsTable::number(m.command_acceleration_std_radps2, 4)});
  }
  table.notes = {
      "Variations of Sec. IV-A: kbar_l -50%, lambda_l +300%, k_rob -33% (one at a "
      "time, from the scenario's base setting). Reaching time: metrics.reaching_"
      "threshold_m of the scenario; -1 = not reached."};
  return table;
}

}  // namespace smoothsteer

#endif  // SMOOTHSTEER_HAS_io
