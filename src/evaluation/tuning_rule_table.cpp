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

//! One row of the table: a controller's held-out run and its place on the scenario's fronts.
struct Row {
  const TunedController& tuned;
  const ScenarioScore& score;
  bool front, front_within;
  const Metrics& metrics() const { return score.metrics; }
};

std::string yes_no(bool value) {
  return value ? "yes" : "no";
}

//! A column's name and its value in one place; an infeasible row (the certified route could not
//! certify the car) shows only the columns marked `always`.
struct Column {
  const char* name;
  std::string (*value)(const Row&);
  bool always = false;
};

std::string fixed(double value, int digits) {
  return ResultsTable::number(value, digits);
}

const Column columns[] = {
    {"scenario", [](const Row& r) { return r.score.scenario; }, true},
    {"controller", [](const Row& r) { return r.tuned.controller; }, true},
    {"pareto", [](const Row& r) { return yes_no(r.front); }, true},
    {"pareto_within_limits", [](const Row& r) { return yes_no(r.front_within); }, true},
    {"max_abs_e_m", [](const Row& r) { return fixed(r.metrics().max_abs_rear_error_m, 3); }},
    {"rms_e_m", [](const Row& r) { return fixed(r.metrics().rms_rear_error_m, 3); }},
    {"held_rate_rms_radps", [](const Row& r) { return fixed(r.metrics().held_rate_rms_radps, 4); }},
    {"held_rate_max_radps", [](const Row& r) { return fixed(r.metrics().held_rate_max_radps, 3); }},
    {"held_accel_rms_radps2",
     [](const Row& r) { return fixed(r.metrics().held_acceleration_rms_radps2, 3); }},
    {"held_accel_max_radps2",
     [](const Row& r) { return fixed(r.metrics().held_acceleration_max_radps2, 2); }},
    {"actual_rate_rms_radps",
     [](const Row& r) { return fixed(r.metrics().actual_rate_rms_radps, 4); }},
    {"actual_rate_max_radps",
     [](const Row& r) { return fixed(r.metrics().actual_rate_max_radps, 3); }},
    {"actual_accel_rms_radps2",
     [](const Row& r) { return fixed(r.metrics().actual_acceleration_rms_radps2, 3); }},
    {"actual_accel_max_radps2",
     [](const Row& r) { return fixed(r.metrics().actual_acceleration_max_radps2, 2); }},
    {"held_above_limits", [](const Row& r) { return std::to_string(r.score.held_above_limits()); }},
    {"actual_above_limits",
     [](const Row& r) { return std::to_string(r.score.actual_above_limits()); }},
    {"clamped_updates", [](const Row& r) { return std::to_string(r.score.clamped_updates); }},
    {"diverged",
     [](const Row& r) -> std::string {
       return r.score.infeasible ? "infeasible" : yes_no(r.score.diverged);
     },
     true},
    {"max_side_slip_rad", [](const Row& r) { return fixed(r.metrics().max_abs_side_slip_rad, 4); }},
    {"admissible_in_training", [](const Row& r) { return yes_no(r.tuned.admissible); }, true},
    {"gains", [](const Row& r) { return gains_text(r.tuned); }, true},
};

}  // namespace

ResultsTable TuningRuleResult::table() const {
  ResultsTable t;
  t.title = "Every controller tuned by one rule, reported on held-out scenarios";
  for (const Column& column : columns) t.header.push_back(column.name);
  const auto n = ResultsTable::number;
  for (std::size_t s = 0; s < held_out.size(); ++s) {
    std::vector<const ScenarioScore*> rows;
    for (const TunedController& c : controllers) rows.push_back(&c.held_out[s]);
    const std::vector<bool> front = pareto_front(rows, false);
    const std::vector<bool> front_within = pareto_front(rows, true);
    for (std::size_t i = 0; i < controllers.size(); ++i) {
      const Row row{controllers[i], *rows[i], front[i], front_within[i]};
      std::vector<std::string>& cells = t.rows.emplace_back();
      for (const Column& column : columns) {
        cells.push_back(column.always || !row.score.infeasible ? column.value(row) : "");
      }
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
