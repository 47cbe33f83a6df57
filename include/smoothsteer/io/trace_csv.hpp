#pragma once
//! \file trace_csv.hpp
//! trace.csv (columns in docs/cli.md): one row per control step, written as the simulation
//! produces it, so memory does not grow with the run's length. Numbers are formatted with
//! std::to_chars (9 significant digits, the precision of earlier releases). io owns the columns:
//! their names and order are defined here (src/io/trace_columns.cpp), not in sim.

#include <array>
#include <cstdio>
#include <string>

#include "smoothsteer/sim/simulation.hpp"

namespace smoothsteer::io {

//! Number of columns of trace.csv.
inline constexpr std::size_t trace_column_count = 30;
//! Column names of trace.csv (docs/cli.md), in the order of trace_row().
const std::array<const char*, trace_column_count>& trace_column_names() noexcept;
//! The sample's values in the order of trace_column_names().
std::array<double, trace_column_count> trace_row(const TraceSample& sample) noexcept;

class TraceCsvWriter {
 public:
  //! Creates `file` and writes the header. Throws std::runtime_error naming the file.
  explicit TraceCsvWriter(std::string file);
  TraceCsvWriter(const TraceCsvWriter&) = delete;
  TraceCsvWriter& operator=(const TraceCsvWriter&) = delete;
  ~TraceCsvWriter();

  //! Appends one row (buffered). Errors are reported by close().
  void write(const TraceSample& sample);
  //! Flushes and closes; throws std::runtime_error naming the file if any write failed.
  void close();

 private:
  std::string file_;
  std::FILE* stream_ = nullptr;
};

//! The trace as CSV text (header + rows); for tests and small traces.
std::string trace_csv(const std::vector<TraceSample>& trace);

}  // namespace smoothsteer::io
