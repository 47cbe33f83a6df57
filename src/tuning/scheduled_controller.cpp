#include "smoothsteer/tuning/scheduled_controller.hpp"

#include <cmath>
#include <stdexcept>

namespace smoothsteer {
namespace {

const GainSchedule& non_empty(const GainSchedule& schedule) {
  if (schedule.empty()) throw std::invalid_argument("ScheduledController: the schedule is empty");
  return schedule;
}

}  // namespace

ScheduledController::ScheduledController(GainSchedule schedule, std::shared_ptr<const Path> path)
    : schedule_(std::move(schedule)),
      controller_(non_empty(schedule_).parameters_at(schedule_.entries().front().speed_mps),
                  std::move(path)) {}

Status ScheduledController::compute_command(const ControllerInput& input,
                                            ControllerOutput& output) noexcept {
  if (!std::isfinite(input.speed_mps)) return Status::invalid_input;
  const double speed = std::abs(input.speed_mps);
  if (speed != tuned_speed_) {
    const Status tuned = controller_.retune(schedule_.parameters_at(speed));
    if (tuned != Status::ok) return tuned;
    tuned_speed_ = speed;
  }
  return controller_.update(input, output);
}

void ScheduledController::reset(double measured_steering_angle_rad) noexcept {
  controller_.reset(measured_steering_angle_rad);
  tuned_speed_ = -1.0;
}

}  // namespace smoothsteer
