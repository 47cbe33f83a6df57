// Cost of a driving stack's path at set_path() time: one planner window (5 m behind to 100 m
// ahead, 1 m apart, 106 waypoints, on an S of two 60 m arcs between clothoids) read for its
// jitter, fitted by the conditioner at the pooled jitter, and, for comparison, interpolated.
// A stack sends one every 0.1 s. Figures: docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/path/waypoint_conditioner.hpp"
#include "smoothsteer/path/waypoint_jitter.hpp"

namespace {

using namespace smoothsteer;

//! 20 windows of the S, each 2 m further along, with `sigma` of Gaussian jitter per coordinate.
std::vector<std::vector<Vec2>> windows(double sigma) {
  const Path road = PathBuilder({0.0, 0.0}, 0.0)
                        .line(20.0)
                        .clothoid(15.0, 1.0 / 60.0)
                        .arc(60.0, 0.8)
                        .clothoid(20.0, -1.0 / 60.0)
                        .arc(60.0, -0.8)
                        .clothoid(15.0, 0.0)
                        .line(40.0)
                        .build();
  std::mt19937_64 engine(7);
  std::normal_distribution<double> jitter(0.0, sigma);
  std::vector<std::vector<Vec2>> result;
  for (int k = 0; k < 20; ++k) {
    std::vector<Vec2> points;
    for (int i = 0; i <= 105; ++i) {
      const Vec2 p = road.evaluate(2.0 * k + i).position;
      points.push_back(p + Vec2{jitter(engine), jitter(engine)});
    }
    result.push_back(std::move(points));
  }
  return result;
}

void BM_EstimateWaypointJitter(benchmark::State& state) {
  const auto all = windows(0.02);
  std::size_t k = 0;
  for (auto _ : state) benchmark::DoNotOptimize(estimate_waypoint_jitter(all[k++ % all.size()]));
}

//! state.range(0): jitter [mm]; 0 is a clean window, interpolated.
void BM_WaypointConditionerFit(benchmark::State& state) {
  const auto all = windows(1e-3 * static_cast<double>(state.range(0)));
  WaypointConditioner conditioner;
  std::size_t k = 0;
  for (auto _ : state) benchmark::DoNotOptimize(conditioner.fit(all[k++ % all.size()]));
}

void BM_InterpolatedWindow(benchmark::State& state) {
  const auto all = windows(0.02);
  std::size_t k = 0;
  for (auto _ : state) benchmark::DoNotOptimize(Path::from_waypoints(all[k++ % all.size()]));
}

}  // namespace

BENCHMARK(BM_EstimateWaypointJitter)->Repetitions(3);
BENCHMARK(BM_WaypointConditionerFit)->Arg(0)->Arg(5)->Arg(20)->Arg(50)->Repetitions(3);
BENCHMARK(BM_InterpolatedWindow)->Repetitions(3);
