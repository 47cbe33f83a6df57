#pragma once
//! \file dynamics_inversion.hpp
//! Stage of LeadWheelController::compute_command(): the single-track inversion of the
//! feedforward at the current speed (ControllerParameters::single_track,
//! docs/vehicle_dynamics.md section 3). The chain aims at gain kappa(s + preview_m) +
//! bend_m2 kappa''; off, that is kappa(s) itself.

#include <algorithm>
#include <cmath>

#include "smoothsteer/controller/controller_parameters.hpp"
#include "smoothsteer/math/angles.hpp"

namespace smoothsteer {

struct DynamicsInversion {
  //! g = 1 + (K_f - K_r) v^2 / L + 2 K_r d|v|/dt, at least 0.5
  double gain = 1.0;
  double bend_m2 = 0.0;    //!< the second-order term's weight on kappa'' [m^2]
  double preview_m = 0.0;  //!< how far ahead the feedforward reads the path [m]
  //! (K_f + K_r) v^2 / g: how far the tires' slip lags the chain's curvature (the part of
  //! preview_m that the model asks for) [m].
  double slip_lag_m = 0.0;
  //! The front tire's slip angle per unit of course curvature, K_f v^2, and the rear axle's,
  //! K_r v^2 [m] (driving forwards; 0 in reverse and with the inversion off).
  double front_slip_m = 0.0;
  double rear_slip_m = 0.0;

  //! The least share of its static load an axle is taken to keep under longitudinal
  //! acceleration: the slip gradient grows at most 4 times (a wheel lifting off is beyond the
  //! linear model anyway).
  static constexpr double min_load_share = 0.25;

  //! speed_mps: the signed speed v; acceleration_mps2: the measured dv/dt
  //! (ControllerInput::acceleration_mps2).
  //! slip_gradient_scale: ControllerInput::slip_gradient_scale.
  void update(const SingleTrackInversion& inversion, double speed_mps, double vehicle_wheelbase_m,
              double acceleration_mps2, double slip_gradient_scale = 1.0) noexcept {
    const double speed_magnitude = std::abs(speed_mps);
    // An axle's slip gradient is inversely proportional to its load (cornering stiffness
    // B C mu Fz, the Magic Formula's slope at zero slip).
    const double front_load =
        std::max(min_load_share, 1.0 - acceleration_mps2 * inversion.front_load_transfer_s2pm);
    const double rear_load =
        std::max(min_load_share, 1.0 + acceleration_mps2 * inversion.rear_load_transfer_s2pm);
    const double scale = inversion.enabled ? slip_gradient_scale : 0.0;
    const double rear = scale * inversion.rear_slip_gradient_s2pm / rear_load;
    const double front = scale * inversion.front_slip_gradient_s2pm / front_load;
    const double preview_s = inversion.enabled ? inversion.preview_time_s : 0.0;
    const double v2 = speed_magnitude * speed_magnitude;
    const double lag = (front + rear) * v2;  // L (K_f + K_r) v^2 kappa' / L
    // As the speed changes, so does the rear axle's slip -K_r v^2 kappa on a given curvature:
    // the heading turns by d(K_r v^2 kappa)/dt more than the course, which adds 2 K_r a kappa to
    // the stationary steering per wheelbase, a = d|v|/dt (docs/vehicle_dynamics.md, section 3).
    const double speed_change = sign(speed_mps) * acceleration_mps2;
    gain =
        std::max(0.5, 1.0 + (front - rear) * v2 / vehicle_wheelbase_m + 2.0 * rear * speed_change);
    slip_lag_m = lag / gain;
    front_slip_m = speed_mps > 0.0 ? front * v2 : 0.0;
    rear_slip_m = speed_mps > 0.0 ? rear * v2 : 0.0;
    preview_m = preview_s * speed_magnitude + slip_lag_m;
    // g kappa(s + d) carries lag^2 / (2 g) kappa''; the model asks K_f K_r v^4 kappa''.
    bend_m2 = inversion.second_order ? front * rear * v2 * v2 - 0.5 * lag * lag / gain : 0.0;
  }

  //! Steering beyond which the steady geometry is not applied [rad]: the chain's own angle
  //! bound is far below it.
  static constexpr double max_exact_steering_rad = 1.2;

  //! The gain for a course curvature `curvature` [1/m] on a car of wheelbase L: `gain` with the
  //! stationary steering's small-angle part replaced by the single-track model's exact geometry
  //! (docs/vehicle_dynamics.md, section 3, "Large steering angles"). The chain steers
  //! atan(L kappa_chain); the car needs
  //! delta = alpha_f / cos(delta) + atan2(L kappa - sin beta_r, cos beta_r)
  //! with the slips alpha_f = K_f v^2 kappa, beta_r = K_r v^2 kappa, so that
  //! kappa_chain = tan(delta) / L, where the linear inversion gives kappa + (alpha_f - beta_r) / L.
  //! `gain` itself without slips (the inversion off, reversing) or at kappa = 0. Five
  //! transcendental calls, no allocation.
  double gain_at(double curvature, double wheelbase_m) const noexcept {
    if ((front_slip_m == 0.0 && rear_slip_m == 0.0) || curvature == 0.0) return gain;
    const double front_slip = front_slip_m * curvature;
    const double rear_slip = rear_slip_m * curvature;
    const double front_course =
        std::atan2(wheelbase_m * curvature - std::sin(rear_slip), std::cos(rear_slip));
    // The front tire pushes the car sideways by cos(delta) of its force: it slips 1 / cos(delta)
    // more (one fixed-point step from the small-angle steering; the rest is O(alpha_f^2 delta^2)).
    const double steering = front_slip / std::cos(front_slip + front_course) + front_course;
    if (!(std::abs(steering) < max_exact_steering_rad)) return gain;
    const double exact = std::tan(steering) / wheelbase_m;
    const double linear = curvature + (front_slip - rear_slip) / wheelbase_m;
    return gain + (exact - linear) / curvature;
  }
};

}  // namespace smoothsteer
