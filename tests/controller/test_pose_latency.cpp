// A late pose with its age given: the controller carries the pose forward through its own
// commands, so on the kinematic model it steers exactly as it would with the pose on time.
// Without the age the same late pose changes the run.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/sim/closed_loop_count.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"
#include "support/property.hpp"
#include "support/random_setup.hpp"

namespace smoothsteer::testing {
namespace {

//! The commands of a kinematic closed loop in which the controller sees the pose
//! `latency_steps` periods late, told its age (`tell_age`) or not; latency 0: on time.
std::vector<double> commands_with_late_pose(const ControllerParameters& parameters,
                                            const std::shared_ptr<const Path>& path, Pose2 start,
                                            double speed, int latency_steps, bool tell_age,
                                            int steps) {
  constexpr double period = 0.02;
  LeadWheelController controller(parameters, path);
  const KinematicSingleTrack plant{parameters.chain.vehicle_wheelbase_m};
  std::vector<Pose2> poses{start};  // the true pose of every period so far
  std::vector<double> commands;
  ControllerOutput output;
  smoothsteer::detail::count_closed_loop();
  for (int k = 0; k < steps; ++k) {
    // Before the start the car stood at `start`: the oldest pose there is, with its true age.
    const int lag = std::min(k, latency_steps);
    const Pose2& seen = poses[static_cast<std::size_t>(k - lag)];
    ControllerInput input{seen.position, seen.heading_rad, speed, 0.0, period};
    input.pose_age_s = tell_age ? lag * period : 0.0;
    if (controller.update(input, output) != Status::ok) return {};
    commands.push_back(output.steering_angle_rad);
    poses.push_back(plant.step(poses.back(), output.steering_angle_rad, speed, period));
  }
  return commands;
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size() || a.empty()) return std::numeric_limits<double>::infinity();
  double largest = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) largest = std::max(largest, std::abs(a[k] - b[k]));
  return largest;
}

TEST(PoseLatency, AGivenAgeGivesTheOnTimeCommands) {
  int told_apart = 0;
  const int cases = property_cases(20);
  for (int index = 0; index < cases; ++index) {
    const auto seed = case_seed(index);
    Random random(seed + 31);
    const int order = random.integer(1, 3);
    const ControllerParameters parameters =
        random_parameters(random, order, random.uniform(0.35, 0.6));
    const PathKind kind = random.coin() ? PathKind::circle : PathKind::waypoints;
    const auto path = random_path(
        random, kind, 0.5 * parameters.law.k_rob * parameters.chain.lead_curvature_bound);
    const PathPoint begin = path->evaluate(0.0);
    const Pose2 start{begin.position + Vec2{random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0)},
                      begin.heading_rad + random.uniform(-0.3, 0.3)};
    const double speed = random.uniform(3.0, 25.0);
    const int latency_steps = random.integer(1, 5);  // 20-100 ms
    SCOPED_TRACE(seed_message(seed) + " " + describe(parameters) + " path=" + to_string(kind) +
                 " v=" + std::to_string(speed) + " latency_steps=" + std::to_string(latency_steps));
    const int steps = 1000;
    const auto on_time = commands_with_late_pose(parameters, path, start, speed, 0, true, steps);
    const auto told =
        commands_with_late_pose(parameters, path, start, speed, latency_steps, true, steps);
    const auto untold =
        commands_with_late_pose(parameters, path, start, speed, latency_steps, false, steps);
    ASSERT_EQ(on_time.size(), static_cast<std::size_t>(steps));
    // The prediction rolls the same kinematic model through the same commands: the law sees
    // the on-time pose up to rounding.
    EXPECT_LT(largest_difference(told, on_time), 1e-9);
    if (largest_difference(untold, on_time) > 1e-3) ++told_apart;
  }
  // The check can fail: without the age, the late pose changes the commands of most runs.
  EXPECT_GE(told_apart, cases / 2);
}

TEST(PoseLatency, AnAgeOutsideItsRangeIsRefusedAndChangesNothing) {
  ControllerParameters parameters;
  const auto path = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 100.0));
  LeadWheelController controller(parameters, path);
  ControllerOutput output;
  const ControllerInput good{{0.0, 0.5}, 0.0, 5.0, 0.0, 0.02};
  ASSERT_EQ(controller.update(good, output), Status::ok);
  const double command = output.steering_angle_rad;
  for (const double age :
       {-1e-3, ControllerInput::max_pose_age_s * 1.001, std::numeric_limits<double>::quiet_NaN(),
        std::numeric_limits<double>::infinity()}) {
    SCOPED_TRACE(age);
    ControllerInput bad = good;
    bad.pose_age_s = age;
    EXPECT_EQ(controller.update(bad, output), Status::invalid_input);
    EXPECT_EQ(output.steering_angle_rad, command);
  }
  ControllerInput oldest = good;
  oldest.pose_age_s = ControllerInput::max_pose_age_s;
  EXPECT_EQ(controller.update(oldest, output), Status::ok);
}

}  // namespace
}  // namespace smoothsteer::testing
