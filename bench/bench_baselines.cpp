// update() cost of every comparison controller next to the proposed one, in ns per call, on a
// circle of radius 40 m at 10 m/s and 50 Hz (state advanced by the kinematic model each call).

#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"

namespace {

void BM_ControllerUpdate(benchmark::State& state, const std::string& name) {
  using namespace smoothsteer;
  ComparisonSetup setup;
  setup.path = std::make_shared<const Path>(Path::circle({0.0, 0.0}, 40.0));
  setup.nominal_speed_mps = 10.0;
  auto controller = make_comparison_controller(name, setup);
  KinematicSingleTrack plant{setup.wheelbase_m};
  Pose2 pose{{40.5, 0.0}, 1.5707963};
  ControllerOutput output;
  for (auto _ : state) {
    const ControllerInput input{pose.position, pose.heading_rad, 10.0, 0.0, 0.02};
    benchmark::DoNotOptimize(controller->update(input, output));
    pose = plant.step(pose, output.steering_angle_rad, 10.0, 0.02);
  }
}

const bool registered = [] {
  for (const std::string& name : smoothsteer::comparison_controller_names()) {
    benchmark::RegisterBenchmark(("update/" + name).c_str(), BM_ControllerUpdate, name);
  }
  return true;
}();

}  // namespace
