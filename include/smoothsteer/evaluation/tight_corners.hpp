#pragma once
//! \file tight_corners.hpp
//! Tight corners (docs/corners.md): the corners where the car's steering is asked the most, each
//! run from the path with the scenario's own controller and every limiter-held baseline (the
//! engagement family's construction, engagement_study.hpp), against two optimal-control
//! references of the corner, the least max |e| any steering reaches under the car's angle, rate
//! and acceleration limits at the corner's speed: on the kinematic single track
//! (engagement_bound.hpp, started on the path) and on the linear kinetic single track, which adds
//! the slip's lag behind the steering (kinetic_reference.hpp). Both leave out the tires'
//! saturation and the actuator's lag, which only make a corner harder: on the plants they are
//! estimates from below, not strict bounds.

#include <string>
#include <vector>

#include "smoothsteer/evaluation/engagement_study.hpp"
#include "smoothsteer/evaluation/kinetic_reference.hpp"
#include "smoothsteer/evaluation/results_table.hpp"

namespace smoothsteer {

struct TightCorner {
  std::string file;        //!< scenario file
  double speed_mps = 0.0;  //!< overrides speed.initial_mps of a constant-speed file; 0: its own
};

//! The shipped corners: the hairpin at 7, 8.49 (its file) and 10 m/s, the urban turn, the
//! mountain hairpins and the parking lot (which changes gear: its row has no bound).
std::vector<TightCorner> shipped_tight_corners(const std::string& scenario_directory);

struct TightCornerOptions {
  std::vector<TightCorner> corners;
  std::vector<std::string> baselines;  //!< default: default_study_baselines()
  double bound_time_step_s = 0.04;     //!< grid of the reference's transcription [s]
  int threads = 2;                     //!< worker threads (corners run in parallel)
  //! Throws std::invalid_argument naming the field, its value and the rule.
  void validate() const;
};

struct TightCornerResult {
  TightCornerOptions options;            //!< with the default baselines filled in
  std::vector<EngagementCase> cases;     //!< one per corner, in options' order
  std::vector<double> bound_speeds_mps;  //!< the speed each reference holds (bound_speed_mps)
  //! The kinetic reference of each corner (controller "kinetic_reference"; NaN across a change
  //! of gear) and its re-simulation.
  std::vector<EngagementRun> kinetic_references;
  std::vector<KineticReferenceCheck> kinetic_checks;
  double wall_time_s = 0.0;
  //! Every corner and controller (docs/results/tight_corners.csv).
  ResultsTable table() const;
  //! One row per corner: the certified controller, the best baseline, the reference, the ratios.
  ResultsTable summary() const;
};

//! Runs every corner (in parallel on options.threads). Throws std::invalid_argument for invalid
//! options, io::ConfigError for a scenario that does not load.
TightCornerResult run_tight_corner_study(const TightCornerOptions& options);

}  // namespace smoothsteer
