// Example 2: follow a C2 spline through the waypoints of a CSV file ("x,y" per line, metres),
// with the kinematic car at 8 m/s. Usage: example_02_follow_waypoints [WAYPOINTS.csv]
#include <smoothsteer/io/waypoint_csv.hpp>
#include <smoothsteer/smoothsteer.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

int main(int argc, char** argv) {
  using namespace smoothsteer;
  const std::string file = argc > 1 ? argv[1] : "scenarios/waypoints/s_curve.csv";
  const auto waypoints = io::read_waypoint_csv(file);  // ConfigError names file and line
  auto path = std::make_shared<const Path>(Path::from_waypoints(waypoints));
  LeadWheelController controller(ControllerParameters{}, path);
  const KinematicSingleTrack car{2.7};
  Pose2 pose{{0.0, -2.0}, 0.3};  // 2 m right of the first waypoint
  ControllerOutput out;
  double worst_after_5s = 0.0;
  for (int k = 0; out.diagnostics.path_arc_length_m < path->length(); ++k) {  // 50 Hz
    if (controller.update({pose.position, pose.heading_rad, 8.0, 0.0, 0.02}, out) != Status::ok)
      return 1;
    pose = car.step(pose, out.steering_angle_rad, 8.0, 0.02);
    if (k * 0.02 > 5.0)
      worst_after_5s = std::max(worst_after_5s, std::abs(out.diagnostics.lateral_error_m));
  }
  std::printf("%zu waypoints, path %.1f m: max |e| after 5 s = %.3f m\n", waypoints.size(),
              path->length(), worst_after_5s);
  return 0;
}
