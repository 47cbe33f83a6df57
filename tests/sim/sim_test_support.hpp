#pragma once
// Shared helpers of the simulation tests.

#include "smoothsteer/controller/steering_controller.hpp"

namespace smoothsteer::testing {

//! Holds a fixed steering angle (open loop).
class ConstantSteering final : public SteeringController {
 public:
  explicit ConstantSteering(double angle) : angle_(angle) {}
  Status compute_command(const ControllerInput&, ControllerOutput& output) noexcept override {
    output = ControllerOutput{};
    output.steering_angle_rad = angle_;
    output.derivatives_available = 2;
    return Status::ok;
  }
  void reset(double) noexcept override {}
  const char* name() const noexcept override { return "constant"; }

 private:
  double angle_;
};

}  // namespace smoothsteer::testing
