// update() cost of every comparison controller next to the proposed one, in ns per call, on a
// circle of radius 40 m at 10 m/s and 50 Hz (state advanced by the kinematic model each call).
// `certified` is the study's certified lead-wheel controller (docs/baselines.md): a
// ScheduledController with the feedforward schedule for the shipped car's limits on this circle,
// behind the same saturation, so that its cost and the MPC's come from one run. `limiter/*` is the
// second-order limiter alone (SteeringSaturator::apply) at the car's limits and 100 Hz, on a
// command that keeps the limits (passes unchanged) and on noise that it clamps every call.

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/tuning/scheduled_controller.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"

namespace {

std::unique_ptr<smoothsteer::SaturatedController> make_controller(
    const std::string& name, const smoothsteer::ComparisonSetup& setup) {
  using namespace smoothsteer;
  if (name != "certified") return make_comparison_controller(name, setup);
  VehicleLimits car;  // the shipped passenger car: 0.4 rad/s, 8 rad/s^2
  car.wheelbase_m = setup.wheelbase_m;
  car.max_steering_acceleration_radps2 = 8.0;
  TuningOptions route;
  route.path_curvature_bound = 1.0 / 40.0;
  route.base.feedforward.cornering_target = CorneringTarget::rear_axle;
  auto scheduled = std::make_unique<ScheduledController>(
      compute_feedforward_schedule(car, route, speed_grid(0.5, 10.5, 0.5)), setup.path);
  return std::make_unique<SaturatedController>(std::move(scheduled), setup.limits, name);
}

void BM_ControllerUpdate(benchmark::State& state, const std::string& name) {
  using namespace smoothsteer;
  ComparisonSetup setup;
  setup.path = std::make_shared<const Path>(Path::circle({0.0, 0.0}, 40.0));
  setup.nominal_speed_mps = 10.0;
  auto controller = make_controller(name, setup);
  KinematicSingleTrack plant{setup.wheelbase_m};
  Pose2 pose{{40.5, 0.0}, 1.5707963};
  ControllerOutput output;
  for (auto _ : state) {
    const ControllerInput input{pose.position, pose.heading_rad, 10.0, 0.0, 0.02};
    benchmark::DoNotOptimize(controller->update(input, output));
    pose = plant.step(pose, output.steering_angle_rad, 10.0, 0.02);
  }
}

void BM_LimiterApply(benchmark::State& state, bool clamped) {
  using namespace smoothsteer;
  SteeringSaturator saturator({1.066, 0.4, 8.0});
  std::vector<double> raw(4096);
  std::mt19937_64 engine(1);
  std::uniform_real_distribution<double> noise(-1.5, 1.5);
  for (std::size_t k = 0; k < raw.size(); ++k) {
    // 0.05 rad at about 2 rad/s (13 periods in the 4096 samples, so the cycle closes): rate
    // 0.1 rad/s, acceleration 0.2 rad/s^2.
    const double phase = 2.0 * 3.141592653589793 * 13.0 * static_cast<double>(k) / 4096.0;
    raw[k] = clamped ? noise(engine) : 0.05 * std::sin(phase);
  }
  std::size_t k = 0;
  double rate = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(saturator.apply(raw[k], 0.01, rate));
    k = (k + 1) % raw.size();
  }
}

const bool registered = [] {
  benchmark::RegisterBenchmark("limiter/passes", BM_LimiterApply, false);
  benchmark::RegisterBenchmark("limiter/clamps", BM_LimiterApply, true);
  benchmark::RegisterBenchmark("update/certified", BM_ControllerUpdate, std::string("certified"));
  for (const std::string& name : smoothsteer::comparison_controller_names()) {
    benchmark::RegisterBenchmark(("update/" + name).c_str(), BM_ControllerUpdate, name);
  }
  return true;
}();

}  // namespace
