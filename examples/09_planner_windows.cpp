// Example 9: the car's steering system driven as a driving stack drives it. It is built once
// from the car alone (no path at set-up); a planner sends a window of waypoints every 0.1 s
// (5 m behind the car to 100 m ahead, 1 m apart, here with 2 cm of Gaussian jitter, as planners
// and recordings deliver them), and set_waypoints() fits each window at the jitter it reads from
// the windows, pooled over them, before it replaces the path. The car is the kinematic
// single-track model behind a first-order steering lag; it has no tire slip, which the system,
// built for the car's tires, partly steers for: with clean windows the S costs 0.08 m, with 2 cm
// of jitter 0.11.
#include <smoothsteer/io/vehicle_file.hpp>
#include <smoothsteer/path/path_builder.hpp>
#include <smoothsteer/tuning/vehicle_steering_system.hpp>
#include <smoothsteer/vehicle/kinematic_single_track.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

int main() {
  using namespace smoothsteer;
  VehicleDescription car;
  car.vehicle = io::load_vehicle_file("vehicles/passenger_car.yaml");
  car.actuator.bandwidth_hz = 10.0;
  SteeringSystemOptions options;
  options.max_speed_mps = 20.0;
  SteeringSystem system = make_steering_system(car, options);  // the car alone

  // The road the planner knows (the system never sees it): an S of two 100 m arcs.
  const Path road = PathBuilder({0.0, 0.0}, 0.0)
                        .line(50.0)
                        .clothoid(30.0, 0.01)
                        .arc(100.0, 0.6)
                        .clothoid(40.0, -0.01)
                        .arc(100.0, -0.6)
                        .clothoid(30.0, 0.0)
                        .line(250.0)
                        .build();
  std::mt19937_64 engine(1);
  std::normal_distribution<double> jitter(0.0, 0.02);

  const double wheelbase = car.vehicle.wheelbase_m();
  const KinematicSingleTrack stand_in{wheelbase};
  Pose2 pose{{0.0, 0.5}, 0.0};
  double road_wheel_angle = 0.0, worst = 0.0;
  const double speed = 15.0, period = 0.02;
  SteeringSystemOutput out;
  for (int k = 0; k <= 1000; ++k) {
    const PathProjection on_road = road.project(pose.position);
    if (k % 5 == 0) {  // the planner's window, every 0.1 s
      std::vector<Vec2> window;
      const double end = std::min(road.length(), on_road.arc_length_m + 100.0);
      for (double s = std::max(0.0, on_road.arc_length_m - 5.0); s <= end; s += 1.0) {
        window.push_back(road.evaluate(s).position + Vec2{jitter(engine), jitter(engine)});
      }
      if (system.set_waypoints(window) != Status::ok) return 1;  // set-up time: may throw
    }
    SteeringSystemInput input;
    input.rear_axle_position = pose.position;
    input.heading_rad = pose.heading_rad;
    input.speed_mps = speed;
    input.yaw_rate_radps = speed * std::tan(road_wheel_angle) / wheelbase;
    input.lateral_acceleration_mps2 = speed * input.yaw_rate_radps;
    input.steering_angle_rad = road_wheel_angle;
    input.period_s = period;
    if (system.update(input, out) != Status::ok) return 1;
    if (k >= 150) worst = std::max(worst, std::abs(on_road.lateral_error_m));
    if (k % 200 == 0) {
      std::printf("t %5.2f s  e %+.3f m (to the road)  delta %+.4f rad  jitter read %.4f m\n",
                  k * period, on_road.lateral_error_m, out.steering_angle_rad,
                  system.waypoint_conditioner().jitter_m());
    }
    road_wheel_angle += (out.steering_angle_rad - road_wheel_angle) * period / 0.03;
    pose = stand_in.step(pose, road_wheel_angle, speed, period);
  }
  const double read = system.waypoint_conditioner().jitter_m();
  std::printf("max |e| to the road after 3 s: %.3f m; the planner's jitter read as %.4f m\n", worst,
              read);
  return worst < 0.15 && std::abs(read / 0.02 - 1.0) < 0.25 ? 0 : 1;
}
