#pragma once
//! \file sweep.hpp
//! Parameter sweeps: run one scenario under many sets of --set overrides in parallel, one row of
//! metrics per set.

#include <functional>
#include <string>
#include <vector>

#include "smoothsteer/runner/scenario.hpp"

namespace smoothsteer::runner {

//! One axis of a grid: key and the values it takes ("controller.k_rob", {"0.2", "0.3"}).
struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
};
//! Parses "key=v1,v2,v3". Throws ConfigError.
SweepAxis parse_sweep_axis(const std::string& text);
//! Most runs one sweep may ask for.
inline constexpr std::size_t max_sweep_rows = 100'000;
//! Cartesian product of the axes: every combination as a list of "key=value" overrides.
//! Throws ConfigError if it would exceed max_sweep_rows.
std::vector<std::vector<std::string>> sweep_grid(const std::vector<SweepAxis>& axes);
//! The paper's Sec. IV-A variations of a lead_wheel scenario: the base, lead_curvature_bound
//! -50 %, lead_wheelbase_m +300 % and k_rob -33 %, each alone.
std::vector<std::vector<std::string>> paper_variations(const Scenario& base);

struct SweepRow {
  std::vector<std::string> overrides;
  bool ok = false;
  std::string error;  //!< load or run error of this row
  Metrics metrics;
};

//! Calls task(i) once for every i in [0, count) on `threads` worker threads (0 = all cores),
//! `progress(done, count)` after each, serialised. `task` must not throw. Each task also ticks
//! the installed progress observer (progress.hpp); once it asks to stop, no new task starts and
//! Interrupted is thrown after every worker has stopped.
void run_parallel(std::size_t count, int threads, const std::function<void(std::size_t)>& task,
                  const std::function<void(int, int)>& progress = {});

//! Runs every override set (added to `base_overrides`) on `threads` worker threads (0 = all
//! cores). `progress(done, total)` is called from the workers after each run, serialised.
std::vector<SweepRow> run_sweep(const std::string& scenario_file,
                                const std::vector<std::string>& base_overrides,
                                const std::vector<std::vector<std::string>>& sets, int threads,
                                const std::function<void(int, int)>& progress = {});

//! CSV table: one column per swept key, then ok, error and every metric.
std::string sweep_csv(const std::vector<SweepRow>& rows);

}  // namespace smoothsteer::runner
