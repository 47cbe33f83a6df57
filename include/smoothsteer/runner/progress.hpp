#pragma once
//! \file progress.hpp
//! Progress and interruption of long set-up-time work (sweeps, comparisons, tuning studies).
//!
//! The work announces how many cases it will run (`expect`), ticks each finished one
//! (`case_done`) and asks before each new one whether it should stop (`stop_requested`). Whoever
//! starts the work installs an observer for its duration (ScopedProgress); the CLI's observer
//! prints to the terminal (apps/cli/progress_reporter.hpp), the library itself does no I/O.
//! Without an observer every call is a no-op and nothing stops. Never called from the control
//! step: only between whole simulation runs.

#include <cstddef>
#include <stdexcept>

namespace smoothsteer::runner {

//! Watches long work. Every member may be called from several worker threads at once.
class ProgressObserver {
 public:
  virtual ~ProgressObserver() = default;
  //! `cases` more cases will run (work in several phases calls this once per phase).
  virtual void expect(std::size_t cases) = 0;
  //! One case finished.
  virtual void case_done() = 0;
  //! True once the work should stop taking new cases (an interrupt).
  [[nodiscard]] virtual bool stop_requested() const = 0;
};

//! Thrown by work that stopped because stop_requested() said so; what() says what was finished.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! Installs `observer` for the lifetime of this object (process-wide; not nested).
class ScopedProgress {
 public:
  explicit ScopedProgress(ProgressObserver& observer);
  ~ScopedProgress();
  ScopedProgress(const ScopedProgress&) = delete;
  ScopedProgress& operator=(const ScopedProgress&) = delete;
};

//! The calls the work makes; each forwards to the installed observer, if any.
void progress_expect(std::size_t cases);
void progress_case_done();
[[nodiscard]] bool progress_stop_requested();
//! Throws Interrupted("<what> interrupted") if the observer asks to stop.
void throw_if_interrupted(const char* what);

}  // namespace smoothsteer::runner
