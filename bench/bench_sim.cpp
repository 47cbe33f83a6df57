// Closed-loop simulation throughput: the kinetic single-track model with Pacejka tires, the
// third-order actuator and the n = 2 lead-wheel controller in the loop (circle_sections-like run).
// Reports control steps/s and plant RK4 sub-steps/s. Figures: docs/results.md.
// BM_ClosedLoop10s: a 10 s run with the default plant integrator (dopri5) on the single-track and
// the double-track model, reported as real-time factor (simulated s per wall-clock s; the
// double-track model must reach 50). Figures: docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <memory>
#include <numbers>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/sim/simulation.hpp"
#include "smoothsteer/vehicle/double_track.hpp"

namespace {

using namespace smoothsteer;

void BM_DynamicClosedLoop(benchmark::State& state) {
  constexpr double pi = std::numbers::pi;
  const VehicleParameters car;
  auto path = std::make_shared<const Path>(
      PathBuilder({0, 0}, 0.0).line(15).arc(30, pi / 2).arc(40, -pi).arc(50, pi / 2).build());
  LeadWheelController controller(ControllerParameters::paper_c1(car.wheelbase_m(), 0.5, 0.2, 0.3),
                                 path);
  DynamicSingleTrack model(car);
  ActuatorParameters actuator;
  actuator.dead_time_s = 0.0;
  actuator.max_rate_radps = 3.0;
  SimulationParameters sim;
  // RK4 at 1 ms (plant sub-steps per second is its measure); bench_io compares the default.
  sim.integrator = PlantIntegrator::fixed_rk4;
  sim.control_period_s = 0.001 * static_cast<double>(state.range(0));
  sim.duration_s = 20.0;
  sim.stop_at_path_end = false;
  const SpeedProfile speed{2.8, 12.5, 0.5, 2.0};
  std::int64_t control_steps = 0;
  for (auto _ : state) {
    const SimulationResult result =
        simulate(*path, model, actuator, speed, sim, {{0, -1}, 0}, controller);
    control_steps += static_cast<std::int64_t>(result.trace.size());
    benchmark::DoNotOptimize(result.final_state.x_m);
  }
  const double substeps_per_step = sim.control_period_s / sim.substep_s;
  state.counters["control_steps_per_s"] =
      benchmark::Counter(static_cast<double>(control_steps), benchmark::Counter::kIsRate);
  state.counters["plant_substeps_per_s"] = benchmark::Counter(
      static_cast<double>(control_steps) * substeps_per_step, benchmark::Counter::kIsRate);
}
// Argument: control period in ms (50 Hz and 20 Hz).
BENCHMARK(BM_DynamicClosedLoop)->Arg(20)->Arg(50)->Unit(benchmark::kMillisecond);

template <typename Model>
void BM_ClosedLoop10s(benchmark::State& state) {
  constexpr double pi = std::numbers::pi;
  VehicleParameters car;
  car.double_track.emplace();  // CommonRoad vehicle 2
  auto path = std::make_shared<const Path>(
      PathBuilder({0, 0}, 0.0).line(15).arc(30, pi / 2).arc(40, -pi).arc(50, pi / 2).build());
  LeadWheelController controller(ControllerParameters::paper_c1(car.wheelbase_m(), 0.5, 0.2, 0.3),
                                 path);
  const Model model(car);
  ActuatorParameters actuator;
  actuator.dead_time_s = 0.0;
  actuator.max_rate_radps = car.max_steering_rate_radps;
  SimulationParameters sim;  // default integrator (dopri5 at 1e-6), 50 Hz control
  sim.duration_s = 10.0;
  sim.stop_at_path_end = false;
  const SpeedProfile speed{2.8, 12.5, 0.5, 2.0};
  double simulated_s = 0.0;
  for (auto _ : state) {
    const SimulationResult result =
        simulate(*path, model, actuator, speed, sim, {{0, -1}, 0}, controller);
    simulated_s += result.trace.back().time_s;
    benchmark::DoNotOptimize(result.final_state.x_m);
  }
  state.counters["real_time_factor"] = benchmark::Counter(simulated_s, benchmark::Counter::kIsRate);
}
BENCHMARK_TEMPLATE(BM_ClosedLoop10s, DynamicSingleTrack)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_ClosedLoop10s, DoubleTrack)->Unit(benchmark::kMillisecond);

}  // namespace
