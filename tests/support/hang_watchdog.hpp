#pragma once
//! A guard against real hangs, not a timing assertion. Tests never assert how long something
//! took: CI machines are loaded and the sanitizer build is several times slower, so a bound on
//! wall-clock time fails on a healthy run (docs/contributing.md). Where a defect would show as a
//! hang (a loop driven by an input, a read that blocks), the test holds a HangWatchdog whose
//! limit is far above any plausible run time (at least 10x the slowest seen under ASan). Only if
//! the guarded code is still running then does the watchdog print what hung and abort the test
//! process, which CTest reports as a failure. A run that merely is slow passes.

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>

namespace smoothsteer::testing {

class HangWatchdog {
 public:
  //! The default limit: milliseconds are expected, ASan on a busy machine takes seconds.
  static constexpr std::chrono::seconds default_limit{120};

  explicit HangWatchdog(std::string what, std::chrono::seconds limit = default_limit)
      : what_(std::move(what)), thread_([this, limit] { watch(limit); }) {}
  HangWatchdog(const HangWatchdog&) = delete;
  HangWatchdog& operator=(const HangWatchdog&) = delete;
  ~HangWatchdog() {
    {
      const std::lock_guard lock(mutex_);
      done_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }

 private:
  void watch(std::chrono::seconds limit) {
    std::unique_lock lock(mutex_);
    if (wake_.wait_for(lock, limit, [this] { return done_; })) return;
    std::fprintf(stderr, "HANG: '%s' still runs after %lld s (a real hang, not a slow run)\n",
                 what_.c_str(), static_cast<long long>(limit.count()));
    std::fflush(stderr);
    std::abort();
  }

  std::string what_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;  //!< last: starts after the members it reads
};

}  // namespace smoothsteer::testing
