#include "smoothsteer/tuning/scheduled_controller.hpp"

#include <cmath>
#include <stdexcept>

namespace smoothsteer {
namespace {

const GainSchedule& non_empty(const GainSchedule& schedule) {
  if (schedule.empty()) throw std::invalid_argument("ScheduledController: the schedule is empty");
  return schedule;
}

std::optional<SpeedCompensation> checked(std::optional<SpeedCompensation> compensation) {
  if (compensation) compensation->validate();
  return compensation;
}

}  // namespace

ScheduledController::ScheduledController(GainSchedule schedule, std::shared_ptr<const Path> path,
                                         std::optional<SpeedCompensation> compensation)
    : schedule_(std::move(schedule)),
      compensation_(checked(compensation)),
      controller_(parameters_at(non_empty(schedule_).entries().front().speed_mps),
                  std::move(path)) {}

ScheduledController::ScheduledController(GainSchedule schedule, PathLater later,
                                         std::optional<SpeedCompensation> compensation)
    : schedule_(std::move(schedule)),
      compensation_(checked(compensation)),
      controller_(parameters_at(non_empty(schedule_).entries().front().speed_mps), later),
      compensation_follows_path_(true) {}

Status ScheduledController::set_path(std::shared_ptr<const Path> path) noexcept {
  const double curvature = path ? path->max_abs_curvature() : 0.0;
  const Status status = controller_.set_path(std::move(path));
  if (status == Status::ok && compensation_follows_path_ && compensation_) {
    compensation_->design_curvature_per_m = curvature;
    tuned_speed_ = -1.0;  // the next update() retunes with the new compensation
  }
  return status;
}

ControllerParameters ScheduledController::parameters_at(double speed_mps) const noexcept {
  ControllerParameters p = schedule_.parameters_at(speed_mps);
  if (compensation_) {
    // A group switched on must carry a value (ControllerParameters::validate): a zero delay
    // (an ideal actuator at rest) switches the predictor off, and the catch-up needs a
    // feedforward to catch up with.
    const double delay = compensation_->delay_s(speed_mps);
    p.delay_compensation.enabled = delay > 0.0;
    p.delay_compensation.actuator_delay_s = delay;
    p.feedforward.catch_up = p.feedforward.share > 0.0 ? compensation_->catch_up(speed_mps) : 0.0;
  }
  return p;
}

Status ScheduledController::compute_command(const ControllerInput& input,
                                            ControllerOutput& output) noexcept {
  if (!std::isfinite(input.speed_mps)) return Status::invalid_input;
  if (!controller_.has_path()) return Status::not_configured;  // before the retune changes it
  const double speed = std::abs(input.speed_mps);
  if (speed != tuned_speed_) {
    const Status tuned = controller_.retune(parameters_at(speed));
    if (tuned != Status::ok) return tuned;
    tuned_speed_ = speed;
  }
  return controller_.update(input, output);
}

Status ScheduledController::reset(double measured_steering_angle_rad) noexcept {
  // The car's angle limit is the one the parameters carry (governor.max_steering_angle_rad), as
  // for a LeadWheelController alone. The schedule's vehicle angle is what its rows were tuned
  // for; a loaded schedule's is only the largest angle its rows certify (0.93 rad for
  // passenger_car_parking.csv, whose car steers to 1.066 rad).
  const Status status = controller_.reset(measured_steering_angle_rad);
  if (status == Status::ok) tuned_speed_ = -1.0;
  return status;
}

}  // namespace smoothsteer
