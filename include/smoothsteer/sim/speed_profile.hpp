#pragma once
//! \file speed_profile.hpp
//! Prescribed longitudinal speed: constant, or a constant acceleration from the initial to the
//! final speed starting at start_time_s (paper Sec. IV-A: 2.8 -> 12.5 m/s), or a table of
//! speeds over time, linear in between (curvature_speed_profile.hpp computes one from a path).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "smoothsteer/validation.hpp"

namespace smoothsteer {

//! A knot of a tabulated profile.
struct SpeedKnot {
  double time_s = 0.0;
  double speed_mps = 0.0;
};

struct SpeedProfile {
  double initial_speed_mps = 10.0;  //!< v(0) [m/s]
  double final_speed_mps = 10.0;    //!< speed after the ramp [m/s]
  double acceleration_mps2 = 0.0;   //!< |dv/dt| during the ramp [m/s^2]; 0 = constant speed
  double start_time_s = 0.0;        //!< ramp start [s]
  //! When set (>= 2 knots, times increasing from 0), the profile is this table instead of the
  //! ramp: speed linear in time between knots (constant acceleration), the last speed after the
  //! last knot. initial_speed_mps must equal the first knot's speed.
  std::shared_ptr<const std::vector<SpeedKnot>> knots{};
  //! Tabulated profiles only: the knots' speeds are signed (negative: reversing), in
  //! [-100, 100], for a path with gear changes (simulate() on a PathPlan, path_plan.hpp).
  bool signed_speeds = false;

  //! Duration of the ramp [s] (0 for a constant or tabulated profile).
  double ramp_duration_s() const noexcept {
    if (knots || acceleration_mps2 <= 0.0) return 0.0;
    return std::abs(final_speed_mps - initial_speed_mps) / acceleration_mps2;
  }
  //! Index of the knot interval [knot i, knot i + 1) that holds t, or none before the first
  //! knot and after the last (binary search: noexcept, allocation free).
  static constexpr std::size_t no_interval = static_cast<std::size_t>(-1);
  std::size_t knot_interval(double t) const noexcept {
    if (!knots || knots->size() < 2 || !(t >= knots->front().time_s) ||
        !(t < knots->back().time_s)) {
      return no_interval;
    }
    const auto after =
        std::upper_bound(knots->begin(), knots->end(), t,
                         [](double value, const SpeedKnot& knot) { return value < knot.time_s; });
    return static_cast<std::size_t>(after - knots->begin()) - 1;
  }
  double speed(double t) const noexcept {
    if (knots && !knots->empty()) {
      const std::size_t i = knot_interval(t);
      if (i == no_interval)
        return t < knots->front().time_s ? initial_speed_mps : knots->back().speed_mps;
      const SpeedKnot& a = (*knots)[i];
      const SpeedKnot& b = (*knots)[i + 1];
      return a.speed_mps + (t - a.time_s) / (b.time_s - a.time_s) * (b.speed_mps - a.speed_mps);
    }
    const double ramp = ramp_duration_s();
    if (ramp <= 0.0) return initial_speed_mps;
    const double f = std::clamp((t - start_time_s) / ramp, 0.0, 1.0);
    return initial_speed_mps + f * (final_speed_mps - initial_speed_mps);
  }
  double acceleration(double t) const noexcept {
    if (knots) {
      const std::size_t i = knot_interval(t);
      if (i == no_interval) return 0.0;
      const SpeedKnot& a = (*knots)[i];
      const SpeedKnot& b = (*knots)[i + 1];
      return (b.speed_mps - a.speed_mps) / (b.time_s - a.time_s);
    }
    const double ramp = ramp_duration_s();
    if (ramp <= 0.0 || t < start_time_s || t >= start_time_s + ramp) return 0.0;
    return final_speed_mps > initial_speed_mps ? acceleration_mps2 : -acceleration_mps2;
  }

  //! The first rule broken (validation.hpp).
  std::optional<Violation> first_violation() const noexcept {
    auto bad = [](const char* field, double value, const char* rule,
                  double reference = std::numeric_limits<double>::quiet_NaN()) {
      return Violation{"SpeedProfile", "", field, value, rule, reference};
    };
    if (signed_speeds && !knots) {
      return bad("signed_speeds", 1.0, "needs a tabulated profile (knots)");
    }
    const bool reverse_ok = signed_speeds;
    if (reverse_ok && !(std::abs(initial_speed_mps) <= 100.0)) {
      return bad("initial_speed_mps", initial_speed_mps, "must be in [-100, 100] (signed_speeds)");
    }
    if (!reverse_ok && (!std::isfinite(initial_speed_mps) || initial_speed_mps <= 0.0 ||
                        initial_speed_mps > 100.0)) {
      return bad("initial_speed_mps", initial_speed_mps, "must be in (0, 100] (forward driving)");
    }
    if (reverse_ok && !(std::abs(final_speed_mps) <= 100.0)) {
      return bad("final_speed_mps", final_speed_mps, "must be in [-100, 100] (signed_speeds)");
    }
    if (!reverse_ok &&
        (!std::isfinite(final_speed_mps) || final_speed_mps <= 0.0 || final_speed_mps > 100.0)) {
      return bad("final_speed_mps", final_speed_mps, "must be in (0, 100] (forward driving)");
    }
    if (!std::isfinite(acceleration_mps2) || acceleration_mps2 < 0.0 || acceleration_mps2 > 20.0) {
      return bad("acceleration_mps2", acceleration_mps2, "must be in [0, 20]");
    }
    if (!std::isfinite(start_time_s) || start_time_s < 0.0) {
      return bad("start_time_s", start_time_s, "must be finite and >= 0");
    }
    if (knots) {
      const std::vector<SpeedKnot>& k = *knots;
      if (k.size() < 2) return bad("knots.size()", static_cast<double>(k.size()), "must be >= 2");
      if (k.front().time_s != 0.0) return bad("knots[0].time_s", k.front().time_s, "must be 0");
      if (k.front().speed_mps != initial_speed_mps) {
        return bad("knots[0].speed_mps", k.front().speed_mps, "must equal initial_speed_mps",
                   initial_speed_mps);
      }
      for (std::size_t i = 0; i < k.size(); ++i) {
        if (reverse_ok && !(std::abs(k[i].speed_mps) <= 100.0)) {
          return bad("knots[i].speed_mps", k[i].speed_mps,
                     "must be in [-100, 100] (signed_speeds) at knot i =", static_cast<double>(i));
        }
        if (!reverse_ok &&
            (!std::isfinite(k[i].speed_mps) || k[i].speed_mps <= 0.0 || k[i].speed_mps > 100.0)) {
          return bad("knots[i].speed_mps", k[i].speed_mps,
                     "must be in (0, 100] at knot i =", static_cast<double>(i));
        }
        if (i > 0 && !(k[i].time_s > k[i - 1].time_s && std::isfinite(k[i].time_s))) {
          return bad("knots[i].time_s", k[i].time_s,
                     "must be finite and increase; not at knot i =", static_cast<double>(i));
        }
        if (i > 0 && !(std::abs(k[i].speed_mps - k[i - 1].speed_mps) <=
                       20.0 * (k[i].time_s - k[i - 1].time_s))) {
          return bad("knots[i].speed_mps", k[i].speed_mps,
                     "must change by at most 20 m/s^2 from the previous knot; not at knot i =",
                     static_cast<double>(i));
        }
      }
    }
    return std::nullopt;
  }
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else a message naming the field, value and rule.
  std::string validation_error() const { return describe(first_violation()); }
  void validate() const { throw_if_violated(first_violation()); }
};

}  // namespace smoothsteer
