#include "smoothsteer/controller/trailer_chain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace smoothsteer {
double vehicle_angle_gain(double front_cosine, double front_sine, double ratio) noexcept {
  return ratio / (front_cosine * front_cosine + ratio * ratio * front_sine * front_sine);
}

double vehicle_angle_gain(double front_angle, double ratio) noexcept {
  return vehicle_angle_gain(std::cos(front_angle), std::sin(front_angle), ratio);
}

double vehicle_angle_gain_slope(double front_angle, double ratio, double gain) noexcept {
  return -gain * gain * std::sin(2.0 * front_angle) * (ratio * ratio - 1.0) / ratio;
}

double vehicle_angle_gain_slope(double front_angle, double ratio) noexcept {
  return vehicle_angle_gain_slope(front_angle, ratio, vehicle_angle_gain(front_angle, ratio));
}

namespace {

//! |d delta_1/ds| in the worst case for a given delta_1 inside the invariant set:
//! |kappa_1| <= kbar_1 gives kbar_1/cos(delta_1) + tan|delta_1|/lambda_1 (eq. ddelta_kappaf).
double worst_front_rate(double front_angle, double kbar_1, double lambda_1) noexcept {
  return kbar_1 / std::cos(front_angle) + std::tan(std::abs(front_angle)) / lambda_1;
}

}  // namespace

ChainBounds compute_invariant_sets(const ControllerParameters& parameters) noexcept {
  ChainBounds bounds;
  const int n = parameters.chain.order;
  bounds.curvature[static_cast<std::size_t>(n)] = parameters.chain.lead_curvature_bound;
  for (int i = n; i >= 1; --i) {
    const auto index = static_cast<std::size_t>(i);
    const double kbar = bounds.curvature[index];
    const double lambda = parameters.chain.wheelbases_m[index - 1];
    const double product = kbar * lambda;
    bounds.angle[index - 1] = std::asin(product);                             // eq. (kappaf_constr)
    bounds.curvature[index - 1] = kbar / std::sqrt(1.0 - product * product);  // paper_notes §2
  }
  bounds.steering_angle_rad = std::atan(parameters.chain.vehicle_wheelbase_m * bounds.curvature[0]);
  return bounds;
}

ChainBounds compute_chain_bounds(const ControllerParameters& parameters) {
  ChainBounds bounds = compute_invariant_sets(parameters);
  const int n = parameters.chain.order;
  if (n == 0) {
    bounds.steering_rate_per_meter = std::numeric_limits<double>::infinity();
    return bounds;
  }
  // sup over |delta_1| <= delta-bar_1 of gain(delta_1) * worst_front_rate(delta_1): a grid, then
  // golden-section refinement around the best sample. The product of a monotone gain and an
  // increasing, convex rate has at most one interior maximum, so 64 samples bracket it;
  // ChainBounds.RateBoundEqualsBruteForce compares with 200 000 samples. Cheap enough for
  // LeadWheelController::retune() in the control loop (~2 us).
  const double ratio = parameters.chain.vehicle_wheelbase_m / parameters.chain.wheelbases_m[0];
  const double kbar_1 = bounds.curvature[1];
  const double lambda_1 = parameters.chain.wheelbases_m[0];
  const double limit = bounds.angle[0];
  auto rate = [&](double angle) {
    return vehicle_angle_gain(angle, ratio) * worst_front_rate(angle, kbar_1, lambda_1);
  };
  constexpr int samples = 64;
  int best = 0;
  double best_value = 0.0;
  for (int k = 0; k <= samples; ++k) {
    const double value = rate(limit * k / samples);
    if (value > best_value) {
      best_value = value;
      best = k;
    }
  }
  double low = limit * std::max(0, best - 1) / samples;
  double high = limit * std::min(samples, best + 1) / samples;
  const double golden = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double a = high - golden * (high - low);
    const double b = low + golden * (high - low);
    if (rate(a) > rate(b)) {
      high = b;
    } else {
      low = a;
    }
  }
  bounds.steering_rate_per_meter = std::max(best_value, rate(0.5 * (low + high)));
  return bounds;
}

namespace {

ChainAngles chain_tangents(const ChainAngles& delta, int order) noexcept {
  ChainAngles tangent{};
  for (std::size_t k = 0; k < static_cast<std::size_t>(order); ++k) tangent[k] = std::tan(delta[k]);
  return tangent;
}

}  // namespace

ChainTrigonometry chain_trigonometry(const ChainAngles& delta, int order) noexcept {
  ChainTrigonometry result;
  result.tangent = chain_tangents(delta, order);
  if (order >= 2) {
    result.front_cosine = std::cos(delta[0]);
    result.front_sine = std::sin(delta[0]);
    result.second_cosine = std::cos(delta[1]);
  }
  return result;
}

void chain_rates(const ChainTrigonometry& trigonometry, const double* wheelbases, int order,
                 double lead_curvature, ChainAngles& rates) noexcept {
  // Inside the invariant sets |delta_i| < pi/2, so 1/cos = sqrt(1 + tan^2).
  const ChainAngles& tangent = trigonometry.tangent;
  double distance_ratio = 1.0;  // ds_{i-1} / ds
  for (int i = 0; i < order; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double next_curvature =
        (i + 1 < order) ? tangent[k + 1] / wheelbases[i + 1] : lead_curvature;
    const double secant = std::sqrt(1.0 + tangent[k] * tangent[k]);
    rates[k] = distance_ratio * (next_curvature * secant - tangent[k] / wheelbases[i]);
    distance_ratio *= secant;
  }
}

void chain_rates(const ChainAngles& delta, const double* wheelbases, int order,
                 double lead_curvature, ChainAngles& rates) noexcept {
  // One tan per angle: the RK4 stages need no cos or sin (chain_trigonometry's front terms).
  ChainTrigonometry trigonometry;
  trigonometry.tangent = chain_tangents(delta, order);
  chain_rates(trigonometry, wheelbases, order, lead_curvature, rates);
}

FrontAngleDerivatives front_angle_derivatives(const ChainTrigonometry& trigonometry,
                                              const double* wheelbases, int order,
                                              double lead_curvature) noexcept {
  FrontAngleDerivatives result;
  if (order < 1) return result;
  ChainAngles rates{};
  chain_rates(trigonometry, wheelbases, order, lead_curvature, rates);
  result.first = rates[0];
  if (order < 2) return result;
  // delta_1' = K_1 / cos(delta_1) - tan(delta_1) / lambda_1 with K_1 = tan(delta_2) / lambda_2.
  const double c1 = trigonometry.front_cosine;
  const double c2 = trigonometry.second_cosine;
  const double front_curvature = trigonometry.tangent[1] / wheelbases[1];
  const double front_curvature_rate = rates[1] / (c2 * c2 * wheelbases[1]);
  result.second = front_curvature_rate / c1 +
                  front_curvature * trigonometry.front_sine / (c1 * c1) * rates[0] -
                  rates[0] / (c1 * c1 * wheelbases[0]);
  return result;
}

FrontAngleDerivatives front_angle_derivatives(const ChainAngles& delta, const double* wheelbases,
                                              int order, double lead_curvature) noexcept {
  return front_angle_derivatives(chain_trigonometry(delta, order), wheelbases, order,
                                 lead_curvature);
}

void chain_geometry(Vec2 rear_position, double rear_heading, const ChainAngles& delta,
                    const double* wheelbases, int order, ChainGeometry& geometry) noexcept {
  geometry.position[0] = rear_position;
  geometry.heading[0] = rear_heading;
  for (int i = 1; i <= order; ++i) {
    const auto k = static_cast<std::size_t>(i);
    geometry.position[k] =
        geometry.position[k - 1] + wheelbases[i - 1] * unit_from_heading(geometry.heading[k - 1]);
    geometry.heading[k] = geometry.heading[k - 1] + delta[k - 1];
  }
}

void stationary_chain(double front_angle, const double* wheelbases, int order,
                      ChainAngles& delta) noexcept {
  delta.fill(0.0);
  if (order < 1) return;
  delta[0] = front_angle;
  for (int i = 1; i < order; ++i) {
    const auto k = static_cast<std::size_t>(i);
    delta[k] = std::atan(wheelbases[i] * std::sin(delta[k - 1]) / wheelbases[i - 1]);
  }
}

namespace {

//! d tan(delta_i) / ds = (1 + tan^2 delta_i) d delta_i / ds, written in t_i = tan(delta_i) only:
//! the RK4 stages then need square roots but no trigonometric calls.
void tangent_rates(const ChainAngles& tangent, const double* wheelbases, int order,
                   double lead_curvature, ChainAngles& rates) noexcept {
  double distance_ratio = 1.0;  // ds_{i-1} / ds
  for (int i = 0; i < order; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double next_curvature =
        (i + 1 < order) ? tangent[k + 1] / wheelbases[i + 1] : lead_curvature;
    const double squared = 1.0 + tangent[k] * tangent[k];
    const double secant = std::sqrt(squared);
    rates[k] = squared * distance_ratio * (next_curvature * secant - tangent[k] / wheelbases[i]);
    distance_ratio *= secant;
  }
}

}  // namespace

void integrate_chain(ChainAngles& delta, const double* wheelbases, int order, double lead_curvature,
                     double ds, const ChainAngles& angle_bound) noexcept {
  integrate_chain(delta, wheelbases, order, lead_curvature, lead_curvature, ds, angle_bound);
}

void integrate_chain(ChainAngles& delta, const double* wheelbases, int order, double lead_curvature,
                     double lead_curvature_end, double ds,
                     const ChainAngles& angle_bound) noexcept {
  ChainAngles t{}, k1{}, k2{}, k3{}, k4{}, probe{};
  const auto n = static_cast<std::size_t>(order);
  const double lead_curvature_mid = 0.5 * (lead_curvature + lead_curvature_end);
  for (std::size_t i = 0; i < n; ++i) t[i] = std::tan(delta[i]);
  tangent_rates(t, wheelbases, order, lead_curvature, k1);
  for (std::size_t i = 0; i < n; ++i) probe[i] = t[i] + 0.5 * ds * k1[i];
  tangent_rates(probe, wheelbases, order, lead_curvature_mid, k2);
  for (std::size_t i = 0; i < n; ++i) probe[i] = t[i] + 0.5 * ds * k2[i];
  tangent_rates(probe, wheelbases, order, lead_curvature_mid, k3);
  for (std::size_t i = 0; i < n; ++i) probe[i] = t[i] + ds * k3[i];
  tangent_rates(probe, wheelbases, order, lead_curvature_end, k4);
  for (std::size_t i = 0; i < n; ++i) {
    const double next = t[i] + ds / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    // Never outward past the set, never inward by a jump: a state that a retune left outside a
    // shrunken set returns under the chain's own flow (which points inward there), so
    // delta_veh stays C^1 while a gain schedule changes the sets.
    // The set of delta_i is invariant only while its input kappa_i is bounded, i.e. while
    // delta_{i+1} lies in its own set. A retune can leave delta_{i+1} outside a shrunken set:
    // then delta_i follows the flow unclamped, instead of being frozen at its bound (which
    // stalled the command and overshot its acceleration, ScheduledLoop.RetuneNeverFreezes...).
    const bool input_bounded = i + 1 >= n || std::abs(delta[i + 1]) <= angle_bound[i + 1];
    const double limit = input_bounded ? std::max(angle_bound[i], std::abs(delta[i]))
                                       : std::numeric_limits<double>::infinity();
    delta[i] = std::clamp(std::atan(next), -limit, limit);
  }
}

}  // namespace smoothsteer
