// The composed update() performs no heap allocation (counting allocator of tests/support): the
// certified schedule, the Magic-Formula observer, the governor and the Smith predictor included.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "smoothsteer/system/steering_system.hpp"
#include "smoothsteer/tuning/vehicle_steering_system.hpp"
#include "support/counting_allocator.hpp"

namespace smoothsteer {
namespace {

TEST(SteeringSystemRealTime, UpdateDoesNotAllocate) {
  VehicleDescription car;
  car.vehicle.max_steering_acceleration_radps2 = 8.0;
  auto path = std::make_shared<const Path>(Path::circle({0.0, 0.0}, 60.0));
  for (const SlipInput slip : {SlipInput::observer, SlipInput::sensor, SlipInput::kinematic}) {
    SteeringSystemOptions options;
    options.max_speed_mps = 15.0;
    options.slip_input = slip;
    options.friction_guard = true;
    SteeringSystem system = make_steering_system(car, path, options);
    SteeringSystemOutput output;
    const long before = allocation_count.load();
    for (int k = 0; k < 3000; ++k) {
      const double angle = 0.002 * k;
      SteeringSystemInput input;
      input.rear_axle_position = {61.0 * std::cos(angle), 61.0 * std::sin(angle)};
      input.heading_rad = angle + 1.5;
      input.speed_mps = k < 2500 ? 3.0 + 0.004 * k : -2.0;  // retunes, reversing
      input.yaw_rate_radps = 0.2;
      input.lateral_acceleration_mps2 = 2.0;
      if (k % 2 == 0) input.steering_angle_rad = 0.05;
      input.rear_axle_side_slip_rad = 0.01;
      system.update(input, output);
      input.rear_axle_position.x = std::nan("");  // invalid input: an error status, no allocation
      system.update(input, output);
      if (k % 500 == 0) system.set_path(path);
      if (k == 1000) system.reset(0.01);
    }
    EXPECT_EQ(allocation_count.load() - before, 0) << "slip input " << static_cast<int>(slip);
  }
}

}  // namespace
}  // namespace smoothsteer
