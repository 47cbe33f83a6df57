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

#include <cmath>
#include <utility>
#include <vector>

#include "path_detail.hpp"

namespace smoothsteer::detail {
namespace {

//! The knots of one fit: the smoothed points and their second derivatives.
struct SmoothingFit {
  std::vector<Vec2> knot_points;
  std::vector<Vec2> moments;
  double rms_deviation_m = 0.0;
};

class SmoothingProblem {
 public:
  explicit SmoothingProblem(const std::vector<Vec2>& waypoints)
      : waypoints_(waypoints), spacing_(waypoints.size() - 1), inverse_(waypoints.size() - 1) {
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

  SmoothingFit fit(double alpha) const {
    const std::size_t n = waypoints_.size();
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
      rhs[k] = r[i] * (waypoints_[i + 1] - waypoints_[i]) -
               r[i - 1] * (waypoints_[i] - waypoints_[i - 1]);
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
      result.knot_points[i] = waypoints_[i] - offset;
      squares += dot(offset, offset);
    }
    result.rms_deviation_m = std::sqrt(squares / static_cast<double>(n));
    return result;
  }

 private:
  const std::vector<Vec2>& waypoints_;
  std::vector<double> spacing_;
  std::vector<double> inverse_;
};

}  // namespace

std::vector<PathSegment> smoothing_cubic_spline(const std::vector<Vec2>& waypoints,
                                                double tolerance_m) {
  const SmoothingProblem problem(waypoints);
  // alpha from 1e-10 to 1e10 times the spacing's cube spans interpolation to the line fit.
  const double scale = problem.alpha_scale();
  double low = std::log(1e-10 * scale);
  double high = std::log(1e10 * scale);
  SmoothingFit best = problem.fit(std::exp(high));
  if (best.rms_deviation_m > tolerance_m) {
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
    if (!within) best = problem.fit(std::exp(low));
  }
  return cubic_segments_from_moments(best.knot_points, best.moments, problem.spacing());
}

}  // namespace smoothsteer::detail
