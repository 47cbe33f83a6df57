#include "smoothsteer/controller/steering_certificate.hpp"

#include <algorithm>
#include <cmath>

#include "smoothsteer/controller/trailer_chain.hpp"

namespace smoothsteer {

double SteeringCertificate::rate_radps(double speed_mps) const noexcept {
  return std::abs(speed_mps) * rate_per_meter;
}

double SteeringCertificate::acceleration_radps2(double speed_mps,
                                                double acceleration_mps2) const noexcept {
  return speed_mps * speed_mps * acceleration_per_meter2 +
         std::abs(acceleration_mps2) * rate_per_meter;
}

OutputSlopes output_slope_bounds(double vehicle_wheelbase_m, double front_wheelbase_m,
                                 double front_sine_bound) noexcept {
  // With q = sin(delta_1) and c = r^2 - 1:
  //   D1 = d delta_veh / d sigma_0 = lambda_veh / ((1 + c q^2) sqrt(1 - q^2)),
  //   D2 = lambda_1 dD1/dq = lambda_veh lambda_1 [q (1 + c q^2)^-1 (1 - q^2)^-3/2
  //                                               - 2 c q (1 + c q^2)^-2 (1 - q^2)^-1/2].
  // On 0 <= q <= q_max, 1 + c q^2 >= m = min(1, 1 + c q_max^2), and every other factor grows with
  // q, which gives the closed-form bounds below.
  const double ratio = vehicle_wheelbase_m / front_wheelbase_m;
  const double c = ratio * ratio - 1.0;
  const double q = front_sine_bound;
  const double m = std::min(1.0, 1.0 + c * q * q);
  const double root = std::sqrt(1.0 - q * q);
  OutputSlopes slopes;
  slopes.first = vehicle_wheelbase_m / (m * root);
  slopes.second = vehicle_wheelbase_m * front_wheelbase_m *
                  (q / (m * root * root * root) + 2.0 * std::abs(c) * q / (m * m * root));
  return slopes;
}

SteeringCertificate feedforward_certificate(const ControllerParameters& parameters) noexcept {
  return feedforward_certificate(parameters, compute_invariant_sets(parameters));
}

SteeringCertificate feedforward_certificate(const ControllerParameters& parameters,
                                            const ChainBounds& bounds) noexcept {
  SteeringCertificate certificate;
  certificate.steering_angle_rad = bounds.steering_angle_rad;
  const int n = parameters.chain.order;
  const double feedforward_rate = parameters.feedforward.curvature_rate;
  if (n == 0 || !std::isfinite(feedforward_rate)) return certificate;
  const double* lambda = parameters.chain.wheelbases_m.data();

  // Input of stage i (kappa_i): its feedforward part changes by at most `rate` per metre of s,
  // its switching part stays within `magnitude`. Stage i's output sigma_{i-1} obeys the same
  // bounds in s_{i-1}; ds_{i-1}/ds <= stretch = prod_{j<i} sec(dbar_j), and the map to kappa_{i-1}
  // has slope <= (1 - lambda_i^2 kbar_i^2)^(-3/2).
  double rate = feedforward_rate;
  double magnitude = parameters.switching_curvature_bound();
  double stage2_rate = 0.0, stage2_magnitude = 0.0, stage2_slope = 0.0;
  for (int i = n; i >= 2; --i) {
    const auto k = static_cast<std::size_t>(i);
    double stretch = 1.0;
    for (std::size_t j = 0; j + 1 < k; ++j) stretch /= std::cos(bounds.angle[j]);
    const double product = lambda[i - 1] * bounds.curvature[k];
    const double slope = 1.0 / std::pow(1.0 - product * product, 1.5);
    if (i == 2) stage2_rate = rate, stage2_magnitude = magnitude, stage2_slope = slope * stretch;
    rate *= slope * stretch;
    magnitude *= slope;
  }
  // Stage 1 runs in s itself: |sigma_0'| <= rate + 2 magnitude / lambda_1.
  const double sigma_rate = rate + 2.0 * magnitude / lambda[0];
  const OutputSlopes out = output_slope_bounds(parameters.chain.vehicle_wheelbase_m, lambda[0],
                                               std::sin(bounds.angle[0]));
  certificate.rate_per_meter = out.first * sigma_rate;
  if (n >= 2) {
    // sigma_0'' = (kappa_1' - sigma_0') / lambda_1 and kappa_1' = N'(sigma_1) sec(delta_1)
    // (kappa_2 - sigma_1) / lambda_2, whose two parts are bounded as in stage 2.
    const double front_curvature_rate =
        stage2_slope * (stage2_rate + 2.0 * stage2_magnitude / lambda[1]);
    const double sigma_acceleration = (front_curvature_rate + sigma_rate) / lambda[0];
    certificate.acceleration_per_meter2 =
        out.second * sigma_rate * sigma_rate + out.first * sigma_acceleration;
  }
  return certificate;
}

double stationary_rear_curvature(double lead_curvature, double chain_length_squared) noexcept {
  return lead_curvature / std::sqrt(1.0 - lead_curvature * lead_curvature * chain_length_squared);
}

double stationary_lead_curvature(double rear_curvature, double chain_length_squared) noexcept {
  return rear_curvature / std::sqrt(1.0 + rear_curvature * rear_curvature * chain_length_squared);
}

double cornering_front_wheelbase(double vehicle_wheelbase_m, double outer_length_squared) noexcept {
  const double squared = vehicle_wheelbase_m * vehicle_wheelbase_m - outer_length_squared;
  return std::isfinite(squared) && squared > 0.0 ? std::sqrt(squared) : 0.0;
}

}  // namespace smoothsteer
