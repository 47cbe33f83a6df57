// The command continues through a change of direction and through reset(delta): the chain
// restarts in stationary cornering at the steering the car holds (lead_wheel_controller.cpp,
// initialise_chain), so the held command, differenced at the control period, stays within the
// certificate at every period, with the paper's law (feedforward_share = 0) and with the split.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/controller/steering_certificate.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/sim/closed_loop_count.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"
#include "support/held_command.hpp"
#include "support/random_setup.hpp"

namespace smoothsteer {
namespace {

using namespace smoothsteer::testing;

//! The command of one update at speed v from the rear axle at the origin on the +x line.
//! d delta_veh / ds bound: the split certificate, or the box bound where it certifies none
//! (an unlimited feedforward rate, as the defaults).
double rate_per_meter(const ControllerParameters& p, const SteeringCertificate& c) {
  return std::min(c.rate_per_meter, compute_chain_bounds(p).steering_rate_per_meter);
}

double first_command(LeadWheelController& controller, double speed, double dt) {
  ControllerOutput out;
  EXPECT_EQ(controller.update({{0.0, 0.0}, 0.0, speed, 0.0, dt}, out), Status::ok);
  return out.steering_angle_rad;
}

TEST(CuspAndReset, ResetContinuesFromTheMeasuredAngle) {
  // reset(0.3) used to restart at 0 (paper's law) or at the stationary angle of kbar_ff.
  const auto path = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 100.0));
  for (const double share : {0.0, ControllerParameters{}.feedforward.share}) {
    ControllerParameters p;
    p.feedforward.share = share;
    LeadWheelController controller(p, path);
    const SteeringCertificate& c = controller.certificate();
    for (const double measured : {0.3, -0.2, 0.05, 0.0}) {
      SCOPED_TRACE("share=" + std::to_string(share) + " measured=" + std::to_string(measured));
      ASSERT_LE(std::abs(measured), c.steering_angle_rad);
      controller.reset(measured);
      const double speed = 2.0, dt = 0.02;
      const double command = first_command(controller, speed, dt);
      EXPECT_LE(std::abs(command - measured), speed * dt * rate_per_meter(p, c) * (1.0 + 1e-9));
    }
  }
}

TEST(CuspAndReset, ReversingOnACircleKeepsTheSteering) {
  // Reversing on an 8 m circle: the default parameters jumped from 0.3225 to 0.2038 rad.
  const auto path = std::make_shared<const Path>(Path::circle({0.0, 8.0}, 8.0, true, -0.5 * pi));
  for (const double share : {0.0, ControllerParameters{}.feedforward.share}) {
    ControllerParameters p;
    p.feedforward.share = share;
    LeadWheelController controller(p, path);
    const SteeringCertificate& c = controller.certificate();
    const KinematicSingleTrack plant{p.chain.vehicle_wheelbase_m};
    Pose2 pose{{0.0, 0.0}, 0.0};
    const double dt = 0.02;
    HeldCommand held;
    for (int step = 0; step < 1000; ++step) {
      const double speed = step < 500 ? 2.0 : -2.0;
      ControllerOutput out;
      ASSERT_EQ(controller.update({pose.position, pose.heading_rad, speed, 0.0, dt}, out),
                Status::ok);
      held.push(out.steering_angle_rad, dt);
      const std::string failure =
          held.violation({.rate_radps = std::abs(speed) * rate_per_meter(p, c)});
      EXPECT_TRUE(failure.empty()) << failure << " with share " << share << " at step " << step;
      pose = plant.step(pose, out.steering_angle_rad, speed, dt);
    }
  }
}

//! One random closed loop of 20 s whose speed flips sign every 1-4 s on the same path (the law
//! then turns the car round to follow the path in its own direction, docs/controller.md) and,
//! that is reset to a random measured angle every 0.5-6 s. Checks the held command against the
//! certificate at every period.
void reversing_loop(std::uint64_t seed) {
  Random random(seed + 271);
  const int order = random.coin() ? 2 : 1;
  ControllerParameters p = random_parameters(random, order, random.uniform(0.15, 0.6));
  p.feedforward.share = random.coin() ? 0.0 : random.uniform(0.0, 0.9);
  p.feedforward.curvature_rate = random.uniform(0.001, 0.05);
  p.law.boundary_layer = random.coin() ? 0.0 : random.uniform(0.005, 0.05);
  const auto kind = static_cast<PathKind>(random.integer(0, 3));
  const auto path =
      random_path(random, kind, random.uniform(0.3, 1.0) * p.chain.lead_curvature_bound);
  const PathPoint begin = path->evaluate(0.0);
  const Pose2 start{
      begin.position + random.uniform(-1.0, 1.0) * unit_from_heading(begin.heading_rad + 0.5 * pi),
      begin.heading_rad + random.uniform(-0.3, 0.3)};
  const double dt = random.uniform(0.01, 0.05);
  const double speed_magnitude = random.uniform(0.3, 4.0);
  std::ostringstream text;
  text << seed_message(seed) << " " << describe(p) << " share=" << p.feedforward.share
       << " path=" << to_string(kind) << " dt=" << dt << " |v|=" << speed_magnitude;
  SCOPED_TRACE(text.str());
  LeadWheelController controller(p, path);
  const SteeringCertificate& c = controller.certificate();
  const KinematicSingleTrack plant{p.chain.vehicle_wheelbase_m};
  smoothsteer::detail::count_closed_loop();
  Pose2 pose = start;
  HeldCommand held;
  double direction = 1.0, previous_speed = 0.0;
  double next_cusp = random.uniform(1.0, 4.0), next_reset = random.uniform(0.5, 6.0);
  int since_reset = 0;
  for (int step = 0; step < static_cast<int>(20.0 / dt); ++step) {
    const double t = step * dt;
    if (t >= next_cusp) {
      direction = -direction;
      next_cusp += random.uniform(1.0, 4.0);
    }
    if (t >= next_reset) {
      // A re-engagement: the stack resets the controller to the angle the car measures.
      const double measured = random.uniform(-1.0, 1.0) * c.steering_angle_rad;
      controller.reset(measured);
      held.restart(measured);
      since_reset = 0;
      next_reset += random.uniform(0.5, 6.0);
    }
    const double speed = direction * speed_magnitude;
    ControllerOutput out;
    EXPECT_EQ(controller.update({pose.position, pose.heading_rad, speed, 0.0, dt}, out),
              Status::ok);
    const double command = out.steering_angle_rad;
    EXPECT_TRUE(std::isfinite(command));
    EXPECT_LE(std::abs(command), c.steering_angle_rad * (1.0 + 1e-12));
    HeldLimits limits{.rate_radps = speed_magnitude * c.rate_per_meter};
    if (since_reset >= 2 && order >= 2) {
      // At a cusp the mirrored chain restarts stationary: the second difference is what the
      // certificate allows for the speed's change, 2 |v| / dt.
      limits.acceleration_radps2 = std::abs(speed - previous_speed) / dt * c.rate_per_meter +
                                   speed_magnitude * speed_magnitude * c.acceleration_per_meter2;
    }
    held.push(command, dt);
    const std::string failure = held.violation(limits, {1e-6, 1e-9, 1e-9});
    EXPECT_TRUE(failure.empty()) << failure << " at step " << step << " t=" << t;
    if (::testing::Test::HasFailure()) return;
    previous_speed = speed;
    ++since_reset;
    pose = plant.step(pose, command, speed, dt);
  }
}

TEST(CuspAndReset, HeldCommandStaysWithinTheCertificateThroughCuspsAndResets) {
  const int cases = property_cases(40);
  for (int k = 0; k < cases && !HasFailure(); ++k) reversing_loop(case_seed(k));
}

}  // namespace
}  // namespace smoothsteer
