//! The planner's windows fitted at their pooled jitter (include/smoothsteer/path/
//! waypoint_conditioner.hpp).

#include "smoothsteer/path/waypoint_conditioner.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "smoothsteer/path/waypoint_jitter.hpp"

namespace smoothsteer {

std::optional<Violation> WaypointConditioner::Parameters::first_violation() const noexcept {
  RuleChecker check("WaypointConditioner::Parameters");
  check.require(std::isfinite(memory_windows) && memory_windows >= 1.0 && memory_windows <= 1e6,
                "memory_windows", memory_windows, "must be finite and in [1, 1e6]");
  check.require(std::isfinite(tolerance_m) && tolerance_m >= 0.0 && tolerance_m <= 10.0,
                "tolerance_m", tolerance_m, "must be finite and in [0, 10] m");
  check.require(std::isfinite(history_m) && history_m >= 0.0 && history_m <= 1000.0, "history_m",
                history_m, "must be finite and in [0, 1000] m");
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
  // History is for the jitter: a clean window is interpolated alone, exactly.
  std::vector<Vec2> behind =
      tolerance > 0.0 ? history_behind(waypoints, tolerance) : std::vector<Vec2>{};
  std::optional<Path> with_history;
  if (!behind.empty()) {
    try {
      with_history = fit_with_history(behind, waypoints, tolerance);
    } catch (const std::invalid_argument&) {
      behind.clear();  // the history folds the fit back on itself (a reversal): the window alone
    }
  }
  Path path = with_history ? std::move(*with_history)
                           : Path::from_waypoints(waypoints, WaypointSmoothing{tolerance, false});
  history_ = std::move(behind);
  previous_ = waypoints;
  previous_path_ = path;
  pooled_variance_ = variance;
  windows_ = windows;
  last_tolerance_m_ = tolerance;
  return path;
}

std::vector<Vec2> WaypointConditioner::history_behind(const std::vector<Vec2>& waypoints,
                                                      double tolerance) const {
  if (parameters_.history_m <= 0.0 || !previous_path_ || waypoints.size() < 2) return {};
  // The new window must start on the last one's road (no replan in between), ahead of its start.
  const Vec2 start = waypoints.front();
  const PathProjection at = previous_path_->project(start);
  const double spacing = norm(waypoints[1] - waypoints[0]);
  if (std::abs(at.lateral_error_m) > 4.0 * tolerance + 0.02 || at.arc_length_m < 0.5 * spacing) {
    return {};
  }
  // The history behind the last window's start, then the last window's waypoints behind this
  // one's (along the last window's own order; arc length on its fit, chords on its waypoints).
  std::vector<Vec2> behind = history_;
  double s = 0.0;
  for (std::size_t i = 0; i < previous_.size(); ++i) {
    if (i > 0) s += norm(previous_[i] - previous_[i - 1]);
    if (s < at.arc_length_m - 0.5 * spacing) behind.push_back(previous_[i]);
  }
  // Keep history_m of chord length behind the start.
  double length = norm(start - (behind.empty() ? start : behind.back()));
  std::size_t first = behind.size();
  while (first > 0) {
    if (length > parameters_.history_m) break;
    --first;
    if (first > 0) length += norm(behind[first] - behind[first - 1]);
  }
  behind.erase(behind.begin(), behind.begin() + static_cast<std::ptrdiff_t>(first));
  return behind;
}

Path WaypointConditioner::fit_with_history(const std::vector<Vec2>& behind,
                                           const std::vector<Vec2>& waypoints,
                                           double tolerance) const {
  std::vector<Vec2> all = behind;
  all.insert(all.end(), waypoints.begin(), waypoints.end());
  const Path fitted = Path::from_waypoints(all, WaypointSmoothing{tolerance, false});
  // One cubic per pair of waypoints: the window's own start after those of the history.
  std::vector<PathSegment> segments(
      fitted.segments().begin() + static_cast<std::ptrdiff_t>(behind.size()),
      fitted.segments().end());
  return Path::from_segments(std::move(segments));
}

double WaypointConditioner::jitter_m() const noexcept {
  return std::sqrt(pooled_variance_);
}

void WaypointConditioner::reset() noexcept {
  pooled_variance_ = 0.0;
  windows_ = 0;
  last_tolerance_m_ = 0.0;
  history_.clear();
  previous_.clear();
  previous_path_.reset();
}

}  // namespace smoothsteer
