#pragma once
//! Inputs recorded from a closed loop, so that a benchmark times only update() (shared by the
//! controller and projection benchmarks).

#include <memory>
#include <vector>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/sim/kinematic_closed_loop.hpp"

namespace smoothsteer::bench {

//! Poses of a kinematic closed loop at 10 m/s that starts 2 m off the path and then tracks it
//! for 200 s, as ControllerInputs for the same controller.
inline std::vector<ControllerInput> recorded_inputs(const std::shared_ptr<const Path>& path,
                                                    const ControllerParameters& parameters) {
  LeadWheelController controller(parameters, path);
  KinematicLoopOptions options;
  options.speed_mps = 10.0;
  options.duration_s = 200.0;
  const KinematicLoopResult result =
      run_kinematic_closed_loop(controller, {{0.0, 2.0}, 0.0}, options);
  std::vector<ControllerInput> inputs;
  inputs.reserve(result.trace.size());
  for (const KinematicTraceSample& sample : result.trace) {
    inputs.push_back(
        {sample.pose.position, sample.pose.heading_rad, options.speed_mps, 0.0, options.period_s});
  }
  return inputs;
}

}  // namespace smoothsteer::bench
