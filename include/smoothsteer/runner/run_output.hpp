#pragma once
//! \file run_output.hpp
//! Output files of a run: trace.csv (one row per control step, columns in docs/cli.md) and
//! summary.json (metrics + full resolved parameters). They are written into an
//! OutputDirectory and appear together, or not at all, when it is committed.

#include <nlohmann/json.hpp>

#include <string>

#include "smoothsteer/io/atomic_output.hpp"
#include "smoothsteer/runner/scenario.hpp"

namespace smoothsteer::runner {

//! Version of the project (CMake's project version) and the git commit it was configured from
//! ("unknown" outside a git checkout).
std::string tool_version();
std::string tool_commit();

//! {"tool": {"version", "commit"}, "scenario", "controller", "status", "stop_reason", "metrics":
//! {...}, "parameters": {...}}.
nlohmann::json summary_json(const Scenario& scenario, const RunResult& result);

//! Simulates the scenario, streaming trace.csv into `out` as the steps are computed (memory
//! does not grow with the run's length) and then writing summary.json. result.simulation.trace
//! stays empty. Does not commit `out`.
RunResult run_scenario(const Scenario& scenario, io::OutputDirectory& out);

//! Writes trace.csv and summary.json of a finished run into `directory` (atomically, through an
//! OutputDirectory).
void write_run_outputs(const std::string& directory, const Scenario& scenario,
                       const RunResult& result);

}  // namespace smoothsteer::runner
