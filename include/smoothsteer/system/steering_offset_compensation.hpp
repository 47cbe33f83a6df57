#pragma once
//! \file steering_offset_compensation.hpp
//! Stage of SteeringSystem::update(): the command made up for a steering offset, so that the
//! road wheels steer what the controller asks (docs/steering_system.md, "Steering offset").
//!
//! The side-slip observer learns delta_o, the road wheels' angle minus the measured one
//! (docs/vehicle_dynamics.md, "Steering offset"). That is a misaligned rack (the wheels beside
//! the actuator's angle, which the command must make up for) or an angle sensor that reads off
//! (the actuator holds the command, only the reading is off: nothing to make up for); the
//! observer alone cannot tell them apart. They differ in how the measured angle follows the
//! command: this stage predicts the actuator's angle from the commands it held and the actuator's
//! model (dead time and three equal lags, steering_actuator.hpp), and low-passes the reading's
//! bias b = measured - predicted. The wheels then steer the command plus
//!   c = delta_o + b        (rack r: delta_o = r, b = 0; sensor s: delta_o = -s, b = s),
//! and the held command is the controller's minus c.
//!
//! The applied offset follows c within a share of the car's rate and acceleration limits and
//! within the observer's bound, and the held command passes the car's limiter
//! (command_limiter.hpp): whatever the estimate does, the held command keeps the car's angle,
//! rate and acceleration limits. A command that keeps them with c constant passes unchanged.
//! The offset persists across reset(), as the observer's does. update() is noexcept and
//! allocation free.

#include <array>
#include <cstddef>
#include <optional>

#include "smoothsteer/controller/command_limiter.hpp"
#include "smoothsteer/controller/disturbance_estimator.hpp"
#include "smoothsteer/vehicle/steering_actuator.hpp"

namespace smoothsteer {

//! The actuator's angle predicted at the control period from the commands held, with the
//! actuator's dead time and its three equal lags integrated exactly for each held command (no
//! rate saturation: a held command within the car's limits does not reach it).
class ActuatorAnglePrediction {
 public:
  //! The longest dead time the history covers, in periods.
  static constexpr std::size_t history_periods = 64;

  explicit ActuatorAnglePrediction(const ActuatorParameters& actuator) noexcept;
  //! Everything settled at `angle_rad`.
  void reset(double angle_rad) noexcept;
  //! The command held from now on over the period `period_s`; advances the lags by that period
  //! and returns the predicted angle at its end.
  double advance(double held_command_rad, double period_s) noexcept;
  double angle() const noexcept { return lags_[2]; }

 private:
  //! The three lags over `duration_s` with the input `input_rad` held: exact (a Jordan block).
  void integrate(double input_rad, double duration_s) noexcept;

  double dead_time_s_ = 0.0;
  double pole_radps_ = 0.0;  //!< 0: ideal, the output is the delayed input
  std::array<double, 3> lags_{};
  std::array<double, history_periods> held_{};  //!< held_[j]: the command j periods ago
  std::size_t newest_ = 0;
};

struct SteeringOffsetCompensationParameters {
  ActuatorParameters actuator;   //!< the actuator model the controller is given
  SteeringLimits limits;         //!< the car's limits on the held command
  double max_offset_rad = 0.02;  //!< |c| bound (the observer's max_steering_offset_rad)
  //! The share of the car's rate and acceleration limits the applied offset moves with: at 0.4
  //! rad/s a rack offset of 0.01 rad is made up for within 0.1 s once learned. 0.1 left the
  //! 19 m/s lane change with a 0.02 rad rack at 0.69 m (0.38 m at 0.25).
  double limit_share = 0.25;
  //! The low-pass time constant of the reading's bias [s]: faster than the observer learns
  //! delta_o (about 0.3 s at speed), so that an angle sensor's offset is not made up for
  //! meanwhile (0.3 s: the 15 m/s lane change 0.030 -> 0.059 m with a 0.01 rad sensor offset;
  //! 0.1 s: 0.029 m).
  double bias_time_constant_s = 0.1;
  //! |c| below this is not made up for [rad], and the rest of a larger one is: the observer's
  //! offset moves by about 1e-4 rad through a lane change (the tires' lag its model leaves),
  //! which the command turned into 8 mm at 15 m/s (0.030 -> 0.038 m).
  double deadband_rad = 5e-4;
  //! ... and at least this many of the observer's standard deviations of delta_o: before it has
  //! learned (std 0.01 rad at 0.02 rad bound) its offset swings by up to 0.7 mrad in the first
  //! periods, which put 1.1 rad/s^2 into the nominal lane change's held command (0.54 without).
  //! 0.2 keeps that out and costs a rack offset at most 1 mm.
  double deadband_per_offset_std = 0.2;
  //! c is taken only while the controller's command turns slower than this [rad/s], the rate
  //! below which the disturbance estimate also learns: through an engagement from a heading
  //! error the observer's offset swings by more than the deadband (the engagement table's
  //! cases within 1.1x the best baseline at 19 m/s 35 -> 33 without this hold).
  double steady_command_rate_radps = DisturbanceEstimator::settled_steering_rate_radps;
};

class SteeringOffsetCompensation {
 public:
  explicit SteeringOffsetCompensation(const SteeringOffsetCompensationParameters& parameters);

  //! A new engagement at the measured angle: the prediction settles there, the limiter starts at
  //! rest; the applied offset and the bias stay.
  void reset(double measured_angle_rad) noexcept;
  //! Back to no offset and no bias (a realigned rack or sensor); the held command moves there
  //! within the car's limits.
  void forget() noexcept;
  //! The angle the controller's chain starts from after reset(): the wheels' estimate, the
  //! measured angle less the bias plus the offset.
  double wheels_from_measured(double measured_angle_rad) const noexcept;
  //! One period: the held command for the controller's `command_rad`, given the observer's
  //! offset and its standard deviation, and the measured angle (absent: the reading is the
  //! command). `rate_radps` and
  //! `acceleration_radps2` receive the held command's differenced rate and acceleration.
  double update(double command_rad, std::optional<double> measured_angle_rad,
                double observer_offset_rad, double observer_offset_std_rad, double period_s,
                double& rate_radps, double& acceleration_radps2) noexcept;

  //! The offset the held command is made up by [rad] (wheels = held + this).
  double applied_offset_rad() const noexcept { return offset_limiter_.previous(); }
  //! The measured angle's bias against the actuator's predicted angle [rad].
  double sensor_bias_rad() const noexcept { return bias_rad_; }
  //! How often the car's limiter changed the held command.
  const SaturationStatistics& limiter_statistics() const noexcept {
    return command_limiter_.statistics();
  }
  const SteeringOffsetCompensationParameters& parameters() const noexcept { return parameters_; }

 private:
  SteeringOffsetCompensationParameters parameters_;
  ActuatorAnglePrediction prediction_;
  SteeringSaturator offset_limiter_;
  SteeringSaturator command_limiter_;
  double bias_rad_ = 0.0;
  bool has_held_ = false;  //!< a command has been held since reset(): the prediction can step
  double held_rad_ = 0.0;  //!< the command held in the last period
  double previous_command_rad_ = 0.0;           //!< the controller's command in the last period
  double observer_offset_taken_rad_ = 0.0;      //!< delta_o as last taken (while steady)
  double observer_offset_std_taken_rad_ = 0.0;  //!< and its standard deviation
};

}  // namespace smoothsteer
