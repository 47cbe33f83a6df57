#pragma once
//! \file dynamics_inversion.hpp
//! Stage of LeadWheelController::compute_command(): the single-track inversion of the
//! feedforward at the current speed (ControllerParameters::single_track,
//! docs/vehicle_dynamics.md section 3). The chain aims at gain kappa(s + preview_m) +
//! bend_m2 kappa''; off, that is kappa(s) itself.

#include <algorithm>

#include "smoothsteer/controller/controller_parameters.hpp"

namespace smoothsteer {

struct DynamicsInversion {
  double gain = 1.0;       //!< g = 1 + (K_f - K_r) v^2 / L, at least 0.5
  double bend_m2 = 0.0;    //!< the second-order term's weight on kappa'' [m^2]
  double preview_m = 0.0;  //!< how far ahead the feedforward reads the path [m]
  //! (K_f + K_r) v^2 / g: how far the tires' slip lags the chain's curvature (the part of
  //! preview_m that the model asks for) [m].
  double slip_lag_m = 0.0;

  void update(const SingleTrackInversion& inversion, double speed_magnitude,
              double vehicle_wheelbase_m) noexcept {
    const double rear = inversion.enabled ? inversion.rear_slip_gradient_s2pm : 0.0;
    const double front = inversion.enabled ? inversion.front_slip_gradient_s2pm : 0.0;
    const double preview_s = inversion.enabled ? inversion.preview_time_s : 0.0;
    const double v2 = speed_magnitude * speed_magnitude;
    const double lag = (front + rear) * v2;  // L (K_f + K_r) v^2 kappa' / L
    gain = std::max(0.5, 1.0 + (front - rear) * v2 / vehicle_wheelbase_m);
    slip_lag_m = lag / gain;
    preview_m = preview_s * speed_magnitude + slip_lag_m;
    // g kappa(s + d) carries lag^2 / (2 g) kappa''; the model asks K_f K_r v^4 kappa''.
    bend_m2 = inversion.second_order ? front * rear * v2 * v2 - 0.5 * lag * lag / gain : 0.0;
  }
};

}  // namespace smoothsteer
