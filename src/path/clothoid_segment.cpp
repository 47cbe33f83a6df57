//! Clothoid segments (Euler spirals): curvature kappa(u) = kappa_0 + c u along the local arc
//! length u, heading theta(u) = theta_0 + kappa_0 u + c u^2 / 2, and the position the integral
//! of (cos theta, sin theta), the Fresnel integrals in general position (Abramowitz and Stegun,
//! Handbook of Mathematical Functions, 7.3). They are evaluated by composite 8-point
//! Gauss-Legendre quadrature on pieces over which the phase turns by at most
//! kChunkTurning_rad: the rule's error term (A&S 25.4.30) is of order
//! h (turning)^16 (8!)^4 / (17 (16!)^3) ~ 1e-20 h, far below the 1e-9 m asked. The closest
//! point is found by Newton's method on the distance's derivative, bracketed on sub-pieces of
//! bounded turning for the global search. No allocation, bounded iteration counts.

#include <algorithm>
#include <array>
#include <cmath>

#include "gauss_legendre.hpp"
#include "path_detail.hpp"
#include "smoothsteer/math/angles.hpp"

namespace smoothsteer::detail {
namespace {

//! Largest turning integral(|kappa|) of one quadrature piece [rad]. A piece of turning tau also
//! has |c| h^2 <= 4 tau, so the quadratic part of the phase is bounded as well.
constexpr double kChunkTurning_rad = 0.75;
//! Largest turning of one bracket of the global closest-point search [rad]: within it the
//! distance's derivative has one sign change near any query that is not close to a center of
//! curvature (where every point of the bracket is nearly equally far).
constexpr double kBracketTurning_rad = 0.25;
constexpr int kMaxNewtonIterations = 40;

struct Pose {
  Vec2 position;
  double heading_rad = 0.0;
  double curvature = 0.0;
};

//! Integral of |k + c u| over u in [0, h] [rad].
double turning(double k, double c, double h) noexcept {
  const double k_end = k + c * h;
  if ((k >= 0.0) == (k_end >= 0.0) || c == 0.0) return 0.5 * std::abs(k + k_end) * h;
  return 0.5 * (k * k + k_end * k_end) / std::abs(c);
}

//! The pose `h` further along a clothoid of curvature rate `c` from `from`.
Pose advance(const Pose& from, double c, double h) noexcept {
  const double k = from.curvature;
  const int pieces = std::max(1, static_cast<int>(std::ceil(turning(k, c, h) / kChunkTurning_rad)));
  const double piece = h / pieces;
  double x = 0.0, y = 0.0;
  for (int j = 0; j < pieces; ++j) {
    const double middle = (j + 0.5) * piece;
    double sx = 0.0, sy = 0.0;
    for (std::size_t i = 0; i < gauss_legendre_8_nodes.size(); ++i) {
      for (const double side : {-1.0, 1.0}) {
        const double u = middle + side * 0.5 * piece * gauss_legendre_8_nodes[i];
        const double phase = u * (k + 0.5 * c * u);
        sx += gauss_legendre_8_weights[i] * std::cos(phase);
        sy += gauss_legendre_8_weights[i] * std::sin(phase);
      }
    }
    x += 0.5 * piece * sx;
    y += 0.5 * piece * sy;
  }
  const double cos0 = std::cos(from.heading_rad), sin0 = std::sin(from.heading_rad);
  return {from.position + Vec2{cos0 * x - sin0 * y, sin0 * x + cos0 * y},
          from.heading_rad + h * (k + 0.5 * c * h), k + c * h};
}

Pose start_pose(const PathSegment& segment) noexcept {
  return {segment.start, segment.start_heading_rad, segment.curvature};
}

Pose pose_at(const PathSegment& segment, double s) noexcept {
  return advance(start_pose(segment), segment.curvature_rate, s);
}

double max_abs_curvature(const PathSegment& segment) noexcept {
  return std::max(std::abs(segment.curvature), std::abs(segment.end_curvature()));
}

//! Half the derivative of the squared distance, (p(s) - q) . t(s), and its derivative
//! 1 + kappa (p - q) . n.
struct Slope {
  double value = 0.0;
  double derivative = 0.0;
};
Slope slope(const Pose& pose, Vec2 query) noexcept {
  const Vec2 offset = pose.position - query;
  const Vec2 tangent = unit_from_heading(pose.heading_rad);
  return {dot(offset, tangent), 1.0 + pose.curvature * cross(tangent, offset)};
}

//! Newton on the slope within [lower, upper], from `s`. Where the derivative is not clearly
//! positive (near a distance maximum) the Gauss-Newton denominator 1 is used; steps are held to
//! a quarter radian of turning. With `bracketed` (slope(lower) < 0 < slope(upper)) a step that
//! leaves the bracket bisects it instead, so the root in it is always found.
double newton(const PathSegment& segment, Vec2 query, double s, double lower, double upper,
              bool bracketed) noexcept {
  const double max_step = kBracketTurning_rad / std::max(max_abs_curvature(segment), 1e-12);
  for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
    const Slope g = slope(pose_at(segment, s), query);
    if (bracketed) {
      if (g.value < 0.0) lower = s;
      if (g.value > 0.0) upper = s;
    }
    const double denominator = g.derivative > 0.1 ? g.derivative : 1.0;
    const double step = std::clamp(-g.value / denominator, -max_step, max_step);
    double next = std::clamp(s + step, lower, upper);
    if (bracketed && (next <= lower || next >= upper)) next = 0.5 * (lower + upper);
    const bool converged = std::abs(next - s) <= 1e-12 * (1.0 + segment.length);
    s = next;
    if (converged || (bracketed && upper - lower <= 1e-12 * (1.0 + segment.length))) break;
  }
  return s;
}

}  // namespace

PathPoint clothoid_point(const PathSegment& segment, double s) noexcept {
  const Pose pose = pose_at(segment, s);
  return {pose.position, wrap_angle(pose.heading_rad), pose.curvature};
}

SegmentProjection clothoid_project(const PathSegment& segment, Vec2 query, double warm_parameter,
                                   bool exhaustive) noexcept {
  const double length = segment.length;
  double best_s = newton(segment, query, std::clamp(warm_parameter, 0.0, length), 0.0, length,
                         /*bracketed=*/false);
  double best_distance = norm(clothoid_point(segment, best_s).position - query);
  auto consider = [&](double s) {
    const double distance = norm(clothoid_point(segment, s).position - query);
    if (distance < best_distance) {
      best_distance = distance;
      best_s = s;
    }
  };
  if (exhaustive) {
    // Brackets of bounded turning: the ends of each are candidates, and a sign change of the
    // slope from - to + holds a local minimum, found by bracketed Newton.
    const int brackets = std::clamp(
        static_cast<int>(std::ceil(max_abs_curvature(segment) * length / kBracketTurning_rad)), 1,
        max_clothoid_brackets);
    const double width = length / brackets;
    Pose pose = start_pose(segment);
    Slope before = slope(pose, query);
    consider(0.0);
    for (int i = 0; i < brackets; ++i) {
      const double lower = i * width;
      const double upper = i + 1 == brackets ? length : (i + 1) * width;
      pose = advance(pose, segment.curvature_rate, upper - lower);
      const Slope after = slope(pose, query);
      consider(upper);
      if (before.value < 0.0 && after.value > 0.0) {
        consider(newton(segment, query, 0.5 * (lower + upper), lower, upper, true));
      }
      before = after;
    }
  }

  const PathPoint point = clothoid_point(segment, best_s);
  const Vec2 offset = query - point.position;
  const Vec2 tangent = unit_from_heading(point.heading_rad);
  SegmentProjection result;
  result.parameter = best_s;
  result.local_arc_length_m = best_s;
  result.point = point.position;
  result.heading_rad = point.heading_rad;
  result.curvature = point.curvature;
  result.distance_m = norm(offset);
  result.lateral_error_m = signed_distance(tangent, offset);
  const double along = dot(offset, tangent);
  result.clamped_at_start = best_s <= 0.0 && along < 0.0;
  result.clamped_at_end = best_s >= length && along > 0.0;
  return result;
}

}  // namespace smoothsteer::detail
