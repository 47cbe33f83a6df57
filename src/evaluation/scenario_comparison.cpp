#include "smoothsteer/evaluation/scenario_comparison.hpp"

#include <cmath>
#include <stdexcept>

#include "scenario_setup.hpp"
#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/runner/progress.hpp"
#include "smoothsteer/runner/scenario.hpp"

namespace smoothsteer {

namespace {

//! The held-command columns of the lane-change table (docs/metrics.md): what the actuator
//! receives, by differences over the control period, whatever derivative a controller reports.
std::vector<std::string> held_columns(const Metrics& m) {
  const long above = static_cast<long>(m.angle_violations) + m.held_rate_violations +
                     m.held_acceleration_violations;
  return {ResultsTable::number(m.max_abs_rear_error_m), ResultsTable::number(m.held_rate_rms_radps),
          ResultsTable::number(m.held_rate_max_radps),
          ResultsTable::number(m.held_acceleration_max_radps2, 2), std::to_string(above)};
}

}  // namespace

ResultsTable run_lane_change_comparison(const std::vector<std::string>& scenario_files,
                                        const PaperFigures& paper,
                                        const std::vector<std::string>& overrides) {
  ResultsTable table;
  table.title = "Lane change (Falcone et al. 2007) on the kinetic model with actuator";
  table.header = {"speed_mps",           "controller",          "max_abs_e_m",
                  "held_rate_rms_radps", "held_rate_max_radps", "held_accel_max_radps2",
                  "held_above_limits",   "clamped_updates",     "max_side_slip_rad",
                  "paper_max_e_m"};
  const auto add_row = [&](double speed, const std::string& name, const Metrics& m,
                           const std::string& clamped, const std::string& paper_figure) {
    std::vector<std::string> row{ResultsTable::number(speed, 1), name};
    for (std::string& cell : held_columns(m)) row.push_back(std::move(cell));
    row.push_back(clamped);
    row.push_back(ResultsTable::number(m.max_abs_side_slip_rad));
    row.push_back(paper_figure);
    table.rows.push_back(std::move(row));
  };
  runner::progress_expect(scenario_files.size() * (1 + comparison_controller_names().size()));
  for (const std::string& file : scenario_files) {
    runner::throw_if_interrupted("the lane-change comparison was");
    const runner::Scenario scenario = runner::load_scenario(file, overrides);
    const double speed = scenario.speed.initial_speed_mps;
    const std::string speed_key = ResultsTable::number(speed, 1);
    // The scenario's own controller: the certified lead-wheel controller of its schedule.
    add_row(speed, "scenario (" + scenario.controller["type"].as<std::string>() + ")",
            runner::run_scenario(scenario).metrics, "",
            paper.text("lane_change", speed_key, "proposed_max_e_m", 3));
    runner::progress_case_done();
    for (const std::string& name : comparison_controller_names()) {
      runner::throw_if_interrupted("the lane-change comparison was");
      // Every controller gets the limits the simulated actuator enforces, so that all rows are
      // compared under the same C1 and C2.
      auto controller = make_comparison_controller(name, detail::comparison_setup_for(scenario));
      const runner::RunResult run = runner::run_scenario(scenario, *controller);
      const SaturationStatistics& s = controller->saturation();
      add_row(speed, name, run.metrics, std::to_string(s.limited), "");
      runner::progress_case_done();
    }
  }
  table.notes = {
      "Default gains, not tuned (the tuned comparison is tuning_rule.md). max_abs_e_m: "
      "rear-axle lateral error over the run. held_*: the held command (zero-order hold) by "
      "differences over the control period (docs/metrics.md). held_above_limits: held-command "
      "samples above the car's angle, rate (0.4 rad/s) or acceleration (8 rad/s^2) limit. "
      "Every baseline is held to the scenario actuator's angle and rate limits and the car's "
      "steering acceleration limit by the second-order limiter (docs/baselines.md); "
      "clamped_updates: updates in which that limiter cut the raw command. proposed_c0/c1 "
      "are sized so that their worst case fits those limits at the scenario speed. "
      "paper_max_e_m: the paper's proposed C^1 controller (Sec. IV-C), from "
      "data/paper_figures.csv."};
  return table;
}

ResultsTable run_parameter_comparison(const std::string& scenario_file) {
  struct Setting {
    const char* name;
    std::vector<std::string> overrides;
  };
  const runner::Scenario base = runner::load_scenario(scenario_file);
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
  runner::progress_expect(settings.size());
  for (const Setting& setting : settings) {
    runner::throw_if_interrupted("the parameter comparison was");
    const runner::Scenario scenario = runner::load_scenario(scenario_file, setting.overrides);
    const runner::RunResult run = runner::run_scenario(scenario);
    runner::progress_case_done();
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
