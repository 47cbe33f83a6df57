// One validation shape for the tuner's structs: is_valid() noexcept,
// validation_error() and validate() agree on "<Struct>: <field> = <exact value> <rule>".

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "smoothsteer/tuning/gain_schedule.hpp"
#include "smoothsteer/tuning/static_map.hpp"
#include "smoothsteer/tuning/vehicle_limits.hpp"
#include "support/validation_shape.hpp"

namespace smoothsteer {
namespace {

using testing::expect_shape;

TEST(ValidationShape, TunerStructs) {
  VehicleLimits limits;
  limits.max_steering_acceleration_radps2 = std::numeric_limits<double>::quiet_NaN();
  expect_shape(VehicleLimits{}, limits,
               "VehicleLimits: max_steering_acceleration_radps2 = nan must be > 0 (+inf for no "
               "limit)");
  TuningOptions options;
  options.k_rob_floor = 0.95;
  expect_shape(TuningOptions{}, options,
               "TuningOptions: k_rob_floor = 0.95 must be in [0, k_rob_ceiling)");
  StaticMapOptions map;
  map.ratio_samples = 1;
  expect_shape(StaticMapOptions{}, map,
               "StaticMapOptions: ratio_samples = 1 must be in [2, 100000]");
}

// 1:1e300:1e-300 has 1e600 speeds: counted in double, refused before any integer holds it.
TEST(ValidationShape, SpeedGridCountsBeforeItConverts) {
  EXPECT_THROW(speed_grid(1.0, 1e300, 1e-300), std::invalid_argument);
  EXPECT_THROW(speed_grid(1.0, 2e5, 1.0), std::invalid_argument);
  EXPECT_EQ(speed_grid(1.0, 3.0, 0.5).size(), 5u);
}

}  // namespace
}  // namespace smoothsteer
