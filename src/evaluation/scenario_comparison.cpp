#include "smoothsteer/evaluation/scenario_comparison.hpp"

#include <cmath>
#include <stdexcept>

#include "scenario_setup.hpp"
#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/io/scenario.hpp"

namespace smoothsteer {

ResultsTable run_lane_change_comparison(const std::vector<std::string>& scenario_files,
                                        const PaperFigures& paper) {
  ResultsTable table;
  table.title = "Lane change (Falcone et al. 2007) on the kinetic model with actuator";
  table.header = {"speed_mps",         "controller",       "max_abs_e_m",
                  "std_rate_radps",    "max_accel_radps2", "angle_hits",
                  "rate_hits",         "limited_fraction", "max_rate_excess_radps",
                  "max_side_slip_rad", "paper_max_e_m"};
  for (const std::string& file : scenario_files) {
    const io::Scenario scenario = io::load_scenario(file);
    const double speed = scenario.speed.initial_speed_mps;
    const std::string speed_key = ResultsTable::number(speed, 1);
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
                            paper.text("lane_change", speed_key, "proposed_max_e_m", 3)});
    }
    for (const std::string& name : comparison_controller_names()) {
      // Every controller gets the limits the simulated actuator enforces, so that all rows are
      // compared under the same C1 and C2.
      auto controller = make_comparison_controller(name, detail::comparison_setup_for(scenario));
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
      "limits (0.4 rad/s). paper_max_e_m: the paper's proposed C^1 controller (Sec. IV-C), from "
      "data/paper_figures.csv."};
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
