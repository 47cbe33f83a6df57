#pragma once
//! The one progress display of the long commands (compare, sweep, tune; docs/cli.md "Progress"):
//! on a terminal, "LABEL: 120/462 runs, 1m32s elapsed, ~4m10s left" rewritten in place a few
//! times per second on stderr; otherwise one line at the end, "LABEL: 462 runs in 712 s", so CI
//! logs stay short. Quiet prints neither. It also owns the interrupt: while a LongCommand is
//! alive, SIGINT and SIGTERM ask the work to stop taking new cases (a second signal ends the
//! process at once), and main() turns the runner::Interrupted that follows into exit status 130.

#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

#include "interrupt_signal.hpp"
#include "smoothsteer/runner/progress.hpp"

namespace smoothsteer::cli {

//! Counts finished cases and prints them; the observer the library's long work ticks.
class ProgressReporter final : public runner::ProgressObserver {
 public:
  //! `terminal`: rewrite one line in place; else print only the summary line at the end. `unit`
  //! names what is counted ("runs", "speeds").
  ProgressReporter(std::string label, bool quiet, bool terminal, std::string unit = "runs");

  void expect(std::size_t cases) override;
  void case_done() override;
  [[nodiscard]] bool stop_requested() const override;

  //! Ends the display: the summary line (no terminal) or the last update and a newline.
  void finish();
  //! "interrupted: 120 of 462 runs done; no table written" (printed even when quiet).
  void report_interruption();
  //! Ends a terminal line left open (before an error message).
  void end_line();

 private:
  void print_line(bool final_update);

  std::string label_;
  std::string unit_;
  bool quiet_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
  mutable std::mutex mutex_;
  std::size_t total_ = 0;
  std::size_t done_ = 0;
  bool line_open_ = false;  //!< a terminal line without its newline yet
};

//! One long command's progress and interrupt handling, from construction to destruction: it
//! installs the reporter (runner::ScopedProgress) and the signal handlers, and on the way out
//! prints the summary, or the interruption line if a signal stopped the work.
class LongCommand {
 public:
  LongCommand(std::string label, bool quiet, std::string unit = "runs");
  ~LongCommand();
  LongCommand(const LongCommand&) = delete;
  LongCommand& operator=(const LongCommand&) = delete;

 private:
  InterruptSignals signals_;
  ProgressReporter reporter_;
  runner::ScopedProgress scope_;
  int uncaught_on_entry_;
};

//! True when stderr is a terminal (isatty).
bool stderr_is_terminal();

}  // namespace smoothsteer::cli
