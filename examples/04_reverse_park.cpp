// Example 4: reverse and park. A parallel-parking plan of three pieces (reverse S into the slot,
// forward, reverse) meets at two cusps; CuspSequencer hands each piece to the controller and
// brakes to a standstill at every cusp (docs/cusps.md).
#include <smoothsteer/controller/cusp_sequencer.hpp>
#include <smoothsteer/math/angles.hpp>
#include <smoothsteer/smoothsteer.hpp>

#include <cmath>
#include <cstdio>
#include <memory>

int main() {
  using namespace smoothsteer;
  const double turn = std::acos(1.0 - 2.5 / (2.0 * 8.0));  // S of two 8 m arcs, 2.5 m sideways
  auto back_in = std::make_shared<const Path>(
      PathBuilder({0.0, 0.0}, pi).line(3.0).arc(8.0, turn).arc(8.0, -turn).line(6.0).build());
  const Vec2 slot = back_in->evaluate(back_in->length()).position;
  auto forward = std::make_shared<const Path>(PathBuilder(slot, 0.0).line(6.0).build());
  auto back =
      std::make_shared<const Path>(PathBuilder(slot + Vec2{6.0, 0.0}, pi).line(8.0).build());
  const PathPlan plan = PathPlan::from_pieces(
      {{back_in, Gear::reverse}, {forward, Gear::forward}, {back, Gear::reverse}});

  LeadWheelController controller(ControllerParameters{}, back_in);
  CuspSequencer sequencer(plan, controller);  // cruise 1.5 m/s, braking 0.5 m/s^2
  const KinematicSingleTrack car{2.7};
  Pose2 pose{{0.0, 0.0}, 0.0};  // facing +x, about to reverse along -x
  ControllerOutput out;
  double t = 0.0;
  for (; t < 120.0 && !sequencer.finished(); t += 0.02) {
    const double speed = sequencer.speed_command(pose.position, 0.02);  // signed: < 0 reverses
    if (controller.update({pose.position, pose.heading_rad, speed, 0.0, 0.02}, out) != Status::ok)
      return 1;
    pose = car.step(pose, out.steering_angle_rad, speed, 0.02);
  }
  const double position_error = norm(pose.position - plan.final_position());
  const double heading_error =
      std::abs(wrap_angle(pose.heading_rad - plan.final_vehicle_heading_rad()));
  std::printf(
      "parked after %.1f s through %zu cusps: position error %.3f m, heading error %.4f rad\n", t,
      plan.cusp_count(), position_error, heading_error);
  return sequencer.finished() && position_error < 0.05 ? 0 : 1;
}
