#include "smoothsteer/vehicle/kinematic_single_track.hpp"

#include <cmath>

namespace smoothsteer {

Pose2 KinematicSingleTrack::step(const Pose2& pose, double steering_angle_rad, double speed_mps,
                                 double dt_s) const noexcept {
  const double distance = speed_mps * dt_s;
  const double curvature = std::tan(steering_angle_rad) / wheelbase_m;
  const double turn = curvature * distance;
  // Chord of the arc: length 2 sin(turn/2)/curvature along heading + turn/2; the series form
  // sin(t/2)/(t/2) avoids 0/0 on straight motion.
  const double half = 0.5 * turn;
  const double sinc = std::abs(half) < 1e-6 ? 1.0 - half * half / 6.0 : std::sin(half) / half;
  const double chord = distance * sinc;
  Pose2 next;
  next.position = pose.position + chord * unit_from_heading(pose.heading_rad + half);
  next.heading_rad = pose.heading_rad + turn;
  return next;
}

double disturbed_steering_angle(double steering_angle_rad, double wheelbase_m,
                                double curvature_disturbance) noexcept {
  return std::atan(std::tan(steering_angle_rad) + wheelbase_m * curvature_disturbance);
}

}  // namespace smoothsteer
