#pragma once
//! \file tuning_rule.hpp
//! One stated tuning rule for every comparison controller (issue 9, item 3; docs/baselines.md
//! "Tuning rule"):
//!   1. each controller gets a log-spaced grid over its gains with the same number of
//!      configurations (`budget`, a power of two; every axis gets a power-of-two share);
//!   2. every configuration runs on the *training* scenarios under the scenario actuator's
//!      limits (the SaturatedController clamps and counts);
//!   3. the chosen configuration is, lexicographically: admissible (no clamped update and no
//!      divergence on any training scenario) first, then the smallest worst-case max |e| over
//!      the training scenarios, then the smallest mean RMS of the held command's rate, then the
//!      grid order;
//!   4. it is reported on the *held-out* scenarios only (other speeds or paths), so that no
//!      reported row was chosen in-sample.
//! The lead-wheel controllers (proposed_c0/c1, dubins_smc) keep their fixed parameters for now
//! (one configuration); the certified tuning of issue 8 replaces them. Deterministic: the same
//! inputs give the same result (no randomness, no timing, sequential runs).

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/evaluation/results_table.hpp"
#include "smoothsteer/io/scenario.hpp"

namespace smoothsteer {

//! One gain of a controller's grid: its scenario key and its range (log-spaced, inclusive).
struct GainAxis {
  std::string key;
  double low = 0.0;
  double high = 0.0;
};

//! The axes of `controller`; empty for the controllers with fixed parameters.
std::vector<GainAxis> gain_axes(std::string_view controller);

//! Sets the gain `key` of `controller` in `setup` (the same keys as its scenario section).
//! Throws std::invalid_argument for a key the controller does not have.
void apply_gain(std::string_view controller, const std::string& key, double value,
                ComparisonSetup& setup);

//! Points per axis whose product is exactly `budget`: the budget's factors of two are dealt
//! round-robin over the axes. Throws std::invalid_argument naming the field unless `budget` is
//! a power of two >= 2^axes.
std::vector<int> grid_shape(int budget, std::size_t axes);

struct TuningRuleOptions {
  int budget = 16;            //!< configurations per tuned controller (power of two)
  double divergence_m = 5.0;  //!< a max |e| above this counts as divergence (spin) [m]
  std::vector<std::string> controllers = comparison_controller_names();
  void validate() const;
};

//! How one configuration did on one scenario.
struct ScenarioScore {
  std::string scenario;
  double max_abs_e_m = 0.0;                  //!< rear axle, whole run
  double max_abs_e_after_reaching_m = -1.0;  //!< rear axle after reaching; -1: not reached
  double held_rate_rms_radps = 0.0;          //!< RMS of the held command's rate (sim/metrics)
  double actual_rate_rms_radps = 0.0;        //!< RMS of the actuator output's rate
  double max_side_slip_rad = 0.0;
  long clamped_updates = 0;  //!< updates the saturation clamped (above the limits)
  bool diverged = false;     //!< max |e| > divergence_m or a non-finite sample
};

struct TunedController {
  std::string controller;
  std::vector<std::pair<std::string, double>> gains;  //!< the chosen configuration
  int configurations = 0;                             //!< evaluated on the training scenarios
  bool admissible = false;  //!< the chosen one has no clamp and no divergence in training
  double training_worst_max_abs_e_m = 0.0;
  std::vector<ScenarioScore> held_out;  //!< one per held-out scenario
};

struct TuningRuleResult {
  TuningRuleOptions options;
  std::vector<std::string> training, held_out;  //!< scenario names
  std::vector<TunedController> controllers;
  ResultsTable table() const;
};

TuningRuleResult run_tuning_rule(const std::vector<io::Scenario>& training,
                                 const std::vector<io::Scenario>& held_out,
                                 const TuningRuleOptions& options = {});

}  // namespace smoothsteer
