#pragma once
//! \file steering_limits.hpp
//! Comparison controllers that do not respect the car's steering limits by construction run
//! behind SaturatedController: its SteeringSaturator (controller/command_limiter.hpp) holds the
//! command to the angle, rate and acceleration limits and counts how often and by how much the
//! raw command hit them.

#include <memory>
#include <string>
#include <utility>

#include "smoothsteer/controller/command_limiter.hpp"
#include "smoothsteer/controller/steering_controller.hpp"

namespace smoothsteer {

//! A comparison controller behind the common interface, with its output held to the limits.
//! The applied command's rate and acceleration are reported from differences (derivatives = 2).
class SaturatedController final : public SteeringController {
 public:
  SaturatedController(std::unique_ptr<SteeringController> inner, const SteeringLimits& limits,
                      std::string name);

 protected:
  Status compute_command(const ControllerInput& input, ControllerOutput& output) noexcept override;

 public:
  //! Restarts the inner controller and the limiter from the measured angle, at rest.
  Status reset(double measured_steering_angle_rad = 0.0) noexcept override;
  const char* name() const noexcept override { return name_.c_str(); }
  //! Forwarded: the wrapped controller decides whether it has a matched-disturbance input.
  Status set_path(std::shared_ptr<const Path> path) noexcept override {
    return inner_->set_path(std::move(path));
  }
  bool set_matched_disturbance(double lead_curvature_disturbance) noexcept override {
    return inner_->set_matched_disturbance(lead_curvature_disturbance);
  }

  const SaturationStatistics& saturation() const noexcept { return saturator_.statistics(); }
  const SteeringLimits& limits() const noexcept { return saturator_.limits(); }
  SteeringController& inner() noexcept { return *inner_; }

 private:
  std::unique_ptr<SteeringController> inner_;
  SteeringSaturator saturator_;
  std::string name_;
};

}  // namespace smoothsteer
