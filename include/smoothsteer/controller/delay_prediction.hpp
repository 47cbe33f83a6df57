#pragma once
//! \file delay_prediction.hpp
//! Stage of LeadWheelController::compute_command(): the Smith predictor
//! (ControllerParameters::delay_compensation, docs/controller.md "Actuator delay compensation").
//! It keeps the commands of the last periods and rolls the kinematic model forward through those
//! still in the pipe, so that the law acts on the pose at which the new command takes effect.

#include <array>
#include <cstddef>

#include "smoothsteer/math/pose2.hpp"

namespace smoothsteer {

class DelayPrediction {
 public:
  struct IssuedCommand {
    double steering_rad = 0.0;
    double period_s = 0.0;
  };
  //! 512 periods cover 1 s (ControllerParameters::max_actuator_delay_s) down to 2 ms. A ring
  //! buffer, so that update() does not allocate.
  static constexpr std::size_t capacity = 512;

  void reset() noexcept {
    count_ = 0;
    next_ = 0;
  }
  void record(double steering_rad, double period_s) noexcept {
    history_[next_] = {steering_rad, period_s};
    next_ = (next_ + 1) % capacity;
    count_ = count_ + 1 < capacity ? count_ + 1 : capacity;
  }
  //! Valid entries.
  std::size_t count() const noexcept { return count_; }
  //! The command issued `age` periods ago (0 = the newest); age < count().
  const IssuedCommand& issued(std::size_t age) const noexcept {
    return history_[(next_ + capacity - 1 - age) % capacity];
  }
  //! `pose` (the rear axle's position and course) rolled forward over `delay_s` through the
  //! commands issued during the last `delay_s`, at `speed_mps`, with the plant's estimated
  //! curvature disturbance; `pose` itself for no delay or no history.
  Pose2 predict(Pose2 pose, double delay_s, double speed_mps, double wheelbase_m,
                double disturbance_curvature) const noexcept;

 private:
  std::array<IssuedCommand, capacity> history_{};
  std::size_t count_ = 0;
  std::size_t next_ = 0;
};

}  // namespace smoothsteer
