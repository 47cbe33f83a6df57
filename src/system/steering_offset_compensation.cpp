#include "smoothsteer/system/steering_offset_compensation.hpp"

#include <algorithm>
#include <cmath>

namespace smoothsteer {

ActuatorAnglePrediction::ActuatorAnglePrediction(const ActuatorParameters& actuator) noexcept
    : dead_time_s_(actuator.dead_time_s),
      pole_radps_(actuator.ideal ? 0.0 : actuator.pole_radps()) {}

void ActuatorAnglePrediction::reset(double angle_rad) noexcept {
  lags_.fill(angle_rad);
  held_.fill(angle_rad);
  newest_ = 0;
}

void ActuatorAnglePrediction::integrate(double input_rad, double duration_s) noexcept {
  if (!(duration_s > 0.0)) return;
  if (pole_radps_ == 0.0) {
    lags_.fill(input_rad);
    return;
  }
  // With e_i = x_i - u, the cascade e1' = -p e1, e_{i+1}' = p (e_i - e_{i+1}) is a Jordan block:
  // over t, with a = exp(-p t) and q = p t, e1 <- a e1, e2 <- a (e2 + q e1),
  // e3 <- a (e3 + q e2 + q^2 / 2 e1).
  const double q = pole_radps_ * duration_s;
  const double a = std::exp(-q);
  const double e1 = lags_[0] - input_rad, e2 = lags_[1] - input_rad, e3 = lags_[2] - input_rad;
  lags_[0] = input_rad + a * e1;
  lags_[1] = input_rad + a * (e2 + q * e1);
  lags_[2] = input_rad + a * (e3 + q * e2 + 0.5 * q * q * e1);
}

double ActuatorAnglePrediction::advance(double held_command_rad, double period_s) noexcept {
  newest_ = (newest_ + history_periods - 1) % history_periods;
  held_[newest_] = held_command_rad;
  if (!(period_s > 0.0)) return angle();
  // The dead time T_d = (K + f) h: over this period the lags see the command held K + 1 periods
  // ago for f h, then the one held K periods ago for (1 - f) h.
  const double periods = dead_time_s_ / period_s;
  const auto whole = std::min(static_cast<std::size_t>(periods), history_periods - 2);
  const double fraction = std::clamp(periods - static_cast<double>(whole), 0.0, 1.0);
  const auto held = [this](std::size_t age) { return held_[(newest_ + age) % history_periods]; };
  integrate(held(whole + 1), fraction * period_s);
  integrate(held(whole), (1.0 - fraction) * period_s);
  return angle();
}

SteeringOffsetCompensation::SteeringOffsetCompensation(
    const SteeringOffsetCompensationParameters& parameters)
    : parameters_(parameters),
      prediction_(parameters.actuator),
      offset_limiter_(SteeringLimits{
          .angle_rad = parameters.max_offset_rad,
          .rate_radps = parameters.limit_share * parameters.limits.rate_radps,
          .acceleration_radps2 = parameters.limit_share * parameters.limits.acceleration_radps2}),
      command_limiter_(parameters.limits) {}

double SteeringOffsetCompensation::wheels_from_measured(double measured_angle_rad) const noexcept {
  return measured_angle_rad - bias_rad_ + applied_offset_rad();
}

void SteeringOffsetCompensation::forget() noexcept {
  bias_rad_ = 0.0;
  observer_offset_taken_rad_ = observer_offset_std_taken_rad_ = 0.0;
  offset_limiter_.reset(0.0, 0.0);
}

void SteeringOffsetCompensation::reset(double measured_angle_rad) noexcept {
  // The actuator is taken to rest at the angle it holds: the measured one less its bias.
  const double actuator = measured_angle_rad - bias_rad_;
  prediction_.reset(actuator);
  offset_limiter_.reset(applied_offset_rad(), 0.0);
  command_limiter_.reset(actuator, 0.0);
  has_held_ = false;
}

double SteeringOffsetCompensation::update(double command_rad,
                                          std::optional<double> measured_angle_rad,
                                          double observer_offset_rad,
                                          double observer_offset_std_rad, double period_s,
                                          double& rate_radps,
                                          double& acceleration_radps2) noexcept {
  // The actuator's angle now, from the commands held up to the last period.
  if (has_held_) prediction_.advance(held_rad_, period_s);
  const double bound = parameters_.max_offset_rad;
  if (measured_angle_rad && has_held_) {
    const double gain = period_s / (parameters_.bias_time_constant_s + period_s);
    const double bias = *measured_angle_rad - prediction_.angle();
    bias_rad_ = std::clamp(bias_rad_ + gain * (bias - bias_rad_), -bound, bound);
  }
  // Without a measured angle the observer compares the wheels with the command itself.
  const double bias = measured_angle_rad ? bias_rad_ : 0.0;
  // While the controller's command turns fast (an engagement, a swerve) the tires' lag that the
  // observer's model leaves moves its offset: the offset taken holds then. The bias, which
  // compares the reading with the actuator's model alone, is taken every period.
  const bool steady = !has_held_ || std::abs(command_rad - previous_command_rad_) <=
                                        parameters_.steady_command_rate_radps * period_s;
  if (steady) {
    observer_offset_taken_rad_ = observer_offset_rad;
    observer_offset_std_taken_rad_ = observer_offset_std_rad;
  }
  previous_command_rad_ = command_rad;
  // c = delta_o + b, less the deadband (soft: continuous in c), within the bound. The deadband
  // grows with the observer's uncertainty while it has learned little.
  const double deadband = std::max(parameters_.deadband_rad, parameters_.deadband_per_offset_std *
                                                                 observer_offset_std_taken_rad_);
  const double offset_and_bias = observer_offset_taken_rad_ + bias;
  const double target = std::clamp(
      std::copysign(std::max(std::abs(offset_and_bias) - deadband, 0.0), offset_and_bias), -bound,
      bound);
  double offset_rate = 0.0;
  const double offset = offset_limiter_.apply(target, period_s, offset_rate);
  const double held =
      command_limiter_.apply(command_rad - offset, period_s, rate_radps, acceleration_radps2);
  held_rad_ = held;
  has_held_ = true;
  return held;
}

}  // namespace smoothsteer
