#pragma once
//! Reverse forms of Stanley and pure pursuit (for paths with cusps, path_plan.hpp). Reversing,
//! the rear axle leads: it moves along the travel heading phi = psi + pi, which turns at
//! d phi / dt = -|v| tan(delta) / lambda_veh. Both laws act on the rear axle against the path
//! (which runs in the direction of travel) and flip the sign of the steering angle.

#include <cmath>

#include "smoothsteer/baselines/geometric_controllers.hpp"
#include "smoothsteer/math/angles.hpp"

namespace smoothsteer {

//! Stanley at the rear axle: delta = (phi - theta_path) + atan(k e / (v_soft + |v|)). Linearised,
//! e'' = -(|v| / lambda) e' - (|v| k / lambda) e: stable for every k > 0.
inline double reverse_stanley_steering(const PathProjection& rear, const ControllerInput& input,
                                       const StanleyParameters& parameters) noexcept {
  const double heading_error = wrap_angle(input.heading_rad + pi - rear.heading_rad);
  return heading_error + std::atan(parameters.gain_per_s * rear.lateral_error_m /
                                   (parameters.softening_mps + std::abs(input.speed_mps)));
}

//! Pure pursuit in the travel frame: the arc from the rear axle along phi through the target
//! (look-ahead ahead in the direction of travel) has curvature 2 sin(alpha) / d, and
//! tan(delta) = -lambda * that curvature.
inline double reverse_pure_pursuit_steering(Vec2 to_target, double distance,
                                            const ControllerInput& input,
                                            const PurePursuitParameters& parameters) noexcept {
  const double bearing = wrap_angle(std::atan2(to_target.y, to_target.x) - input.heading_rad - pi);
  return -std::atan(2.0 * parameters.wheelbase_m * std::sin(bearing) / distance);
}

}  // namespace smoothsteer
