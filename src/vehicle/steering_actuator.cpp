#include "smoothsteer/vehicle/steering_actuator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace smoothsteer {

double ActuatorParameters::pole_radps() const noexcept {
  // (1 + (w / w_p)^2)^3 = 2 at w = 2 pi f_b.
  return 2.0 * std::numbers::pi * bandwidth_hz / std::sqrt(std::cbrt(2.0) - 1.0);
}

std::optional<Violation> ActuatorParameters::first_violation(double step_s) const noexcept {
  auto bad = [](const char* field, double value, const char* rule,
                double reference = std::numeric_limits<double>::quiet_NaN()) {
    return Violation{"ActuatorParameters", "", field, value, rule, reference};
  };
  if (!std::isfinite(step_s) || step_s <= 0.0) {
    return bad("integration step", step_s, "must be finite and > 0");
  }
  if (!ideal) {
    if (!std::isfinite(bandwidth_hz) || bandwidth_hz <= 0.0) {
      return bad("bandwidth_hz", bandwidth_hz, "must be finite and > 0");
    }
    if (pole_radps() * step_s > 0.5) {
      return bad("bandwidth_hz", bandwidth_hz,
                 "is too high for the plant sub-step (needs pole * step <= 0.5 for accurate RK4); "
                 "sub-step [s] =",
                 step_s);
    }
    if (!(max_angle_rad > 0.0)) return bad("max_angle_rad", max_angle_rad, "must be > 0");
    if (!(max_rate_radps > 0.0)) return bad("max_rate_radps", max_rate_radps, "must be > 0");
  }
  if (!std::isfinite(dead_time_s) || dead_time_s < 0.0 || dead_time_s > 10.0) {
    return bad("dead_time_s", dead_time_s, "must be in [0, 10]");
  }
  const double steps = dead_time_s / step_s;
  if (std::abs(steps - std::round(steps)) > 1e-6) {
    return bad(
        "dead_time_s", dead_time_s,
        "must be a whole multiple of the plant sub-step (the delay is exact); sub-step [s] =",
        step_s);
  }
  return std::nullopt;
}

std::string ActuatorParameters::validation_error(double step_s) const {
  return describe(first_violation(step_s));
}

void ActuatorParameters::validate(double step_s) const {
  throw_if_violated(first_violation(step_s));
}

SteeringActuator::SteeringActuator(const ActuatorParameters& parameters, double step_s)
    : parameters_(parameters), step_s_(step_s), pole_(parameters.pole_radps()) {
  parameters_.validate(step_s);
  delay_line_.assign(static_cast<std::size_t>(std::lround(parameters_.dead_time_s / step_s)), 0.0);
}

void SteeringActuator::reset(double angle_rad) noexcept {
  state_ = {angle_rad, angle_rad, angle_rad};
  std::fill(delay_line_.begin(), delay_line_.end(), angle_rad);
  delay_head_ = 0;
}

double SteeringActuator::push_command(double command_rad) noexcept {
  if (delay_line_.empty()) return command_rad;
  const double delayed = delay_line_[delay_head_];
  delay_line_[delay_head_] = command_rad;
  delay_head_ = (delay_head_ + 1) % delay_line_.size();
  return delayed;
}

SteeringActuator::State SteeringActuator::derivative(const State& x, double u) const noexcept {
  if (parameters_.ideal) return {0.0, 0.0, 0.0};
  double rate =
      std::clamp(pole_ * (x[1] - x[2]), -parameters_.max_rate_radps, parameters_.max_rate_radps);
  if ((x[2] >= parameters_.max_angle_rad && rate > 0.0) ||
      (x[2] <= -parameters_.max_angle_rad && rate < 0.0)) {
    rate = 0.0;
  }
  return {pole_ * (u - x[0]), pole_ * (x[0] - x[1]), rate};
}

void SteeringActuator::clamp(State& x) const noexcept {
  if (parameters_.ideal) return;
  x[2] = std::clamp(x[2], -parameters_.max_angle_rad, parameters_.max_angle_rad);
}

double SteeringActuator::rate(double input_rad) const noexcept {
  return derivative(state_, input_rad)[2];
}

double SteeringActuator::acceleration(double input_rad) const noexcept {
  if (parameters_.ideal) return 0.0;
  const State d = derivative(state_, input_rad);
  const double unsaturated = pole_ * (state_[1] - state_[2]);
  if (std::abs(unsaturated) >= parameters_.max_rate_radps || d[2] == 0.0) return 0.0;
  return pole_ * (d[1] - d[2]);
}

void SteeringActuator::advance(double u) noexcept {
  if (parameters_.ideal) {
    state_ = {u, u, u};
    return;
  }
  const double h = step_s_;
  const State& x = state_;
  auto add = [](const State& a, const State& b, double k) {
    return State{a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]};
  };
  const State k1 = derivative(x, u);
  const State k2 = derivative(add(x, k1, 0.5 * h), u);
  const State k3 = derivative(add(x, k2, 0.5 * h), u);
  const State k4 = derivative(add(x, k3, h), u);
  for (std::size_t i = 0; i < 3; ++i) {
    state_[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  }
  clamp(state_);
}

}  // namespace smoothsteer
