#pragma once
//! \file road_suite_comparison.hpp
//! Every controller on the road suite (scenarios/roads/, the hairpin), with each of the three
//! published cars (vehicles/) and on each plant (the single-track model and the held-out
//! double-track model): rear-axle max and RMS |e|, held command samples above the car's limits,
//! runs wide (max |e| > 1 m) or spun (|heading error| > 1 rad or |rear-axle side slip| >
//! 0.5 rad). The scenario's own controller is the certified route, with the schedule tuned for
//! the car (a road's schedules/passenger_car_X.csv becomes schedules/<car>_X.csv); every baseline
//! runs behind the second-order limiter of `compare` (the scenario actuator's angle and rate limits
//! and the car's acceleration limit), so every row holds the same limits.
//! docs/results/road_suite.md.

#include <string>
#include <vector>

#include "smoothsteer/evaluation/results_table.hpp"
#include "smoothsteer/sim/planner_windows.hpp"

namespace smoothsteer {

struct RoadSuiteOptions {
  std::vector<std::string> road_files;     //!< scenario files of the roads
  std::vector<std::string> vehicle_files;  //!< vehicle files (each road runs with each)
  //! Scenario `model` values: "dynamic" (single-track) and/or "double_track".
  std::vector<std::string> models{"dynamic", "double_track"};
  //! "certified" (the scenario's own controller), "steering_system" (the car's system built
  //! from the car alone, the scenario's `controller: {type: steering_system}`) and comparison
  //! controller names.
  std::vector<std::string> controllers;
  //! Stack mode (planner_windows.hpp): with period_s > 0 every run's road arrives as the
  //! planner's windows, once for each jitter of `jitters_m` (the windows' jitter_std_m; the
  //! fit's tolerance as `planner` says). period_s = 0: the whole road at the start.
  PlannerWindows planner;
  std::vector<double> jitters_m{0.0};  //!< each in [0, 1] m; used in stack mode only
  //! When not empty, each run's trace (t, s, x, y, e, delta_cmd) goes to
  //! <trace_directory>/<road>/<car>_<model>_<controller>.csv (for scripts/road_suite_figures.py).
  std::string trace_directory;
  int threads = 1;  //!< worker threads, in [1, 256]

  //! Throws std::invalid_argument naming the field: empty lists, an unknown model or controller,
  //! threads or a jitter out of range.
  void validate() const;
};

//! A run is wide above this rear-axle max |e| [m] and spun above these angles [rad].
inline constexpr double road_suite_wide_error_m = 1.0;
inline constexpr double road_suite_spin_heading_error_rad = 1.0;
inline constexpr double road_suite_spin_side_slip_rad = 0.5;

struct RoadSuiteResult {
  ResultsTable runs;     //!< one row per road x car x plant x controller
  ResultsTable summary;  //!< per plant x controller: totals over roads and cars
};

RoadSuiteResult run_road_suite_comparison(const RoadSuiteOptions& options);

//! The name of the car's system built from the car alone (no schedule file, no path).
inline constexpr const char* road_suite_car_system = "steering_system";

//! The default controller list: "certified" and every comparison controller.
std::vector<std::string> road_suite_controller_names();

}  // namespace smoothsteer
