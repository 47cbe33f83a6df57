// The progress display and interrupt scope of the long commands (progress_reporter.hpp).

#include "progress_reporter.hpp"

#include <unistd.h>

#include <cstdio>
#include <exception>
#include <utility>

namespace smoothsteer::cli {
namespace {

using Clock = std::chrono::steady_clock;

//! A terminal line is rewritten at most this often (a few times per second).
constexpr auto redraw_interval = std::chrono::milliseconds(250);

//! "42s", "3m05s", "1h02m".
std::string duration_text(double seconds) {
  const long s = seconds < 0.0 ? 0 : static_cast<long>(seconds + 0.5);
  char text[32];
  if (s < 60) {
    std::snprintf(text, sizeof text, "%lds", s);
  } else if (s < 3600) {
    std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
  } else {
    std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  }
  return text;
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

bool stderr_is_terminal() {
  return isatty(STDERR_FILENO) == 1;
}

ProgressReporter::ProgressReporter(std::string label, bool quiet, bool terminal, std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      quiet_(quiet),
      terminal_(terminal),
      start_(Clock::now()),
      last_print_(start_) {}

void ProgressReporter::expect(std::size_t cases) {
  const std::lock_guard lock(mutex_);
  total_ += cases;
  print_line(false);
}

void ProgressReporter::case_done() {
  const std::lock_guard lock(mutex_);
  ++done_;
  if (Clock::now() - last_print_ >= redraw_interval || done_ == total_) print_line(false);
}

bool ProgressReporter::stop_requested() const {
  return interrupt_requested();
}

void ProgressReporter::print_line(bool final_update) {
  if (quiet_ || !terminal_ || (final_update && !line_open_)) return;
  const double elapsed = seconds_since(start_);
  std::string estimate;
  if (done_ > 0 && done_ < total_) {
    const double left = elapsed / static_cast<double>(done_) * static_cast<double>(total_ - done_);
    estimate = ", ~" + duration_text(left) + " left";
  }
  // The last case ends the line, so the tables printed next start on a line of their own.
  const bool end = final_update || (total_ > 0 && done_ == total_);
  // Trailing blanks clear what a longer previous line left on the terminal.
  std::fprintf(stderr, "\r%s: %zu/%zu %s, %s elapsed%s   %s", label_.c_str(), done_, total_,
               unit_.c_str(), duration_text(elapsed).c_str(), estimate.c_str(), end ? "\n" : "");
  std::fflush(stderr);
  last_print_ = Clock::now();
  line_open_ = !end;
}

void ProgressReporter::finish() {
  const std::lock_guard lock(mutex_);
  if (quiet_) return;
  if (terminal_) {
    print_line(true);
    return;
  }
  std::fprintf(stderr, "%s: %zu %s in %.0f s\n", label_.c_str(), done_, unit_.c_str(),
               seconds_since(start_));
}

void ProgressReporter::report_interruption() {
  const std::lock_guard lock(mutex_);
  if (line_open_) std::fprintf(stderr, "\n");
  line_open_ = false;
  std::fprintf(stderr, "interrupted: %zu of %zu %s done; no table written\n", done_, total_,
               unit_.c_str());
}

void ProgressReporter::end_line() {
  const std::lock_guard lock(mutex_);
  if (line_open_) std::fprintf(stderr, "\n");
  line_open_ = false;
}

LongCommand::LongCommand(std::string label, bool quiet, std::string unit)
    : reporter_(std::move(label), quiet, stderr_is_terminal(), std::move(unit)),
      scope_(reporter_),
      uncaught_on_entry_(std::uncaught_exceptions()) {}

LongCommand::~LongCommand() {
  if (std::uncaught_exceptions() == uncaught_on_entry_) {
    reporter_.finish();
  } else if (interrupt_requested()) {
    reporter_.report_interruption();
  } else {
    reporter_.end_line();  // main() prints the error on a line of its own
  }
}

}  // namespace smoothsteer::cli
