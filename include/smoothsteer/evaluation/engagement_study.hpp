#pragma once
//! \file engagement_study.hpp
//! The engagement family (docs/engagement.md): the lane-change scenarios started off the path,
//! every start offset times every heading error, each case run with the scenario's own
//! (certified) controller, with every real-time baseline held to the car's limits (the same
//! construction as the lane-change comparison, scenario_comparison.hpp), and compared with the
//! optimal-control lower bound of the case (engagement_bound.hpp).

#include <string>
#include <vector>

#include "smoothsteer/evaluation/engagement_bound.hpp"
#include "smoothsteer/evaluation/results_table.hpp"
#include "smoothsteer/runner/scenario.hpp"

namespace smoothsteer {

//! The bound problem of a scenario: its path, start pose, speed, wheelbase and the car's steering
//! limits (vehicle file), over the scenario's duration or until the rear axle's closest point
//! reaches the end of an open path, whichever is first. The speed is held constant: a constant
//! profile's speed, else the profile's slowest moving speed (bound_speed_mps).
EngagementBoundProblem engagement_bound_problem(const runner::Scenario& scenario,
                                                double time_step_s = 0.04);

//! The speed the bound holds: a constant profile's, else the slowest |v| >= 0.1 m/s among the
//! profile's knots or ramp ends. In arc length a slower car has more steering rate and
//! acceleration per metre, so holding the slowest speed can only lower the bound.
double bound_speed_mps(const SpeedProfile& speed) noexcept;

//! Travel of the rear axle from the start to the first row after which its |e| stays below
//! `threshold_m` to the end of the trace [m]; 0 if it never leaves, -1 if the last row is above.
double rear_reaching_distance(const std::vector<TraceSample>& trace, double threshold_m);

struct EngagementStudyOptions {
  //! The lane-change scenario files (lane_change_{10,15,19}.yaml).
  std::vector<std::string> scenario_files;
  //! Start offsets (override start.y_m) and heading errors (start.heading_rad): every pair.
  std::vector<double> offsets_m{0.0, 0.5, -0.5, 1.0, -1.0};
  std::vector<double> headings_rad{0.0, 0.05, -0.05, 0.1, -0.1, 0.15, -0.15};
  //! The limiter-equipped baselines (comparison controller names); default: every real-time
  //! baseline of the tuning study.
  std::vector<std::string> baselines;
  double bound_time_step_s = 0.04;    //!< grid of the lower bound's transcription [s]
  double reaching_threshold_m = 0.1;  //!< rear-axle reaching distance threshold [m]
  double divergence_m = 5.0;          //!< max |e| above this counts as diverged [m]
  int threads = 2;                    //!< worker threads (cases run in parallel)
  //! Throws std::invalid_argument naming the field, its value and the rule.
  void validate() const;
};

//! One controller (or the bound) on one case.
struct EngagementRun {
  std::string controller;
  double max_abs_e_m = 0.0;           //!< rear axle, whole run
  double reaching_distance_m = -1.0;  //!< rear_reaching_distance; NaN for the bound
  long held_above_limits = 0;         //!< angle + held rate + held acceleration samples above
  bool diverged = false;              //!< max |e| > divergence_m, a non-finite sample or an error
  std::string note;                   //!< stop reason or solver status
};

struct EngagementCase {
  std::string scenario;
  double speed_mps = 0.0;
  //! Overrides speed.initial_mps of the file with speed_mps (a constant-speed file).
  bool speed_overridden = false;
  double offset_m = 0.0;
  double heading_rad = 0.0;
  EngagementRun certified;               //!< the scenario's own controller
  std::vector<EngagementRun> baselines;  //!< in options.baselines order
  EngagementRun bound;                   //!< controller "lower_bound"
  EngagementBoundCheck bound_check;      //!< its re-simulation
  bool bound_converged = false;
  double bound_solve_time_s = 0.0;
  //! The baseline with the least max |e| (index into baselines).
  std::size_t best_baseline() const noexcept;
  double ratio_to_best_baseline() const noexcept;  //!< certified / best baseline max |e|
  double ratio_to_bound() const noexcept;          //!< certified / bound max |e|
};

struct EngagementStudyResult {
  EngagementStudyOptions options;
  std::vector<EngagementCase> cases;  //!< by scenario file, then offset, then heading
  double wall_time_s = 0.0;
  //! Every case and controller (the CSV of docs/results/engagement.csv).
  ResultsTable table() const;
  //! Per speed: worst and median ratios, how many cases meet certified <= 1.1x the best
  //! baseline and <= 1.5x the bound, the worst cases, and every controller's medians.
  std::string summary_markdown() const;
};

//! The overrides of `smoothsteer run --set` that make a scenario file a case: its start offset
//! and heading, and its speed when speed_overridden.
std::vector<std::string> engagement_case_overrides(const EngagementCase& c);

//! Every real-time baseline of the tuning study (the default of options.baselines).
std::vector<std::string> default_study_baselines();

//! Runs one case of `file` in place: the file with the case's start (and speed, when
//! speed_overridden), its own controller, options.baselines and the bound. A path with gear
//! changes gets no bound (NaN, note says why). Errors are recorded in the case, not thrown.
void run_engagement_case(const std::string& file, const EngagementStudyOptions& options,
                         EngagementCase& c);

//! Runs every case (in parallel on options.threads). Throws std::invalid_argument for invalid
//! options, io::ConfigError for a scenario that does not load.
EngagementStudyResult run_engagement_study(const EngagementStudyOptions& options);

}  // namespace smoothsteer
