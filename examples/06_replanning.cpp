// Example 6: replanning. The car follows a straight lane at 10 m/s; after 5 s the planner moves
// the path 3.5 m to the left (a new lane) and the control thread swaps it in with set_path()
// between two update() calls. The command stays continuous: no jump in delta (docs/replanning.md).
#include <smoothsteer/smoothsteer.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

int main() {
  using namespace smoothsteer;
  auto lane = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 400.0));
  auto next_lane = std::make_shared<const Path>(Path::straight_line({0.0, 3.5}, 0.0, 400.0));
  LeadWheelController controller(ControllerParameters{}, lane);
  const KinematicSingleTrack car{2.7};
  Pose2 pose{{0.0, 0.0}, 0.0};
  ControllerOutput out;
  double largest_step = 0.0, previous = 0.0;
  for (int k = 0; k < 1000; ++k) {                                           // 20 s at 50 Hz
    if (k == 250 && controller.set_path(next_lane) != Status::ok) return 1;  // t = 5 s
    if (controller.update({pose.position, pose.heading_rad, 10.0, 0.0, 0.02}, out) != Status::ok)
      return 1;
    pose = car.step(pose, out.steering_angle_rad, 10.0, 0.02);
    largest_step = std::max(largest_step, std::abs(out.steering_angle_rad - previous));
    previous = out.steering_angle_rad;
  }
  std::printf(
      "after the swap: y = %.3f m (new lane at 3.5 m), largest change of delta per period "
      "%.4f rad\n",
      pose.position.y, largest_step);
  return std::abs(pose.position.y - 3.5) < 0.05 ? 0 : 1;
}
