// The closed loop on a path with gear changes (simulate() on a PathPlan): the signed speed
// profile of curvature_speed_profile() comes to rest at every cusp, the piece switches there, the
// errors refer to the active piece and the heading error to the direction of travel; and the
// rules of check_gear_changes() / gear_changes() reject a profile that does not fit the plan
// with a message naming the field.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/sim/curvature_speed_profile.hpp"
#include "smoothsteer/sim/gear_changes.hpp"
#include "smoothsteer/sim/simulation.hpp"
#include "smoothsteer/vehicle/vehicle_model.hpp"

namespace smoothsteer {
namespace {

std::shared_ptr<const Path> share(Path path) {
  return std::make_shared<const Path>(std::move(path));
}

//! Forward 12 m, reverse 10 m through a left arc (travel frame), forward 8 m.
PathPlan three_point_plan() {
  const auto first = share(PathBuilder({0.0, 0.0}, 0.0).line(12.0).build());
  const auto second = share(PathBuilder({12.0, 0.0}, pi).line(2.0).arc(8.0, 0.5).line(4.0).build());
  const PathPoint end = second->evaluate(second->length());
  const auto third = share(PathBuilder(end.position, end.heading_rad + pi).line(8.0).build());
  return PathPlan::from_pieces(
      {{first, Gear::forward}, {second, Gear::reverse}, {third, Gear::forward}});
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(PlanSimulation, StopsAtEachCuspSwitchesPiecesAndEndsOnTheLastOne) {
  const PathPlan plan = three_point_plan();
  CurvatureSpeedLimits limits;
  limits.max_speed_mps = 1.5;
  limits.max_lateral_acceleration_mps2 = 1.0;
  limits.max_acceleration_mps2 = 0.5;
  limits.max_deceleration_mps2 = 0.5;
  const SpeedProfile speed = curvature_speed_profile(plan, limits);
  ASSERT_TRUE(speed.signed_speeds);
  const std::vector<GearChange> changes = gear_changes(speed);
  ASSERT_EQ(changes.size(), 2u);
  for (const GearChange& change : changes) {
    EXPECT_NEAR(change.resume_time_s - change.stop_time_s, limits.cusp_rest_s, 1e-12);
    EXPECT_EQ(speed.speed(change.stop_time_s), 0.0);
  }
  EXPECT_EQ(speed.knots->back().speed_mps, 0.0);  // at rest at the end

  VehicleParameters car;  // the defaults: the passenger car
  const KinematicVehicleModel model(car);
  ActuatorParameters actuator;
  actuator.dead_time_s = 0.0;
  SimulationParameters parameters;
  parameters.duration_s = 120.0;
  LeadWheelController controller(ControllerParameters{}, plan.piece(0).path);
  const SimulationResult result =
      simulate(plan, model, actuator, speed, parameters, Pose2{{0.0, 0.0}, 0.0}, controller);
  ASSERT_EQ(result.status, Status::ok) << result.stop_detail;
  EXPECT_EQ(result.stop_reason, "path_end");
  double max_error = 0.0, max_heading_error = 0.0, min_speed = 0.0;
  for (const TraceSample& sample : result.trace) {
    max_error = std::max(max_error, std::abs(sample.lateral_error_m));
    max_heading_error = std::max(max_heading_error, std::abs(sample.heading_error_rad));
    min_speed = std::min(min_speed, sample.speed_mps);
  }
  EXPECT_LT(min_speed, -1.0);  // the reverse piece is driven in reverse
  // Projected on the active piece and measured against the direction of travel: no jump of
  // the error or of pi in the heading error at the cusps.
  EXPECT_LT(max_error, 0.1);
  EXPECT_LT(max_heading_error, 0.2);
  const Pose2 end = result.trace.back().rear_axle;
  EXPECT_LT(norm(end.position - plan.final_position()), 0.1);
  EXPECT_LT(std::abs(wrap_angle(end.heading_rad - plan.final_vehicle_heading_rad())), 0.05);
}

TEST(PlanSimulation, ProfilesThatDoNotFitThePlanAreRejectedNamingTheField) {
  const PathPlan plan = three_point_plan();
  CurvatureSpeedLimits limits;
  limits.max_speed_mps = 1.5;
  const SpeedProfile good = curvature_speed_profile(plan, limits);
  EXPECT_EQ(message_of([&] { check_gear_changes(plan, good, 0.02); }), "");

  // A rest shorter than a control period: no control instant to switch the piece at.
  EXPECT_NE(message_of([&] { check_gear_changes(plan, good, 2.0); }).find("at least one control"),
            std::string::npos);
  // An unsigned profile.
  SpeedProfile forward;
  EXPECT_NE(message_of([&] { check_gear_changes(plan, forward, 0.02); }).find("signed_speeds"),
            std::string::npos);
  // Through zero between two knots without a rest.
  SpeedProfile through;
  through.signed_speeds = true;
  through.initial_speed_mps = 1.0;
  through.knots = std::make_shared<std::vector<SpeedKnot>>(
      std::vector<SpeedKnot>{{0.0, 1.0}, {1.0, -1.0}, {2.0, 0.0}});
  EXPECT_NE(message_of([&] { (void)gear_changes(through); }).find("knots[1].speed_mps"),
            std::string::npos);
  // Too few gear changes for the cusps.
  SpeedProfile one;
  one.signed_speeds = true;
  one.initial_speed_mps = 1.0;
  one.knots = std::make_shared<std::vector<SpeedKnot>>(
      std::vector<SpeedKnot>{{0.0, 1.0}, {1.0, 0.0}, {2.0, 0.0}, {3.0, -1.0}});
  EXPECT_NE(message_of([&] { check_gear_changes(plan, one, 0.02); }).find("2 cusps"),
            std::string::npos);
  // The first gear wrong.
  SpeedProfile backwards = one;
  backwards.initial_speed_mps = -1.0;
  backwards.knots = std::make_shared<std::vector<SpeedKnot>>(
      std::vector<SpeedKnot>{{0.0, -1.0}, {1.0, 0.0}, {2.0, 0.0}, {3.0, 1.0}});
  EXPECT_NE(message_of([&] { check_gear_changes(plan, backwards, 0.02); }).find("first piece"),
            std::string::npos);
  // Signed knots without the flag, and the flag on a ramp.
  SpeedProfile unflagged = one;
  unflagged.signed_speeds = false;
  EXPECT_NE(unflagged.validation_error().find("knots[i].speed_mps"), std::string::npos);
  SpeedProfile ramp;
  ramp.signed_speeds = true;
  EXPECT_NE(ramp.validation_error().find("signed_speeds"), std::string::npos);
  // The rest itself.
  CurvatureSpeedLimits no_rest = limits;
  no_rest.cusp_rest_s = 0.0;
  EXPECT_NE(no_rest.validation_error().find("cusp_rest_s"), std::string::npos);
  // A piece too short for a stop at both ends.
  const auto a = share(PathBuilder({0.0, 0.0}, 0.0).line(0.8).build());
  const auto b = share(PathBuilder({0.8, 0.0}, pi).line(5.0).build());
  const PathPlan short_plan = PathPlan::from_pieces({{a, Gear::forward}, {b, Gear::reverse}});
  EXPECT_NE(
      message_of([&] { (void)curvature_speed_profile(short_plan, limits); }).find("pieces[0]"),
      std::string::npos);
}

}  // namespace
}  // namespace smoothsteer
