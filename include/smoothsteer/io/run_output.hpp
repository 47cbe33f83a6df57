#pragma once
//! \file run_output.hpp
//! Output files of a run: trace.csv (one row per control step, columns in docs/cli.md) and
//! summary.json (metrics + full resolved parameters). Every file is written to a temporary
//! file in the same directory and renamed, so no half-written file is ever visible.

#include <nlohmann/json.hpp>

#include <string>

#include "smoothsteer/io/scenario.hpp"

namespace smoothsteer::io {

//! Writes `content` to `path` atomically (temporary file + rename). Throws std::runtime_error.
void write_file_atomically(const std::string& path, const std::string& content);

//! The trace as CSV text (header + one row per control step).
std::string trace_csv(const SimulationResult& result);
//! Column names of trace_csv(), in order.
const std::vector<std::string>& trace_columns();

//! {"scenario", "controller", "status", "stop_reason", "metrics": {...}, "parameters": {...}}.
nlohmann::json summary_json(const Scenario& scenario, const RunResult& result);

//! Creates `directory` if needed and writes trace.csv and summary.json into it.
void write_run_outputs(const std::string& directory, const Scenario& scenario,
                       const RunResult& result);

}  // namespace smoothsteer::io
