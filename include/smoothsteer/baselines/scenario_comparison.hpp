#pragma once
//! \file scenario_comparison.hpp
//! Benchmarks 2 and 3 on the kinetic single-track model with actuator (smoothsteer_io):
//! every comparison controller on the lane-change scenarios, and the proposed controller's
//! four parameter settings of Sec. IV-A on circle_sections. Also registers the comparison
//! controllers in the io registry, so scenario files can name them (`controller: {type: hosm}`).
//! Available only when smoothsteer_io is built (SMOOTHSTEER_HAS_io).

#include <string>
#include <vector>

#include "smoothsteer/baselines/results_table.hpp"

namespace smoothsteer {

//! Registers every name of comparison_controller_names() as an io controller type. Keys read
//! from the controller section: nominal_speed_mps (default: 10), k_rob (0.3),
//! hosm_heading_bound_rad (0.6), lead_wheelbase_m (1.0). Limits come from the vehicle's
//! max_steering_angle_rad and max_steering_rate_radps. Idempotent.
void register_comparison_controllers();

//! Benchmark 2: for each scenario file (lane_change_{10,15,19}.yaml) and every controller:
//! max |e|, std of the steering rate, max steering acceleration, limit hits of the saturation.
ResultsTable run_lane_change_comparison(const std::vector<std::string>& scenario_files);

//! Benchmark 3: circle_sections.yaml with the paper's base setting and the three variations of
//! Sec. IV-A (k_rob, kbar_l and lambda_l changed one at a time).
ResultsTable run_parameter_comparison(const std::string& scenario_file);

}  // namespace smoothsteer
