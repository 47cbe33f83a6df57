#pragma once
//! \file steering_controller.hpp
//! The real-time interface shared by the lead-wheel controller and the comparison controllers:
//! fill a ControllerInput, call update(input, output) once per control period, read the output.

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <optional>

#include "smoothsteer/controller/active_limits.hpp"
#include "smoothsteer/controller/command_limiter.hpp"
#include "smoothsteer/math/vec2.hpp"
#include "smoothsteer/status.hpp"

namespace smoothsteer {

class Path;
class LeadWheelController;

struct ControllerInput {
  Vec2 rear_axle_position;   //!< rear-axle reference point in the world frame [m]
  double heading_rad = 0.0;  //!< vehicle heading psi [rad]
  double speed_mps = 0.0;    //!< signed longitudinal speed v [m/s]; v < 0 reverses
  //! dv/dt [m/s^2]: the held command's second difference budgets for it, and the single-track
  //! inversion shifts its slip gradients with it (load transfer, the rear slip's change with the
  //! speed; docs/vehicle_dynamics.md section 3). Give it smoothed (the speed controller's
  //! reference or a low-passed derivative of the wheel speeds): on a curve 0.5 m/s^2 of noise
  //! moves the passenger car's feedforward gain by about 4 % at 20 m/s.
  double acceleration_mps2 = 0.0;
  double period_s = 0.02;  //!< control period dt [s]
  //! beta_r: side slip of the rear axle [rad], the angle from the vehicle's heading to the
  //! rear axle's velocity (atan((vy - l_r r) / vx) on a single-track model). The kinematic law
  //! steers the direction of travel, which on a real car is the course psi + beta_r, not psi
  //! (paper Outlook; docs/vehicle_dynamics.md). 0 (the default) is the kinematic assumption.
  //! Measured by a slip sensor or estimated by SideSlipObserver. |beta_r| <= max_side_slip_rad.
  double rear_axle_side_slip_rad = 0.0;
  static constexpr double max_side_slip_rad = 0.5;
  //! How old the pose (rear_axle_position, heading_rad, rear_axle_side_slip_rad) is when update()
  //! runs [s]: localization delivers it late (20-100 ms in driving stacks), while speed and the
  //! commands are current. The lead-wheel controller carries the pose forward over this age
  //! through its own commands in effect since then, as its delay prediction carries it over the
  //! actuator's delay (docs/controller.md, "Pose latency"). The comparison controllers take the
  //! pose as it is. 0 (the default): the pose is current. 0 <= pose_age_s <= max_pose_age_s.
  double pose_age_s = 0.0;
  //! Half the span of the command history the prediction reads (DelayPrediction::capacity
  //! periods of 2 ms cover 1 s, shared with the actuator delay).
  static constexpr double max_pose_age_s = 0.5;
  //! How much more the car's tires slip than the controller's model says: the single-track
  //! inversion's slip gradients K_f, K_r are taken times this factor (a loaded car, worn or
  //! stiffer tires, a wrong vehicle file; SteeringSystem learns it from the pose,
  //! course_error_estimator.hpp). 1 (the default): the model as given. In [min, max].
  double slip_gradient_scale = 1.0;
  static constexpr double min_slip_gradient_scale = 0.5;
  static constexpr double max_slip_gradient_scale = 2.0;
};

//! Diagnostics of the path-tracking state (all relative to the reference path).
struct TrackingDiagnostics {
  double lateral_error_m = 0.0;         //!< e of the rear axle, left positive
  double heading_error_rad = 0.0;       //!< psi - path heading at the rear axle's closest point
  double front_lateral_error_m = 0.0;   //!< e of the real front axle (lambda_veh ahead)
  double lead_lateral_error_m = 0.0;    //!< e_lead of the controlled (lead) wheel
  double lead_heading_error_rad = 0.0;  //!< psi_lead relative to the path at its closest point
  double sliding_variable = 0.0;        //!< sigma [m] (paper surface) or heading gap [rad] (global)
  double lead_curvature = 0.0;          //!< kappa_n applied to the lead wheel [1/m]
  double feedforward_curvature = 0.0;   //!< kappa_ff, its feedforward part [1/m]
  double path_arc_length_m = 0.0;       //!< s of the rear axle's closest point
  double path_curvature = 0.0;          //!< path curvature at the rear axle's closest point
  double fictive_steering_angle_rad = 0.0;  //!< delta_1 of the fictive chain
  //! The estimate of the curvature the plant adds at the rear axle (a rack offset, crossfall,
  //! crosswind; docs/feedforward.md section 7) [1/m]; 0 without the estimation.
  double disturbance_curvature = 0.0;
};

struct ControllerOutput {
  double steering_angle_rad = 0.0;            //!< delta_veh command for the real vehicle
  double steering_rate_radps = 0.0;           //!< d(delta_veh)/dt, valid if derivatives >= 1
  double steering_acceleration_radps2 = 0.0;  //!< d2(delta_veh)/dt2, valid if derivatives >= 2
  int derivatives_available = 0;              //!< how many time derivatives are meaningful
  TrackingDiagnostics diagnostics;
};

//! The range of ControllerInput that update() accepts. Beyond it the arithmetic breaks: squared
//! distances overflow from 1e154 m on, angles and positions lose every digit that matters. The
//! bounds are far beyond any car (beyond them the arithmetic returns inf or NaN).
struct ControllerInputRange {
  static constexpr double max_abs_coordinate_m = 1e9;  //!< |x|, |y|; resolution 1.2e-7 m there
  static constexpr double max_abs_heading_rad = 1e6;   //!< |psi|; resolution 1.2e-10 rad there
  static constexpr double max_abs_speed_mps = 1e3;
  static constexpr double max_abs_acceleration_mps2 = 1e4;
  static constexpr double max_period_s = 1e3;  //!< period in (0, max_period_s]
};

//! The first field of an input outside ControllerInputRange: its name in ControllerInput, its
//! value, and the range as [low, high] (low = -high for a magnitude; low_open: low excluded).
struct InputRangeViolation {
  const char* field = "";
  double value = 0.0;
  double low = 0.0;
  double high = 0.0;
  bool low_open = false;
  const char* unit = "";
};

//! The first field outside ControllerInputRange (NaN and inf included), or none: the one table
//! that update() checks and that error messages name.
inline std::optional<InputRangeViolation> first_input_range_violation(
    const ControllerInput& input) noexcept {
  using R = ControllerInputRange;
  const InputRangeViolation checks[] = {
      {"rear_axle_position.x", input.rear_axle_position.x, -R::max_abs_coordinate_m,
       R::max_abs_coordinate_m, false, "m"},
      {"rear_axle_position.y", input.rear_axle_position.y, -R::max_abs_coordinate_m,
       R::max_abs_coordinate_m, false, "m"},
      {"heading_rad", input.heading_rad, -R::max_abs_heading_rad, R::max_abs_heading_rad, false,
       "rad"},
      {"speed_mps", input.speed_mps, -R::max_abs_speed_mps, R::max_abs_speed_mps, false, "m/s"},
      {"acceleration_mps2", input.acceleration_mps2, -R::max_abs_acceleration_mps2,
       R::max_abs_acceleration_mps2, false, "m/s^2"},
      {"period_s", input.period_s, 0.0, R::max_period_s, true, "s"},
      {"rear_axle_side_slip_rad", input.rear_axle_side_slip_rad,
       -ControllerInput::max_side_slip_rad, ControllerInput::max_side_slip_rad, false, "rad"},
      {"pose_age_s", input.pose_age_s, 0.0, ControllerInput::max_pose_age_s, false, "s"},
      {"slip_gradient_scale", input.slip_gradient_scale, ControllerInput::min_slip_gradient_scale,
       ControllerInput::max_slip_gradient_scale, false, ""},
  };
  for (const InputRangeViolation& check : checks) {
    const bool above_low = check.low_open ? check.value > check.low : check.value >= check.low;
    if (!(above_low && check.value <= check.high)) return check;  // NaN: not within
  }
  return std::nullopt;
}

//! True if every value of `input` is finite and within ControllerInputRange.
inline bool input_in_range(const ControllerInput& input) noexcept {
  return !first_input_range_violation(input);
}

//! A measured steering angle that reset() accepts: |angle| <= limit_rad (the vehicle's angle
//! limit, where the controller knows one) and below pi / 2 in any case: a road wheel at right
//! angles to the car or beyond steers along no path, and tan(angle) would wrap it to the other
//! lock. NaN and inf are refused.
inline bool valid_reset_angle(double angle_rad,
                              double limit_rad = std::numbers::pi / 2.0) noexcept {
  return std::abs(angle_rad) < std::numbers::pi / 2.0 && std::abs(angle_rad) <= limit_rad;
}

//! True if the command, its derivatives and every diagnostic are finite.
inline bool all_finite(const ControllerOutput& output) noexcept {
  // Every field of TrackingDiagnostics is a double, so it reads as an array of them; a field
  // added later is checked too.
  constexpr std::size_t count = sizeof(TrackingDiagnostics) / sizeof(double);
  static_assert(count * sizeof(double) == sizeof(TrackingDiagnostics),
                "TrackingDiagnostics must hold doubles only (all_finite reads it as an array)");
  bool finite = std::isfinite(output.steering_angle_rad) &&
                std::isfinite(output.steering_rate_radps) &&
                std::isfinite(output.steering_acceleration_radps2);
  for (double value : std::bit_cast<std::array<double, count>>(output.diagnostics)) {
    finite = finite && std::isfinite(value);
  }
  return finite;
}

//! Tag of the constructors whose path arrives later, by set_path(): a driving stack has no path
//! at start-up and sends its first trajectory after the controller is built. Until a path
//! arrives, update() returns Status::not_configured and changes nothing.
struct PathLater {};

//! Interface of every steering controller in the library. update() is noexcept, allocation-free
//! and deterministic. It checks what every controller must guarantee, so that no controller can
//! miss it: an input outside ControllerInputRange gives invalid_input, a non-finite result gives
//! numerical_error (and a reset to the last command), and in both cases and for any other error
//! the output stays unchanged. Status::ok always comes with a finite output.
class SteeringController {
 public:
  virtual ~SteeringController() = default;
  Status update(const ControllerInput& input, ControllerOutput& output) noexcept {
    if (!input_in_range(input)) return Status::invalid_input;
    ControllerOutput computed = output;
    const Status status = compute_command(input, computed);
    if (status != Status::ok) return status;
    if (!all_finite(computed)) {
      (void)reset(output.steering_angle_rad);
      return Status::numerical_error;
    }
    output = computed;
    return Status::ok;
  }
  //! Restarts from rest with the measured steering angle of the real vehicle [rad]. Returns
  //! invalid_input, and changes nothing, for an angle valid_reset_angle() refuses (NaN, inf,
  //! |angle| >= pi / 2, or beyond the angle limit the controller knows): never wrapped, never
  //! silently 0.
  virtual Status reset(double measured_steering_angle_rad = 0.0) noexcept = 0;
  virtual const char* name() const noexcept = 0;
  //! Replanning: replaces the reference path between two update() calls (docs/replanning.md).
  //! noexcept and allocation free; the controller's state (and so its command) carries on
  //! continuously and its projection hints are re-seeded on the new path near where they were.
  //! Threading contract: build the Path in another thread, hand it over as a shared_ptr, and
  //! call set_path() from the control thread (or under the same lock as update()); it takes
  //! effect at the next update(). The previous path is released here: keep another reference
  //! to it (e.g. the planner keeps its last path) if the control thread must not free memory.
  //! Returns invalid_input for a null path (the old one stays), unsupported if the controller
  //! cannot replace its path.
  virtual Status set_path(std::shared_ptr<const Path> path) noexcept {
    (void)path;
    return Status::unsupported;
  }
  //! Evaluation hook: injects a matched disturbance kappa_d [1/m] into the controller's own
  //! model where it has one (the lead wheel's curvature of the trailer chain). Returns false if
  //! the controller has no such input; simulations then bend the plant's path instead.
  virtual bool set_matched_disturbance(double lead_curvature_disturbance) noexcept {
    (void)lead_curvature_disturbance;
    return false;
  }
  //! Which of its limits `output`, the command of the last update(), is at for |v| =
  //! `speed_mps`: ActiveLimit bits (active_limits.hpp), which SteeringSystem reports. 0 for a
  //! controller that names none.
  virtual std::uint32_t active_limits(const ControllerOutput& output,
                                      double speed_mps) const noexcept {
    (void)output;
    (void)speed_mps;
    return limit_none;
  }
  //! The car's steering angle, rate and acceleration limits as the controller was given them
  //! (the lead wheel's governor limits), which SteeringSystem's offset compensation holds its
  //! command to as well; std::nullopt for a controller that is given none.
  virtual std::optional<SteeringLimits> car_steering_limits() const noexcept {
    return std::nullopt;
  }

 protected:
  //! The controller's own step, called by update() with an input in range; `output` holds the
  //! previous output on entry. noexcept and allocation-free.
  virtual Status compute_command(const ControllerInput& input,
                                 ControllerOutput& output) noexcept = 0;
};

}  // namespace smoothsteer
