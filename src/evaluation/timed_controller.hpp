#pragma once
// Wall-clock cost of every update() of a wrapped controller (internal; evaluation only). The
// figures go to the *_timings tables, never into a committed table: they change on every run.
// The benchmark of record for the cost per update is bench/ (docs/benchmarks.md).

#include <algorithm>
#include <chrono>
#include <memory>
#include <utility>

#include "smoothsteer/controller/steering_controller.hpp"

namespace smoothsteer::detail {

class TimedController final : public SteeringController {
 public:
  explicit TimedController(std::unique_ptr<SteeringController> inner) : inner_(std::move(inner)) {}

  Status reset(double measured_steering_angle_rad = 0.0) noexcept override {
    return inner_->reset(measured_steering_angle_rad);
  }
  const char* name() const noexcept override { return inner_->name(); }
  Status set_path(std::shared_ptr<const Path> path) noexcept override {
    return inner_->set_path(std::move(path));
  }
  bool set_matched_disturbance(double kappa_d) noexcept override {
    return inner_->set_matched_disturbance(kappa_d);
  }

  long updates() const noexcept { return updates_; }
  double mean_us() const noexcept {
    return updates_ > 0 ? 1e6 * total_s_ / static_cast<double>(updates_) : 0.0;
  }
  double max_us() const noexcept { return 1e6 * max_s_; }

 protected:
  //! The wrapped controller's whole update(), timed.
  Status compute_command(const ControllerInput& input, ControllerOutput& output) noexcept override {
    const auto start = std::chrono::steady_clock::now();
    const Status status = inner_->update(input, output);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++updates_;
    total_s_ += seconds;
    max_s_ = std::max(max_s_, seconds);
    return status;
  }

 private:
  std::unique_ptr<SteeringController> inner_;
  long updates_ = 0;
  double total_s_ = 0.0, max_s_ = 0.0;
};

}  // namespace smoothsteer::detail
