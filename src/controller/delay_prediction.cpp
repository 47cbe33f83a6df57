#include "smoothsteer/controller/delay_prediction.hpp"

#include "smoothsteer/vehicle/kinematic_single_track.hpp"

namespace smoothsteer {

Pose2 DelayPrediction::predict(Pose2 pose, double delay_s, double speed_mps, double wheelbase_m,
                               double disturbance_curvature) const noexcept {
  if (delay_s <= 0.0 || count_ == 0) return pose;
  // The steering in effect during the next `delay` seconds is what was commanded during the last
  // `delay` seconds. Find the oldest such command, then roll the kinematic model forward through
  // them, oldest first, at the current speed.
  const KinematicSingleTrack model{wheelbase_m};
  std::size_t count = 0;
  double covered = 0.0;
  while (count < count_ && covered < delay_s) covered += issued(count++).period_s;
  double overshoot = covered > delay_s ? covered - delay_s : 0.0;  // part of the oldest one
  for (std::size_t k = count; k-- > 0;) {
    const IssuedCommand& command = issued(k);
    const double duration = command.period_s - overshoot;
    overshoot = 0.0;
    // The car turns by the estimated plant disturbance too: tan(delta) + lambda_veh kappa_d.
    const double steering =
        disturbance_curvature == 0.0
            ? command.steering_rad
            : disturbed_steering_angle(command.steering_rad, wheelbase_m, disturbance_curvature);
    pose = model.step(pose, steering, speed_mps, duration);
  }
  return pose;
}

}  // namespace smoothsteer
