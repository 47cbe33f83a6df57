// Stanley and pure pursuit with their reverse forms drive the cusp scenarios of
// tests/controller/test_cusp_scenarios.cpp (the same plans) through CuspSequencer, wrapped in
// SaturatedController with |delta| <= 0.57 rad (the lead-wheel controller's certified angle bound)
// and |d delta / dt| <= 1 rad/s. The final pose must be within 5 cm and 0.02 rad. Unlike the
// lead-wheel controller, these two keep the limits only through the saturation; the test prints
// how often it clamped.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "smoothsteer/baselines/geometric_controllers.hpp"
#include "smoothsteer/baselines/steering_limits.hpp"
#include "smoothsteer/controller/cusp_sequencer.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/path/path_plan.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"

namespace smoothsteer {
namespace {

constexpr double kPeriod_s = 0.02;

std::shared_ptr<const Path> share(Path path) {
  return std::make_shared<const Path>(std::move(path));
}

PathPlan parallel_parking() {
  const double turn = std::acos(1.0 - 2.5 / (2.0 * 8.0));
  const auto back_in =
      share(PathBuilder({0.0, 0.0}, pi).line(3.0).arc(8.0, turn).arc(8.0, -turn).line(6.0).build());
  const Vec2 in_slot = back_in->evaluate(back_in->length()).position;
  return PathPlan::from_pieces(
      {{back_in, Gear::reverse},
       {share(PathBuilder(in_slot, 0.0).line(6.0).build()), Gear::forward},
       {share(PathBuilder(in_slot + Vec2{6.0, 0.0}, pi).line(8.0).build()), Gear::reverse}});
}

PathPlan three_point_turn() {
  const auto first =
      share(PathBuilder({0.0, 0.0}, 0.0).line(3.0).arc(7.0, pi / 2).line(1.0).build());
  const Vec2 a = first->evaluate(first->length()).position;
  const auto second = share(PathBuilder(a, -pi / 2).line(1.0).arc(7.0, pi / 2).line(1.0).build());
  const Vec2 b = second->evaluate(second->length()).position;
  return PathPlan::from_pieces({{first, Gear::forward},
                                {second, Gear::reverse},
                                {share(PathBuilder(b, pi).line(12.0).build()), Gear::forward}});
}

PathPlan reverse_s_curve() {
  std::vector<Vec2> waypoints;
  std::vector<int> directions;
  for (int i = 0; i <= 10; ++i) {
    waypoints.push_back({static_cast<double>(i), 0.0});
    directions.push_back(1);
  }
  directions.back() = -1;
  for (int i = 1; i <= 60; ++i) {
    const double x = 10.0 - static_cast<double>(i);
    const double y = x < 0.0 && x > -40.0 ? 2.0 * (1.0 - std::cos(pi * x / 20.0)) : 0.0;
    waypoints.push_back({x, y});
    directions.push_back(-1);
  }
  return PathPlan::from_waypoints(waypoints, directions);
}

void expect_reached(const std::string& name, const PathPlan& plan,
                    std::unique_ptr<SteeringController> inner) {
  SteeringLimits limits;
  limits.angle_rad = 0.57;
  limits.rate_radps = 1.0;
  SaturatedController controller(std::move(inner), limits, name);
  const PathPoint start = plan.piece(0).path->evaluate(0.0);
  Pose2 pose{start.position,
             wrap_angle(start.heading_rad + (plan.piece(0).gear == Gear::reverse ? pi : 0.0))};
  CuspSequencer sequencer(plan, controller);
  const KinematicSingleTrack model{2.7};
  ControllerOutput output;
  for (int k = 0; k < static_cast<int>(120.0 / kPeriod_s) && !sequencer.finished(); ++k) {
    const double speed = sequencer.speed_command(pose.position, kPeriod_s);
    ASSERT_EQ(controller.update({pose.position, pose.heading_rad, speed, 0.0, kPeriod_s}, output),
              Status::ok);
    pose = model.step(pose, output.steering_angle_rad, speed, kPeriod_s);
  }
  const double position_error = norm(pose.position - plan.final_position());
  const double heading_error =
      std::abs(wrap_angle(pose.heading_rad - plan.final_vehicle_heading_rad()));
  const SaturationStatistics& statistics = controller.saturation();
  std::printf(
      "%s: final position error %.4f m, heading error %.4f rad, angle-limited %ld, "
      "rate-limited %ld of %ld updates\n",
      name.c_str(), position_error, heading_error, statistics.angle_limited,
      statistics.rate_limited, statistics.updates);
  EXPECT_TRUE(sequencer.finished()) << name;
  EXPECT_LT(position_error, 0.05) << name;
  EXPECT_LT(heading_error, 0.02) << name;
}

TEST(CuspsGeometric, StanleyAndPurePursuitDriveTheCuspScenarios) {
  const std::vector<std::pair<std::string, PathPlan>> plans{
      {"parallel parking", parallel_parking()},
      {"three-point turn", three_point_turn()},
      {"reverse S-curve", reverse_s_curve()}};
  for (const auto& [name, plan] : plans) {
    expect_reached("stanley, " + name, plan,
                   std::make_unique<StanleyController>(StanleyParameters{}, plan.piece(0).path));
    expect_reached(
        "pure pursuit, " + name, plan,
        std::make_unique<PurePursuitController>(PurePursuitParameters{}, plan.piece(0).path));
  }
}

}  // namespace
}  // namespace smoothsteer
