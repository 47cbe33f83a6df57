#pragma once
//! SIGINT and SIGTERM as a request to stop (docs/cli.md "Interrupt"): the first signal only sets a
//! flag that the long work polls between cases; the handler then resets itself, so a second
//! signal ends the process the default way. A signal ignored when the command started (`nohup`,
//! a background job of a non-interactive shell) stays ignored.

namespace smoothsteer::cli {

//! Installs the handlers for its lifetime and clears the flag; the previous handlers come back
//! on destruction.
class InterruptSignals {
 public:
  InterruptSignals();
  ~InterruptSignals();
  InterruptSignals(const InterruptSignals&) = delete;
  InterruptSignals& operator=(const InterruptSignals&) = delete;
};

//! True once SIGINT or SIGTERM arrived while InterruptSignals was installed.
bool interrupt_requested();

}  // namespace smoothsteer::cli
