// Set-up cost of the parametrization (paper Sec. III): building the static map and solving a
// 60-speed gain schedule; also the real-time schedule lookup. Figures: docs/tuning.md.
#include <benchmark/benchmark.h>

#include "smoothsteer/tuning/gain_schedule.hpp"

namespace {

using namespace smoothsteer;

VehicleLimits example_vehicle() {
  VehicleLimits v;  // CommonRoad vehicle 2 + 5 rad/s^2
  v.max_steering_acceleration_radps2 = 5.0;
  return v;
}

void BM_StaticMap(benchmark::State& state) {
  for (auto _ : state) {
    const StaticMap map = StaticMap::computed();
    benchmark::DoNotOptimize(map.max_q());
  }
}
BENCHMARK(BM_StaticMap)->Unit(benchmark::kMillisecond)->Repetitions(3);

void BM_Schedule60Speeds(benchmark::State& state) {
  const StaticMap map;
  const std::vector<double> speeds = speed_grid(0.5, 30.0, 0.5);  // 60 speeds
  for (auto _ : state) {
    const GainSchedule schedule = compute_gain_schedule(example_vehicle(), {}, speeds, map);
    benchmark::DoNotOptimize(schedule.entries().data());
  }
}
BENCHMARK(BM_Schedule60Speeds)->Unit(benchmark::kMillisecond)->Repetitions(3);

// What `smoothsteer tune --certificate box` computes for 60 speeds: the map (shipped for the
// default options, src/tuning/static_map_table.inc) and the schedule; the aim is < 40 ms.
void BM_TuneBox60Speeds(benchmark::State& state) {
  const std::vector<double> speeds = speed_grid(0.5, 30.0, 0.5);
  for (auto _ : state) {
    const GainSchedule schedule = compute_gain_schedule(example_vehicle(), {}, speeds, StaticMap{});
    benchmark::DoNotOptimize(schedule.entries().data());
  }
}
BENCHMARK(BM_TuneBox60Speeds)->Unit(benchmark::kMillisecond)->Repetitions(3);

void BM_ScheduleLookup(benchmark::State& state) {
  const StaticMap map;
  const GainSchedule schedule =
      compute_gain_schedule(example_vehicle(), {}, speed_grid(0.5, 30.0, 0.5), map);
  double v = 0.0;
  for (auto _ : state) {
    v = v > 30.0 ? 0.0 : v + 0.013;
    benchmark::DoNotOptimize(schedule.parameters_at(v));
  }
}
BENCHMARK(BM_ScheduleLookup);

}  // namespace
