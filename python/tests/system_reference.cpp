// Reference for tests/test_steering_system.py: a closed loop of the car's SteeringSystem in C++.
// The car is the vehicle file's with the default actuator, the system make_steering_system()'s
// on a fixed S-curve (options: max_speed_mps = 12). The plant is the kinematic single-track
// model behind a first-order steering lag; the sensors report its yaw rate and lateral
// acceleration plus the noise read from stdin. One stdin line per period:
//   speed acceleration yaw_noise lateral_noise measured
// (measured 1: the lagged angle is the measured steering angle; 0: none). Prints per period
//   status delta rate acceleration beta_r e kappa_n r_observer active_limits
// with 17 significant digits, so that Python's loop can be compared exactly.
//
// usage: python_system_reference VEHICLE_YAML

#include <cmath>
#include <cstdio>
#include <memory>

#include "smoothsteer/io/vehicle_file.hpp"
#include "smoothsteer/tuning/vehicle_steering_system.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"

int main(int argc, char** argv) {
  using namespace smoothsteer;
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s VEHICLE_YAML\n", argv[0]);
    return 2;
  }
  VehicleDescription car;
  car.vehicle = io::load_vehicle_file(argv[1]);
  auto path = std::make_shared<const Path>(
      Path::from_waypoints({{0, 0}, {30, 0}, {60, 8}, {90, 8}, {120, 0}, {150, 0}}));
  SteeringSystemOptions options;
  options.max_speed_mps = 12.0;
  SteeringSystem system = make_steering_system(car, path, options);
  const double wheelbase = car.vehicle.wheelbase_m();
  const KinematicSingleTrack model{wheelbase};
  Pose2 pose{{-5.0, 1.0}, 0.05};
  double actual = 0.0;  // the road-wheel angle behind the lag
  double speed = 0.0, acceleration = 0.0, yaw_noise = 0.0, lateral_noise = 0.0;
  int measured = 0;
  while (std::scanf("%lf %lf %lf %lf %d", &speed, &acceleration, &yaw_noise, &lateral_noise,
                    &measured) == 5) {
    const double yaw_rate = speed * std::tan(actual) / wheelbase;
    SteeringSystemInput input;
    input.rear_axle_position = pose.position;
    input.heading_rad = pose.heading_rad;
    input.speed_mps = speed;
    input.acceleration_mps2 = acceleration;
    input.yaw_rate_radps = yaw_rate + yaw_noise;
    input.lateral_acceleration_mps2 = speed * yaw_rate + lateral_noise;
    input.period_s = 0.02;
    if (measured) input.steering_angle_rad = actual;
    SteeringSystemOutput out;
    const Status status = system.update(input, out);
    std::printf("%s %.17g %.17g %.17g %.17g %.17g %.17g %.17g %u\n", to_string(status),
                out.steering_angle_rad, out.steering_rate_radps, out.steering_acceleration_radps2,
                out.side_slip.rear_axle_side_slip_rad, out.tracking.lateral_error_m,
                out.tracking.lead_curvature, out.side_slip.yaw_rate_radps, out.active_limits);
    if (status != Status::ok) break;
    actual = actual + 0.3 * (out.steering_angle_rad - actual);
    pose = model.step(pose, actual, speed, 0.02);
  }
  return 0;
}
