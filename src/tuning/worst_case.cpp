#include "smoothsteer/tuning/worst_case.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace smoothsteer {
namespace {

// Resolution of the worst-case search. The grid includes the box edges and corners; pattern
// search then refines the best samples until the step is below kRefineTolerance of the box.
constexpr int kRateSamples = 128;
constexpr int kGridSamples = 16;
constexpr int kRefinedStarts = 3;
constexpr double kRefineTolerance = 1e-9;

double gain(double front_angle, double ratio) noexcept {
  const double c = std::cos(front_angle), s = std::sin(front_angle);
  return ratio / (c * c + ratio * ratio * s * s);
}

double gain_slope(double front_angle, double ratio) noexcept {
  const double c = std::cos(front_angle), s = std::sin(front_angle);
  const double denominator = c * c + ratio * ratio * s * s;
  return -ratio * std::sin(2.0 * front_angle) * (ratio * ratio - 1.0) / (denominator * denominator);
}

//! Maximum of a smooth function on [low, high]: uniform samples, then golden section around the
//! best one (bracketed by its neighbours).
template <class F>
double maximize_1d(F&& f, double low, double high, int samples) {
  int best = 0;
  double best_value = -std::numeric_limits<double>::infinity();
  for (int k = 0; k <= samples; ++k) {
    const double value = f(low + (high - low) * k / samples);
    if (value > best_value) best_value = value, best = k;
  }
  double a = low + (high - low) * std::max(0, best - 1) / samples;
  double b = low + (high - low) * std::min(samples, best + 1) / samples;
  const double golden = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = b - golden * (b - a), x2 = a + golden * (b - a);
  double f1 = f(x1), f2 = f(x2);
  for (int iteration = 0; iteration < 50; ++iteration) {
    if (f1 > f2) {
      b = x2, x2 = x1, f2 = f1, x1 = b - golden * (b - a), f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + golden * (b - a), f2 = f(x2);
    }
  }
  return std::max({best_value, f1, f2});
}

}  // namespace

SteeringDerivatives vehicle_steering_derivatives(const ControllerParameters& parameters,
                                                 const ChainAngles& delta,
                                                 double lead_curvature) noexcept {
  const FrontAngleDerivatives d = front_angle_derivatives(delta, parameters.wheelbases_m.data(),
                                                          parameters.order, lead_curvature);
  const double ratio = parameters.vehicle_wheelbase_m / parameters.wheelbases_m[0];
  const double g = gain(delta[0], ratio);
  SteeringDerivatives result;
  result.rate_per_meter = g * d.first;
  if (parameters.order >= 2) {
    result.acceleration_per_meter2 = gain_slope(delta[0], ratio) * d.first * d.first + g * d.second;
  }
  return result;
}

SteeringDerivatives worst_case_steering_derivatives(const ControllerParameters& parameters) {
  parameters.validate();
  if (parameters.order < 1 || parameters.order > 2) {
    throw std::invalid_argument(
        "worst_case_steering_derivatives: order = " + std::to_string(parameters.order) +
        " is not supported (the static map covers n = 1 and n = 2)");
  }
  const ChainBounds bounds = compute_chain_bounds(parameters);
  const double ratio = parameters.vehicle_wheelbase_m / parameters.wheelbases_m[0];
  const double lambda_1 = parameters.wheelbases_m[0];
  const double kbar_1 = bounds.curvature[1];
  SteeringDerivatives result;
  // Rate: delta_1' = kappa_1 / cos(delta_1) - tan(delta_1)/lambda_1 (eq. ddelta_kappaf) does not
  // depend on kappa_n for n = 2; its extreme over the box takes |kappa_1| = kbar_1, i.e.
  // delta_2 on the edge. By symmetry only delta_1 >= 0 is needed.
  result.rate_per_meter = maximize_1d(
      [&](double a) { return gain(a, ratio) * (kbar_1 / std::cos(a) + std::tan(a) / lambda_1); },
      0.0, bounds.angle[0], kRateSamples);
  if (parameters.order == 1) {
    result.acceleration_per_meter2 = std::numeric_limits<double>::infinity();
    return result;
  }
  // Acceleration: |f(d1, d2)| with kappa_l = +kbar_l; the map is odd under (d, kappa) -> -(d,
  // kappa), so -kbar_l gives the same extreme. f is affine in kappa_l, so interior values of
  // kappa_l (at a switch) cannot be worse.
  const double a1 = bounds.angle[0], a2 = bounds.angle[1];
  const double kbar = parameters.lead_curvature_bound;
  auto value = [&](double d1, double d2) {
    ChainAngles delta{};
    delta[0] = d1, delta[1] = d2;
    return std::abs(vehicle_steering_derivatives(parameters, delta, kbar).acceleration_per_meter2);
  };
  struct Sample {
    double value, d1, d2;
  };
  std::array<Sample, kRefinedStarts> best{};
  for (Sample& s : best) s.value = -1.0;
  for (int i = 0; i <= kGridSamples; ++i) {
    for (int j = 0; j <= kGridSamples; ++j) {
      const double d1 = -a1 + 2.0 * a1 * i / kGridSamples;
      const double d2 = -a2 + 2.0 * a2 * j / kGridSamples;
      const Sample sample{value(d1, d2), d1, d2};
      if (sample.value > best.back().value) {
        best.back() = sample;
        std::sort(best.begin(), best.end(),
                  [](const Sample& x, const Sample& y) { return x.value > y.value; });
      }
    }
  }
  double worst = best.front().value;
  constexpr std::array<std::array<double, 2>, 8> directions{
      {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}, {1, -1}, {-1, 1}}};
  for (Sample s : best) {
    double h1 = 2.0 * a1 / kGridSamples, h2 = 2.0 * a2 / kGridSamples;
    while (h1 > kRefineTolerance * a1 || h2 > kRefineTolerance * a2) {
      bool improved = false;
      for (const auto& direction : directions) {
        const double d1 = std::clamp(s.d1 + direction[0] * h1, -a1, a1);
        const double d2 = std::clamp(s.d2 + direction[1] * h2, -a2, a2);
        const double v = value(d1, d2);
        if (v > s.value) {
          s = {v, d1, d2};
          improved = true;
          break;
        }
      }
      if (!improved) h1 *= 0.5, h2 *= 0.5;
    }
    worst = std::max(worst, s.value);
  }
  result.acceleration_per_meter2 = worst;
  return result;
}

}  // namespace smoothsteer
