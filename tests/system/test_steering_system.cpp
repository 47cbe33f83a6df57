// SteeringSystem (system/steering_system.hpp) and make_steering_system (tuning/
// vehicle_steering_system.hpp): construction errors name the field; the slip inputs; the active
// limits; the set_path contract.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/system/steering_system.hpp"
#include "smoothsteer/tuning/vehicle_steering_system.hpp"

namespace smoothsteer {
namespace {

std::shared_ptr<const Path> circle() {
  return std::make_shared<const Path>(Path::circle({0.0, 0.0}, 40.0));
}

ControllerParameters car_parameters(const VehicleParameters& vehicle) {
  ControllerParameters p;
  p.chain.vehicle_wheelbase_m = vehicle.wheelbase_m();
  return p;
}

//! The message of the std::invalid_argument that `build` throws ("" if none).
template <typename Build>
std::string message_of(Build&& build) {
  try {
    build();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(SteeringSystemConstruction, InvalidInputsNameTheField) {
  const VehicleParameters vehicle;
  EXPECT_EQ(message_of([] {
              SteeringSystem s(std::unique_ptr<SteeringController>{}, SteeringSystemParameters{});
            }),
            "SteeringSystem: controller is null; a controller is required");
  SteeringSystemParameters bad_observer;
  bad_observer.observer.mass_kg = -1.0;
  EXPECT_NE(message_of([&] {
              SteeringSystem s(
                  std::make_unique<LeadWheelController>(car_parameters(vehicle), circle()),
                  bad_observer);
            }).find("SteeringSystemParameters: observer.mass_kg = -1"),
            std::string::npos);
  // Without the observer its parameters are not read.
  bad_observer.slip_input = SlipInput::kinematic;
  EXPECT_NO_THROW(SteeringSystem(
      std::make_unique<LeadWheelController>(car_parameters(vehicle), circle()), bad_observer));
  SteeringSystemParameters bad_source;
  bad_source.slip_input = static_cast<SlipInput>(7);
  EXPECT_NE(message_of([&] {
              SteeringSystem s(
                  std::make_unique<LeadWheelController>(car_parameters(vehicle), circle()),
                  bad_source);
            }).find("SteeringSystemParameters: slip_input = 7"),
            std::string::npos);
  ControllerParameters wrong_wheelbase;
  wrong_wheelbase.chain.vehicle_wheelbase_m = 2.7;
  EXPECT_EQ(message_of([&] { SteeringSystem s(vehicle, wrong_wheelbase, circle()); }),
            "ControllerParameters: vehicle_wheelbase_m = 2.7 must be the vehicle's wheelbase lf + "
            "lr = 2.578");
  EXPECT_EQ(message_of([&] { SteeringSystem s(vehicle, car_parameters(vehicle), nullptr); }),
            "SteeringSystem: path is null; a path is required");
  ControllerParameters bad_k_rob = car_parameters(vehicle);
  bad_k_rob.law.k_rob = 1.5;
  EXPECT_NE(message_of([&] { SteeringSystem s(vehicle, bad_k_rob, circle()); }).find("k_rob = 1.5"),
            std::string::npos);
}

TEST(SteeringSystemConstruction, VehicleDescriptionAndOptionsNameTheField) {
  VehicleDescription car;
  car.vehicle.max_steering_acceleration_radps2 = 8.0;
  SteeringSystemOptions options;
  options.max_speed_mps = 12.0;
  EXPECT_NO_THROW(make_steering_system(car, circle(), options));
  EXPECT_EQ(message_of([&] { make_steering_system(car, nullptr, options); }),
            "make_steering_system: path is null; a path is required");
  SteeringSystemOptions bad = options;
  bad.max_speed_mps = -1.0;
  EXPECT_EQ(message_of([&] { make_steering_system(car, circle(), bad); }),
            "SteeringSystemOptions: max_speed_mps = -1 must be in (0, 100] m/s");
  bad = options;
  bad.feedforward_headroom = 0.5;
  EXPECT_EQ(message_of([&] { make_steering_system(car, circle(), bad); }),
            "SteeringSystemOptions: feedforward_headroom = 0.5 must be in [1, 3]");
  bad = options;
  bad.actuator_delay_s = 2.0;
  EXPECT_EQ(message_of([&] { make_steering_system(car, circle(), bad); }),
            "SteeringSystemOptions: actuator_delay_s = 2 must be in [0, max_actuator_delay_s = 1");
  bad = options;
  bad.speed_step_mps = 0.0;
  EXPECT_EQ(message_of([&] { make_steering_system(car, circle(), bad); }),
            "SteeringSystemOptions: speed_step_mps = 0 must be in [0.01, max_speed_mps] m/s");
  VehicleDescription bad_car = car;
  bad_car.actuator.bandwidth_hz = 0.0;
  EXPECT_EQ(message_of([&] { make_steering_system(bad_car, circle(), options); }),
            "VehicleDescription: actuator.bandwidth_hz = 0 must be finite and > 0");
  bad_car = car;
  bad_car.vehicle.mass_kg = 0.0;
  EXPECT_NE(message_of([&] {
              make_steering_system(bad_car, circle(), options);
            }).find("VehicleParameters: mass_kg = 0"),
            std::string::npos);
  bad_car = car;
  bad_car.vehicle.max_steering_acceleration_radps2 = std::numeric_limits<double>::infinity();
  EXPECT_NE(message_of([&] { make_steering_system(bad_car, circle(), options); })
                .find("controller.governor.enabled needs the vehicle's "
                      "max_steering_acceleration_radps2"),
            std::string::npos);
}

TEST(SteeringSystemConstruction, TheCarDeterminesItsFields) {
  VehicleDescription car;
  car.vehicle.max_steering_acceleration_radps2 = 8.0;
  car.actuator.dead_time_s = 0.01;
  SteeringSystemOptions options;
  options.friction_guard = true;
  const ControllerParameters p = steering_system_controller(car, options);
  EXPECT_EQ(p.chain.vehicle_wheelbase_m, car.vehicle.wheelbase_m());
  EXPECT_EQ(p.single_track.rear_slip_gradient_s2pm, car.vehicle.rear_slip_gradient());
  EXPECT_EQ(p.single_track.front_slip_gradient_s2pm, car.vehicle.front_slip_gradient());
  EXPECT_EQ(p.friction_guard.max_lateral_acceleration_mps2, car.vehicle.friction_limit_mps2());
  EXPECT_EQ(p.governor.max_steering_rate_radps, car.vehicle.max_steering_rate_radps);
  // 10 Hz third-order low-pass: w_p = 123.2 rad/s, three lags delay by 24.3 ms.
  EXPECT_NEAR(p.delay_compensation.actuator_delay_s, 0.01 + 0.02435, 1e-4);
  options.actuator_delay_s = 0.048;
  options.slip_preview = false;
  EXPECT_EQ(steering_system_controller(car, options).delay_compensation.actuator_delay_s, 0.048);
  EXPECT_EQ(steering_system_controller(car, options).single_track.rear_slip_gradient_s2pm, 0.0);
}

SteeringSystemInput straight_input(double x) {
  SteeringSystemInput input;
  input.rear_axle_position = {x, 0.5};
  input.speed_mps = 10.0;
  return input;
}

TEST(SteeringSystemUpdate, SlipInputs) {
  const VehicleParameters vehicle;
  auto path = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 200.0));
  SteeringSystem kinematic(vehicle, car_parameters(vehicle), path, SlipInput::kinematic);
  SteeringSystem sensor(vehicle, car_parameters(vehicle), path, SlipInput::sensor);
  SteeringSystem observed(vehicle, car_parameters(vehicle), path, SlipInput::observer);
  EXPECT_EQ(kinematic.observer(), nullptr);
  ASSERT_NE(observed.observer(), nullptr);
  SteeringSystemOutput out;
  SteeringSystemInput input = straight_input(10.0);
  input.rear_axle_side_slip_rad = 0.02;
  input.yaw_rate_radps = 0.1;
  input.lateral_acceleration_mps2 = 1.0;
  ASSERT_EQ(kinematic.update(input, out), Status::ok);
  EXPECT_EQ(out.side_slip.rear_axle_side_slip_rad, 0.0);
  ASSERT_EQ(sensor.update(input, out), Status::ok);
  EXPECT_EQ(out.side_slip.rear_axle_side_slip_rad, 0.02);
  EXPECT_EQ(sensor.controller_input().rear_axle_side_slip_rad, 0.02);
  ASSERT_EQ(observed.update(input, out), Status::ok);
  EXPECT_EQ(out.side_slip.observer_status, Status::ok);
  EXPECT_EQ(out.side_slip.rear_axle_side_slip_rad, observed.observer()->rear_axle_side_slip_rad());
  EXPECT_NE(out.side_slip.rear_axle_side_slip_rad, 0.0);
  // A sensor beyond the controller's range is the controller's invalid input; the output stays.
  const SteeringSystemOutput kept = out;
  input.rear_axle_side_slip_rad = 0.9;
  EXPECT_EQ(sensor.update(input, out), Status::invalid_input);
  EXPECT_EQ(out.steering_angle_rad, kept.steering_angle_rad);
  // A NaN gyro is a dropped sample: the observer predicts that channel, counts it, and the law
  // keeps its estimate.
  input.yaw_rate_radps = std::nan("");
  ASSERT_EQ(observed.update(input, out), Status::ok);
  EXPECT_EQ(out.side_slip.observer_status, Status::ok);
  EXPECT_EQ(out.side_slip.sensors.yaw_rate_dropped, 1u);
  EXPECT_EQ(out.side_slip.sensors.last_period, fault_yaw_rate_dropped);
  EXPECT_TRUE(out.side_slip.estimate_trusted);
  EXPECT_EQ(out.side_slip.rear_axle_side_slip_rad, observed.observer()->rear_axle_side_slip_rad());
}

TEST(SteeringSystemUpdate, ActiveLimitsNameTheBindingBound) {
  const VehicleParameters vehicle;
  auto path = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 500.0));
  ControllerParameters p = car_parameters(vehicle);
  p.chain.lead_curvature_bound = 0.1;
  SteeringSystem system(vehicle, p, path, SlipInput::kinematic);
  SteeringSystemOutput out;
  // On the path: nothing binds.
  SteeringSystemInput on_path = straight_input(0.0);
  on_path.rear_axle_position.y = 0.0;
  ASSERT_EQ(system.update(on_path, out), Status::ok);
  EXPECT_EQ(out.active_limits, limit_none) << describe_active_limits(out.active_limits);
  // 20 m off: the switching part saturates.
  SteeringSystemInput far = straight_input(1.0);
  far.rear_axle_position.y = 20.0;
  for (int k = 0; k < 5; ++k) ASSERT_EQ(system.update(far, out), Status::ok);
  EXPECT_TRUE(out.active_limits & limit_switching_bound)
      << describe_active_limits(out.active_limits);
  EXPECT_EQ(describe_active_limits(limit_lead_curvature | limit_friction_guard),
            "lead_curvature|friction_guard");
  EXPECT_EQ(describe_active_limits(0), "none");
  // The friction guard: at 30 m/s with mu g = 1 m/s^2 the lead curvature is held to ~1/900.
  p.friction_guard = {.enabled = true, .max_lateral_acceleration_mps2 = 1.0};
  SteeringSystem guarded(vehicle, p, path, SlipInput::kinematic);
  far.speed_mps = 30.0;
  for (int k = 0; k < 5; ++k) ASSERT_EQ(guarded.update(far, out), Status::ok);
  EXPECT_TRUE(out.active_limits & limit_friction_guard)
      << describe_active_limits(out.active_limits);
}

TEST(SteeringSystemUpdate, SetPathHasTheControllersContract) {
  const VehicleParameters vehicle;
  SteeringSystem system(vehicle, car_parameters(vehicle), circle(), SlipInput::kinematic);
  EXPECT_EQ(system.set_path(nullptr), Status::invalid_input);
  SteeringSystemOutput out;
  ASSERT_EQ(system.update(straight_input(0.0), out), Status::ok);
  EXPECT_EQ(system.set_path(std::make_shared<const Path>(Path::straight_line({0, 0}, 0.0, 100.0))),
            Status::ok);
  ASSERT_EQ(system.update(straight_input(0.2), out), Status::ok);
  EXPECT_NEAR(out.tracking.lateral_error_m, 0.5, 1e-9);  // now against the straight path
}

}  // namespace
}  // namespace smoothsteer
