#pragma once
// Shared helpers of the comparison controllers (internal).

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path.hpp"

namespace smoothsteer::detail {

//! Throws std::invalid_argument "<owner>: <field> = <value> <rule>" unless `ok`.
inline void require(bool ok, const char* owner, const char* field, double value,
                    const std::string& rule) {
  if (ok) return;
  std::ostringstream message;
  message.precision(10);
  message << owner << ": " << field << " = " << value << " " << rule;
  throw std::invalid_argument(message.str());
}

inline bool positive_finite(double value) {
  return std::isfinite(value) && value > 0.0;
}

//! The parameters of the extended system x_ext (eq. x_ext) with C1 and C2, shared by HOSM and the
//! optimal reaching problem: lambda > 0, delta-bar in (0, pi/2), delta-bar' > 0.
inline void require_x_ext_limits(const char* owner, double wheelbase_m,
                                 double steering_angle_bound_rad,
                                 double steering_rate_bound_per_m) {
  require(positive_finite(wheelbase_m), owner, "wheelbase_m", wheelbase_m,
          "must be finite and > 0");
  require(positive_finite(steering_angle_bound_rad) && steering_angle_bound_rad < pi / 2.0, owner,
          "steering_angle_bound_rad", steering_angle_bound_rad, "must be in (0, pi/2)");
  require(positive_finite(steering_rate_bound_per_m), owner, "steering_rate_bound_per_m",
          steering_rate_bound_per_m, "must be finite and > 0");
}

inline bool valid_input(const ControllerInput& input) noexcept {
  return std::isfinite(input.rear_axle_position.x) && std::isfinite(input.rear_axle_position.y) &&
         std::isfinite(input.heading_rad) && std::isfinite(input.speed_mps) &&
         std::isfinite(input.acceleration_mps2) && std::isfinite(input.period_s) &&
         input.period_s > 0.0;
}

//! Rear-axle tracking state relative to the path, for forward driving.
struct RearTracking {
  PathProjection projection;
  double heading_error_rad = 0.0;  //!< psi - path heading at the closest point, wrapped
};

inline RearTracking track_rear_axle(const Path& path, ProjectionHint& hint,
                                    const ControllerInput& input) noexcept {
  RearTracking tracking;
  tracking.projection = path.project(input.rear_axle_position, hint);
  tracking.heading_error_rad = wrap_angle(input.heading_rad - tracking.projection.heading_rad);
  return tracking;
}

//! Fills the diagnostics every comparison controller reports: rear and real-front-axle errors.
inline void fill_diagnostics(const Path& path, ProjectionHint& front_hint,
                             const ControllerInput& input, const RearTracking& rear,
                             double vehicle_wheelbase_m, double steering_angle_rad,
                             TrackingDiagnostics& diagnostics) noexcept {
  const Vec2 front =
      input.rear_axle_position + vehicle_wheelbase_m * unit_from_heading(input.heading_rad);
  const PathProjection front_projection = path.project(front, front_hint);
  diagnostics.lateral_error_m = rear.projection.lateral_error_m;
  diagnostics.heading_error_rad = rear.heading_error_rad;
  diagnostics.front_lateral_error_m = front_projection.lateral_error_m;
  diagnostics.lead_lateral_error_m = front_projection.lateral_error_m;
  diagnostics.lead_heading_error_rad =
      wrap_angle(input.heading_rad + steering_angle_rad - front_projection.heading_rad);
  diagnostics.path_arc_length_m = rear.projection.arc_length_m;
  diagnostics.path_curvature = rear.projection.curvature;
  diagnostics.fictive_steering_angle_rad = steering_angle_rad;
}

}  // namespace smoothsteer::detail
