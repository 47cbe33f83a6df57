#pragma once
//! \file scenario_comparison.hpp
//! Benchmarks 2 and 3 on the kinetic single-track model with actuator (smoothsteer_runner):
//! every comparison controller on the lane-change scenarios, and the proposed controller's
//! four parameter settings of Sec. IV-A on circle_sections.

#include <string>
#include <vector>

#include "smoothsteer/evaluation/paper_figures.hpp"
#include "smoothsteer/evaluation/results_table.hpp"

namespace smoothsteer {

//! Benchmark 2: for each scenario file (lane_change_{10,15,19}.yaml) and every controller:
//! max |e|, std of the steering rate, max steering acceleration, limit hits of the saturation.
//! `paper` supplies the paper_max_e_m column (table "lane_change", case = speed with 1 decimal).
//! `overrides` go to every scenario (e.g. "model=double_track": the held-out plant).
ResultsTable run_lane_change_comparison(const std::vector<std::string>& scenario_files,
                                        const PaperFigures& paper = {},
                                        const std::vector<std::string>& overrides = {});

//! Benchmark 3: circle_sections.yaml with the paper's base setting and the three variations of
//! Sec. IV-A (k_rob, kbar_l and lambda_l changed one at a time).
ResultsTable run_parameter_comparison(const std::string& scenario_file);

}  // namespace smoothsteer
