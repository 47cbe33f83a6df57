// Example 8: a car's steering system, from its vehicle file to a running loop. The system is
// built once from what is known about the car (vehicles/passenger_car.yaml and its steering
// actuator) and the path: the certified schedule, the Smith predictor, the single-track
// inversion and the side-slip observer. Every period the loop hands it what the car's buses and
// localization give (rear-axle pose, speed, dv/dt, yaw rate, lateral acceleration, the measured
// steering angle) and sends the command to the actuator. The car here is a stand-in: the
// kinematic single-track model behind a first-order steering lag, with a gyro and an
// accelerometer that read its motion.
#include <smoothsteer/io/vehicle_file.hpp>
#include <smoothsteer/tuning/vehicle_steering_system.hpp>
#include <smoothsteer/vehicle/kinematic_single_track.hpp>

#include <cmath>
#include <cstdio>
#include <memory>

int main() {
  using namespace smoothsteer;
  VehicleDescription car;
  car.vehicle = io::load_vehicle_file("vehicles/passenger_car.yaml");
  car.actuator.bandwidth_hz = 10.0;  // third-order low-pass, no dead time
  car.actuator.dead_time_s = 0.0;
  auto path = std::make_shared<const Path>(
      Path::from_waypoints({{0, 0}, {30, 0}, {60, 3.5}, {90, 3.5}, {120, 0}, {160, 0}}));
  SteeringSystemOptions options;
  options.max_speed_mps = 15.0;
  SteeringSystem system = make_steering_system(car, path, options);  // set-up: may throw

  const double wheelbase = car.vehicle.wheelbase_m();
  const KinematicSingleTrack stand_in{wheelbase};
  Pose2 pose{{-10.0, 0.8}, 0.0};
  double road_wheel_angle = 0.0;
  const double speed = 12.0, period = 0.02;
  SteeringSystemOutput out;
  for (int k = 0; k <= 750; ++k) {
    // What the buses and the localization report this period.
    SteeringSystemInput input;
    input.rear_axle_position = pose.position;
    input.heading_rad = pose.heading_rad;
    input.speed_mps = speed;
    input.yaw_rate_radps = speed * std::tan(road_wheel_angle) / wheelbase;
    input.lateral_acceleration_mps2 = speed * input.yaw_rate_radps;
    input.steering_angle_rad = road_wheel_angle;
    input.period_s = period;
    if (system.update(input, out) != Status::ok) {  // real time: a status, never an exception
      std::printf("update failed at t = %.2f s\n", k * period);
      return 1;
    }
    if (k % 100 == 0) {
      std::printf("t %5.2f s  e %+.3f m  delta %+.4f rad  beta_r %+.5f rad  limits %s\n",
                  k * period, out.tracking.lateral_error_m, out.steering_angle_rad,
                  out.side_slip.rear_axle_side_slip_rad,
                  describe_active_limits(out.active_limits).c_str());
    }
    // The actuator follows the command with a 30 ms lag; the car moves on.
    road_wheel_angle += (out.steering_angle_rad - road_wheel_angle) * period / 0.03;
    pose = stand_in.step(pose, road_wheel_angle, speed, period);
  }
  return std::abs(out.tracking.lateral_error_m) < 0.1 ? 0 : 1;
}
