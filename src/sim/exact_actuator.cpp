// The actuator's exact solution over a control period (src/sim/exact_actuator.hpp).

#include "exact_actuator.hpp"

#include <cmath>

#include "exp_polynomial.hpp"

namespace smoothsteer::detail {
namespace {

//! A mode ends when its margin falls below -hysteresis [rad], not at 0: a state placed on the
//! boundary by the previous mode's end then starts inside its new mode (no chattering between
//! two modes through rounding). The switching instant moves by hysteresis / |margin rate|,
//! about 1e-14 s here.
constexpr double hysteresis_rad = 1e-12;

struct Candidate {
  ExpPolynomial margin;
  ActuatorMode next;
};

}  // namespace

ActuatorMode classify_actuator_mode(const SteeringActuator::State& x, double pole, double max_rate,
                                    double max_angle) noexcept {
  const double rate = pole * (x[1] - x[2]);
  if (x[2] >= max_angle && rate > 0.0) return ActuatorMode::angle_up;
  if (x[2] <= -max_angle && rate < 0.0) return ActuatorMode::angle_down;
  if (rate > max_rate) return ActuatorMode::rate_up;
  if (rate < -max_rate) return ActuatorMode::rate_down;
  return ActuatorMode::linear;
}

SteeringActuator::State ExactActuatorPeriod::at(const Segment& s, double tau) const noexcept {
  const double q = pole_ * tau, e = std::exp(-q);
  const std::array<double, 3>& d = s.deviation;
  SteeringActuator::State x{s.input + d[0] * e, s.input + (d[1] + d[0] * q) * e, 0.0};
  switch (s.mode) {
    case ActuatorMode::linear:
      x[2] = s.input + (d[2] + d[1] * q + 0.5 * d[0] * q * q) * e;
      break;
    case ActuatorMode::rate_up:
      x[2] = s.output_start + max_rate_ * tau;
      break;
    case ActuatorMode::rate_down:
      x[2] = s.output_start - max_rate_ * tau;
      break;
    case ActuatorMode::angle_up:
      x[2] = max_angle_;
      break;
    case ActuatorMode::angle_down:
      x[2] = -max_angle_;
      break;
  }
  return x;
}

double ExactActuatorPeriod::mode_end(const Segment& s, double length,
                                     ActuatorMode& next) const noexcept {
  // Margins in rad as functions of q = p tau (positive while the mode holds).
  const std::array<double, 3>& d = s.deviation;
  const double u = s.input, r = max_rate_ / pole_, a = max_angle_;
  std::array<Candidate, 4> candidates{};
  int count = 0;
  switch (s.mode) {
    case ActuatorMode::linear: {
      // x1 - x2 = ((e1 - e2) + (e0 - e1) q - e0 q^2 / 2) e^{-q}; x2 - u = (e2 + e1 q + e0 q^2/2)
      // e^{-q}
      const double l0 = d[1] - d[2], l1 = d[0] - d[1], l2 = -0.5 * d[0];
      candidates[0] = {{-l0, -l1, -l2, r, 0.0}, ActuatorMode::rate_up};  // r - (x1 - x2)
      candidates[1] = {{l0, l1, l2, r, 0.0}, ActuatorMode::rate_down};   // r + (x1 - x2)
      candidates[2] = {{-d[2], -d[1], -0.5 * d[0], a - u, 0.0}, ActuatorMode::angle_up};
      candidates[3] = {{d[2], d[1], 0.5 * d[0], a + u, 0.0}, ActuatorMode::angle_down};
      count = 4;
      break;
    }
    case ActuatorMode::rate_up:
    case ActuatorMode::rate_down: {
      // s (x1 - x2) - r with x2 = x2(start) + s r q, and A - s x2.
      const double sign = s.mode == ActuatorMode::rate_up ? 1.0 : -1.0;
      candidates[0] = {{sign * d[1], sign * d[0], 0.0, sign * (u - s.output_start) - r, -r},
                       ActuatorMode::linear};
      candidates[1] = {{0.0, 0.0, 0.0, a - sign * s.output_start, -r},
                       sign > 0.0 ? ActuatorMode::angle_up : ActuatorMode::angle_down};
      count = 2;
      break;
    }
    case ActuatorMode::angle_up:
    case ActuatorMode::angle_down: {
      // s x1 - A: the output leaves the limit once x1 has come back to it.
      const double sign = s.mode == ActuatorMode::angle_up ? 1.0 : -1.0;
      candidates[0] = {{sign * d[1], sign * d[0], 0.0, sign * u - a, 0.0}, ActuatorMode::linear};
      count = 1;
      break;
    }
  }
  const double end_q = pole_ * length;
  double first = end_q + 1.0;
  for (int i = 0; i < count; ++i) {
    Candidate& candidate = candidates[static_cast<std::size_t>(i)];
    candidate.margin.alpha += hysteresis_rad;
    const double exit = first_exit(candidate.margin, 0.0, end_q);
    if (exit < first) {
      first = exit;
      next = candidate.next;
    }
  }
  return first <= end_q ? first / pole_ : length + 1.0;
}

bool ExactActuatorPeriod::solve(const ActuatorParameters& parameters,
                                const SteeringActuator::State& start, const double* inputs,
                                int substeps, double substep_s) noexcept {
  pole_ = parameters.pole_radps();
  max_rate_ = parameters.max_rate_radps;
  max_angle_ = parameters.max_angle_rad;
  count_ = 0;
  SteeringActuator::State x = start;
  ActuatorMode mode = classify_actuator_mode(x, pole_, max_rate_, max_angle_);
  for (int j = 0; j < substeps;) {
    int k = j + 1;
    while (k < substeps && inputs[k] == inputs[j]) ++k;
    const double u = inputs[j];
    const double end = k * substep_s;
    double t = j * substep_s;
    // A mode can follow another only a few times per stretch; more means chattering.
    for (int transitions = 0;; ++transitions) {
      if (count_ == max_segments || transitions > 8) return false;
      Segment& segment = segments_[index(count_++)];
      segment = {t, mode, u, {x[0] - u, x[1] - u, x[2] - u}, x[2]};
      ActuatorMode next = mode;
      const double local = mode_end(segment, end - t, next);
      if (local > end - t) {
        x = at(segment, end - t);
        break;
      }
      x = at(segment, local);
      if (next == ActuatorMode::angle_up) x[2] = max_angle_;
      if (next == ActuatorMode::angle_down) x[2] = -max_angle_;
      if (local == 0.0) --count_;  // the mode was left as soon as it began
      t += local;
      mode = next;
    }
    j = k;
  }
  return true;
}

SteeringActuator::State ExactActuatorPeriod::state(double tau) const noexcept {
  int i = count_ - 1;
  while (i > 0 && tau < segments_[index(i)].start_s) --i;
  const Segment& segment = segments_[index(i)];
  return at(segment, tau - segment.start_s);
}

}  // namespace smoothsteer::detail
