// Linked into every test executable: at exit, appends the number of closed loops the process ran
// and its test name to the file named by SMOOTHSTEER_LOOP_COUNT_FILE, one line per process
// (scripts/test.sh sums them and prints the total of the run, docs/benchmarks.md). Nothing happens
// without the variable.

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "smoothsteer/sim/closed_loop_count.hpp"

namespace {

//! The --gtest_filter of this process (ctest runs one test per process), for the breakdown.
std::string test_filter() {
  std::ifstream cmdline("/proc/self/cmdline", std::ios::binary);
  std::string argument;
  while (std::getline(cmdline, argument, '\0')) {
    if (argument.rfind("--gtest_filter=", 0) == 0) return argument.substr(15);
  }
  return "all";
}

struct ClosedLoopReport {
  ~ClosedLoopReport() {
    const char* file = std::getenv("SMOOTHSTEER_LOOP_COUNT_FILE");
    const long count = smoothsteer::closed_loops_run();
    if (file == nullptr || *file == '\0' || count == 0) return;
    if (std::FILE* out = std::fopen(file, "a")) {
      std::fprintf(out, "%ld %s\n", count, test_filter().c_str());
      std::fclose(out);
    }
  }
};

const ClosedLoopReport report;

}  // namespace
