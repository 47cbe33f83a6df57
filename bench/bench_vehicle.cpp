// Side-slip observer update (docs/vehicle_dynamics.md, section 2): the linear Kalman filter
// against the extended one on the Magic Formula tires, on a measurement stream near the friction
// limit (lateral acceleration up to 9 m/s^2) at the speed in cm/s given as the argument: 19 m/s,
// and 2 m/s, the worst case (the most RK4 sub-steps). Figures: docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "smoothsteer/vehicle/double_track.hpp"
#include "smoothsteer/vehicle/side_slip_observer.hpp"

namespace smoothsteer {
namespace {

void observer_update(benchmark::State& state, ObserverTireModel tire_model) {
  const VehicleParameters car;
  SideSlipObserver observer(SideSlipObserverParameters::from_vehicle(car, 1.0, 1.0, tire_model));
  const double wheelbase = car.wheelbase_m();
  const double speed = 0.01 * static_cast<double>(state.range(0));
  // Up to 9 m/s^2, and steering angles up to 0.3 rad at low speed.
  const double amplitude = std::min(9.0, 0.3 * speed * speed / wheelbase);
  int k = 0;
  for (auto _ : state) {
    const double phase = 0.02 * static_cast<double>(k++);
    SideSlipMeasurement m;
    m.speed_mps = speed;
    m.lateral_acceleration_mps2 = amplitude * std::sin(0.8 * phase);
    m.yaw_rate_radps = m.lateral_acceleration_mps2 / speed;
    m.steering_angle_rad = wheelbase * m.lateral_acceleration_mps2 / (speed * speed);
    benchmark::DoNotOptimize(observer.update(m, 0.02));
    benchmark::DoNotOptimize(observer.rear_axle_side_slip_rad());
  }
}

void BM_SideSlipObserverLinear(benchmark::State& state) {
  observer_update(state, ObserverTireModel::linear);
}
void BM_SideSlipObserverMagicFormula(benchmark::State& state) {
  observer_update(state, ObserverTireModel::magic_formula);
}
BENCHMARK(BM_SideSlipObserverLinear)->Arg(1900)->Arg(200);
BENCHMARK(BM_SideSlipObserverMagicFormula)->Arg(1900)->Arg(200);

// One evaluation of a model's derivative in a 4 m/s^2 corner at 20 m/s (the double-track model's
// cost against the single-track one; docs/benchmarks.md).
template <typename Model>
void BM_ModelDerivative(benchmark::State& state) {
  VehicleParameters car;
  car.double_track.emplace();
  const Model model(car);
  VehicleState s;
  s.vx_mps = 20.0;
  s.vy_mps = -0.2;
  s.yaw_rate_radps = 0.2;
  s.roll_rad = 0.05;
  double delta = 0.026;
  for (auto _ : state) {
    benchmark::DoNotOptimize(delta);
    const VehicleState d = model.derivative(s, delta, 0.1);
    benchmark::DoNotOptimize(d);
  }
}
BENCHMARK_TEMPLATE(BM_ModelDerivative, DynamicSingleTrack);
BENCHMARK_TEMPLATE(BM_ModelDerivative, DoubleTrack);

}  // namespace
}  // namespace smoothsteer
