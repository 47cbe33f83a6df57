#include "smoothsteer/tuning/invariant_bounds.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "smoothsteer/controller/steering_certificate.hpp"
#include "smoothsteer/controller/trailer_chain.hpp"

namespace smoothsteer {
namespace {

[[noreturn]] void fail(const std::string& text) {
  throw std::invalid_argument(text);
}

}  // namespace

double lead_curvature_bound_for_steering_angle(const ControllerParameters& parameters,
                                               double max_steering_angle_rad) {
  if (!std::isfinite(max_steering_angle_rad) || max_steering_angle_rad <= 0.0 ||
      max_steering_angle_rad >= std::numbers::pi / 2.0) {
    std::ostringstream text;
    text << "max_steering_angle_rad = " << max_steering_angle_rad << " must be in (0, pi/2)";
    fail(text.str());
  }
  if (parameters.chain.order < 1 || parameters.chain.order > ControllerParameters::max_order) {
    fail("order = " + std::to_string(parameters.chain.order) + " must be in [1, " +
         std::to_string(ControllerParameters::max_order) + "] for a steering-angle bound");
  }
  // 1/kbar_n^2 = 1/kbar_0^2 + sum lambda_i^2 (header); each factor keeps kbar_i lambda_i < 1.
  const double kbar_0 = std::tan(max_steering_angle_rad) / parameters.chain.vehicle_wheelbase_m;
  double inverse_squared = 1.0 / (kbar_0 * kbar_0);
  for (int i = 0; i < parameters.chain.order; ++i) {
    const double lambda = parameters.chain.wheelbases_m[static_cast<std::size_t>(i)];
    if (!std::isfinite(lambda) || lambda <= 0.0) {
      fail("wheelbases_m[" + std::to_string(i) + "] = " + std::to_string(lambda) +
           " must be finite and > 0");
    }
    inverse_squared += lambda * lambda;
  }
  return 1.0 / std::sqrt(inverse_squared);
}

double steering_angle_bound(const ControllerParameters& parameters) {
  parameters.validate();
  return compute_chain_bounds(parameters).steering_angle_rad;
}

double fictive_wheelbase(double vehicle_wheelbase_m, const double* outer_wheelbases, int count) {
  double outer = 0.0;
  for (int i = 0; i < count; ++i) outer += outer_wheelbases[i] * outer_wheelbases[i];
  const double lambda = cornering_front_wheelbase(vehicle_wheelbase_m, outer);
  if (!(lambda > 0.0)) {
    std::ostringstream text;
    text << "fictive wheelbase: lambda_veh^2 - sum lambda_i^2 = "
         << vehicle_wheelbase_m * vehicle_wheelbase_m - outer
         << " must be > 0 (eq. cornering_constr: the outer wheelbases must be shorter than "
            "lambda_veh = "
         << vehicle_wheelbase_m << " m)";
    fail(text.str());
  }
  return lambda;
}

double minimum_k_rob(double matched_disturbance_curvature, double path_curvature_bound,
                     double lead_curvature_bound, double k_rob_floor, double k_rob_ceiling) {
  if (!(matched_disturbance_curvature >= 0.0) || !(path_curvature_bound >= 0.0) ||
      !std::isfinite(matched_disturbance_curvature + path_curvature_bound)) {
    std::ostringstream text;
    text << "minimum_k_rob: matched disturbance " << matched_disturbance_curvature
         << " 1/m and path curvature bound " << path_curvature_bound
         << " 1/m must be finite and >= 0";
    fail(text.str());
  }
  if (!std::isfinite(lead_curvature_bound) || lead_curvature_bound <= 0.0) {
    fail("minimum_k_rob: lead_curvature_bound = " + std::to_string(lead_curvature_bound) +
         " must be finite and > 0");
  }
  const double needed = std::max(
      k_rob_floor, (matched_disturbance_curvature + path_curvature_bound) / lead_curvature_bound);
  if (!(needed < k_rob_ceiling)) {
    std::ostringstream text;
    text << "k_rob >= (kappa_d + kbar_path) / kbar_l = (" << matched_disturbance_curvature << " + "
         << path_curvature_bound << ") / " << lead_curvature_bound << " = " << needed
         << " is not below " << k_rob_ceiling
         << " (Sec. III item 2): the lead curvature bound is too small for the disturbance";
    fail(text.str());
  }
  return needed;
}

ControllerParameters second_order_parameters(const ControllerParameters& base,
                                             double vehicle_wheelbase_m, double lead_wheelbase_m,
                                             double lead_curvature_bound, double k_rob) noexcept {
  ControllerParameters parameters = base;
  parameters.chain.order = 2;
  parameters.chain.vehicle_wheelbase_m = vehicle_wheelbase_m;
  parameters.chain.wheelbases_m[0] =
      cornering_front_wheelbase(vehicle_wheelbase_m, lead_wheelbase_m * lead_wheelbase_m);
  parameters.chain.wheelbases_m[1] = lead_wheelbase_m;
  parameters.chain.lead_curvature_bound = lead_curvature_bound;
  parameters.law.k_rob = k_rob;
  return parameters;
}

}  // namespace smoothsteer
