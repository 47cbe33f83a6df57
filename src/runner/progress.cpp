// The installed progress observer (include/smoothsteer/runner/progress.hpp).

#include "smoothsteer/runner/progress.hpp"

#include <atomic>
#include <string>

namespace smoothsteer::runner {
namespace {

std::atomic<ProgressObserver*> installed{nullptr};

}  // namespace

ScopedProgress::ScopedProgress(ProgressObserver& observer) {
  installed.store(&observer);
}

ScopedProgress::~ScopedProgress() {
  installed.store(nullptr);
}

void progress_expect(std::size_t cases) {
  if (ProgressObserver* observer = installed.load()) observer->expect(cases);
}

void progress_case_done() {
  if (ProgressObserver* observer = installed.load()) observer->case_done();
}

bool progress_stop_requested() {
  const ProgressObserver* observer = installed.load();
  return observer != nullptr && observer->stop_requested();
}

void throw_if_interrupted(const char* what) {
  if (progress_stop_requested()) throw Interrupted(std::string(what) + " interrupted");
}

}  // namespace smoothsteer::runner
