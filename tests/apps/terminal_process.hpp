#pragma once
//! Runs the `smoothsteer` binary with its stderr on a pseudo-terminal (openpty), as a user at a
//! terminal sees it, and reads what it writes there; stdout goes to a file. `on_output` sees the
//! terminal's text so far after every read and may act on the running child (send it a signal
//! once it has started work).

#include <fcntl.h>
#include <pty.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

extern char** environ;

namespace smoothsteer::testing {

struct TerminalResult {
  int exit_code = -1;    //!< -1 if it did not exit normally
  std::string terminal;  //!< everything written to stderr (the terminal)
};

inline TerminalResult run_on_terminal(
    const std::vector<std::string>& arguments, const std::filesystem::path& directory,
    const std::function<void(pid_t, const std::string&)>& on_output = {}) {
  TerminalResult result;
  int controller = -1, device = -1;
  if (::openpty(&controller, &device, nullptr, nullptr, nullptr) != 0) return result;
  std::vector<std::string> copy = arguments;
  std::vector<char*> argv;
  for (std::string& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, directory.c_str());
  const std::string out = (directory / ".terminal.out").string();
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, device, 2);
  posix_spawn_file_actions_addclose(&actions, controller);
  posix_spawn_file_actions_addclose(&actions, device);
  // SIGINT and SIGTERM at their defaults in the child, even where the test runs with them
  // ignored (a background job): the binary keeps an ignored signal ignored.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  pid_t child = -1;
  const int spawned =
      posix_spawn(&child, copy[0].c_str(), &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(device);  // the child holds the terminal now: reads end (EIO) once it exits
  if (spawned == 0) {
    char buffer[4096];
    for (;;) {
      const ssize_t n = ::read(controller, buffer, sizeof buffer);
      if (n > 0) {
        result.terminal.append(buffer, static_cast<std::size_t>(n));
        if (on_output) on_output(child, result.terminal);
      } else if (n < 0 && errno == EINTR) {
        continue;
      } else {
        break;
      }
    }
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  ::close(controller);
  return result;
}

}  // namespace smoothsteer::testing
