#pragma once
//! \file kinematic_single_track.hpp
//! Kinematic single-track (bicycle) model with the rear axle as reference point:
//!   dx/dt = v cos(psi),  dy/dt = v sin(psi),  dpsi/dt = v tan(delta) / lambda_veh  (eq. kappar)
//! This is the model the controller is designed on.

#include "smoothsteer/math/pose2.hpp"
#include "smoothsteer/math/vec2.hpp"

namespace smoothsteer {

struct KinematicSingleTrack {
  double wheelbase_m = 2.7;  //!< lambda_veh [m]

  //! Exact solution for constant steering angle and speed over dt (a circular arc).
  Pose2 step(const Pose2& pose, double steering_angle_rad, double speed_mps,
             double dt_s) const noexcept;
};

//! The steering angle that turns the rear axle as `steering_angle_rad` plus a curvature
//! disturbance kappa_d does (a banked road, a crosswind, a misaligned rack; eq. kappar):
//! tan(delta_eff) / lambda_veh = tan(delta) / lambda_veh + kappa_d.
double disturbed_steering_angle(double steering_angle_rad, double wheelbase_m,
                                double curvature_disturbance) noexcept;

}  // namespace smoothsteer
