#pragma once
//! The command as the zero-order hold applies it (docs/metrics.md), for the tests that check it
//! at every control period: its rate r_k = (u_k - u_{k-1}) / h_k and acceleration
//! (r_k - r_{k-1}) / h_k, differenced at the period, against an angle, a rate and an
//! acceleration limit. A limit may change from sample to sample (a certificate that scales
//! with the speed); +inf leaves it unchecked.

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace smoothsteer::testing {

struct HeldLimits {
  double angle_rad = std::numeric_limits<double>::infinity();
  double rate_radps = std::numeric_limits<double>::infinity();
  double acceleration_radps2 = std::numeric_limits<double>::infinity();
};

//! How far past a limit a sample may go: `relative` of the limit, plus an absolute slack per
//! derivative (round-off of differencing at short periods).
struct HeldTolerance {
  double relative = 1e-9;
  double rate_radps = 0.0;
  double acceleration_radps2 = 0.0;
};

class HeldCommand {
 public:
  //! No command yet: the first sample has neither rate nor acceleration.
  HeldCommand() = default;
  //! Continues a command `command_rad` that was moving at `rate_radps` (a limiter reset to both).
  HeldCommand(double command_rad, double rate_radps)
      : command_(command_rad), rate_(rate_radps), samples_(2) {}

  //! Starts again from `command_rad` (a reset to a measured angle): the next sample has a rate,
  //! the one after it an acceleration.
  void restart(double command_rad) {
    command_ = command_rad;
    rate_ = 0.0;
    samples_ = 1;
  }

  //! The next command, held over the period `period_s` that ends with it.
  void push(double command_rad, double period_s) {
    const double rate = (command_rad - command_) / period_s;
    if (samples_ >= 1) {
      if (samples_ >= 2) acceleration_ = (rate - rate_) / period_s;
      rate_ = rate;
    }
    command_ = command_rad;
    ++samples_;
    if (has_rate()) max_abs_rate_ = std::max(max_abs_rate_, std::abs(rate_));
    if (has_acceleration()) {
      max_abs_acceleration_ = std::max(max_abs_acceleration_, std::abs(acceleration_));
    }
  }

  bool has_rate() const { return samples_ >= 2; }
  bool has_acceleration() const { return samples_ >= 3; }
  double command() const { return command_; }
  double rate() const { return rate_; }                  //!< of the last sample, if has_rate()
  double acceleration() const { return acceleration_; }  //!< if has_acceleration()
  double max_abs_rate() const { return max_abs_rate_; }
  double max_abs_acceleration() const { return max_abs_acceleration_; }

  //! "" when the last sample keeps `limits` within `tolerance`, else each limit it broke, with
  //! the value and the limit.
  std::string violation(const HeldLimits& limits, const HeldTolerance& tolerance = {}) const {
    std::ostringstream failure;
    failure.precision(17);
    const auto beyond = [&](const char* what, double value, double limit, double slack) {
      if (!(std::abs(value) <= limit * (1.0 + tolerance.relative) + slack)) {
        failure << (failure.tellp() > 0 ? "; " : "") << "held " << what << " " << value
                << " beyond " << limit;
      }
    };
    beyond("angle", command_, limits.angle_rad, 0.0);
    if (has_rate()) beyond("rate", rate_, limits.rate_radps, tolerance.rate_radps);
    if (has_acceleration()) {
      beyond("acceleration", acceleration_, limits.acceleration_radps2,
             tolerance.acceleration_radps2);
    }
    return failure.str();
  }

 private:
  double command_ = 0.0;
  double rate_ = 0.0;
  double acceleration_ = 0.0;
  int samples_ = 0;
  double max_abs_rate_ = 0.0;
  double max_abs_acceleration_ = 0.0;
};

}  // namespace smoothsteer::testing
