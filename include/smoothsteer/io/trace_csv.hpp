#pragma once
//! \file trace_csv.hpp
//! trace.csv (columns in docs/cli.md): one row per control step, written as the simulation
//! produces it, so memory does not grow with the run's length. Numbers are formatted with
//! std::to_chars (9 significant digits, the precision of earlier releases).

#include <cstdio>
#include <string>

#include "smoothsteer/sim/simulation.hpp"

namespace smoothsteer::io {

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
