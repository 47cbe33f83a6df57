// Time per control step and model evaluations per step of every shipped scenario with the
// plant integrator of earlier releases, the default and rkf78 (docs/benchmarks.md, "Plant
// integration"). Run from the repository root:
//   build/release/bench/bench_io --benchmark_counters_tabular=true

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "smoothsteer/runner/scenario.hpp"

namespace {

using namespace smoothsteer;

void run_scenario_with(benchmark::State& state, const std::string& file,
                       const std::vector<std::string>& overrides) {
  const runner::Scenario scenario = runner::load_scenario(file, overrides);
  double steps = 0.0, evaluations = 0.0;
  for (auto _ : state) {
    const runner::RunResult result = runner::run_scenario(scenario);
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
    // Before: RK4 at 1 ms. After: the default (dopri5 at 1e-6). And rkf78 at 1e-8, the
    // opt-in setting of the previous release.
    const std::vector<std::pair<std::string, std::vector<std::string>>> methods{
        {"fixed_rk4", {"simulation.integrator=fixed_rk4"}},
        {"default", {}},
        {"rkf78_1e-8", {"simulation.integrator=rkf78", "simulation.integrator_tolerance=1e-8"}}};
    for (const auto& [label, overrides] : methods) {
      benchmark::RegisterBenchmark(("Scenario/" + file.stem().string() + "/" + label).c_str(),
                                   [file, overrides](benchmark::State& state) {
                                     run_scenario_with(state, file.string(), overrides);
                                   })
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
