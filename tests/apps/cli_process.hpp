#pragma once
//! Runs the `smoothsteer` and `smoothsteer_demo` binaries as child processes (argument vector,
//! no shell) in a chosen working directory, with extra environment variables, and captures
//! their exit status, stdout and stderr.

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;

namespace smoothsteer::testing {

struct ProcessResult {
  int exit_code = -1;  //!< -1 if it did not exit normally
  std::string out;
  std::string err;
};

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

//! Starts `arguments` (arguments[0] is the executable's path) in `directory`. Each entry of
//! `environment` ("NAME=value" or "NAME" to unset) changes the inherited environment.
inline pid_t start_process(const std::vector<std::string>& arguments,
                           const std::filesystem::path& directory,
                           const std::vector<std::string>& environment,
                           const std::filesystem::path& out, const std::filesystem::path& err) {
  std::vector<std::string> variables;
  for (char** e = environ; *e; ++e) variables.emplace_back(*e);
  for (const std::string& change : environment) {
    const std::string name = change.substr(0, change.find('='));
    std::erase_if(variables, [&](const std::string& v) { return v.rfind(name + "=", 0) == 0; });
    if (change.find('=') != std::string::npos) variables.push_back(change);
  }
  std::vector<char*> envp, argv;
  for (std::string& v : variables) envp.push_back(v.data());
  envp.push_back(nullptr);
  std::vector<std::string> copy = arguments;
  for (std::string& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, directory.c_str());
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t child = -1;
  if (posix_spawn(&child, copy[0].c_str(), &actions, nullptr, argv.data(), envp.data()) != 0) {
    child = -1;
  }
  posix_spawn_file_actions_destroy(&actions);
  return child;
}

//! Waits for `child`; its peak resident set size [kB] goes to `peak_rss_kb` if given.
inline int wait_process(pid_t child, long* peak_rss_kb = nullptr) {
  int status = 0;
  struct rusage usage {};
  if (child < 0 || wait4(child, &status, 0, &usage) < 0) return -1;
  if (peak_rss_kb) *peak_rss_kb = usage.ru_maxrss;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline ProcessResult run_process(const std::vector<std::string>& arguments,
                                 const std::filesystem::path& directory,
                                 const std::vector<std::string>& environment = {}) {
  const std::filesystem::path out = directory / ".process.out", err = directory / ".process.err";
  ProcessResult result;
  result.exit_code = wait_process(start_process(arguments, directory, environment, out, err));
  result.out = read_text(out);
  result.err = read_text(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return result;
}

}  // namespace smoothsteer::testing
