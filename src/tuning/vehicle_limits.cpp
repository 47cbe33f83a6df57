#include "smoothsteer/tuning/vehicle_limits.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace smoothsteer {
namespace {

std::string describe(const char* field, double value, const char* rule) {
  std::ostringstream message;
  message.precision(10);
  message << "VehicleLimits: " << field << " = " << value << " " << rule;
  return message.str();
}

}  // namespace

std::string VehicleLimits::validation_error() const {
  if (!std::isfinite(wheelbase_m) || wheelbase_m <= 0.0) {
    return describe("wheelbase_m", wheelbase_m, "must be finite and > 0");
  }
  if (!std::isfinite(max_steering_angle_rad) || max_steering_angle_rad <= 0.0 ||
      max_steering_angle_rad >= std::numbers::pi / 2.0) {
    return describe("max_steering_angle_rad", max_steering_angle_rad, "must be in (0, pi/2)");
  }
  if (!std::isfinite(max_steering_rate_radps) || max_steering_rate_radps <= 0.0) {
    return describe("max_steering_rate_radps", max_steering_rate_radps, "must be finite and > 0");
  }
  if (std::isnan(max_steering_acceleration_radps2) || max_steering_acceleration_radps2 <= 0.0) {
    return describe("max_steering_acceleration_radps2", max_steering_acceleration_radps2,
                    "must be > 0 (+inf for no limit)");
  }
  if (std::isnan(max_lateral_acceleration_mps2) || max_lateral_acceleration_mps2 <= 0.0) {
    return describe("max_lateral_acceleration_mps2", max_lateral_acceleration_mps2,
                    "must be > 0 (+inf for no friction limit)");
  }
  return {};
}

void VehicleLimits::validate() const {
  const std::string error = validation_error();
  if (!error.empty()) throw std::invalid_argument(error);
}

}  // namespace smoothsteer
