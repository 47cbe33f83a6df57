#pragma once
// The planner of stack mode (internal to src/sim; SimulationParameters::planner,
// planner_windows.hpp): the window of the road a driving stack's planner would send, as the
// path the system is handed by set_path().

#include <memory>
#include <random>

#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/waypoint_conditioner.hpp"
#include "smoothsteer/sim/planner_windows.hpp"

namespace smoothsteer::detail {

//! The window of `road` around arc length `center_m` (the rear axle's closest point): from
//! center_m - behind_m to center_m + ahead_m, cut to [0, length] on an open road (at least two
//! spacings long where the road allows) and wrapped on a closed one (at most 3/4 of
//! its length), in equal steps of at most
//! spacing_m, each coordinate jittered by N(0, jitter_std_m^2) from `engine`, fitted by
//! Path::from_waypoints at the windows' smoothing_tolerance_m or, without one, by `conditioner`
//! (the jitter pooled over the windows so far). Allocates; throws what from_waypoints throws.
std::shared_ptr<const Path> planner_window(const Path& road, double center_m,
                                           const PlannerWindows& windows, std::mt19937_64& engine,
                                           WaypointConditioner& conditioner);

}  // namespace smoothsteer::detail
