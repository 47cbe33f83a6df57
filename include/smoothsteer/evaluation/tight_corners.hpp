#pragma once
//! \file tight_corners.hpp
//! Tight corners (docs/corners.md): the corners where the car's steering rate binds, each run
//! from the path with the scenario's own controller and every limiter-held baseline (the
//! engagement family's construction, engagement_study.hpp), against the optimal-control
//! reference of the corner: the least max |e| any steering reaches under the car's angle, rate
//! and acceleration limits (engagement_bound.hpp, started on the path), on the kinematic single
//! track at the corner's speed. It leaves out the slip's lag behind the steering and the tires'
//! saturation, which only make a corner harder: on the kinetic plants it is an estimate from
//! below, not a strict bound. (The shipped cars steer neutrally in the tires' linear range: their
//! axles share one tire curve scaled by the static load, so K_f = K_r and the kinematic steering
//! is theirs in steady state.)

#include <string>
#include <vector>

#include "smoothsteer/evaluation/engagement_study.hpp"
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
