//! Parametric cubic segments: arc length by Gauss-Legendre quadrature, its inverse and the
//! closest point by Newton's method. Everything here runs in the real-time loop: no
//! allocation, bounded iteration counts.

#include <algorithm>
#include <array>
#include <cmath>

#include "gauss_legendre.hpp"
#include "path_detail.hpp"
#include "smoothsteer/math/angles.hpp"

namespace smoothsteer::detail {
namespace {

constexpr int kMaxNewtonIterations = 30;

struct CubicState {
  Vec2 position;
  Vec2 first;   //!< p'(t)
  Vec2 second;  //!< p''(t)
};

double poly(const std::array<double, 4>& c, double t) noexcept {
  return c[0] + t * (c[1] + t * (c[2] + t * c[3]));
}
double poly_d1(const std::array<double, 4>& c, double t) noexcept {
  return c[1] + t * (2.0 * c[2] + t * 3.0 * c[3]);
}
double poly_d2(const std::array<double, 4>& c, double t) noexcept {
  return 2.0 * c[2] + 6.0 * c[3] * t;
}

CubicState state_at(const PathSegment& segment, double t) noexcept {
  const auto& x = segment.x_coefficients;
  const auto& y = segment.y_coefficients;
  return {{poly(x, t), poly(y, t)}, {poly_d1(x, t), poly_d1(y, t)}, {poly_d2(x, t), poly_d2(y, t)}};
}

double speed(const PathSegment& segment, double t) noexcept {
  return norm({poly_d1(segment.x_coefficients, t), poly_d1(segment.y_coefficients, t)});
}

double curvature_of(const CubicState& state) noexcept {
  const double speed_value = norm(state.first);
  if (speed_value <= 0.0) return 0.0;
  return cross(state.first, state.second) / (speed_value * speed_value * speed_value);
}

//! Newton on g(t) = (p(t) - q) . p'(t), the half-derivative of the squared distance. Where
//! g' = |p'|^2 + (p - q) . p'' is not clearly positive (near a distance maximum) the step falls
//! back to the Gauss-Newton denominator |p'|^2, which always moves downhill.
double newton_closest(const PathSegment& segment, Vec2 query, double t) noexcept {
  for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
    const CubicState s = state_at(segment, t);
    const Vec2 offset = s.position - query;
    const double gradient = dot(offset, s.first);
    const double gauss_newton = dot(s.first, s.first);
    const double hessian = gauss_newton + dot(offset, s.second);
    const double denominator = hessian > 0.1 * gauss_newton ? hessian : gauss_newton;
    if (!(denominator > 0.0)) break;
    const double next = std::clamp(t - gradient / denominator, 0.0, segment.t_end);
    // Quadratic convergence: a step of 1e-12 leaves an error far below 1e-20 relative.
    const bool converged = std::abs(next - t) <= 1e-12 * (1.0 + segment.t_end);
    t = next;
    if (converged) break;
  }
  return t;
}

}  // namespace

PathPoint cubic_point(const PathSegment& segment, double t) noexcept {
  const CubicState s = state_at(segment, t);
  return PathPoint{s.position, std::atan2(s.first.y, s.first.x), curvature_of(s)};
}

double cubic_arc_length(const PathSegment& segment, double t) noexcept {
  const double half = 0.5 * t;
  double sum = 0.0;
  // |p'(t)| is the square root of a quartic; for the chord-length parametrized spline it is
  // nearly constant and the 8-point rule integrates it to ~1e-12 relative.
  for (std::size_t i = 0; i < gauss_legendre_8_nodes.size(); ++i) {
    sum += gauss_legendre_8_weights[i] * (speed(segment, half * (1.0 - gauss_legendre_8_nodes[i])) +
                                          speed(segment, half * (1.0 + gauss_legendre_8_nodes[i])));
  }
  return half * sum;
}

double cubic_parameter_at(const PathSegment& segment, double local_s) noexcept {
  if (!(segment.length > 0.0)) return 0.0;
  // Chord-length parametrization makes s/length * t_end an excellent first guess.
  double t = std::clamp(local_s / segment.length * segment.t_end, 0.0, segment.t_end);
  for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
    const double error = cubic_arc_length(segment, t) - local_s;
    const double rate = speed(segment, t);
    if (std::abs(error) <= 1e-13 * (1.0 + segment.length) || !(rate > 0.0)) break;
    t = std::clamp(t - error / rate, 0.0, segment.t_end);
  }
  return t;
}

SegmentProjection cubic_project(const PathSegment& segment, Vec2 query, double warm_parameter,
                                bool exhaustive, bool with_arc_length) noexcept {
  // The squared distance is a degree-6 polynomial in t with up to three local minima; the
  // warm start keeps continuity while the query moves, the fixed seeds find the others.
  const double t_end = segment.t_end;
  const std::array<double, 4> seeds{std::clamp(warm_parameter, 0.0, t_end), 0.0, 0.5 * t_end,
                                    t_end};
  double best_t = 0.0;
  double best_distance = 0.0;
  bool have_best = false;
  const std::size_t seed_count = exhaustive ? seeds.size() : 1;
  for (std::size_t k = 0; k < seed_count; ++k) {
    const double seed = seeds[k];
    const double t = newton_closest(segment, query, seed);
    const CubicState s = state_at(segment, t);
    const double distance = norm(query - s.position);
    if (!have_best || distance < best_distance) {
      best_t = t;
      best_distance = distance;
      have_best = true;
    }
  }

  const CubicState s = state_at(segment, best_t);
  const Vec2 offset = query - s.position;
  SegmentProjection result;
  result.parameter = best_t;
  if (best_t >= t_end) {
    result.local_arc_length_m = segment.length;
  } else if (with_arc_length) {
    result.local_arc_length_m = cubic_arc_length(segment, best_t);
  } else {  // chord-length parametrization: t is within a few percent of the arc length
    result.local_arc_length_m = best_t / t_end * segment.length;
  }
  result.point = s.position;
  result.heading_rad = std::atan2(s.first.y, s.first.x);
  result.curvature = curvature_of(s);
  result.distance_m = best_distance;
  result.lateral_error_m = signed_distance(s.first, offset);
  // Clamped only when the distance still decreases beyond the end (query ahead of the end's
  // normal line), so a query exactly abreast of a knot does not bounce between segments.
  const double along = dot(offset, s.first);
  result.clamped_at_start = best_t <= 0.0 && along < 0.0;
  result.clamped_at_end = best_t >= t_end && along > 0.0;
  return result;
}

}  // namespace smoothsteer::detail
