//! The waypoints' jitter from the second divided difference of their three-point curvature
//! (include/smoothsteer/path/waypoint_jitter.hpp).

#include "smoothsteer/path/waypoint_jitter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace smoothsteer {
namespace {

//! Median of |N(0, 1)|: the median absolute value of unit Gaussian samples.
constexpr double half_normal_median = 0.6744897501960817;

//! The three-point curvature at waypoint i and its weights on the lateral noise of waypoints
//! i - 1, i, i + 1 (k = c (l_i - beta l_{i-1} - gamma l_{i+1}) to first order in the noise).
struct ThreePointCurvature {
  double curvature = 0.0;
  std::array<double, 3> noise_weights{};
  bool valid = false;
};

ThreePointCurvature three_point_curvature(Vec2 before, Vec2 at, Vec2 after) {
  ThreePointCurvature k;
  const double a = norm(at - before);
  const double b = norm(after - at);
  const Vec2 chord = after - before;
  const double chord_length = norm(chord);
  if (!(a > 0.0) || !(b > 0.0) || !(chord_length > 0.0)) return k;
  const Vec2 on_chord = before + (a / (a + b)) * chord;
  const double offset = cross(chord, at - on_chord) / chord_length;
  const double scale = 2.0 / (a * b);
  k.curvature = scale * offset;
  k.noise_weights = {-scale * b / (a + b), scale, -scale * a / (a + b)};
  k.valid = std::isfinite(k.curvature);
  return k;
}

}  // namespace

double estimate_waypoint_jitter(const std::vector<Vec2>& waypoints) {
  const std::size_t n = waypoints.size();
  if (n < min_jitter_waypoints) return 0.0;
  std::vector<ThreePointCurvature> curvature(n);
  // The three-point curvature is the road's at the mean arc length of the three points (exact
  // for a curvature linear in arc length, to first order in the heading turned), not at the
  // middle one: unevenly spaced waypoints are read there.
  std::vector<double> arc(n, 0.0), at(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) arc[i] = arc[i - 1] + norm(waypoints[i] - waypoints[i - 1]);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    curvature[i] = three_point_curvature(waypoints[i - 1], waypoints[i], waypoints[i + 1]);
    at[i] = (arc[i - 1] + arc[i] + arc[i + 1]) / 3.0;
  }
  std::vector<double> normalized;
  normalized.reserve(n);
  for (std::size_t i = 2; i + 2 < n; ++i) {
    if (!curvature[i - 1].valid || !curvature[i].valid || !curvature[i + 1].valid) continue;
    // Second divided difference over the arc length (the chords): 0 where k is linear in s.
    const double back = at[i] - at[i - 1];
    const double ahead = at[i + 1] - at[i];
    const std::array<double, 3> over_k = {1.0 / back, -(1.0 / back + 1.0 / ahead), 1.0 / ahead};
    double difference = 0.0;
    std::array<double, 5> noise_weights{};  // on the lateral noise of waypoints i-2 ... i+2
    for (std::size_t j = 0; j < 3; ++j) {
      const ThreePointCurvature& k = curvature[i - 1 + j];
      difference += over_k[j] * k.curvature;
      for (std::size_t m = 0; m < 3; ++m) noise_weights[j + m] += over_k[j] * k.noise_weights[m];
    }
    double weight_norm = 0.0;
    for (const double w : noise_weights) weight_norm += w * w;
    weight_norm = std::sqrt(weight_norm);
    const double sample = std::abs(difference) / weight_norm;
    if (std::isfinite(sample)) normalized.push_back(sample);
  }
  if (normalized.size() < min_jitter_waypoints / 2) return 0.0;  // degenerate chords
  const auto middle = normalized.begin() + static_cast<std::ptrdiff_t>(normalized.size() / 2);
  std::nth_element(normalized.begin(), middle, normalized.end());
  const double estimate = *middle / half_normal_median;
  return estimate >= min_jitter_m ? estimate : 0.0;
}

}  // namespace smoothsteer
