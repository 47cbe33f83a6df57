// Cost of the controller update on long paths (10^4, 10^5, 10^6 waypoints): while tracking
// (warm-started projections) and far from the path (every projection a global search through
// the bounding-volume hierarchy), and of one global projection. Besides Google Benchmark's mean
// per call, each far-from-path benchmark reports the worst single call (counter worst_us),
// timed with steady_clock around each call. Figures: docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include "smoothsteer/smoothsteer.hpp"
#include "support/recorded_inputs.hpp"

namespace {

using namespace smoothsteer;

//! The curved path of bench_controller, 0.5 m between waypoints, extended to `points`.
std::shared_ptr<const Path> curved_path(std::int64_t points) {
  static std::map<std::int64_t, std::shared_ptr<const Path>> cache;
  auto& path = cache[points];
  if (!path) {
    std::vector<Vec2> waypoints;
    waypoints.reserve(static_cast<std::size_t>(points));
    for (std::int64_t k = 0; k < points; ++k) {
      const double x = 0.5 * static_cast<double>(k);
      waypoints.push_back({x, 15.0 * std::sin(x / 40.0) + 4.0 * std::sin(x / 13.0)});
    }
    path = std::make_shared<const Path>(Path::from_waypoints(waypoints));
  }
  return path;
}

ControllerParameters second_order() {
  ControllerParameters parameters;
  parameters.chain.order = 2;
  parameters.chain.lead_curvature_bound = 0.1;
  return parameters;
}

void BM_TrackingUpdate(benchmark::State& state) {
  const auto path = curved_path(state.range(0));
  const std::vector<ControllerInput> inputs = bench::recorded_inputs(path, second_order());
  LeadWheelController controller(second_order(), path);
  ControllerOutput output;
  std::size_t index = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(controller.update(inputs[index], output));
    benchmark::DoNotOptimize(output.steering_angle_rad);
    if (++index == inputs.size()) index = 0;
  }
}

//! Query positions 60 m beside the path. Moving: a vehicle driving parallel to the path at
//! 10 m/s and 50 Hz (0.2 m per call), caches warm. Jumping: a pseudo-random place along all of
//! the path at every call, so that the tree and the segments come cold from memory.
Vec2 far_position(bool jumping, std::size_t call, double path_extent_m) {
  const double step = jumping ? 7.31 * 97.0 : 0.2;
  return {std::fmod(100.0 + step * static_cast<double>(call), path_extent_m - 200.0), 60.0};
}

template <typename Call>
void timed_far_calls(benchmark::State& state, bool jumping, Call call) {
  const double extent = 0.5 * static_cast<double>(state.range(0));
  std::size_t index = 0;
  double worst_s = 0.0;
  for (auto _ : state) {
    const Vec2 position = far_position(jumping, index++, extent);
    const auto begin = std::chrono::steady_clock::now();
    call(position);
    const auto end = std::chrono::steady_clock::now();
    worst_s = std::max(worst_s, std::chrono::duration<double>(end - begin).count());
  }
  state.counters["worst_us"] = 1e6 * worst_s;
}

void far_update(benchmark::State& state, bool jumping) {
  const auto path = curved_path(state.range(0));
  LeadWheelController controller(second_order(), path);
  ControllerOutput output;
  timed_far_calls(state, jumping, [&](Vec2 position) {
    benchmark::DoNotOptimize(controller.update({position, 0.0, 10.0, 0.0, 0.02}, output));
  });
}

void global_projection(benchmark::State& state, bool jumping) {
  const auto path = curved_path(state.range(0));
  timed_far_calls(state, jumping,
                  [&](Vec2 position) { benchmark::DoNotOptimize(path->project(position)); });
}

void BM_FarFromPathUpdateMoving(benchmark::State& state) {
  far_update(state, false);
}
void BM_FarFromPathUpdateJumping(benchmark::State& state) {
  far_update(state, true);
}
void BM_GlobalProjectionMoving(benchmark::State& state) {
  global_projection(state, false);
}
void BM_GlobalProjectionJumping(benchmark::State& state) {
  global_projection(state, true);
}

BENCHMARK(BM_TrackingUpdate)->Arg(10000)->Arg(100000)->Arg(1000000)->Repetitions(3);
BENCHMARK(BM_FarFromPathUpdateMoving)->Arg(10000)->Arg(100000)->Arg(1000000)->Repetitions(3);
BENCHMARK(BM_FarFromPathUpdateJumping)->Arg(10000)->Arg(100000)->Arg(1000000)->Repetitions(3);
BENCHMARK(BM_GlobalProjectionMoving)->Arg(10000)->Arg(100000)->Arg(1000000)->Repetitions(3);
BENCHMARK(BM_GlobalProjectionJumping)->Arg(10000)->Arg(100000)->Arg(1000000)->Repetitions(3);

}  // namespace
