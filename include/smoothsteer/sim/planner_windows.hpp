#pragma once
//! \file planner_windows.hpp
//! A driving stack's planner as the simulator plays it (docs/simulation.md, "Stack mode"):
//! every `period_s` it samples the scenario's road from `behind_m` behind the rear axle's
//! closest point to `ahead_m` ahead, `spacing_m` apart, adds Gaussian jitter to each waypoint's
//! coordinates, fits them with `Path::from_waypoints` and hands the window to the car's system
//! by `set_path()`. The system never sees the whole road; the metrics still measure against it.

#include <optional>

namespace smoothsteer {

struct PlannerWindows {
  //! A new window every this many seconds, a whole multiple of the control period, in
  //! [0, 10]; 0: off (the system is given the whole road at the start). Stacks: 0.1 s.
  double period_s = 0.0;
  double behind_m = 5.0;    //!< window start behind the rear axle's closest point, [0, 1000] m
  double ahead_m = 100.0;   //!< window end ahead of it, [2 spacing_m, 10000] m
  double spacing_m = 1.0;   //!< waypoint spacing, [0.05, 50] m (equal steps over the window)
  double jitter_std_m = 0;  //!< Gaussian noise per waypoint coordinate, [0, 1] m
  //! Path::from_waypoints' smoothing tolerance [m], in [0, 10]; absent: as a stack that does
  //! not know its planner's noise fits them, by a WaypointConditioner (the jitter estimated
  //! from the windows themselves and pooled over them; clean windows are interpolated exactly).
  std::optional<double> smoothing_tolerance_m;

  bool active() const noexcept { return period_s > 0.0; }
};
// The rules are SimulationParameters::first_violation's (fields "planner.<key>").

}  // namespace smoothsteer
