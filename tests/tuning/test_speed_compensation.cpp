// The Smith predictor's delay and the catch-up over speed (speed_compensation.hpp): the formula at
// random cars and speeds, recomputed here from its definition; the limits of its range; the
// validation messages; and the ScheduledController handing them to the inner controller.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/tuning/path_demand.hpp"
#include "smoothsteer/tuning/scheduled_controller.hpp"
#include "smoothsteer/tuning/speed_compensation.hpp"
#include "smoothsteer/tuning/vehicle_steering_system.hpp"
#include "smoothsteer/vehicle/vehicle_parameters.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

using testing::case_seed;
using testing::property_cases;
using testing::Random;
using testing::seed_message;

SpeedCompensation random_compensation(Random& random) {
  SpeedCompensation c;
  c.actuator_group_delay_s = random.uniform(0.0, 0.1);
  c.slip_gradient_sum_s2pm = random.uniform(0.0, 0.03);
  c.design_curvature_per_m = random.uniform(0.0, 0.2);
  c.friction_limit_mps2 = random.uniform(2.0, 12.0);
  return c;
}

TEST(SpeedCompensation, FollowsItsDefinitionAndGrowsWithSpeed) {
  const int cases = property_cases();
  for (int k = 0; k < cases; ++k) {
    const auto seed = case_seed(k);
    Random random(seed);
    const SpeedCompensation c = random_compensation(random);
    const double v = random.uniform(0.0, 40.0);
    SCOPED_TRACE(seed_message(seed) + " v = " + std::to_string(v) +
                 " kappa_d = " + std::to_string(c.design_curvature_per_m));
    const double usage = std::min(1.0, v * v * c.design_curvature_per_m / c.friction_limit_mps2);
    EXPECT_NEAR(c.friction_usage(v), usage, 1e-12);
    EXPECT_NEAR(c.delay_s(v),
                c.actuator_group_delay_s +
                    SpeedCompensation::tire_lag_share * c.slip_gradient_sum_s2pm * v * usage,
                1e-12);
    EXPECT_EQ(c.delay_s(-v), c.delay_s(v));  // reversing: the same |v|
    EXPECT_GE(c.delay_s(v + 0.5), c.delay_s(v));
    EXPECT_EQ(c.catch_up(v),
              usage >= SpeedCompensation::catch_up_usage ? SpeedCompensation::catch_up_gain : 0.0);
  }
}

TEST(SpeedCompensation, StartsAtTheActuatorsDelayAndStaysWithinThePredictorsRange) {
  SpeedCompensation c;
  c.actuator_group_delay_s = 0.0243;
  c.slip_gradient_sum_s2pm = 0.0093;
  c.design_curvature_per_m = 0.0271;
  c.friction_limit_mps2 = 10.29;
  EXPECT_EQ(c.delay_s(0.0), 0.0243);
  EXPECT_EQ(c.catch_up(0.0), 0.0);
  // Beyond the tires' limit the usage saturates at 1; the delay never leaves the predictor's range.
  EXPECT_EQ(c.friction_usage(1e3), 1.0);
  c.slip_gradient_sum_s2pm = 0.2;
  EXPECT_EQ(c.delay_s(1e3), ControllerParameters::max_actuator_delay_s);
}

TEST(SpeedCompensation, ValidationNamesTheField) {
  SpeedCompensation c;
  c.actuator_group_delay_s = -0.01;
  EXPECT_NE(c.first_violation(), std::nullopt);
  EXPECT_EQ(describe(c.first_violation()),
            "SpeedCompensation: actuator_group_delay_s = -0.01 must be in [0, "
            "ControllerParameters::max_actuator_delay_s = 1");
  c = {};
  c.slip_gradient_sum_s2pm = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(describe(c.first_violation()).find("slip_gradient_sum_s2pm = nan"), std::string::npos)
      << describe(c.first_violation());
  c = {};
  c.design_curvature_per_m = -1.0;
  EXPECT_NE(
      describe(c.first_violation()).find("design_curvature_per_m = -1 must be finite and >= 0"),
      std::string::npos);
  c = {};
  c.friction_limit_mps2 = 0.0;
  EXPECT_NE(describe(c.first_violation()).find("friction_limit_mps2 = 0 must be finite and > 0"),
            std::string::npos);
}

TEST(SpeedCompensation, IsDerivedFromTheVehicleAndThePath) {
  const VehicleParameters car;  // the passenger car (vehicles/passenger_car.yaml)
  const auto path = std::make_shared<const Path>(
      PathBuilder({0.0, 0.0}, 0.0).line(20.0).arc(30.0, 1.0).line(20.0).build());
  const SpeedCompensation c = speed_compensation(car, 0.0243, path_demand(*path));
  EXPECT_EQ(c.actuator_group_delay_s, 0.0243);
  EXPECT_NEAR(c.design_curvature_per_m, 1.0 / 30.0, 1e-6);
  EXPECT_NEAR(c.slip_gradient_sum_s2pm, car.front_slip_gradient() + car.rear_slip_gradient(),
              1e-15);
  EXPECT_EQ(c.friction_limit_mps2, car.friction_limit_mps2());
}

}  // namespace
}  // namespace smoothsteer
