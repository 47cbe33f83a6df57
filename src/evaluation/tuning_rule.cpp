#include "smoothsteer/evaluation/tuning_rule.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

#include "smoothsteer/baselines/parameter_checks.hpp"
#include "smoothsteer/evaluation/certified_route.hpp"
#include "smoothsteer/runner/progress.hpp"

namespace smoothsteer {

namespace {

// Ranges: about a factor 4 either side of each default (docs/baselines.md "Gains"); for the
// certified controller the knobs of its tuning route (certified_route.hpp).
const std::map<std::string, std::vector<GainAxis>, std::less<>>& axes_table() {
  static const std::map<std::string, std::vector<GainAxis>, std::less<>> table{
      {certified_controller_name,
       {{"feedforward_rate_share", 0.2, 0.8}, {"boundary_layer", 0.005, 0.08}}},
      {"hosm", {{"hosm_heading_bound_rad", 0.1, 1.2}}},
      {"newton_raphson", {{"horizon_s", 0.3, 2.4}, {"gain_per_s", 1.0, 16.0}}},
      {"stanley", {{"gain_per_s", 0.5, 8.0}, {"softening_mps", 0.25, 4.0}}},
      {"pure_pursuit", {{"min_lookahead_m", 1.5, 12.0}, {"lookahead_time_s", 0.15, 1.2}}},
      {"lqr",
       {{"weight_lateral", 0.1, 10.0},
        {"weight_heading", 0.1, 10.0},
        {"weight_steering", 1.0, 1000.0}}},
      {"mpc",
       {{"weight_lateral_error", 0.01, 10.0},
        {"weight_heading_error_squared_speed", 0.03, 3.0},
        {"weight_steering_input", 0.1, 10.0}}},
      {"mpc_constrained",
       {{"weight_lateral_error", 0.01, 10.0},
        {"weight_heading_error_squared_speed", 0.03, 3.0},
        {"weight_steering_input", 0.1, 10.0}}}};
  return table;
}

double grid_value(const GainAxis& axis, int index, int count) {
  if (count == 1) return std::sqrt(axis.low * axis.high);
  const double fraction = static_cast<double>(index) / (count - 1);
  return axis.low * std::pow(axis.high / axis.low, fraction);
}

}  // namespace

const std::vector<std::string>& study_controller_names() {
  static const std::vector<std::string> names{
      certified_controller_name, "pure_pursuit", "stanley",        "lqr", "hosm",
      "newton_raphson",          "mpc",          "mpc_constrained"};
  return names;
}

std::vector<GainAxis> gain_axes(std::string_view controller) {
  const auto found = axes_table().find(controller);
  return found == axes_table().end() ? std::vector<GainAxis>{} : found->second;
}

void apply_gain(std::string_view controller, const std::string& key, double value,
                ComparisonSetup& setup) {
  const auto unknown = [&] {
    throw std::invalid_argument("apply_gain: key '" + key + "' is not a tuned gain of '" +
                                std::string(controller) + "'");
  };
  if (controller == "hosm" && key == "hosm_heading_bound_rad") {
    setup.hosm_heading_bound_rad = value;
  } else if (controller == "newton_raphson") {
    if (key == "horizon_s")
      setup.newton_raphson.horizon_s = value;
    else if (key == "gain_per_s")
      setup.newton_raphson.gain_per_s = value;
    else
      unknown();
  } else if (controller == "stanley") {
    if (key == "gain_per_s")
      setup.stanley.gain_per_s = value;
    else if (key == "softening_mps")
      setup.stanley.softening_mps = value;
    else
      unknown();
  } else if (controller == "pure_pursuit") {
    if (key == "min_lookahead_m")
      setup.pure_pursuit.min_lookahead_m = value;
    else if (key == "lookahead_time_s")
      setup.pure_pursuit.lookahead_time_s = value;
    else
      unknown();
  } else if (controller == "lqr") {
    if (key == "weight_lateral")
      setup.lqr.weight_lateral = value;
    else if (key == "weight_heading")
      setup.lqr.weight_heading = value;
    else if (key == "weight_steering")
      setup.lqr.weight_steering = value;
    else
      unknown();
  } else if (controller == "mpc" || controller == "mpc_constrained") {
    if (key == "weight_lateral_error")
      setup.mpc.weight_lateral_error = value;
    else if (key == "weight_heading_error_squared_speed")
      setup.mpc.weight_heading_error_squared_speed = value;
    else if (key == "weight_steering_input")
      setup.mpc.weight_steering_input = value;
    else
      unknown();
  } else {
    unknown();
  }
}

std::vector<int> grid_shape(int budget, std::size_t axes) {
  const bool power_of_two = budget >= 1 && budget <= 4096 && (budget & (budget - 1)) == 0;
  int factors = 0;
  while (power_of_two && (1 << factors) < budget) ++factors;
  detail::require(power_of_two && static_cast<std::size_t>(factors) >= axes, "TuningRuleOptions",
                  "budget", budget,
                  "must be a power of two in [2^" + std::to_string(axes) +
                      ", 4096] (at least two grid points per gain)");
  std::vector<int> shape(axes, 1);
  for (int factor = 0; axes > 0 && factor < factors; ++factor) shape[factor % axes] *= 2;
  return shape;
}

void TuningRuleOptions::validate() const {
  detail::require(positive_finite(divergence_m), "TuningRuleOptions", "divergence_m", divergence_m,
                  "must be finite and > 0");
  for (const std::string& name : controllers) {
    const auto& known = comparison_controller_names();
    if (name != certified_controller_name &&
        std::find(known.begin(), known.end(), name) == known.end()) {
      throw std::invalid_argument("TuningRuleOptions: controllers contains '" + name +
                                  "', which is neither 'certified' nor a comparison controller");
    }
    if (const std::size_t axes = gain_axes(name).size(); axes > 0) grid_shape(budget, axes);
  }
}

namespace {

//! Runs of the whole study: each controller's grid on every training scenario, then the chosen
//! gains on every held-out one (the count the progress display expects).
std::size_t study_runs(const TuningRuleOptions& options, std::size_t training,
                       std::size_t held_out) {
  std::size_t runs = 0;
  for (const std::string& controller : options.controllers) {
    const std::vector<GainAxis> axes = gain_axes(controller);
    std::size_t configurations = 1;
    if (!axes.empty()) {
      for (int count : grid_shape(options.budget, axes.size())) configurations *= count;
    }
    runs += configurations * training + held_out;
  }
  return runs;
}

}  // namespace

TuningRuleResult run_tuning_rule(const std::vector<runner::Scenario>& training,
                                 const std::vector<runner::Scenario>& held_out,
                                 const TuningRuleOptions& options) {
  options.validate();
  if (training.empty() || held_out.empty()) {
    throw std::invalid_argument(
        "run_tuning_rule: training and held_out each need at least one scenario");
  }
  TuningRuleResult result;
  result.options = options;
  for (const runner::Scenario& s : training) result.training.push_back(s.name);
  for (const runner::Scenario& s : held_out) result.held_out.push_back(s.name);
  runner::progress_expect(study_runs(options, training.size(), held_out.size()));
  for (const std::string& controller : options.controllers) {
    const std::vector<GainAxis> axes = gain_axes(controller);
    const std::vector<int> shape =
        axes.empty() ? std::vector<int>{} : grid_shape(options.budget, axes.size());
    int configurations = 1;
    for (int count : shape) configurations *= count;
    // Key of a configuration: (not admissible, training scenarios diverged or not certifiable,
    // held-command samples above the limits, worst max |e|, mean held rate RMS, grid
    // index). For admissible configurations the second and third are 0: the rule of the header.
    using Rank = std::tuple<bool, int, long, double, double, int>;
    Rank best{true, INT_MAX, LONG_MAX, HUGE_VAL, HUGE_VAL, configurations};
    std::vector<std::pair<std::string, double>> best_gains;
    for (int index = 0; index < configurations; ++index) {
      std::vector<std::pair<std::string, double>> gains;
      int remainder = index;
      for (std::size_t a = axes.size(); a-- > 0;) {  // last axis varies fastest
        const int count = shape[a];
        gains.insert(gains.begin(), {axes[a].key, grid_value(axes[a], remainder % count, count)});
        remainder /= count;
      }
      bool admissible = true;
      int failed = 0;
      long violations = 0;
      double worst = 0.0, rate_sum = 0.0;
      for (const runner::Scenario& scenario : training) {
        runner::throw_if_interrupted("the tuning study was");
        const ScenarioScore s =
            score_configuration(scenario, controller, gains, options.divergence_m);
        runner::progress_case_done();
        admissible = admissible && s.admissible();
        failed += (s.diverged || s.infeasible) ? 1 : 0;
        violations += s.held_above_limits();
        const double max_e = s.metrics.max_abs_rear_error_m;
        worst = std::max(worst, std::isfinite(max_e) ? max_e : HUGE_VAL);
        rate_sum += s.metrics.held_rate_rms_radps;
      }
      const Rank rank{
          !admissible, failed, violations, worst, rate_sum / static_cast<double>(training.size()),
          index};
      if (rank < best) {
        best = rank;
        best_gains = gains;
      }
    }
    TunedController tuned;
    tuned.controller = controller;
    tuned.gains = best_gains;
    tuned.configurations = configurations;
    tuned.admissible = !std::get<0>(best);
    tuned.training_worst_max_abs_e_m = std::get<3>(best);
    for (const runner::Scenario& scenario : held_out) {
      runner::throw_if_interrupted("the tuning study was");
      tuned.held_out.push_back(
          score_configuration(scenario, controller, best_gains, options.divergence_m));
      runner::progress_case_done();
    }
    result.controllers.push_back(std::move(tuned));
  }
  return result;
}

}  // namespace smoothsteer
