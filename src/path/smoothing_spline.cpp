//! Smoothing cubic spline through noisy waypoints (set-up time only).
//!
//! Reinsch (1967), in the notation of Green and Silverman, "Nonparametric Regression and
//! Generalized Linear Models" (1994), Sec. 2.3: over the chord-length parameter t_i of the
//! waypoints y_i, the curve g(t) that minimises
//!   sum_i |y_i - g(t_i)|^2 + alpha * integral |g''(t)|^2 dt
//! is the natural cubic spline with knots t_i whose knot values g and interior second
//! derivatives gamma (0 at both ends) solve
//!   (R + alpha Q^T Q) gamma = Q^T y,   g = y - alpha Q gamma,
//! with Q (n x (n-2)) the second divided differences, Q(i-1,i) = 1/h_{i-1},
//! Q(i,i) = -1/h_{i-1} - 1/h_i, Q(i+1,i) = 1/h_i, and R ((n-2) x (n-2)) tridiagonal,
//! R(i,i) = (h_{i-1} + h_i) / 3, R(i,i+1) = h_i / 6: at alpha = 0 it is the interpolating
//! system of cubic_spline.cpp divided by 6. x and y share alpha, so the fit does not depend on
//! the frame.
//!
//! Reinsch's criterion picks alpha: the RMS distance of the knots from the waypoints equals the
//! tolerance. That distance grows monotonically with alpha (from 0 at interpolation to the
//! least-squares line's residual as alpha -> infinity), so a bisection on log(alpha) finds it.
//! The matrix is symmetric positive definite and pentadiagonal: a banded LDL^T solves it in
//! O(n), so the whole fit is O(n) per bisection step.
//!
//! Through a tight corner the fit is then twiced (restore_tight_corners): the fit of its own
//! residual at the same alpha is added, which gives back the corner the smoothing cut.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "path_detail.hpp"

namespace smoothsteer::detail {
namespace {

//! How many waypoints the mirror extends each end by (at most all but one): 40 m at a planner's
//! 1 m spacing, beyond the reach of the heaviest smoothing that keeps an arc's shape.
constexpr std::size_t end_extension_points = 40;
//! How many waypoints from each end fitted_end() reads: 20 m at a planner's 1 m spacing.
constexpr std::size_t end_fit_points = 21;

//! The largest heading change of the road a least-squares cubic across an end's waypoints is
//! asked to follow [rad]. A cubic in the chord's frame keeps an arc's tangent at the end over a
//! small turn; across a tight corner (a 12 m hairpin turns 1.7 rad in 20 m) its tangent is off
//! by tenths of a radian, and the mirror then bends the fit there (0.2 1/m of curvature error
//! on a parking bay's 5 m radius jittered by 5 mm).
constexpr double end_fit_turn_rad = 0.25;
//! The fewest waypoints an end's cubic reads (7 m at a planner's 1 m spacing): fewer would let
//! the jitter, not the road, set the end's tangent.
constexpr std::size_t end_fit_least_points = 8;

//! The corners a fit restores (restore_tight_corners) are those of a radius below 50 m. On
//! gentler roads, driven at 20 m/s and more, the cut is small against the twiced fit's extra
//! noise: a planner's windows of the motorway exit jittered by 5 cm, all twiced, ran 0.150
//! instead of 0.092 m. A threshold of 0.04 1/m (25 m) spares the 15 m/s lane change (radius 37
//! m; with 2 cm of jitter 0.131 instead of 0.124 m, mean over 5 seeds) but gives up most of the
//! mountain road's gain with 5 cm (0.07-0.08 -> 0.10-0.11 m), whose curves of 45-50 m are
//! twiced too (docs/studies/waypoint_jitter.md).
constexpr double corner_least_curvature_per_m = 0.02;
//! ... and only where the tolerance is at least that of 1 cm of jitter (sigma sqrt(2)). Below
//! it the cut is a few millimetres and the twiced fit's overshoot at a clothoid's end costs more:
//! the urban turn's 10 m radius with 0.5 cm of jitter, twiced, 0.045 -> 0.080 m.
constexpr double corner_least_tolerance_m = 0.014;

//! The knots of one fit: the smoothed points and their second derivatives.
struct SmoothingFit {
  std::vector<Vec2> knot_points;
  std::vector<Vec2> moments;
  double rms_deviation_m = 0.0;
  double alpha = 0.0;
};

class SmoothingProblem {
 public:
  //! Reinsch's distance is measured over waypoints [measured_from, measured_from +
  //! measured_count) (all of them by default; the given ones of an extended window).
  explicit SmoothingProblem(const std::vector<Vec2>& waypoints, std::size_t measured_from = 0,
                            std::size_t measured_count = 0)
      : waypoints_(waypoints),
        spacing_(waypoints.size() - 1),
        inverse_(waypoints.size() - 1),
        measured_from_(measured_from),
        measured_count_(measured_count > 0 ? measured_count : waypoints.size()) {
    for (std::size_t i = 0; i + 1 < waypoints.size(); ++i) {
      spacing_[i] = norm(waypoints[i + 1] - waypoints[i]);
      inverse_[i] = 1.0 / spacing_[i];
    }
  }

  const std::vector<double>& spacing() const noexcept { return spacing_; }

  //! Mean knot spacing cubed [m^3]: the scale of alpha (|y|^2 against alpha |g''|^2 t).
  double alpha_scale() const noexcept {
    double total = 0.0;
    for (const double h : spacing_) total += h;
    const double mean = total / static_cast<double>(spacing_.size());
    return mean * mean * mean;
  }

  SmoothingFit fit(double alpha) const { return fit(alpha, waypoints_); }

  //! The fit of `data` (one point per waypoint) over the waypoints' chord-length parameter.
  SmoothingFit fit(double alpha, const std::vector<Vec2>& data) const {
    const std::size_t n = data.size();
    const std::size_t m = n - 2;  // interior knots; unknown k is knot k + 1
    const std::vector<double>& h = spacing_;
    const std::vector<double>& r = inverse_;
    // The band of R + alpha Q^T Q: entries (k, k), (k, k + 1), (k, k + 2).
    std::vector<double> diagonal(m), first(m, 0.0), second(m, 0.0);
    std::vector<Vec2> rhs(m);
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t i = k + 1;
      const double middle = r[i - 1] + r[i];
      diagonal[k] =
          (h[i - 1] + h[i]) / 3.0 + alpha * (r[i - 1] * r[i - 1] + middle * middle + r[i] * r[i]);
      if (k + 1 < m) first[k] = h[i] / 6.0 - alpha * r[i] * (middle + r[i] + r[i + 1]);
      if (k + 2 < m) second[k] = alpha * r[i] * r[i + 1];
      rhs[k] = r[i] * (data[i + 1] - data[i]) - r[i - 1] * (data[i] - data[i - 1]);
    }
    // Banded LDL^T: lower_1[k] = L(k, k - 1), lower_2[k] = L(k, k - 2).
    std::vector<double> pivot(m), lower_1(m, 0.0), lower_2(m, 0.0);
    for (std::size_t k = 0; k < m; ++k) {
      if (k >= 2) lower_2[k] = second[k - 2] / pivot[k - 2];
      if (k >= 1) {
        const double coupling = k >= 2 ? lower_2[k] * pivot[k - 2] * lower_1[k - 1] : 0.0;
        lower_1[k] = (first[k - 1] - coupling) / pivot[k - 1];
      }
      pivot[k] = diagonal[k];
      if (k >= 1) pivot[k] -= lower_1[k] * lower_1[k] * pivot[k - 1];
      if (k >= 2) pivot[k] -= lower_2[k] * lower_2[k] * pivot[k - 2];
    }
    for (std::size_t k = 0; k < m; ++k) {
      if (k >= 1) rhs[k] = rhs[k] - lower_1[k] * rhs[k - 1];
      if (k >= 2) rhs[k] = rhs[k] - lower_2[k] * rhs[k - 2];
    }
    SmoothingFit result;
    result.alpha = alpha;
    result.moments.assign(n, Vec2{});
    for (std::size_t k = m; k-- > 0;) {
      Vec2 value = (1.0 / pivot[k]) * rhs[k];
      if (k + 1 < m) value = value - lower_1[k + 1] * result.moments[k + 2];
      if (k + 2 < m) value = value - lower_2[k + 2] * result.moments[k + 3];
      result.moments[k + 1] = value;
    }
    // g = y - alpha Q gamma, with gamma = 0 at both ends.
    result.knot_points.resize(n);
    double squares = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      Vec2 second_difference{};
      if (i + 1 < n) {
        second_difference = second_difference + r[i] * (result.moments[i + 1] - result.moments[i]);
      }
      if (i > 0) {
        second_difference =
            second_difference - r[i - 1] * (result.moments[i] - result.moments[i - 1]);
      }
      const Vec2 offset = alpha * second_difference;
      result.knot_points[i] = data[i] - offset;
      if (i >= measured_from_ && i < measured_from_ + measured_count_) {
        squares += dot(offset, offset);
      }
    }
    result.rms_deviation_m = std::sqrt(squares / static_cast<double>(measured_count_));
    return result;
  }

 private:
  const std::vector<Vec2>& waypoints_;
  std::vector<double> spacing_;
  std::vector<double> inverse_;
  std::size_t measured_from_, measured_count_;
};

//! The fit of `problem` whose knots keep Reinsch's RMS distance `tolerance_m` from its points.
SmoothingFit fit_within(const SmoothingProblem& problem, double tolerance_m) {
  // alpha from 1e-10 to 1e10 times the spacing's cube spans interpolation to the line fit.
  const double scale = problem.alpha_scale();
  double low = std::log(1e-10 * scale);
  double high = std::log(1e10 * scale);
  SmoothingFit best = problem.fit(std::exp(high));
  if (best.rms_deviation_m <= tolerance_m) return best;
  // The largest alpha within the tolerance; the least one tried if none is within it.
  bool within = false;
  for (int step = 0; step < 60 && high - low > 1e-6; ++step) {
    const double middle = 0.5 * (low + high);
    SmoothingFit trial = problem.fit(std::exp(middle));
    if (trial.rms_deviation_m > tolerance_m) {
      high = middle;
    } else {
      low = middle;
      best = std::move(trial);
      within = true;
    }
  }
  return within ? best : problem.fit(std::exp(low));
}

//! `point` mirrored across the line through `centre` normal to the unit `tangent`.
Vec2 mirrored(Vec2 point, Vec2 centre, Vec2 tangent) {
  return point - (2.0 * dot(point - centre, tangent)) * tangent;
}

//! Where a window of waypoints ends, as the road it samples does there: a point and a unit
//! tangent.
struct EndFrame {
  Vec2 point;
  Vec2 tangent;
};

//! How many waypoints from `ordered(0)` on the end's cubic reads: end_fit_points, or fewer where
//! the road turns more than end_fit_turn_rad from its heading at the end within them (headings
//! of chords two waypoints long, which the jitter moves little), but at least
//! end_fit_least_points.
template <class Ordered>
std::size_t end_fit_count(std::size_t count, Ordered ordered) {
  const std::size_t most = std::min(count, end_fit_points);
  if (most <= end_fit_least_points) return most;
  const Vec2 first = ordered(2) - ordered(0);
  for (std::size_t i = end_fit_least_points; i < most; ++i) {
    const Vec2 chord = ordered(i) - ordered(i - 2);
    if (std::abs(std::atan2(cross(first, chord), dot(first, chord))) > end_fit_turn_rad) return i;
  }
  return most;
}

//! The end of `waypoints` at `ordered(0)`: a least-squares cubic b(a) through the first
//! end_fit_count() of them, in the frame of their chord (a along it, b to its left), at a = 0.
//! It averages the jitter out of the end's point and tangent, and a cubic keeps an arc's shape
//! over the span (a road's radius, not the noise, decides how it bends there).
template <class Ordered>
EndFrame fitted_end(std::size_t count, Ordered ordered) {
  const std::size_t m = end_fit_count(count, ordered);
  const Vec2 origin = ordered(0);
  const Vec2 chord = ordered(m - 1) - origin;
  const Vec2 along = (1.0 / norm(chord)) * chord;
  const Vec2 left{-along.y, along.x};
  const std::size_t terms = m >= 4 ? 4 : m >= 3 ? 3 : 2;
  // Normal equations of b = sum c_j (a / span)^j, solved by elimination with partial pivoting.
  const double span = norm(chord);
  double matrix[4][5] = {};
  for (std::size_t i = 0; i < m; ++i) {
    const Vec2 d = ordered(i) - origin;
    const double a = dot(d, along) / span, b = dot(d, left);
    double power[4] = {1.0, a, a * a, a * a * a};
    for (std::size_t r = 0; r < terms; ++r) {
      for (std::size_t c = 0; c < terms; ++c) matrix[r][c] += power[r] * power[c];
      matrix[r][terms] += power[r] * b;
    }
  }
  for (std::size_t col = 0; col < terms; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < terms; ++r) {
      if (std::abs(matrix[r][col]) > std::abs(matrix[pivot][col])) pivot = r;
    }
    for (std::size_t c = 0; c <= terms; ++c) std::swap(matrix[col][c], matrix[pivot][c]);
    if (!(std::abs(matrix[col][col]) > 0.0)) return {origin, along};
    for (std::size_t r = 0; r < terms; ++r) {
      if (r == col) continue;
      const double factor = matrix[r][col] / matrix[col][col];
      for (std::size_t c = col; c <= terms; ++c) matrix[r][c] -= factor * matrix[col][c];
    }
  }
  const double offset = matrix[0][terms] / matrix[0][0];
  const double slope = matrix[1][terms] / matrix[1][1] / span;
  const Vec2 direction = along + slope * left;
  return {origin + offset * left, (1.0 / norm(direction)) * direction};
}

//! Restores the corner `fit` cut: adds the fit of its own residual at the same alpha (twicing;
//! Tukey, "Exploratory Data Analysis", 1977, Sec. 16B). The residual of a smoothing spline holds
//! what the smoothing took off the road as well as the jitter; smoothing it once more at the
//! same weight keeps the first and mostly drops the second, and added back it cancels the fit's
//! first-order bias (a kernel of twice the smoother minus its square). Both terms are natural
//! cubic splines on the same knots, so their sum is one: knot values and moments add. Only where
//! the tolerance is at least corner_least_tolerance_m and the fit bends tighter than
//! corner_least_curvature_per_m (the moments' magnitude) at one of the waypoints
//! [from, from + count).
void restore_tight_corners(const SmoothingProblem& problem, const std::vector<Vec2>& data,
                           double tolerance_m, std::size_t from, std::size_t count,
                           SmoothingFit& fit) {
  if (tolerance_m < corner_least_tolerance_m) return;
  bool tight = false;
  for (std::size_t i = from; i < from + count && !tight; ++i) {
    tight = norm(fit.moments[i]) > corner_least_curvature_per_m;
  }
  if (!tight) return;
  std::vector<Vec2> residual(data.size());
  for (std::size_t i = 0; i < data.size(); ++i) residual[i] = data[i] - fit.knot_points[i];
  const SmoothingFit again = problem.fit(fit.alpha, residual);
  for (std::size_t i = 0; i < data.size(); ++i) {
    fit.knot_points[i] = fit.knot_points[i] + again.knot_points[i];
    fit.moments[i] = fit.moments[i] + again.moments[i];
  }
}

}  // namespace

std::vector<PathSegment> smoothing_cubic_spline(const std::vector<Vec2>& waypoints,
                                                double tolerance_m, bool restore_corners) {
  // A natural spline ends straight: fitted alone, a window of an arc bends too little near its
  // ends (curvature 0 there, ramping up over the smoothing's length), which is where a planner's
  // window puts the car. So the waypoints are extended at each end by their mirror image across
  // the road's normal there (which continues an arc as the same arc), fitted, and the extension
  // cut off again. The normal comes from a least-squares cubic through the end's waypoints
  // (fitted_end): a tangent taken from a first fit keeps that fit's straight end in the mirror
  // (37 % of a 250 m arc's curvature was missing 5 m into a window jittered by 5 mm).
  const std::size_t n = waypoints.size();
  const std::size_t pad = std::min(n - 1, end_extension_points);
  const EndFrame start = fitted_end(n, [&](std::size_t i) { return waypoints[i]; });
  const EndFrame end = fitted_end(n, [&](std::size_t i) { return waypoints[n - 1 - i]; });
  std::vector<Vec2> extended;
  extended.reserve(n + 2 * pad);
  for (std::size_t k = pad; k >= 1; --k) {
    extended.push_back(mirrored(waypoints[k], start.point, start.tangent));
  }
  extended.insert(extended.end(), waypoints.begin(), waypoints.end());
  for (std::size_t k = 1; k <= pad; ++k) {
    extended.push_back(mirrored(waypoints[n - 1 - k], end.point, end.tangent));
  }
  SmoothingFit fit;
  std::vector<double> spacing;
  std::size_t first = pad;  // the knot of waypoints[0] in the fit
  const SmoothingProblem problem(extended, pad, n);
  if (*std::min_element(problem.spacing().begin(), problem.spacing().end()) < 1e-9) {
    const SmoothingProblem alone(waypoints);  // a mirror met its end: the window alone
    fit = fit_within(alone, tolerance_m);
    if (restore_corners) restore_tight_corners(alone, waypoints, tolerance_m, 0, n, fit);
    spacing = alone.spacing();
    first = 0;
  } else {
    fit = fit_within(problem, tolerance_m);
    if (restore_corners) restore_tight_corners(problem, extended, tolerance_m, pad, n, fit);
    spacing = problem.spacing();
  }
  // The segments between waypoints[0] and waypoints[n - 1]: each depends on its two knots only.
  const auto from = static_cast<std::ptrdiff_t>(first);
  const auto count = static_cast<std::ptrdiff_t>(n);
  const std::vector<Vec2> knots(fit.knot_points.begin() + from,
                                fit.knot_points.begin() + from + count);
  const std::vector<Vec2> moments(fit.moments.begin() + from, fit.moments.begin() + from + count);
  const std::vector<double> steps(spacing.begin() + from, spacing.begin() + from + count - 1);
  return cubic_segments_from_moments(knots, moments, steps);
}

}  // namespace smoothsteer::detail
