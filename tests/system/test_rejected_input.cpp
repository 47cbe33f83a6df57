// An update() that returns an error changes no state: not the observer, not the controller's
// disturbance estimator or delay line. For every input field, a system that took one invalid
// update gives, from the next valid update on, bit-identical outputs to a twin that never saw
// it. The gyro and the accelerometer are sensor channels, not errors (a NaN there is a dropped
// sample, test_sensor_faults.cpp): they ride along on an invalid update and leave no trace.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/system/steering_system.hpp"
#include "smoothsteer/vehicle/vehicle_parameters.hpp"

namespace smoothsteer {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

//! A controller whose every stage keeps state: delay line, disturbance estimator, chain.
ControllerParameters stateful_parameters(const VehicleParameters& vehicle) {
  ControllerParameters p;
  p.chain.vehicle_wheelbase_m = vehicle.wheelbase_m();
  p.delay_compensation = {.enabled = true, .actuator_delay_s = 0.1};
  p.disturbance_estimation = {.enabled = true, .length_m = 10.0};
  return p;
}

SteeringSystemInput input_at(int k) {
  SteeringSystemInput in;
  const double t = 0.02 * k;
  in.rear_axle_position = {10.0 * t, 0.5 + 0.1 * std::sin(t)};
  in.heading_rad = 0.02 * std::cos(t);
  in.speed_mps = 10.0;
  in.acceleration_mps2 = 0.1;
  in.yaw_rate_radps = 0.01 * std::sin(3.0 * t);
  in.lateral_acceleration_mps2 = 10.0 * in.yaw_rate_radps;
  in.steering_angle_rad = 0.005 * std::sin(2.0 * t);
  in.rear_axle_side_slip_rad = 0.01;
  in.period_s = 0.02;
  return in;
}

//! The bytes of everything update() reports that is a number.
bool same(const SteeringSystemOutput& a, const SteeringSystemOutput& b) {
  const double xs[] = {a.steering_angle_rad,
                       a.steering_rate_radps,
                       a.steering_acceleration_radps2,
                       a.tracking.lateral_error_m,
                       a.tracking.lead_curvature,
                       a.tracking.feedforward_curvature,
                       a.side_slip.rear_axle_side_slip_rad,
                       a.side_slip.lateral_velocity_mps,
                       a.side_slip.yaw_rate_radps};
  const double ys[] = {b.steering_angle_rad,
                       b.steering_rate_radps,
                       b.steering_acceleration_radps2,
                       b.tracking.lateral_error_m,
                       b.tracking.lead_curvature,
                       b.tracking.feedforward_curvature,
                       b.side_slip.rear_axle_side_slip_rad,
                       b.side_slip.lateral_velocity_mps,
                       b.side_slip.yaw_rate_radps};
  return std::memcmp(xs, ys, sizeof xs) == 0 &&
         a.side_slip.sensors.yaw_rate_rejected == b.side_slip.sensors.yaw_rate_rejected &&
         a.side_slip.sensors.yaw_rate_dropped == b.side_slip.sensors.yaw_rate_dropped;
}

struct BadField {
  const char* field;
  std::function<void(SteeringSystemInput&)> spoil;
  SlipInput slip = SlipInput::observer;
};

std::vector<BadField> bad_fields() {
  return {
      {"rear_axle_position.x = NaN",
       [](SteeringSystemInput& in) { in.rear_axle_position.x = kNaN; }},
      {"rear_axle_position.y = 1e10",
       [](SteeringSystemInput& in) { in.rear_axle_position.y = 1e10; }},
      {"heading_rad = inf",
       [](SteeringSystemInput& in) { in.heading_rad = std::numeric_limits<double>::infinity(); }},
      {"speed_mps = 1e4", [](SteeringSystemInput& in) { in.speed_mps = 1e4; }},
      {"speed_mps = NaN", [](SteeringSystemInput& in) { in.speed_mps = kNaN; }},
      {"acceleration_mps2 = 1e5", [](SteeringSystemInput& in) { in.acceleration_mps2 = 1e5; }},
      {"period_s = 0", [](SteeringSystemInput& in) { in.period_s = 0.0; }},
      {"period_s = -0.02", [](SteeringSystemInput& in) { in.period_s = -0.02; }},
      {"steering_angle_rad = NaN", [](SteeringSystemInput& in) { in.steering_angle_rad = kNaN; }},
      {"steering_angle_rad = 4", [](SteeringSystemInput& in) { in.steering_angle_rad = 4.0; }},
      // A gyro spike and an accelerometer spike on an update refused for its speed.
      {"yaw_rate_radps = 1 with speed_mps = 1e4",
       [](SteeringSystemInput& in) {
         in.yaw_rate_radps = 1.0;
         in.speed_mps = 1e4;
       }},
      {"lateral_acceleration_mps2 = 20 with period_s = NaN",
       [](SteeringSystemInput& in) {
         in.lateral_acceleration_mps2 = 20.0;
         in.period_s = kNaN;
       }},
      {"rear_axle_side_slip_rad = 0.9 (slip sensor)",
       [](SteeringSystemInput& in) {
         in.rear_axle_side_slip_rad = 0.9;
         in.speed_mps = 12.0;  // would retune a schedule
       },
       SlipInput::sensor},
      {"rear_axle_side_slip_rad = NaN (slip sensor)",
       [](SteeringSystemInput& in) { in.rear_axle_side_slip_rad = kNaN; }, SlipInput::sensor},
  };
}

TEST(RejectedInput, ChangesNoStateForAnyField) {
  const VehicleParameters vehicle;
  auto path = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 500.0));
  for (const BadField& bad : bad_fields()) {
    SteeringSystem system(vehicle, stateful_parameters(vehicle), path, bad.slip);
    SteeringSystem twin(vehicle, stateful_parameters(vehicle), path, bad.slip);
    SteeringSystemOutput out, twin_out;
    int k = 0;
    for (; k < 50; ++k) {
      ASSERT_EQ(system.update(input_at(k), out), Status::ok) << bad.field;
      ASSERT_EQ(twin.update(input_at(k), twin_out), Status::ok) << bad.field;
    }
    SteeringSystemInput spoiled = input_at(k);
    bad.spoil(spoiled);
    const SteeringSystemOutput before = out;
    EXPECT_EQ(system.update(spoiled, out), Status::invalid_input) << bad.field;
    EXPECT_TRUE(same(out, before)) << bad.field << ": the output changed";
    // The twin never sees it; from the next period on both must agree bit for bit.
    for (int j = 0; j < 100; ++j, ++k) {
      ASSERT_EQ(system.update(input_at(k), out), Status::ok) << bad.field;
      ASSERT_EQ(twin.update(input_at(k), twin_out), Status::ok) << bad.field;
      if (!same(out, twin_out)) {
        ADD_FAILURE() << bad.field << ": differs " << j << " periods later";
        break;
      }
    }
  }
}

//! The controller alone: its stages (delay line, disturbance estimator, chain) take nothing
//! from an input it refuses.
TEST(RejectedInput, LeadWheelControllerStagesTakeNothing) {
  const VehicleParameters vehicle;
  auto path = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 500.0));
  const std::vector<std::pair<const char*, std::function<void(ControllerInput&)>>> spoilers = {
      {"x", [](ControllerInput& in) { in.rear_axle_position.x = kNaN; }},
      {"heading", [](ControllerInput& in) { in.heading_rad = 1e7; }},
      {"speed", [](ControllerInput& in) { in.speed_mps = -1e4; }},
      {"acceleration", [](ControllerInput& in) { in.acceleration_mps2 = kNaN; }},
      {"period", [](ControllerInput& in) { in.period_s = 2e3; }},
      {"slip", [](ControllerInput& in) { in.rear_axle_side_slip_rad = -0.6; }},
  };
  for (const auto& [field, spoil] : spoilers) {
    LeadWheelController controller(stateful_parameters(vehicle), path);
    LeadWheelController twin(stateful_parameters(vehicle), path);
    ControllerOutput out, twin_out;
    auto input = [](int k) {
      const SteeringSystemInput in = input_at(k);
      return ControllerInput{in.rear_axle_position, in.heading_rad, in.speed_mps,
                             in.acceleration_mps2,  in.period_s,    0.01};
    };
    int k = 0;
    for (; k < 50; ++k) {
      ASSERT_EQ(controller.update(input(k), out), Status::ok);
      ASSERT_EQ(twin.update(input(k), twin_out), Status::ok);
    }
    ControllerInput spoiled = input(k);
    spoil(spoiled);
    EXPECT_EQ(controller.update(spoiled, out), Status::invalid_input) << field;
    for (int j = 0; j < 100; ++j, ++k) {
      ASSERT_EQ(controller.update(input(k), out), Status::ok);
      ASSERT_EQ(twin.update(input(k), twin_out), Status::ok);
      ASSERT_EQ(std::memcmp(&out.steering_angle_rad, &twin_out.steering_angle_rad, sizeof(double)),
                0)
          << field << ": differs " << j << " periods later";
      ASSERT_EQ(controller.disturbance_estimate(), twin.disturbance_estimate()) << field;
    }
  }
}

}  // namespace
}  // namespace smoothsteer
