// SIGINT and SIGTERM as a request to stop (interrupt_signal.hpp).

#include "interrupt_signal.hpp"

#include <signal.h>

#include <atomic>

namespace smoothsteer::cli {
namespace {

// Written by the signal handler: only a lock-free atomic is safe there.
std::atomic<bool> requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);

struct sigaction previous_interrupt {};
struct sigaction previous_terminate {};

void on_stop_signal(int) {
  requested.store(true);
}

}  // namespace

InterruptSignals::InterruptSignals() {
  requested.store(false);
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  // The first signal asks the work to stop; SA_RESETHAND makes a second one end the process.
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, &previous_interrupt);
  sigaction(SIGTERM, &action, &previous_terminate);
  // A signal the parent had ignored stays ignored (`nohup`, a shell's background job).
  if (previous_interrupt.sa_handler == SIG_IGN) sigaction(SIGINT, &previous_interrupt, nullptr);
  if (previous_terminate.sa_handler == SIG_IGN) sigaction(SIGTERM, &previous_terminate, nullptr);
}

InterruptSignals::~InterruptSignals() {
  sigaction(SIGINT, &previous_interrupt, nullptr);
  sigaction(SIGTERM, &previous_terminate, nullptr);
}

bool interrupt_requested() {
  return requested.load();
}

}  // namespace smoothsteer::cli
