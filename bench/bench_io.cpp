// Time per control step and model evaluations per step of every shipped scenario with each
// plant integrator (docs/benchmarks.md, "Plant integration"). Run from the repository root:
//   build/release/bench/bench_io --benchmark_counters_tabular=true

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "smoothsteer/io/scenario.hpp"

namespace {

using namespace smoothsteer;

void run_scenario_with(benchmark::State& state, const std::string& file,
                       const std::string& method) {
  const io::Scenario scenario = io::load_scenario(file, {"simulation.integrator=" + method});
  double steps = 0.0, evaluations = 0.0;
  for (auto _ : state) {
    const io::RunResult result = io::run_scenario(scenario);
    steps = result.metrics.steps;
    evaluations = static_cast<double>(result.simulation.model_evaluations);
    benchmark::DoNotOptimize(result.metrics.max_abs_rear_error_m);
  }
  state.counters["steps"] = steps;
  state.counters["evals_per_step"] = evaluations / steps;
  // Per-step time: iterations * steps events per second, inverted.
  state.counters["time_per_step"] =
      benchmark::Counter(steps * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

const bool registered = [] {
  const char* root = std::getenv("SMOOTHSTEER_SOURCE_DIR");
  const std::filesystem::path directory = std::filesystem::path(root ? root : ".") / "scenarios";
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_directory(directory)) {
    for (const auto& entry : std::filesystem::directory_iterator(directory)) {
      if (entry.path().extension() == ".yaml") files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    for (const char* method : {"fixed_rk4", "rkf78", "dopri5"}) {
      benchmark::RegisterBenchmark(("Scenario/" + file.stem().string() + "/" + method).c_str(),
                                   [file, method](benchmark::State& state) {
                                     run_scenario_with(state, file.string(), method);
                                   })
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
