// Closed loops on the kinematic model with the gain schedule (paper Sec. III): from far away with
// any heading, at constant speeds in [1, 30] m/s and while accelerating/braking between them, the
// commanded steering angle, rate and acceleration (time domain, d2/dt2 with its dv/dt term) stay
// within the vehicle's limits. Also: retune() keeps delta_veh continuous.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/sim/closed_loop_count.hpp"
#include "smoothsteer/sim/kinematic_closed_loop.hpp"
#include "smoothsteer/tuning/scheduled_controller.hpp"
#include "support/held_command.hpp"
#include "support/property.hpp"
#include "support/shared_static_map.hpp"

namespace smoothsteer {
namespace {

//! The paper's route (Certificate::box); the feedforward route has its own tests.
TuningOptions box_route() {
  TuningOptions options;
  options.certificate = Certificate::box;
  return options;
}

using namespace smoothsteer::testing;

VehicleLimits example_vehicle() {
  VehicleLimits v;  // CommonRoad vehicle 2 + a steering-acceleration limit
  v.max_steering_acceleration_radps2 = 5.0;
  return v;
}

TEST(ScheduledLoop, LimitsHoldAtConstantSpeedsFromAnyStart) {
  const VehicleLimits vehicle = example_vehicle();
  const GainSchedule schedule =
      compute_gain_schedule(vehicle, box_route(), speed_grid(1.0, 30.0, 0.5), shared_map());
  auto path = std::make_shared<const Path>(Path::straight_line({-500.0, 0.0}, 0.0, 20000.0));
  const int cases = property_cases(8);
  for (int k = 0; k < cases; ++k) {
    Random random(case_seed(k) + 31);
    const double speed = k == 0 ? 1.0 : k == 1 ? 30.0 : random.uniform(1.0, 30.0);
    const Pose2 start{{random.uniform(-50.0, 50.0), random.uniform(-80.0, 80.0)},
                      random.uniform(-pi, pi)};
    std::ostringstream text;
    text << seed_message(case_seed(k)) << " v=" << speed << " start=(" << start.position.x << ","
         << start.position.y << "," << start.heading_rad << ")";
    SCOPED_TRACE(text.str());
    ScheduledController controller(schedule, path);
    KinematicLoopOptions options;
    options.wheelbase_m = vehicle.wheelbase_m;
    options.speed_mps = speed;
    options.duration_s = std::min(200.0, 1500.0 / speed);
    options.record_trace = false;
    const KinematicLoopResult r = run_kinematic_closed_loop(controller, start, options);
    ASSERT_EQ(r.status, Status::ok);
    EXPECT_FALSE(r.any_non_finite);
    EXPECT_LE(r.max_abs_steering_rad, vehicle.max_steering_angle_rad * (1 + 1e-9));
    EXPECT_LE(r.max_abs_steering_rate_radps, vehicle.max_steering_rate_radps * (1 + 1e-9));
    EXPECT_LE(r.max_abs_steering_difference_rate_radps,
              vehicle.max_steering_rate_radps * (1 + 1e-6));
    EXPECT_LE(r.max_abs_steering_acceleration_radps2,
              vehicle.max_steering_acceleration_radps2 * (1 + 1e-9));
  }
}

//! 1 -> 30 -> 1 m/s twice at random |dv/dt| <= options' limit, from random far starts: the
//! reported derivatives within the limits exactly, the held command's differences within 1 %
//! (rate) and 5 % (acceleration), which also contain the schedule's parameter drift.
void check_limits_while_the_speed_changes(const VehicleLimits& vehicle,
                                          const TuningOptions& options, std::uint64_t seed_offset) {
  const GainSchedule schedule =
      compute_gain_schedule(vehicle, options, speed_grid(0.5, 30.0, 0.5), shared_map());
  auto path = std::make_shared<const Path>(Path::straight_line({-500.0, 0.0}, 0.0, 50000.0));
  for (int k = 0; k < property_cases(3); ++k) {
    Random random(case_seed(k) + seed_offset);
    const double acceleration =
        random.uniform(0.25, 1.0) * options.max_longitudinal_acceleration_mps2;
    Pose2 pose{{0.0, random.uniform(-60.0, 60.0)}, random.uniform(-pi, pi)};
    std::ostringstream text;
    text << seed_message(case_seed(k)) << " dv/dt=+-" << acceleration << " start=("
         << pose.position.y << "," << pose.heading_rad << ")";
    SCOPED_TRACE(text.str());
    ScheduledController controller(schedule, path);
    const KinematicSingleTrack model{vehicle.wheelbase_m};
    const double dt = 0.02;
    double speed = 1.0, direction = 1.0;
    double max_angle = 0, max_rate = 0, max_accel = 0;
    HeldCommand held;
    smoothsteer::detail::count_closed_loop();  // a closed loop (counted)
    for (int step = 0, turns = 0; turns < 4; ++step) {
      const double a = direction * acceleration;
      ControllerOutput out;
      ASSERT_EQ(controller.update({pose.position, pose.heading_rad, speed, a, dt}, out),
                Status::ok);
      max_angle = std::max(max_angle, std::abs(out.steering_angle_rad));
      max_rate = std::max(max_rate, std::abs(out.steering_rate_radps));
      max_accel = std::max(max_accel, std::abs(out.steering_acceleration_radps2));
      held.push(out.steering_angle_rad, dt);
      pose = model.step(pose, out.steering_angle_rad, speed, dt);
      speed += a * dt;
      if (speed >= 30.0 || speed <= 1.0) {
        speed = std::clamp(speed, 1.0, 30.0);
        direction = -direction;
        ++turns;
      }
    }
    EXPECT_LE(max_angle, vehicle.max_steering_angle_rad * (1 + 1e-9));
    EXPECT_LE(max_rate, vehicle.max_steering_rate_radps * (1 + 1e-9));
    EXPECT_LE(max_accel, vehicle.max_steering_acceleration_radps2 * (1 + 1e-9));
    EXPECT_LE(held.max_abs_rate(), vehicle.max_steering_rate_radps * 1.01);
    EXPECT_LE(held.max_abs_acceleration(), vehicle.max_steering_acceleration_radps2 * 1.05);
  }
}

TEST(ScheduledLoop, LimitsHoldWhileTheSpeedChanges) {
  TuningOptions options = box_route();
  options.max_longitudinal_acceleration_mps2 = 2.0;
  check_limits_while_the_speed_changes(example_vehicle(), options, 32);
}

TEST(ScheduledLoop, RetuneNeverFreezesTheFrontAngle) {
  // Regression: wheelbase 2.8 m, 0.45 rad, 0.7 rad/s, 3 rad/s^2, dv/dt up to 2 m/s^2.
  // When a retune left delta_2 outside its shrunken set, integrate_chain's clamp stopped
  // delta_1 at its bound; the command stalled and its acceleration overshot by up to 1.48x.
  VehicleLimits vehicle;
  vehicle.wheelbase_m = 2.8;
  vehicle.max_steering_angle_rad = 0.45;
  vehicle.max_steering_rate_radps = 0.7;
  vehicle.max_steering_acceleration_radps2 = 3.0;
  TuningOptions options = box_route();
  options.max_longitudinal_acceleration_mps2 = 2.0;
  check_limits_while_the_speed_changes(vehicle, options, 33);
  options.certificate = Certificate::feedforward;
  check_limits_while_the_speed_changes(vehicle, options, 34);
}

TEST(ScheduledLoop, AcceptsTheMatchedDisturbanceOfItsChain) {
  // Simulations inject kappa_d through SteeringController::set_matched_disturbance; the
  // scheduled controller must pass it to its lead wheel rather than let it bend the plant.
  auto path = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 100.0));
  ScheduledController controller(compute_gain_schedule(example_vehicle(), box_route(),
                                                       speed_grid(1.0, 5.0, 1.0), shared_map()),
                                 path);
  SteeringController& any = controller;
  EXPECT_TRUE(any.set_matched_disturbance(0.01));
}

//! The paper's C^1 controller for a random lambda_l; kbar_l = sin(theta) / lambda_veh gives the
//! real angle bound theta for any lambda_l.
ControllerParameters random_paper_c1(Random& random, double vehicle, double theta) {
  return ControllerParameters::paper_c1(vehicle, random.uniform(0.1, 0.9) * vehicle,
                                        std::sin(theta) / vehicle, 0.3);
}

TEST(Retune, KeepsTheSteeringRateForTheC1Controller) {
  // n = 2: d delta_veh/ds depends on (delta_1, delta_2) only, so retune() can and does keep it;
  // otherwise every retune of a gain schedule would be a step in the steering rate.
  auto path = std::make_shared<const Path>(Path::straight_line({-100.0, 0.0}, 0.0, 400.0));
  for (int k = 0; k < property_cases(40); ++k) {
    Random random(case_seed(k) + 34);
    const double vehicle = random.uniform(2.0, 3.5);
    const double theta = random.uniform(0.2, 0.8);
    const ControllerParameters a = random_paper_c1(random, vehicle, theta);
    const ControllerParameters b =
        random_paper_c1(random, vehicle, theta * random.uniform(0.9, 1.1));
    SCOPED_TRACE(seed_message(case_seed(k)));
    LeadWheelController controller(a, path);
    ControllerOutput out;
    const Vec2 position{0.0, random.uniform(-5.0, 5.0)};
    const double heading = random.uniform(-0.5, 0.5);
    for (int step = 0; step < random.integer(5, 40); ++step) {
      controller.update({position, heading, 5.0, 0.0, 0.02}, out);
    }
    // With v = 1 m/s and a vanishing period the output rate is d delta_veh / ds itself.
    const ControllerInput probe{position, heading, 1.0, 0.0, 1e-12};
    ASSERT_EQ(controller.update(probe, out), Status::ok);
    const double angle_before = out.steering_angle_rad, rate_before = out.steering_rate_radps;
    ASSERT_EQ(controller.retune(b), Status::ok);
    ASSERT_EQ(controller.update(probe, out), Status::ok);
    // retune() never clamps (a state outside a shrunken set returns under the flow), so both
    // are kept in every case.
    EXPECT_NEAR(out.steering_angle_rad, angle_before, 1e-9);
    EXPECT_NEAR(out.steering_rate_radps, rate_before, 1e-9 * (1.0 + std::abs(rate_before)));
  }
}

TEST(Retune, KeepsSteeringContinuousAndRejectsBadParameters) {
  auto path = std::make_shared<const Path>(Path::circle({0.0, 0.0}, 40.0));
  for (int k = 0; k < property_cases(40); ++k) {
    Random random(case_seed(k) + 33);
    const double vehicle = random.uniform(2.0, 3.5);
    // kbar_l = sin(theta) / lambda_veh gives the real angle bound theta for any lambda_l.
    const double theta = random.uniform(0.1, 0.8);
    const ControllerParameters a = random_paper_c1(random, vehicle, theta);
    const ControllerParameters b =
        random_paper_c1(random, vehicle, theta * random.uniform(1.0, 1.5));
    SCOPED_TRACE(seed_message(case_seed(k)));
    LeadWheelController controller(a, path);
    const double measured = random.uniform(-1.0, 1.0) * controller.bounds().steering_angle_rad;
    controller.reset(measured);
    const double before = controller.vehicle_steering_angle(controller.chain_angles()[0]);
    ASSERT_EQ(controller.retune(b), Status::ok);
    // b's set is at least as large (kbar grows, eq. kappalmax is independent of lambda_l).
    EXPECT_NEAR(controller.vehicle_steering_angle(controller.chain_angles()[0]), before, 1e-12);
    EXPECT_EQ(controller.parameters().chain.wheelbases_m[1], b.chain.wheelbases_m[1]);
    for (int i = 0; i < 2; ++i) {
      EXPECT_LE(std::abs(controller.chain_angles()[i]), controller.bounds().angle[i] * (1 + 1e-15));
    }
    ControllerParameters bad = b;
    bad.chain.lead_curvature_bound = std::nan("");
    EXPECT_EQ(controller.retune(bad), Status::invalid_input);
    bad = b;
    bad.chain.order = 3;
    EXPECT_EQ(controller.retune(bad), Status::invalid_input);
    EXPECT_EQ(controller.parameters().chain.lead_curvature_bound, b.chain.lead_curvature_bound);
  }
}

}  // namespace
}  // namespace smoothsteer
