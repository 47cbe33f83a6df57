#pragma once
//! \file tuning_rule.hpp
//! One stated tuning rule for every controller of the comparison (so that no controller of the
//! comparison is tuned more than another; docs/baselines.md "Tuning rule"):
//!   1. each controller gets a log-spaced grid over its gains with the same number of
//!      configurations (`budget`, a power of two; every axis gets a power-of-two share). The
//!      certified lead-wheel controller (`certified`, certified_route.hpp) gets a grid over the
//!      knobs of its tuning route; every point of it is certified for the car;
//!   2. every configuration runs on the *training* scenarios under the car's actuator (the
//!      scenario's actuator model and its angle and rate saturation; the SaturatedController
//!      clamps and counts what a controller asks beyond them);
//!   3. the chosen configuration is, lexicographically: admissible (certifiable, no
//!      held-command sample above the car's limits and no divergence on any training scenario;
//!      a command the saturation cut to the limits is counted but allowed) first, then the smallest
//!      worst-case max |e| over the training scenarios, then the smallest mean RMS of the held
//!      command's rate, then the grid order. Where no configuration is admissible, fewer diverged
//!      (or uncertifiable) training runs come first, then fewer held-command samples above the
//!      limits, then the same order;
//!   4. it is reported on the *held-out* scenarios only (other speeds or paths), so that no
//!      reported row was chosen in-sample.
//! Deterministic: the same inputs give the same tables (no randomness, sequential runs; the
//! wall-clock cost per update goes to a separate timings table).

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/evaluation/results_table.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "smoothsteer/sim/metrics.hpp"

namespace smoothsteer {

//! One gain of a controller's grid: its scenario key and its range (log-spaced, inclusive).
struct GainAxis {
  std::string key;
  double low = 0.0;
  double high = 0.0;
};

//! The axes of `controller` (a comparison controller or `certified`); empty for the controllers
//! with fixed parameters.
std::vector<GainAxis> gain_axes(std::string_view controller);

//! Sets the gain `key` of the comparison controller `controller` in `setup` (the same keys as
//! its scenario section). Throws std::invalid_argument for a key the controller does not have
//! (the certified controller's knobs go to certified_route_options instead).
void apply_gain(std::string_view controller, const std::string& key, double value,
                ComparisonSetup& setup);

//! Points per axis whose product is exactly `budget`: the budget's factors of two are dealt
//! round-robin over the axes. Throws std::invalid_argument naming the field unless `budget` is
//! a power of two >= 2^axes.
std::vector<int> grid_shape(int budget, std::size_t axes);

//! The controllers of the study: the certified lead-wheel controller and every
//! real-time baseline.
const std::vector<std::string>& study_controller_names();

struct TuningRuleOptions {
  int budget = 16;            //!< configurations per tuned controller (power of two)
  double divergence_m = 5.0;  //!< a max |e| above this counts as divergence (spin) [m]
  std::vector<std::string> controllers = study_controller_names();
  void validate() const;
};

//! How one configuration did on one scenario.
struct ScenarioScore {
  std::string scenario;
  Metrics metrics;           //!< of the run (sim/metrics.hpp, docs/metrics.md)
  long clamped_updates = 0;  //!< updates the saturation clamped (the raw command was above)
  bool diverged = false;     //!< max |e| > divergence_m or a non-finite sample
  bool infeasible = false;   //!< the certified route cannot certify the car with these knobs
  long updates = 0;          //!< update() calls, and their wall-clock cost (timings only)
  double mean_update_us = 0.0;
  double max_update_us = 0.0;

  //! Held-command samples above the car's limits: angle, rate and acceleration counts summed.
  long held_above_limits() const noexcept;
  //! Actuator-output samples above the car's rate and acceleration limits, summed.
  long actual_above_limits() const noexcept;
  //! No held sample above the limits, no divergence, certifiable (clamps are allowed).
  bool admissible() const noexcept;
};

//! Runs `controller` (a study controller) with `gains` on `scenario`; the baselines get the
//! scenario's comparison set-up (scenario_setup.hpp), the certified one its route.
ScenarioScore score_configuration(const runner::Scenario& scenario, const std::string& controller,
                                  const std::vector<std::pair<std::string, double>>& gains,
                                  double divergence_m);

struct TunedController {
  std::string controller;
  std::vector<std::pair<std::string, double>> gains;  //!< the chosen configuration
  int configurations = 0;                             //!< evaluated on the training scenarios
  bool admissible = false;  //!< the chosen one is admissible on every training scenario
  double training_worst_max_abs_e_m = 0.0;
  std::vector<ScenarioScore> held_out;  //!< one per held-out scenario
};

struct TuningRuleResult {
  TuningRuleOptions options;
  std::vector<std::string> training, held_out;  //!< scenario names
  std::vector<TunedController> controllers;
  //! The held-out rows (deterministic), with each scenario's Pareto front in max |e| against
  //! the actuator's RMS steering rate.
  ResultsTable table() const;
  //! Wall-clock cost per update of the held-out runs (changes on every run).
  ResultsTable timings_table() const;
};

TuningRuleResult run_tuning_rule(const std::vector<runner::Scenario>& training,
                                 const std::vector<runner::Scenario>& held_out,
                                 const TuningRuleOptions& options = {});

}  // namespace smoothsteer
