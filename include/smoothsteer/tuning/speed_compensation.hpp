#pragma once
//! \file speed_compensation.hpp
//! The Smith predictor's delay and the feedforward's catch-up over speed, derived from the car
//! instead of set per scenario (docs/vehicle_dynamics.md, "Compensation over speed"):
//!   delay(v)    = t_act + c_tire (K_f + K_r) |v| r(v),   r(v) = min(1, v^2 kappa_d / (mu g)),
//!   catch_up(v) = g_c where r(v) >= r_c, else 0,
//! with t_act the actuator's dead time plus its low-pass group delay, K_f, K_r the single-track
//! slip gradients, kappa_d the design curvature (the path's largest) and mu g the tires' limit.
//! (K_f + K_r) |v| is the time the linear single-track inversion already previews; the share
//! c_tire of it per unit of friction use is the lag the tires add beyond their linear range.
//! c_tire, r_c and g_c are fixed once for every car and road by the held-out tuning of
//! docs/vehicle_dynamics.md (trained on the lane change at 10, 15, 19 m/s and circle_sections,
//! reported on 8, 12, 17, 21 m/s, the road suite and the other cars).

#include <optional>

#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct SpeedCompensation {
  double actuator_group_delay_s = 0.0;  //!< t_act [s]: dead time + group delay of the low-pass
  double slip_gradient_sum_s2pm = 0.0;  //!< K_f + K_r [s^2/m]
  double design_curvature_per_m = 0.0;  //!< kappa_d [1/m]
  double friction_limit_mps2 = 9.81;    //!< mu g [m/s^2]
  static constexpr double tire_lag_share = 0.25;  //!< c_tire
  static constexpr double catch_up_usage = 0.7;   //!< r_c
  static constexpr double catch_up_gain = 0.5;    //!< g_c

  //! r(v): the share of the tires' limit the design curvature asks at |v|, in [0, 1].
  double friction_usage(double speed_mps) const noexcept;
  //! The Smith predictor's delay at |v| [s].
  double delay_s(double speed_mps) const noexcept;
  //! The feedforward's catch-up at |v| (FeedforwardParameters::catch_up).
  double catch_up(double speed_mps) const noexcept;

  //! The first rule broken: every field finite, delays and gradients >= 0, mu g > 0.
  std::optional<Violation> first_violation() const noexcept;
  void validate() const { throw_if_violated(first_violation()); }
};

}  // namespace smoothsteer
