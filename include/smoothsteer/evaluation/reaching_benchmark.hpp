#pragma once
//! \file reaching_benchmark.hpp
//! Benchmark 1, the paper's Tab. roc_vx (Sec. IV-B): travelled distance until the rear axle
//! reaches a straight path, for psi(0) in {0, 0.2 pi, -0.2 pi}, for the optimum, the proposed
//! controller (n = 1, k_rob = 0) and HOSM, on the ideal kinematic model with identical bounds.
//!
//! The paper does not publish the scenario. Chosen here (docs/baselines.md): lambda = 0.5 m,
//! delta-bar = 0.5 rad, e(0) = -0.35 m (right of the path, so psi(0) > 0 points towards it),
//! delta(0) = 0. The proposed controller uses kbar_f = sin(delta-bar) / lambda (C1 tight), and
//! delta-bar' is the rate bound its chain implies (compute_chain_bounds: 2 tan(delta-bar) /
//! lambda); the optimum and HOSM get the same delta-bar'. HOSM's psi-bar is chosen, as in the
//! paper, to minimise the travel for psi(0) = 0 (grid search). "Reached": from that point on
//! |e| <= tol_e and |psi| <= tol_psi; the exact optimum ends at e = psi = delta = 0.

#include <string>
#include <vector>

#include "smoothsteer/evaluation/optimal_reaching.hpp"
#include "smoothsteer/evaluation/paper_figures.hpp"
#include "smoothsteer/evaluation/results_table.hpp"
#include "smoothsteer/sim/kinematic_closed_loop.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct ReachingBenchmarkOptions {
  double wheelbase_m = 0.5;                //!< lambda [m]
  double steering_angle_bound_rad = 0.5;   //!< delta-bar [rad]
  double initial_lateral_error_m = -0.35;  //!< e(0) [m]
  std::vector<double> initial_headings_rad{0.0, 0.2 * 3.141592653589793, -0.2 * 3.141592653589793};
  double lateral_tolerance_m = 0.01;    //!< tol_e of "reached" [m]
  double heading_tolerance_rad = 0.01;  //!< tol_psi of "reached" [rad]
  double speed_mps = 1.0;               //!< kinematic-loop speed (results are per metre)
  double period_s = 0.002;              //!< control period [s]
  double horizon_m = 20.0;              //!< simulated travel [m]
  int intervals = 150;                  //!< collocation intervals of the optimum
  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>".
  std::string validation_error() const { return describe(first_violation()); }
  //! Throws std::invalid_argument with validation_error().
  void validate() const { throw_if_violated(first_violation()); }
};

struct ReachingBenchmarkCase {
  double initial_heading_rad = 0.0;
  ReachingSolution optimum;          //!< exact terminal state e = psi = delta = 0
  ReachingSolution relaxed_optimum;  //!< lower bound: |e| <= tol_e, |psi| <= tol_psi, delta free
  ReachingCheck optimum_check;       //!< re-simulation of the exact optimum
  double proposed_distance_m = 0.0;  //!< NaN if never reached within the horizon
  double hosm_distance_m = 0.0;
  double proposed_max_rate_per_m = 0.0;  //!< max |d delta/ds| seen in the loop [rad/m]
  double hosm_max_rate_per_m = 0.0;
};

struct ReachingBenchmarkResult {
  ReachingBenchmarkOptions options;
  double steering_rate_bound_per_m = 0.0;  //!< delta-bar' shared by all three
  double front_curvature_bound = 0.0;      //!< kbar_f of the proposed controller [1/m]
  double hosm_heading_bound_rad = 0.0;     //!< psi-bar chosen for HOSM
  std::vector<ReachingBenchmarkCase> cases;
  //! The deterministic table (same on every run), with the paper's figures where `paper` has
  //! them (table "roc_vx", case = psi0 with 4 decimals).
  ResultsTable table(const PaperFigures& paper = {}) const;
  //! The wall-clock solve times, apart so that the committed table does not churn.
  ResultsTable timings_table() const;
};

ReachingBenchmarkResult run_reaching_benchmark(const ReachingBenchmarkOptions& options);

//! Travel of the rear axle until it enters |e| <= tol_e, |psi| <= tol_psi and stays (within the
//! recorded trace); NaN if it never does.
double reaching_distance(const KinematicLoopResult& result, double lateral_tolerance_m,
                         double heading_tolerance_rad);

}  // namespace smoothsteer
