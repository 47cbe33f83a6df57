// Path::find_reversal: where a waypoint polyline doubles back, as one sharp turn or as several
// turns close together. The spline through them folds back there (a cusp no forward path has).

#include <cmath>
#include <deque>
#include <optional>
#include <vector>

#include "smoothsteer/path/path.hpp"

namespace smoothsteer {

std::optional<std::size_t> Path::find_reversal(const std::vector<Vec2>& waypoints) {
  const std::size_t n = waypoints.size();
  if (n < 3) return std::nullopt;
  // heading[v]: the unwrapped heading of the chord from waypoint v to v + 1, relative to the
  // first; the turns at waypoints a..b add up to heading[b] - heading[a - 1].
  std::vector<double> heading(n - 1, 0.0);
  std::vector<double> along(n, 0.0);  // arc length of the chords up to waypoint v
  for (std::size_t v = 1; v < n; ++v) {
    along[v] = along[v - 1] + norm(waypoints[v] - waypoints[v - 1]);
    if (v + 1 < n) {
      const Vec2 before = waypoints[v] - waypoints[v - 1];
      const Vec2 after = waypoints[v + 1] - waypoints[v];
      heading[v] = heading[v - 1] + std::atan2(cross(before, after), dot(before, after));
    }
  }
  // For each first waypoint a, the waypoints b in [a, last] with along[b] - along[a] below the
  // spread: the largest and smallest heading[b] over that window, by monotone queues.
  std::deque<std::size_t> highest, lowest;
  std::size_t last = 0;  // waypoints up to `last` have entered the queues
  for (std::size_t a = 1; a + 1 < n; ++a) {
    while (last + 2 < n &&
           (last + 1 == a || along[last + 1] - along[a] < max_waypoint_turn_spread_m)) {
      ++last;
      while (!highest.empty() && heading[highest.back()] <= heading[last]) highest.pop_back();
      highest.push_back(last);
      while (!lowest.empty() && heading[lowest.back()] >= heading[last]) lowest.pop_back();
      lowest.push_back(last);
    }
    while (highest.front() < a) highest.pop_front();
    while (lowest.front() < a) lowest.pop_front();
    const double before = heading[a - 1];
    if (heading[highest.front()] - before > max_waypoint_turn_rad ||
        before - heading[lowest.front()] > max_waypoint_turn_rad) {
      return a;
    }
  }
  return std::nullopt;
}

}  // namespace smoothsteer
