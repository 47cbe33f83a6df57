#pragma once
// The one helper of the comparison controllers (internal): parameter checks
// (parameter_checks.hpp), input validation, rear-axle tracking and filling the output.

#include <algorithm>
#include <cmath>

#include "smoothsteer/baselines/parameter_checks.hpp"
#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path.hpp"

namespace smoothsteer::detail {

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

//! Fills the output of a comparison controller: the command, its rate as the difference to
//! `previous` over the period, `derivatives` and the acceleration where the controller has them,
//! the sliding variable, the lead curvature tan(delta)/lambda and the diagnostics.
inline void fill_output(const Path& path, ProjectionHint& front_hint, const ControllerInput& input,
                        const RearTracking& rear, double vehicle_wheelbase_m,
                        double steering_angle_rad, double previous_steering_angle_rad,
                        double sliding_variable, ControllerOutput& output, int derivatives = 0,
                        double steering_acceleration_radps2 = 0.0) noexcept {
  output.steering_angle_rad = steering_angle_rad;
  output.steering_rate_radps = (steering_angle_rad - previous_steering_angle_rad) / input.period_s;
  output.steering_acceleration_radps2 = steering_acceleration_radps2;
  output.derivatives_available = derivatives;
  output.diagnostics.sliding_variable = sliding_variable;
  output.diagnostics.lead_curvature = std::tan(steering_angle_rad) / vehicle_wheelbase_m;
  fill_diagnostics(path, front_hint, input, rear, vehicle_wheelbase_m, steering_angle_rad,
                   output.diagnostics);
}

}  // namespace smoothsteer::detail
