#pragma once
//! \file path_tracking_baseline.hpp
//! What every comparison controller shares: its validated parameters, the path it tracks, the
//! projection hints at the rear and the front axle, its last command, the restart from a
//! measured angle and replanning by swapping the path.

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "smoothsteer/controller/path_swap.hpp"
#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/path/path.hpp"

namespace smoothsteer {

template <typename Parameters>
class PathTrackingBaseline : public SteeringController {
 public:
  //! Replanning (SteeringController::set_path): swaps the path and re-seeds the hints; the rest
  //! of the controller's state (its last command, a model's estimate) carries on.
  Status set_path(std::shared_ptr<const Path> path) noexcept override {
    return swap_path(path_, path, rear_hint_, front_hint_);
  }
  //! Restarts from the measured steering angle with cold hints; a controller with more state or
  //! an angle bound overrides it and calls restart(). invalid_input for an angle
  //! valid_reset_angle() refuses.
  Status reset(double measured_steering_angle_rad = 0.0) noexcept override {
    if (!valid_reset_angle(measured_steering_angle_rad)) return Status::invalid_input;
    restart(measured_steering_angle_rad);
    return Status::ok;
  }
  const Parameters& parameters() const noexcept { return parameters_; }

 protected:
  //! Validates `parameters` (std::invalid_argument naming the field), then requires a path
  //! (std::invalid_argument naming `controller`).
  PathTrackingBaseline(const Parameters& parameters, std::shared_ptr<const Path> path,
                       const char* controller)
      : parameters_(parameters), path_(std::move(path)) {
    parameters_.validate();
    if (!path_) {
      throw std::invalid_argument(std::string(controller) + ": path is null; a path is required");
    }
  }

  //! The last command becomes the measured angle (clamped to +-bound, 0 if not finite); the
  //! projection hints start cold.
  void restart(double measured_steering_angle_rad, double bound = HUGE_VAL) noexcept {
    steering_ = std::isfinite(measured_steering_angle_rad)
                    ? std::clamp(measured_steering_angle_rad, -bound, bound)
                    : 0.0;
    rear_hint_.reset();
    front_hint_.reset();
  }

  Parameters parameters_;
  std::shared_ptr<const Path> path_;
  ProjectionHint rear_hint_, front_hint_;
  double steering_ = 0.0;  //!< the last command [rad]
};

}  // namespace smoothsteer
