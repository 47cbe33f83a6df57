// One validation shape: is_valid() noexcept, validation_error() and validate() agree,
// and every message is "<Struct>: <field> = <exact value> <rule>".

#include <gtest/gtest.h>

#include <stdexcept>

#include "smoothsteer/sim/metrics.hpp"
#include "smoothsteer/sim/simulation.hpp"
#include "smoothsteer/vehicle/steering_actuator.hpp"
#include "smoothsteer/vehicle/vehicle_parameters.hpp"
#include "support/validation_shape.hpp"

namespace smoothsteer {
namespace {

using testing::expect_shape;

TEST(ValidationShape, EveryParameterStructOffersTheSameThreeCalls) {
  VehicleParameters car;
  car.rear_tire.friction_mu = -0.25;
  expect_shape(VehicleParameters{}, car,
               "VehicleParameters: rear_tire.friction_mu = -0.25 must be finite and > 0");
  SimulationParameters sim;
  sim.control_period_s = 0.0200001;
  expect_shape(SimulationParameters{}, sim,
               "SimulationParameters: control_period_s = 0.0200001 must be a whole multiple of "
               "substep_s = 0.001");
  MetricsParameters metrics;
  metrics.reaching_threshold_m = 0.0;
  expect_shape(MetricsParameters{}, metrics,
               "MetricsParameters: reaching_threshold_m = 0 must be finite and > 0");
  SpeedProfile speed;
  speed.acceleration_mps2 = 25.0;
  expect_shape(SpeedProfile{}, speed, "SpeedProfile: acceleration_mps2 = 25 must be in [0, 20]");

  ActuatorParameters actuator;
  EXPECT_TRUE(actuator.is_valid(0.001));
  actuator.dead_time_s = 0.0105;
  EXPECT_FALSE(actuator.is_valid(0.001));
  EXPECT_EQ(actuator.validation_error(0.001),
            "ActuatorParameters: dead_time_s = 0.0105 must be a whole multiple of the plant "
            "sub-step (the delay is exact); sub-step [s] = 0.001");
  EXPECT_THROW(actuator.validate(0.001), std::invalid_argument);
}

}  // namespace
}  // namespace smoothsteer
