#pragma once
// The closed loop behind every simulate() overload (internal to src/sim): simulation.cpp wraps
// it with the controller's steering system and the stored trace; kinematic_closed_loop.cpp
// shares the controller's part of a trace sample.

#include "smoothsteer/sim/simulation.hpp"

namespace smoothsteer::detail {

//! The fields of a trace sample that the controller reports (from its view of the measured
//! pose), the same in the closed loop and the kinematic loop.
inline void record_controller_report(TraceSample& sample,
                                     const TrackingDiagnostics& diagnostics) noexcept {
  sample.lead_lateral_error_m = diagnostics.lead_lateral_error_m;
  sample.measured_lateral_error_m = diagnostics.lateral_error_m;
  sample.sliding_variable = diagnostics.sliding_variable;
  sample.lead_curvature = diagnostics.lead_curvature;
  sample.disturbance_curvature = diagnostics.disturbance_curvature;
}

//! The closed loop on `path`, or on the pieces of `plan` (then `path` is its piece 0), every
//! sample going to `observer`.
SimulationResult closed_loop(const Path& path, const PathPlan* plan, const VehicleModel& vehicle,
                             const ActuatorParameters& actuator_parameters,
                             const SpeedProfile& speed, const SimulationParameters& parameters,
                             const Pose2& start, SteeringSystem& system,
                             const TraceObserver& observer);

}  // namespace smoothsteer::detail
