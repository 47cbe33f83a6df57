#include "reaching_start.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace smoothsteer::detail {

StartingTrajectory feedback_trajectory(const ReachingProblem& p) {
  const double swing = p.steering_angle_bound_rad / p.steering_rate_bound_per_m;
  const double look_ahead = 2.0 * p.wheelbase_m + 2.0 * swing + 1.0;
  const double max_curvature = 0.8 * std::tan(p.steering_angle_bound_rad) / p.wheelbase_m;
  const double step = 0.01 * std::min({p.wheelbase_m, swing, look_ahead});
  auto rates = [&](const std::array<double, 3>& x, double u) {
    return std::array<double, 3>{std::sin(x[1]), std::tan(x[2]) / p.wheelbase_m, u};
  };
  auto control = [&](const std::array<double, 3>& x) {
    const double heading = -std::atan(x[0] / look_ahead);
    const double curvature =
        std::clamp(2.0 * (heading - x[1]) / look_ahead, -max_curvature, max_curvature);
    const double steering = std::atan(p.wheelbase_m * curvature);
    return std::clamp(3.0 * (steering - x[2]) / swing, -p.steering_rate_bound_per_m,
                      p.steering_rate_bound_per_m);
  };
  std::vector<std::array<double, 4>> samples;  // e, psi, delta, u every `step` metres
  std::array<double, 3> x{p.initial_lateral_error_m, p.initial_heading_rad, p.initial_steering_rad};
  const int max_steps = static_cast<int>(400.0 * look_ahead / step);
  int last_outside = 0;
  for (int k = 0; k < max_steps; ++k) {
    const double u = control(x);
    samples.push_back({x[0], x[1], x[2], u});
    if (std::abs(x[0]) > 1e-3 || std::abs(x[1]) > 1e-3 || std::abs(x[2]) > 1e-3) last_outside = k;
    if (k - last_outside > static_cast<int>(10.0 * look_ahead / step)) break;
    // RK4 with u held over the step (it is re-evaluated every step).
    const auto k1 = rates(x, u);
    std::array<double, 3> y{};
    for (int c = 0; c < 3; ++c) y[c] = x[c] + 0.5 * step * k1[c];
    const auto k2 = rates(y, u);
    for (int c = 0; c < 3; ++c) y[c] = x[c] + 0.5 * step * k2[c];
    const auto k3 = rates(y, u);
    for (int c = 0; c < 3; ++c) y[c] = x[c] + step * k3[c];
    const auto k4 = rates(y, u);
    for (int c = 0; c < 3; ++c) x[c] += step / 6.0 * (k1[c] + 2.0 * k2[c] + 2.0 * k3[c] + k4[c]);
    x[2] = std::clamp(x[2], -p.steering_angle_bound_rad, p.steering_angle_bound_rad);
  }
  StartingTrajectory start;
  if (last_outside + 1 >= static_cast<int>(samples.size())) return start;  // did not settle
  start.valid = true;
  start.distance_m = std::max(step, (last_outside + 1) * step);
  const int n = p.intervals;
  for (int node = 0; node <= n; ++node) {
    const double position = static_cast<double>(node) / n * (last_outside + 1);
    const auto low = static_cast<std::size_t>(std::floor(position));
    const std::size_t high = std::min(low + 1, samples.size() - 1);
    const double t = position - static_cast<double>(low);
    auto at = [&](int c) { return (1.0 - t) * samples[low][c] + t * samples[high][c]; };
    start.e.push_back(at(0));
    start.psi.push_back(at(1));
    start.delta.push_back(at(2));
    start.u.push_back(at(3));
  }
  return start;
}

}  // namespace smoothsteer::detail
