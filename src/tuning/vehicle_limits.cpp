#include "smoothsteer/tuning/vehicle_limits.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace smoothsteer {
std::optional<Violation> VehicleLimits::first_violation() const noexcept {
  RuleChecker check("VehicleLimits");
  check.require_positive({{"wheelbase_m", wheelbase_m}});
  check.require(
      positive_finite(max_steering_angle_rad) && max_steering_angle_rad < std::numbers::pi / 2.0,
      "max_steering_angle_rad", max_steering_angle_rad, "must be in (0, pi/2)");
  check.require_positive({{"max_steering_rate_radps", max_steering_rate_radps}});
  check.require(max_steering_acceleration_radps2 > 0.0, "max_steering_acceleration_radps2",
                max_steering_acceleration_radps2, "must be > 0 (+inf for no limit)");
  check.require(max_lateral_acceleration_mps2 > 0.0, "max_lateral_acceleration_mps2",
                max_lateral_acceleration_mps2, "must be > 0 (+inf for no friction limit)");
  return check.first();
}

}  // namespace smoothsteer
