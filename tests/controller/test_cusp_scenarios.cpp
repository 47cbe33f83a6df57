// Parking manoeuvres with cusps, driven by LeadWheelController through CuspSequencer on the
// kinematic single-track model: parallel parking (2 cusps), a three-point turn (2 cusps) and a
// reverse along an S-curve (1 cusp, from waypoints with a direction column). Each must end
// within 5 cm and 0.02 rad of the plan's final pose, with the steering angle and rate inside
// the controller's certified bounds through every cusp: the reported rate and the HELD command
// differenced at the control period (the chain restarts at the angle the car holds, so nothing
// jumps at a cusp), with the default split and with the paper's law (feedforward_share = 0).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "smoothsteer/controller/cusp_sequencer.hpp"
#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/path/path_plan.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"

namespace smoothsteer {
namespace {

constexpr double kPeriod_s = 0.02;

struct ManoeuvreResult {
  bool finished = false;
  double position_error_m = 0.0;
  double heading_error_rad = 0.0;
  double peak_angle_rad = 0.0;
  double peak_rate_ratio = 0.0;  //!< max |d delta / dt| / (|v| * certified rate per metre)
  //! The same for the held command: max |delta_k - delta_{k-1}| / (dt |v_k| rate per metre).
  double peak_held_rate_ratio = 0.0;
  std::size_t switches = 0;
};

std::shared_ptr<const Path> share(Path path) {
  return std::make_shared<const Path>(std::move(path));
}

//! Drives `plan` from its start pose (vehicle heading = travel heading of piece 0, + pi if it
//! is reversed) until the sequencer finishes or 120 s pass.
ManoeuvreResult drive(const PathPlan& plan, LeadWheelController& controller) {
  const PathPiece& first = plan.piece(0);
  const PathPoint start = first.path->evaluate(0.0);
  Pose2 pose{start.position,
             wrap_angle(start.heading_rad + (first.gear == Gear::reverse ? pi : 0.0))};
  CuspSequencer sequencer(plan, controller);
  const KinematicSingleTrack model{controller.parameters().chain.vehicle_wheelbase_m};
  const ChainBounds bounds = controller.bounds();
  ManoeuvreResult result;
  std::size_t piece = 0;
  ControllerOutput output;
  double held = 0.0;
  for (int k = 0; k < static_cast<int>(120.0 / kPeriod_s) && !sequencer.finished(); ++k) {
    const double speed = sequencer.speed_command(pose.position, kPeriod_s);
    if (sequencer.active_piece() != piece) {
      piece = sequencer.active_piece();
      ++result.switches;
    }
    EXPECT_EQ(controller.update({pose.position, pose.heading_rad, speed, 0.0, kPeriod_s}, output),
              Status::ok);
    result.peak_angle_rad = std::max(result.peak_angle_rad, std::abs(output.steering_angle_rad));
    if (speed != 0.0) {
      result.peak_rate_ratio =
          std::max(result.peak_rate_ratio, std::abs(output.steering_rate_radps) /
                                               (std::abs(speed) * bounds.steering_rate_per_meter));
    }
    const double change = std::abs(output.steering_angle_rad - held);
    if (k > 0 && change > 0.0) {
      result.peak_held_rate_ratio =
          std::max(result.peak_held_rate_ratio,
                   change / (kPeriod_s * std::abs(speed) * bounds.steering_rate_per_meter));
    }
    held = output.steering_angle_rad;
    pose = model.step(pose, held, speed, kPeriod_s);
  }
  result.finished = sequencer.finished();
  result.position_error_m = norm(pose.position - plan.final_position());
  result.heading_error_rad =
      std::abs(wrap_angle(pose.heading_rad - plan.final_vehicle_heading_rad()));
  return result;
}

void expect_reached(const char* name, const PathPlan& plan) {
  for (const double share : {ControllerParameters{}.feedforward.share, 0.0}) {
    ControllerParameters parameters;
    parameters.feedforward.share = share;
    LeadWheelController controller(parameters, plan.piece(0).path);
    const ManoeuvreResult result = drive(plan, controller);
    std::printf(
        "%s (feedforward share %.1f): %zu cusps, final position error %.4f m, heading error "
        "%.4f rad, peak |delta| %.3f (bound %.3f) rad, peak rate / bound %.3f, held %.3f\n",
        name, share, plan.cusp_count(), result.position_error_m, result.heading_error_rad,
        result.peak_angle_rad, controller.bounds().steering_angle_rad, result.peak_rate_ratio,
        result.peak_held_rate_ratio);
    SCOPED_TRACE(std::string(name) + ", feedforward share " + std::to_string(share));
    EXPECT_TRUE(result.finished);
    EXPECT_EQ(result.switches, plan.piece_count() - 1);
    EXPECT_LT(result.position_error_m, 0.05);
    EXPECT_LT(result.heading_error_rad, 0.02);
    EXPECT_LE(result.peak_angle_rad, controller.bounds().steering_angle_rad * (1.0 + 1e-9));
    EXPECT_LE(result.peak_rate_ratio, 1.0 + 1e-9);
    EXPECT_LE(result.peak_held_rate_ratio, 1.0 + 1e-9);
  }
}

TEST(CuspScenarios, ParallelParking) {
  // Reverse into a slot 2.5 m to the right of the lane (an S of two 8 m arcs), pull forwards
  // to straighten up in the slot, reverse to its back end.
  const double turn = std::acos(1.0 - 2.5 / (2.0 * 8.0));
  const auto back_in = share(PathBuilder({0.0, 0.0}, pi)
                                 .line(3.0)
                                 .arc(8.0, turn)  // travelling in -x, a left turn goes to -y
                                 .arc(8.0, -turn)
                                 .line(6.0)
                                 .build());
  const Vec2 in_slot = back_in->evaluate(back_in->length()).position;
  const auto forward = share(PathBuilder(in_slot, 0.0).line(6.0).build());
  const auto back = share(PathBuilder(in_slot + Vec2{6.0, 0.0}, pi).line(8.0).build());
  const PathPlan plan = PathPlan::from_pieces(
      {{back_in, Gear::reverse}, {forward, Gear::forward}, {back, Gear::reverse}});
  ASSERT_EQ(plan.cusp_count(), 2u);
  expect_reached("parallel parking", plan);
}

TEST(CuspScenarios, ThreePointTurn) {
  // Forward left across the road, reverse turning on, forward away in the opposite direction.
  const auto first =
      share(PathBuilder({0.0, 0.0}, 0.0).line(3.0).arc(7.0, pi / 2).line(1.0).build());
  const Vec2 a = first->evaluate(first->length()).position;
  const auto second = share(PathBuilder(a, -pi / 2).line(1.0).arc(7.0, pi / 2).line(1.0).build());
  const Vec2 b = second->evaluate(second->length()).position;
  const auto third = share(PathBuilder(b, pi).line(12.0).build());
  const PathPlan plan = PathPlan::from_pieces(
      {{first, Gear::forward}, {second, Gear::reverse}, {third, Gear::forward}});
  ASSERT_EQ(plan.cusp_count(), 2u);
  expect_reached("three-point turn", plan);
}

TEST(CuspScenarios, ReverseAlongAnSCurveFromWaypointsWithADirectionColumn) {
  // Forward 10 m along +x, then back the same way and on along an S-curve behind the start.
  std::vector<Vec2> waypoints;
  std::vector<int> directions;
  for (int i = 0; i <= 10; ++i) {
    waypoints.push_back({static_cast<double>(i), 0.0});
    directions.push_back(1);
  }
  directions.back() = -1;  // waypoint 10 is the cusp: from here on in reverse
  for (int i = 1; i <= 60; ++i) {
    const double x = 10.0 - static_cast<double>(i);
    const double y = x < 0.0 ? (x > -40.0 ? 2.0 * (1.0 - std::cos(pi * x / 20.0)) : 0.0) : 0.0;
    waypoints.push_back({x, y});
    directions.push_back(-1);
  }
  const PathPlan plan = PathPlan::from_waypoints(waypoints, directions);
  ASSERT_EQ(plan.piece_count(), 2u);
  ASSERT_EQ(plan.cusp_count(), 1u);
  expect_reached("reverse S-curve", plan);
}

TEST(CuspScenarios, InvalidPlansNameTheField) {
  auto message = [](auto build) {
    try {
      build();
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  const auto line = share(Path::straight_line({0.0, 0.0}, 0.0, 5.0));
  const auto far = share(Path::straight_line({9.0, 0.0}, pi, 5.0));
  EXPECT_NE(message([&] {
              PathPlan::from_pieces({{line, Gear::forward}, {far, Gear::reverse}});
            }).find("pieces[1].path starts 4 m"),
            std::string::npos);
  EXPECT_NE(message([&] {
              PathPlan::from_pieces({{nullptr, Gear::forward}});
            }).find("pieces[0].path is null"),
            std::string::npos);
  EXPECT_NE(message([] {
              PathPlan::from_waypoints({{0, 0}, {1, 0}, {2, 0}}, {1, 0, 1});
            }).find("directions[1] = 0 must be +1"),
            std::string::npos);
  EXPECT_NE(message([] {
              PathPlan::from_waypoints({{0, 0}, {1, 0}}, {1});
            }).find("directions.size() = 1 must equal waypoints.size() = 2"),
            std::string::npos);
  CuspSpeedOptions options;
  options.deceleration_mps2 = -1.0;
  EXPECT_NE(message([&] { options.validate(); }).find("deceleration_mps2"), std::string::npos);
}

}  // namespace
}  // namespace smoothsteer
