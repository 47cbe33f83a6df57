#pragma once
//! \file steering_actuator.hpp
//! Steering system of the simulation (paper Sec. IV-A: "a third-order low pass filter for the
//! steering system"): a pure dead time, then three equal first-order lags
//!   G(s) = e^{-T_d s} * (w_p / (s + w_p))^3,
//! with the actuator's own angle and rate saturation on the output. The pole w_p is placed such
//! that |G(j 2 pi f_b)| = 1/sqrt(2) for the bandwidth f_b: w_p = 2 pi f_b / sqrt(2^(1/3) - 1).
//! The dead time is realised exactly as a delay line of whole integration steps.

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct ActuatorParameters {
  //! true: no filter, no saturation (delta_actual = delayed command). For the ideal kinematic
  //! reaching benchmark (paper Sec. IV-B).
  bool ideal = false;
  double bandwidth_hz = 10.0;    //!< f_b, -3 dB frequency of the third-order low-pass [Hz]
  double dead_time_s = 0.01;     //!< T_d, pure delay [s]; a whole multiple of the plant sub-step
  double max_angle_rad = 1.066;  //!< |delta_actual| saturation [rad]
  double max_rate_radps = 0.4;   //!< |d delta_actual / dt| saturation [rad/s]

  //! Pole of each first-order lag [rad/s].
  double pole_radps() const noexcept;
  //! The first rule broken for the plant sub-step `step_s` (validation.hpp), including that
  //! dead_time_s is a whole multiple of it.
  std::optional<Violation> first_violation(double step_s) const noexcept;
  bool is_valid(double step_s) const noexcept { return !first_violation(step_s); }
  std::string validation_error(double step_s) const;
  //! Throws std::invalid_argument with validation_error(step_s).
  void validate(double step_s) const;
};

class SteeringActuator {
 public:
  using State = std::array<double, 3>;  //!< outputs of the three lags; [2] is delta_actual

  //! Validates and sizes the delay line for the integration step `step_s` (set-up: allocates).
  SteeringActuator(const ActuatorParameters& parameters, double step_s);

  //! Settles every state and the delay line at `angle_rad` (no allocation).
  void reset(double angle_rad) noexcept;
  //! Pushes this step's command into the delay line and returns the delayed input u(t - T_d).
  double push_command(double command_rad) noexcept;
  //! d state / dt for the (delayed) input u, with rate and angle saturation of the output.
  State derivative(const State& state, double input_rad) const noexcept;
  //! Clamps the output after an integration step.
  void clamp(State& state) const noexcept;
  //! One RK4 step of length step_s with the (already delayed) input u held constant.
  void advance(double input_rad) noexcept;
  //! Stand-alone use: push_command + advance.
  void step(double command_rad) noexcept { advance(push_command(command_rad)); }

  const State& state() const noexcept { return state_; }
  void set_state(const State& state) noexcept { state_ = state; }
  //! delta_actual [rad], its rate [rad/s] and acceleration [rad/s^2] for input u (analytic from
  //! the filter states; 0 rate/acceleration for the ideal actuator, whose output jumps).
  double angle() const noexcept { return state_[2]; }
  double rate(double input_rad) const noexcept;
  double acceleration(double input_rad) const noexcept;

  const ActuatorParameters& parameters() const noexcept { return parameters_; }
  double step_s() const noexcept { return step_s_; }
  int delay_steps() const noexcept { return static_cast<int>(delay_line_.size()); }

 private:
  ActuatorParameters parameters_;
  double step_s_;
  double pole_;
  State state_{};
  std::vector<double> delay_line_;  //!< ring buffer of the last delay_steps() commands
  std::size_t delay_head_ = 0;
};

}  // namespace smoothsteer
