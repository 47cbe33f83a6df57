#pragma once
//! \file robustness_comparison.hpp
//! Every controller under a car's imperfections, each acting on the plant (or the sensors) only:
//! the controller is told nothing of them. For each scenario x car x plant x imperfection x
//! controller: the rear axle's max |e|, the same run's figure without the imperfection, and the
//! held command's samples above the car's limits. The certified route is the scenario's own
//! controller with the car's schedule (as in the road suite); every baseline runs behind the
//! second-order limiter of `compare`, so every row holds the same angle, rate and acceleration
//! limits. docs/results/robustness.md.

#include <string>
#include <vector>

#include "smoothsteer/evaluation/results_table.hpp"

namespace smoothsteer {

//! One imperfection of a real car: the scenario overrides (`--set` syntax) that put it into the
//! simulation. `group` is "disturbance", "model error" or "sensing".
struct Imperfection {
  std::string name;
  std::string group;
  std::vector<std::string> overrides;
};

//! The imperfections the simulator models: rack offsets of +-0.005, +-0.01 and +-0.02 rad and
//! plant curvature disturbances (docs/simulation.md).
std::vector<Imperfection> default_imperfections();

//! A scenario file and the time from which its max |e| counts [s] (0: the whole run), e.g. 8 s
//! for circle_sections, which starts off the path.
struct RobustnessScenario {
  std::string file;
  double settle_time_s = 0.0;
};

struct RobustnessOptions {
  std::vector<RobustnessScenario> scenarios;
  std::vector<std::string> vehicle_files;  //!< each scenario runs with each car
  //! Scenario `model` values: "dynamic" (single-track) and/or "double_track".
  std::vector<std::string> models{"dynamic"};
  std::vector<Imperfection> imperfections = default_imperfections();
  //! "certified" and comparison controller names.
  std::vector<std::string> controllers;
  int threads = 1;  //!< worker threads, in [1, 256]

  //! Throws std::invalid_argument naming the field: empty lists, an unknown model or controller,
  //! an imperfection without a name or overrides, a settle time or threads out of range.
  void validate() const;
};

struct RobustnessResult {
  ResultsTable runs;     //!< one row per scenario x car x plant x imperfection x controller
  ResultsTable summary;  //!< per scenario x car x plant x imperfection: certified vs best baseline
};

//! Runs every case (the nominal run of each scenario x car x plant x controller first); throws
//! std::runtime_error naming the case that failed to load or run.
RobustnessResult run_robustness_comparison(const RobustnessOptions& options);

}  // namespace smoothsteer
