// Starts the plotter as a child process with an argument vector: no shell parses --out or the
// script's path, so quotes, semicolons and spaces in them are plain characters.

#include "plotter.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_plan.hpp"

extern char** environ;

namespace smoothsteer::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* python = "/usr/bin/python3";

fs::path executable_directory() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  return error ? fs::path() : self.parent_path();
}

}  // namespace

std::string find_plot_script() {
  if (const char* script = std::getenv("SMOOTHSTEER_PLOT_SCRIPT")) return script;
  std::vector<fs::path> candidates;
  if (const fs::path directory = executable_directory(); !directory.empty()) {
    candidates.push_back(directory / ".." / "share" / "smoothsteer" / "plot_trace.py");
  }
  candidates.push_back(fs::path(SMOOTHSTEER_INSTALL_DATADIR) / "plot_trace.py");
  candidates.push_back(fs::path(SMOOTHSTEER_SOURCE_DIR) / "scripts" / "plot_trace.py");
  std::string tried;
  for (const fs::path& candidate : candidates) {
    std::error_code error;
    if (fs::is_regular_file(candidate, error)) return candidate.lexically_normal().string();
    tried += (tried.empty() ? "" : ", ") + candidate.lexically_normal().string();
  }
  throw std::runtime_error("--plot: plot_trace.py not found (looked at " + tried +
                           "); set SMOOTHSTEER_PLOT_SCRIPT");
}

void write_path_csv(const Path& path, const std::string& file, const PathPlan* plan) {
  constexpr double spacing_m = 0.25;
  constexpr double max_rows = 20000.0;
  std::ofstream out(file, std::ios::binary);
  out.precision(9);
  out << "x,y\n";
  const std::size_t pieces = plan ? plan->piece_count() : 1;
  for (std::size_t p = 0; p < pieces; ++p) {  // a plan's pieces one after the other
    const Path& piece = plan ? *plan->piece(p).path : path;
    const double intervals = std::clamp(std::ceil(piece.length() / spacing_m), 1.0,
                                        max_rows / static_cast<double>(pieces) - 1.0);
    for (double i = 0.0; i <= intervals; i += 1.0) {
      const PathPoint point = piece.evaluate(piece.length() * i / intervals);
      out << point.position.x << ',' << point.position.y << '\n';
    }
  }
  out.flush();
  if (!out) throw std::runtime_error("--plot: writing " + file + " failed");
}

void run_plotter(const std::string& script, const std::string& csv, const std::string& png) {
  std::vector<std::string> arguments{python, script, csv, png};
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  pid_t child = 0;
  const int spawn_error = ::posix_spawn(&child, python, nullptr, nullptr, argv.data(), environ);
  if (spawn_error != 0) {
    throw std::runtime_error(std::string("--plot: cannot start ") + python + ": " +
                             std::strerror(spawn_error));
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("--plot: waitpid failed");
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const std::string how = WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                              : "signal " + std::to_string(WTERMSIG(status));
    throw std::runtime_error("--plot: " + std::string(python) + " " + script + " failed (" + how +
                             ")");
  }
}

}  // namespace smoothsteer::cli
