//! Natural cubic spline fit through waypoints (set-up time only).
//!
//! Chord-length parametrization: knot spacing h_i = |w_{i+1} - w_i|, so the parameter is close
//! to arc length and |p'(t)| ~ 1, which keeps quadrature and Newton well conditioned. The
//! second derivatives M_i at the knots solve the classic C2 tridiagonal system
//!   h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1}
//!     = 6 ((w_{i+1} - w_i) / h_i - (w_i - w_{i-1}) / h_{i-1}),
//! with M_0 = M_n = 0 (natural end conditions), for x and y at once.

#include <vector>

#include "path_detail.hpp"

namespace smoothsteer::detail {

std::vector<PathSegment> cubic_segments_from_moments(const std::vector<Vec2>& knot_points,
                                                     const std::vector<Vec2>& moments,
                                                     const std::vector<double>& knot_spacing) {
  std::vector<PathSegment> segments;
  segments.reserve(knot_spacing.size());
  for (std::size_t i = 0; i < knot_spacing.size(); ++i) {
    const double step = knot_spacing[i];
    const Vec2 a = knot_points[i];
    const Vec2 b = (1.0 / step) * (knot_points[i + 1] - knot_points[i]) -
                   (step / 6.0) * (2.0 * moments[i] + moments[i + 1]);
    const Vec2 c = 0.5 * moments[i];
    const Vec2 d = (1.0 / (6.0 * step)) * (moments[i + 1] - moments[i]);
    segments.push_back(PathSegment::make_cubic({a.x, b.x, c.x, d.x}, {a.y, b.y, c.y, d.y}, step));
  }
  return segments;
}

std::vector<PathSegment> natural_cubic_spline(const std::vector<Vec2>& waypoints) {
  const std::size_t n = waypoints.size() - 1;  // number of segments, >= 2
  std::vector<double> h(n);
  for (std::size_t i = 0; i < n; ++i) h[i] = norm(waypoints[i + 1] - waypoints[i]);

  // Thomas algorithm on the interior knots 1..n-1 (diagonally dominant, so no pivoting).
  std::vector<Vec2> moments(n + 1);  // M_i for x and y
  std::vector<double> upper(n + 1, 0.0);
  std::vector<Vec2> rhs(n + 1);
  for (std::size_t i = 1; i < n; ++i) {
    const Vec2 slope_after = (1.0 / h[i]) * (waypoints[i + 1] - waypoints[i]);
    const Vec2 slope_before = (1.0 / h[i - 1]) * (waypoints[i] - waypoints[i - 1]);
    const double lower = h[i - 1];
    const double diagonal = 2.0 * (h[i - 1] + h[i]) - lower * upper[i - 1];
    upper[i] = h[i] / diagonal;
    rhs[i] = (1.0 / diagonal) * (6.0 * (slope_after - slope_before) - lower * rhs[i - 1]);
  }
  for (std::size_t i = n - 1; i >= 1; --i) moments[i] = rhs[i] - upper[i] * moments[i + 1];

  return cubic_segments_from_moments(waypoints, moments, h);
}

}  // namespace smoothsteer::detail
