#pragma once
// Runs independent comparison cases on worker threads (internal): case i is run(i), on the
// calling thread and `threads - 1` workers that take the next case as they finish one. The first
// exception any case throws is rethrown as std::runtime_error("<what>: <its message>") after
// every worker has stopped. Each case ticks the installed progress observer
// (smoothsteer/runner/progress.hpp); once it asks to stop, no new case starts and
// runner::Interrupted is thrown after every worker has stopped.

#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "smoothsteer/runner/progress.hpp"

namespace smoothsteer::detail {

template <class Run>
void run_cases_in_parallel(std::size_t count, int threads, const std::string& what, Run run) {
  std::atomic<std::size_t> next{0};
  std::mutex failure_mutex;
  std::string failure;
  runner::progress_expect(count);
  auto work = [&] {
    for (std::size_t i = next++; i < count && !runner::progress_stop_requested(); i = next++) {
      try {
        run(i);
      } catch (const std::exception& error) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (failure.empty()) failure = error.what();
      }
      runner::progress_case_done();
    }
  };
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t) workers.emplace_back(work);
  work();
  for (std::thread& worker : workers) worker.join();
  runner::throw_if_interrupted(what.c_str());
  if (!failure.empty()) throw std::runtime_error(what + ": " + failure);
}

}  // namespace smoothsteer::detail
