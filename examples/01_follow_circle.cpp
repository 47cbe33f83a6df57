// The README example: the C^1 controller (n = 2) drives a kinematic car onto a circle.
#include <smoothsteer/smoothsteer.hpp>

#include <cstdio>
#include <memory>

int main() {
  using namespace smoothsteer;
  auto path = std::make_shared<const Path>(Path::circle({0.0, 0.0}, 30.0));
  LeadWheelController controller(ControllerParameters{}, path);  // n = 2, SI units
  KinematicSingleTrack car{2.7};
  Pose2 pose{{-50.0, 20.0}, 1.0};
  ControllerOutput out;
  for (int k = 0; k < 3000; ++k) {  // 60 s at 50 Hz, 8 m/s
    controller.update({pose.position, pose.heading_rad, 8.0, 0.0, 0.02}, out);
    pose = car.step(pose, out.steering_angle_rad, 8.0, 0.02);
  }
  std::printf("e = %.4f m, delta = %.4f rad, rate = %.4f rad/s\n", out.diagnostics.lateral_error_m,
              out.steering_angle_rad, out.steering_rate_radps);
  return 0;
}
