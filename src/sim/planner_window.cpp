#include "planner_window.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace smoothsteer {

namespace detail {

std::shared_ptr<const Path> planner_window(const Path& road, double center_m,
                                           const PlannerWindows& windows, std::mt19937_64& engine,
                                           WaypointConditioner& conditioner) {
  double begin = center_m - windows.behind_m;
  double end = center_m + windows.ahead_m;
  if (road.is_closed()) {
    end = std::min(end, begin + 0.75 * road.length());  // less than a lap: no loop on itself
  } else {
    const double length = road.length();
    const double shortest = std::min(length, 2.0 * windows.spacing_m);
    end = std::clamp(end, shortest, length);
    begin = std::clamp(begin, 0.0, end - shortest);
  }
  const auto steps =
      static_cast<std::size_t>(std::max(2.0, std::ceil((end - begin) / windows.spacing_m)));
  const double step = (end - begin) / static_cast<double>(steps);
  std::normal_distribution<double> jitter(0.0, 1.0);
  std::vector<Vec2> waypoints(steps + 1);
  for (std::size_t i = 0; i <= steps; ++i) {
    Vec2 point = road.evaluate(begin + step * static_cast<double>(i)).position;
    if (windows.jitter_std_m > 0.0) {
      point.x += windows.jitter_std_m * jitter(engine);
      point.y += windows.jitter_std_m * jitter(engine);
    }
    waypoints[i] = point;
  }
  if (windows.smoothing_tolerance_m) {
    return std::make_shared<const Path>(
        Path::from_waypoints(waypoints, WaypointSmoothing{*windows.smoothing_tolerance_m}));
  }
  return std::make_shared<const Path>(conditioner.fit(waypoints));
}

}  // namespace detail
}  // namespace smoothsteer
