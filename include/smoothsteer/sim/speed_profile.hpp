#pragma once
//! \file speed_profile.hpp
//! Prescribed longitudinal speed: constant, or a constant acceleration from the initial to the
//! final speed starting at start_time_s (paper Sec. IV-A: 2.8 -> 12.5 m/s).

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct SpeedProfile {
  double initial_speed_mps = 10.0;  //!< v(0) [m/s]
  double final_speed_mps = 10.0;    //!< speed after the ramp [m/s]
  double acceleration_mps2 = 0.0;   //!< |dv/dt| during the ramp [m/s^2]; 0 = constant speed
  double start_time_s = 0.0;        //!< ramp start [s]

  //! Duration of the ramp [s] (0 for a constant profile).
  double ramp_duration_s() const noexcept {
    if (acceleration_mps2 <= 0.0) return 0.0;
    return std::abs(final_speed_mps - initial_speed_mps) / acceleration_mps2;
  }
  double speed(double t) const noexcept {
    const double ramp = ramp_duration_s();
    if (ramp <= 0.0) return initial_speed_mps;
    const double f = std::clamp((t - start_time_s) / ramp, 0.0, 1.0);
    return initial_speed_mps + f * (final_speed_mps - initial_speed_mps);
  }
  double acceleration(double t) const noexcept {
    const double ramp = ramp_duration_s();
    if (ramp <= 0.0 || t < start_time_s || t >= start_time_s + ramp) return 0.0;
    return final_speed_mps > initial_speed_mps ? acceleration_mps2 : -acceleration_mps2;
  }

  //! The first rule broken (validation.hpp).
  std::optional<Violation> first_violation() const noexcept {
    auto bad = [](const char* field, double value, const char* rule) {
      return Violation{"SpeedProfile", "", field, value, rule};
    };
    if (!std::isfinite(initial_speed_mps) || initial_speed_mps <= 0.0 ||
        initial_speed_mps > 100.0) {
      return bad("initial_speed_mps", initial_speed_mps, "must be in (0, 100] (forward driving)");
    }
    if (!std::isfinite(final_speed_mps) || final_speed_mps <= 0.0 || final_speed_mps > 100.0) {
      return bad("final_speed_mps", final_speed_mps, "must be in (0, 100] (forward driving)");
    }
    if (!std::isfinite(acceleration_mps2) || acceleration_mps2 < 0.0 || acceleration_mps2 > 20.0) {
      return bad("acceleration_mps2", acceleration_mps2, "must be in [0, 20]");
    }
    if (!std::isfinite(start_time_s) || start_time_s < 0.0) {
      return bad("start_time_s", start_time_s, "must be finite and >= 0");
    }
    return std::nullopt;
  }
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else a message naming the field, value and rule.
  std::string validation_error() const { return describe(first_violation()); }
  void validate() const { throw_if_violated(first_violation()); }
};

}  // namespace smoothsteer
