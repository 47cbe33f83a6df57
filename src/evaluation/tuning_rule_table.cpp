// The tables of the tuning rule (tuning_rule.hpp): the held-out rows with their Pareto front,
// and the wall-clock cost per update in a table of its own (it changes on every run).

#include <cmath>
#include <string>
#include <vector>

#include "smoothsteer/evaluation/tuning_rule.hpp"

namespace smoothsteer {

namespace {

//! Rows of one scenario not dominated in (max |e|, RMS actuator rate): no other row is at least
//! as good in both and better in one. Diverged and infeasible rows are never on the front.
//! within_limits: only rows without a held-command sample above the car's limits compete.
std::vector<bool> pareto_front(const std::vector<const ScenarioScore*>& rows, bool within_limits) {
  std::vector<bool> front(rows.size(), false);
  const auto valid = [within_limits](const ScenarioScore& s) {
    return !s.diverged && !s.infeasible && (!within_limits || s.held_above_limits() == 0);
  };
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!valid(*rows[i])) continue;
    const double e = rows[i]->metrics.max_abs_rear_error_m;
    const double rate = rows[i]->metrics.actual_rate_rms_radps;
    bool dominated = false;
    for (std::size_t j = 0; j < rows.size() && !dominated; ++j) {
      if (j == i || !valid(*rows[j])) continue;
      const double ej = rows[j]->metrics.max_abs_rear_error_m;
      const double rate_j = rows[j]->metrics.actual_rate_rms_radps;
      dominated = ej <= e && rate_j <= rate && (ej < e || rate_j < rate);
    }
    front[i] = !dominated;
  }
  return front;
}

std::string gains_text(const TunedController& c) {
  std::string text;
  for (const auto& [key, value] : c.gains) {
    text += (text.empty() ? "" : " ") + key + "=" + ResultsTable::number(value, 4);
  }
  return text.empty() ? "fixed" : text;
}

std::string names(const std::vector<std::string>& list) {
  std::string text;
  for (const std::string& name : list) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

ResultsTable TuningRuleResult::table() const {
  ResultsTable t;
  t.title = "Every controller tuned by one rule, reported on held-out scenarios";
  t.header = {"scenario",
              "controller",
              "pareto",
              "pareto_within_limits",
              "max_abs_e_m",
              "rms_e_m",
              "held_rate_rms_radps",
              "held_rate_max_radps",
              "held_accel_rms_radps2",
              "held_accel_max_radps2",
              "actual_rate_rms_radps",
              "actual_rate_max_radps",
              "actual_accel_rms_radps2",
              "actual_accel_max_radps2",
              "held_above_limits",
              "actual_above_limits",
              "clamped_updates",
              "diverged",
              "max_side_slip_rad",
              "admissible_in_training",
              "gains"};
  const auto n = ResultsTable::number;
  for (std::size_t s = 0; s < held_out.size(); ++s) {
    std::vector<const ScenarioScore*> rows;
    for (const TunedController& c : controllers) rows.push_back(&c.held_out[s]);
    const std::vector<bool> front = pareto_front(rows, false);
    const std::vector<bool> front_within = pareto_front(rows, true);
    for (std::size_t i = 0; i < controllers.size(); ++i) {
      const TunedController& c = controllers[i];
      const ScenarioScore& r = *rows[i];
      const Metrics& m = r.metrics;
      if (r.infeasible) {
        std::vector<std::string> row(t.header.size(), "");
        row[0] = r.scenario;
        row[1] = c.controller;
        row[2] = row[3] = "no";
        row[17] = "infeasible";
        row[19] = c.admissible ? "yes" : "no";
        row[20] = gains_text(c);
        t.rows.push_back(row);
        continue;
      }
      t.rows.push_back({r.scenario,
                        c.controller,
                        front[i] ? "yes" : "no",
                        front_within[i] ? "yes" : "no",
                        n(m.max_abs_rear_error_m, 3),
                        n(m.rms_rear_error_m, 3),
                        n(m.held_rate_rms_radps, 4),
                        n(m.held_rate_max_radps, 3),
                        n(m.held_acceleration_rms_radps2, 3),
                        n(m.held_acceleration_max_radps2, 2),
                        n(m.actual_rate_rms_radps, 4),
                        n(m.actual_rate_max_radps, 3),
                        n(m.actual_acceleration_rms_radps2, 3),
                        n(m.actual_acceleration_max_radps2, 2),
                        std::to_string(r.held_above_limits()),
                        std::to_string(r.actual_above_limits()),
                        std::to_string(r.clamped_updates),
                        r.diverged ? "yes" : "no",
                        n(m.max_abs_side_slip_rad, 4),
                        c.admissible ? "yes" : "no",
                        gains_text(c)});
    }
  }
  t.notes = {
      "Tuning rule (docs/baselines.md): a log-spaced grid of " + std::to_string(options.budget) +
          " configurations per controller (the certified one: the knobs of its tuning route), "
          "chosen on: " +
          names(training) + "; reported on: " + names(held_out) +
          ". Chosen: admissible on every training scenario (no held-command sample above the "
          "car's limits, max |e| <= " +
          n(options.divergence_m, 1) +
          " m, certifiable) first, then the smallest worst-case max |e|, then the smallest mean "
          "RMS rate of the held command.",
      "Metrics (docs/metrics.md): rear axle e; held = the command under the zero-order hold, by "
      "differences over the control period; actual = the actuator's output. held_above_limits: "
      "held-command samples above the car's angle, rate or acceleration limit; "
      "actual_above_limits: the same for the actuator output's rate and acceleration; "
      "clamped_updates: updates whose raw command the saturation to the car's limits cut. "
      "pareto: not dominated in (max_abs_e_m, actual_rate_rms_radps) among the scenario's "
      "non-diverged rows; pareto_within_limits: the same among the rows with held_above_limits "
      "= 0. Cost per update: tuning_rule_timings and docs/benchmarks.md."};
  return t;
}

ResultsTable TuningRuleResult::timings_table() const {
  ResultsTable t;
  t.title = "Wall-clock cost per update in the held-out runs (changes on every run)";
  t.header = {"scenario", "controller", "updates", "mean_update_us", "max_update_us"};
  for (std::size_t s = 0; s < held_out.size(); ++s) {
    for (const TunedController& c : controllers) {
      const ScenarioScore& r = c.held_out[s];
      t.rows.push_back({r.scenario, c.controller, std::to_string(r.updates),
                        ResultsTable::number(r.mean_update_us, 2),
                        ResultsTable::number(r.max_update_us, 1)});
    }
  }
  t.notes = {
      "steady_clock around update(), inside the closed-loop simulation; the benchmark "
      "of record is bench_baselines (docs/benchmarks.md)."};
  return t;
}

}  // namespace smoothsteer
