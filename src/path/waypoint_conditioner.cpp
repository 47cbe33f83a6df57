//! The planner's windows fitted at their pooled jitter (include/smoothsteer/path/
//! waypoint_conditioner.hpp).

#include "smoothsteer/path/waypoint_conditioner.hpp"

#include <algorithm>
#include <cmath>

#include "smoothsteer/path/waypoint_jitter.hpp"

namespace smoothsteer {

std::optional<Violation> WaypointConditioner::Parameters::first_violation() const noexcept {
  RuleChecker check("WaypointConditioner::Parameters");
  check.require(std::isfinite(memory_windows) && memory_windows >= 1.0 && memory_windows <= 1e6,
                "memory_windows", memory_windows, "must be finite and in [1, 1e6]");
  check.require(std::isfinite(tolerance_m) && tolerance_m >= 0.0 && tolerance_m <= 10.0,
                "tolerance_m", tolerance_m, "must be finite and in [0, 10] m");
  return check.first();
}

WaypointConditioner::WaypointConditioner() : WaypointConditioner(Parameters{}) {}

WaypointConditioner::WaypointConditioner(Parameters parameters) : parameters_(parameters) {
  parameters_.validate();
}

Path WaypointConditioner::fit(const std::vector<Vec2>& waypoints) {
  double variance = pooled_variance_;
  std::size_t windows = windows_;
  if (waypoints.size() >= min_jitter_waypoints) {
    const double jitter = estimate_waypoint_jitter(waypoints);
    // The mean over the first windows, then an exponential memory of memory_windows.
    ++windows;
    const double weight = 1.0 / std::min(static_cast<double>(windows), parameters_.memory_windows);
    variance += weight * (jitter * jitter - variance);
  }
  const double tolerance =
      std::max(parameters_.tolerance_m, jitter_tolerance_m(std::sqrt(variance)));
  Path path = Path::from_waypoints(waypoints, WaypointSmoothing{tolerance, false});
  pooled_variance_ = variance;
  windows_ = windows;
  last_tolerance_m_ = tolerance;
  return path;
}

double WaypointConditioner::jitter_m() const noexcept {
  return std::sqrt(pooled_variance_);
}

void WaypointConditioner::reset() noexcept {
  pooled_variance_ = 0.0;
  windows_ = 0;
  last_tolerance_m_ = 0.0;
}

}  // namespace smoothsteer
