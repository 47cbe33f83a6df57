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
constexpr int kGridSamples = 16;
constexpr int kRefinedStarts = 3;
constexpr double kRefineTolerance = 1e-9;

}  // namespace

SteeringDerivatives vehicle_steering_derivatives(const ControllerParameters& parameters,
                                                 const ChainAngles& delta,
                                                 double lead_curvature) noexcept {
  const FrontAngleDerivatives d = front_angle_derivatives(
      delta, parameters.chain.wheelbases_m.data(), parameters.chain.order, lead_curvature);
  const double ratio = parameters.chain.vehicle_wheelbase_m / parameters.chain.wheelbases_m[0];
  const double g = vehicle_angle_gain(delta[0], ratio);
  SteeringDerivatives result;
  result.rate_per_meter = g * d.first;
  if (parameters.chain.order >= 2) {
    result.acceleration_per_meter2 =
        vehicle_angle_gain_slope(delta[0], ratio) * d.first * d.first + g * d.second;
  }
  return result;
}

SteeringDerivatives worst_case_steering_derivatives(const ControllerParameters& parameters) {
  parameters.validate();
  if (parameters.chain.order < 1 || parameters.chain.order > 2) {
    throw std::invalid_argument(
        "worst_case_steering_derivatives: order = " + std::to_string(parameters.chain.order) +
        " is not supported (the static map covers n = 1 and n = 2)");
  }
  const ChainBounds bounds = compute_chain_bounds(parameters);
  SteeringDerivatives result;
  // Rate: the 1-D supremum of compute_chain_bounds() (its extreme puts delta_2 on the box edge,
  // |kappa_1| = kbar_1, eq. ddelta_kappaf); one implementation for controller and tuner.
  result.rate_per_meter = bounds.steering_rate_per_meter;
  if (parameters.chain.order == 1) {
    result.acceleration_per_meter2 = std::numeric_limits<double>::infinity();
    return result;
  }
  // Acceleration: |f(d1, d2)| with kappa_l = +kbar_l; the map is odd under (d, kappa) -> -(d,
  // kappa), so -kbar_l gives the same extreme. f is affine in kappa_l, so interior values of
  // kappa_l (at a switch) cannot be worse.
  const double a1 = bounds.angle[0], a2 = bounds.angle[1];
  const double kbar = parameters.chain.lead_curvature_bound;
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
