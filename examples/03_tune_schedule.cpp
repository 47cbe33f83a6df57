// Example 3: tune for your car and drive the schedule. The car's steering limits (vehicle YAML)
// and the path's curvature give certified parameters over speed (docs/tuning.md); the scheduled
// controller then drives a 40 m circle while the car speeds up from 5 to 15 m/s.
#include <smoothsteer/io/schedule_files.hpp>
#include <smoothsteer/smoothsteer.hpp>
#include <smoothsteer/tuning/gain_schedule.hpp>
#include <smoothsteer/tuning/path_demand.hpp>
#include <smoothsteer/tuning/scheduled_controller.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

int main() {
  using namespace smoothsteer;
  const VehicleLimits car = io::load_vehicle_limits("vehicles/passenger_car.yaml");
  auto path = std::make_shared<const Path>(Path::circle({0.0, 0.0}, 40.0));
  TuningOptions options;  // the feedforward route
  options.path_curvature_bound = path_demand(*path).max_curvature;
  options.max_longitudinal_acceleration_mps2 = 0.5;
  GainSchedule schedule = compute_feedforward_schedule(car, options, speed_grid(1.0, 15.0, 1.0));
  ScheduledController controller(schedule, path);

  const KinematicSingleTrack model{car.wheelbase_m};
  Pose2 pose{{40.0, -1.0}, pi / 2};  // 1 m outside the circle, along it
  ControllerOutput out;
  double max_rate = 0.0, max_acceleration = 0.0, max_error_late = 0.0;
  for (int k = 0; k < 2500; ++k) {                              // 50 s at 50 Hz
    const double speed = std::min(15.0, 5.0 + 0.5 * k * 0.02);  // 0.5 m/s^2 ramp
    const double acceleration = speed < 15.0 ? 0.5 : 0.0;
    if (controller.update({pose.position, pose.heading_rad, speed, acceleration, 0.02}, out) !=
        Status::ok)
      return 1;
    pose = model.step(pose, out.steering_angle_rad, speed, 0.02);
    max_rate = std::max(max_rate, std::abs(out.steering_rate_radps));
    max_acceleration = std::max(max_acceleration, std::abs(out.steering_acceleration_radps2));
    if (k > 1500)
      max_error_late = std::max(max_error_late, std::abs(out.diagnostics.lateral_error_m));
  }
  std::printf("schedule: %zu speeds up to %.0f m/s, kbar_l %.4f .. %.4f 1/m\n",
              schedule.entries().size(), schedule.max_speed_mps(),
              schedule.entries().back().lead_curvature_bound,
              schedule.entries().front().lead_curvature_bound);
  std::printf(
      "max |rate| %.3f rad/s (car %.1f), max |acc| %.2f rad/s^2 (car %.1f), "
      "|e| at 15 m/s <= %.3f m\n",
      max_rate, car.max_steering_rate_radps, max_acceleration, car.max_steering_acceleration_radps2,
      max_error_late);
  return max_rate <= car.max_steering_rate_radps ? 0 : 1;
}
