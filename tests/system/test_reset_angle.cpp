// reset(d) with the wheel's measured angle: an angle beyond the certified set is approached
// within the car's rate limit (it used to snap: reset(0.3) at 12 m/s gave 0.1807 rad at once,
// 5.96 rad/s against 0.4), and an angle that is not one (NaN, inf, |d| >= pi / 2, beyond the
// car's angle limit) is refused with invalid_input and changes nothing (reset(2.0) used to wrap
// to -1.066 rad, full lock the other way; NaN and inf were silently 0).

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <numbers>

#include "smoothsteer/io/schedule_files.hpp"
#include "smoothsteer/io/vehicle_file.hpp"
#include "smoothsteer/system/steering_system.hpp"
#include "smoothsteer/tuning/scheduled_controller.hpp"
#include "smoothsteer/tuning/vehicle_steering_system.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer {
namespace {

struct Car {
  VehicleDescription description;
  std::shared_ptr<const Path> path;
  SteeringSystem system;
};

Car example_car() {
  VehicleDescription car;
  car.vehicle = io::load_vehicle_file(testing::source_file("vehicles/passenger_car.yaml"));
  car.actuator.bandwidth_hz = 10.0;
  car.actuator.dead_time_s = 0.0;
  auto path = std::make_shared<const Path>(
      Path::from_waypoints({{0, 0}, {30, 0}, {60, 3.5}, {90, 3.5}, {120, 0}, {160, 0}}));
  SteeringSystemOptions options;
  options.max_speed_mps = 15.0;
  SteeringSystem system = make_steering_system(car, path, options);
  return {car, path, std::move(system)};
}

SteeringSystemInput on_the_line(double speed, int k) {
  SteeringSystemInput in;
  in.rear_axle_position = {speed * 0.02 * k, 0.2};
  in.speed_mps = speed;
  in.period_s = 0.02;
  return in;
}

TEST(ResetAngle, BeyondTheCertifiedSetIsApproachedWithinTheRateLimit) {
  Car car = example_car();
  const double rate_limit = car.description.vehicle.max_steering_rate_radps;  // 0.4 rad/s
  for (const double measured : {0.3, -0.3, 0.6, -1.0}) {
    // At 12 m/s, tuned for it: the certified set ends at 0.18 rad.
    SteeringSystemOutput out;
    int k = 0;
    ASSERT_EQ(car.system.reset(0.0), Status::ok);
    for (; k < 50; ++k) ASSERT_EQ(car.system.update(on_the_line(12.0, k), out), Status::ok);
    ASSERT_EQ(car.system.reset(measured), Status::ok) << measured;
    double previous = measured, worst = 0.0;
    for (; k < 250; ++k) {
      ASSERT_EQ(car.system.update(on_the_line(12.0, k), out), Status::ok);
      worst = std::max(worst, std::abs(out.steering_angle_rad - previous) / 0.02);
      previous = out.steering_angle_rad;
    }
    EXPECT_LE(worst, rate_limit * (1.0 + 1e-9)) << "reset(" << measured << ")";
    // And it got there: after 4 s the command is the chain's, inside the certified set.
    EXPECT_LT(std::abs(out.steering_angle_rad), 0.2) << "reset(" << measured << ")";
  }
}

TEST(ResetAngle, AnglesThatAreNoSteeringAngleAreRefusedAndChangeNothing) {
  Car car = example_car();
  Car twin = example_car();
  SteeringSystemOutput out, twin_out;
  int k = 0;
  for (; k < 20; ++k) {
    ASSERT_EQ(car.system.update(on_the_line(10.0, k), out), Status::ok);
    ASSERT_EQ(twin.system.update(on_the_line(10.0, k), twin_out), Status::ok);
  }
  const double inf = std::numeric_limits<double>::infinity();
  const double limit = car.description.vehicle.max_steering_angle_rad;  // 1.066 rad
  for (const double angle : {2.0, -2.0, 4.0, std::nan(""), inf, -inf, limit + 0.01, -1.5}) {
    EXPECT_EQ(car.system.reset(angle), Status::invalid_input) << "reset(" << angle << ")";
  }
  // The refused resets left no trace: the system carries on as its twin.
  for (int j = 0; j < 50; ++j, ++k) {
    ASSERT_EQ(car.system.update(on_the_line(10.0, k), out), Status::ok);
    ASSERT_EQ(twin.system.update(on_the_line(10.0, k), twin_out), Status::ok);
    ASSERT_EQ(std::memcmp(&out.steering_angle_rad, &twin_out.steering_angle_rad, sizeof(double)), 0)
        << j;
  }
  // The limit itself is a steering angle.
  EXPECT_EQ(car.system.reset(limit), Status::ok);
}

TEST(ResetAngle, ALeadWheelControllerRefusesAnglesAtRightAnglesOrBeyond) {
  const VehicleParameters vehicle;
  ControllerParameters p;
  p.chain.vehicle_wheelbase_m = vehicle.wheelbase_m();
  auto path = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 100.0));
  SteeringSystem system(vehicle, p, path, SlipInput::kinematic);
  EXPECT_EQ(system.reset(std::numbers::pi / 2.0), Status::invalid_input);
  EXPECT_EQ(system.reset(-3.0), Status::invalid_input);
  EXPECT_EQ(system.reset(1.5), Status::ok);
}

TEST(ResetAngle, AScheduledControllerHasTheCarsAngleLimitNotItsSchedules) {
  // A loaded schedule's vehicle angle is the largest its rows certify (0.93 rad here), not the
  // car's 1.066 rad: the scheduled controller refuses what its lead-wheel controller refuses.
  VehicleDescription car;
  car.vehicle = io::load_vehicle_file(testing::source_file("vehicles/passenger_car.yaml"));
  const GainSchedule schedule =
      io::read_schedule_csv(testing::source_file("scenarios/schedules/passenger_car_parking.csv"),
                            steering_system_controller(car, SteeringSystemOptions{}));
  const double tuned = schedule.vehicle().max_steering_angle_rad;
  const double limit = car.vehicle.max_steering_angle_rad;
  ASSERT_LT(tuned, limit - 0.1);
  auto path = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 100.0));
  ScheduledController scheduled(schedule, path);
  LeadWheelController alone(scheduled.parameters_at(5.0), path);
  for (const double angle :
       {0.0, tuned + 0.05, -(tuned + 0.05), limit, -limit, limit + 0.01, -(limit + 0.01), 1.5}) {
    const Status expected = std::abs(angle) <= limit ? Status::ok : Status::invalid_input;
    EXPECT_EQ(scheduled.reset(angle), expected) << "reset(" << angle << ")";
    EXPECT_EQ(alone.reset(angle), expected) << "reset(" << angle << ")";
  }
}

}  // namespace
}  // namespace smoothsteer
