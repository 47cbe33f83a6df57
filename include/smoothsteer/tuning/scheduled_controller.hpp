#pragma once
//! \file scheduled_controller.hpp
//! The lead-wheel controller driven by a gain schedule: every update() looks up the parameters
//! for the measured |v| (GainSchedule::parameters_at, continuous in v) and retunes the controller
//! before the control step. With a SpeedCompensation the Smith predictor's delay and the
//! feedforward's catch-up follow |v| too (speed_compensation.hpp). Real time: noexcept, no
//! allocation.

#include <memory>
#include <optional>
#include <utility>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/tuning/gain_schedule.hpp"
#include "smoothsteer/tuning/speed_compensation.hpp"

namespace smoothsteer {

class ScheduledController final : public SteeringController {
 public:
  //! Throws std::invalid_argument for an empty schedule, a null path or a compensation that
  //! breaks a rule (naming its field). Without a compensation the schedule's base keeps its own
  //! actuator_delay_s and feedforward_catch_up.
  ScheduledController(GainSchedule schedule, std::shared_ptr<const Path> path,
                      std::optional<SpeedCompensation> compensation = std::nullopt);
  //! Without a path: update() returns not_configured, and changes nothing, until set_path().
  //! The compensation's design curvature then follows each path set_path() accepts (its
  //! largest |kappa|, Path::max_abs_curvature()), as if the system had been built on it.
  ScheduledController(GainSchedule schedule, PathLater,
                      std::optional<SpeedCompensation> compensation = std::nullopt);

 protected:
  Status compute_command(const ControllerInput& input, ControllerOutput& output) noexcept override;

 public:
  //! The inner controller's reset: it refuses an angle beyond the car's angle limit the
  //! parameters carry (governor.max_steering_angle_rad, LeadWheelController::reset), not beyond
  //! the schedule's vehicle angle.
  Status reset(double measured_steering_angle_rad = 0.0) noexcept override;
  const char* name() const noexcept override { return "scheduled_lead_wheel"; }

  const GainSchedule& schedule() const noexcept { return schedule_; }
  const std::optional<SpeedCompensation>& compensation() const noexcept { return compensation_; }
  //! What update() gives the inner controller at |v|: the schedule's parameters, with the
  //! compensation's delay and catch-up where there is one.
  ControllerParameters parameters_at(double speed_mps) const noexcept;
  const LeadWheelController& controller() const noexcept { return controller_; }
  //! Replanning, forwarded to the inner controller (see SteeringController::set_path).
  Status set_path(std::shared_ptr<const Path> path) noexcept override;
  //! Forwarded to the inner controller (evaluation hook, see LeadWheelController).
  bool set_matched_disturbance(double kappa_d) noexcept override {
    return controller_.set_matched_disturbance(kappa_d);
  }
  //! The inner controller's, with the parameters of the current speed.
  std::uint32_t active_limits(const ControllerOutput& output,
                              double speed_mps) const noexcept override {
    return controller_.active_limits(output, speed_mps);
  }
  std::optional<SteeringLimits> car_steering_limits() const noexcept override {
    return controller_.car_steering_limits();
  }

 private:
  GainSchedule schedule_;
  std::optional<SpeedCompensation> compensation_;
  LeadWheelController controller_;
  double tuned_speed_ = -1.0;  //!< |v| of the last retune; equal speeds skip the retune
  bool compensation_follows_path_ = false;  //!< set by the PathLater constructor
};

}  // namespace smoothsteer
