#include "smoothsteer/controller/controller_parameters.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace smoothsteer {
namespace {

std::string describe(const std::string& field, double value, const std::string& rule) {
  std::ostringstream message;
  message.precision(10);
  message << "ControllerParameters: " << field << " = " << value << " " << rule;
  return message.str();
}

std::string wheelbase_name(int index) {
  return "wheelbases_m[" + std::to_string(index) + "] (lambda_" + std::to_string(index + 1) + ")";
}

}  // namespace

std::string ControllerParameters::validation_error() const {
  if (order < 0 || order > max_order) {
    return describe("order", order, "must be in [0, " + std::to_string(max_order) + "]");
  }
  if (!std::isfinite(vehicle_wheelbase_m) || vehicle_wheelbase_m <= 0.0) {
    return describe("vehicle_wheelbase_m", vehicle_wheelbase_m, "must be finite and > 0");
  }
  for (int i = 0; i < order; ++i) {
    const double lambda = wheelbases_m[static_cast<std::size_t>(i)];
    if (!std::isfinite(lambda) || lambda <= 0.0) {
      return describe(wheelbase_name(i), lambda,
                      "must be finite and > 0 (reversing is selected by v < 0, not by the sign)");
    }
    // Paper Sec. III item 3: lambda^2 = lambda_veh^2 - lambda_l^2 implies lambda_l < lambda_veh.
    if (i >= 1 && lambda >= vehicle_wheelbase_m) {
      return describe(wheelbase_name(i), lambda,
                      "must be < vehicle_wheelbase_m = " + std::to_string(vehicle_wheelbase_m) +
                          " (eq. cornering_constr: lambda_l < lambda_veh)");
    }
  }
  if (!std::isfinite(lead_curvature_bound) || lead_curvature_bound <= 0.0) {
    return describe("lead_curvature_bound", lead_curvature_bound, "must be finite and > 0");
  }
  if (!std::isfinite(k_rob) || k_rob < 0.0 || k_rob >= 1.0) {
    return describe("k_rob", k_rob, "must be in [0, 1) (eq. sigma divides by 1 - k_rob)");
  }
  if (!std::isfinite(boundary_layer) || boundary_layer < 0.0) {
    return describe("boundary_layer", boundary_layer, "must be finite and >= 0");
  }
  if (!std::isfinite(approach_angle_rad) || approach_angle_rad <= 0.0 ||
      approach_angle_rad > std::numbers::pi / 2.0 + 1e-12) {
    return describe("approach_angle_rad", approach_angle_rad, "must be in (0, pi/2]");
  }
  if (!std::isfinite(max_substep_fraction) || max_substep_fraction <= 0.0 ||
      max_substep_fraction > 1.0) {
    return describe("max_substep_fraction", max_substep_fraction, "must be in (0, 1]");
  }
  if (max_substeps < 1 || max_substeps > 10000) {
    return describe("max_substeps", max_substeps, "must be in [1, 10000]");
  }
  // Invariant sets down the chain (paper-notes §2): kbar_i lambda_i < 1 for every wheel.
  double kbar = lead_curvature_bound;
  for (int i = order; i >= 1; --i) {
    const double lambda = wheelbases_m[static_cast<std::size_t>(i - 1)];
    const double product = kbar * lambda;
    if (product >= 1.0) {
      return describe("kbar_" + std::to_string(i) + " * lambda_" + std::to_string(i), product,
                      "must be < 1 (invariant set |delta_" + std::to_string(i) +
                          "| <= asin(kbar lambda), eq. kappal_constr); reduce "
                          "lead_curvature_bound or the wheelbases");
    }
    kbar /= std::sqrt(1.0 - product * product);
  }
  return {};
}

bool ControllerParameters::is_valid() const noexcept {
  // Mirrors validation_error() rule by rule (tests/tuning compares both on random inputs).
  auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (order < 0 || order > max_order || !positive(vehicle_wheelbase_m)) return false;
  for (int i = 0; i < order; ++i) {
    const double lambda = wheelbases_m[static_cast<std::size_t>(i)];
    if (!positive(lambda) || (i >= 1 && lambda >= vehicle_wheelbase_m)) return false;
  }
  if (!positive(lead_curvature_bound)) return false;
  if (!std::isfinite(k_rob) || k_rob < 0.0 || k_rob >= 1.0) return false;
  if (!std::isfinite(boundary_layer) || boundary_layer < 0.0) return false;
  if (!positive(approach_angle_rad) || approach_angle_rad > std::numbers::pi / 2.0 + 1e-12) {
    return false;
  }
  if (!positive(max_substep_fraction) || max_substep_fraction > 1.0) return false;
  if (max_substeps < 1 || max_substeps > 10000) return false;
  double kbar = lead_curvature_bound;
  for (int i = order; i >= 1; --i) {
    const double product = kbar * wheelbases_m[static_cast<std::size_t>(i - 1)];
    if (product >= 1.0) return false;
    kbar /= std::sqrt(1.0 - product * product);
  }
  return true;
}

void ControllerParameters::validate() const {
  const std::string error = validation_error();
  if (!error.empty()) throw std::invalid_argument(error);
}

ControllerParameters ControllerParameters::paper_c1(double vehicle_wheelbase_m,
                                                    double lead_wheelbase_m,
                                                    double lead_curvature_bound, double k_rob) {
  ControllerParameters parameters;
  parameters.order = 2;
  parameters.vehicle_wheelbase_m = vehicle_wheelbase_m;
  const double squared =
      vehicle_wheelbase_m * vehicle_wheelbase_m - lead_wheelbase_m * lead_wheelbase_m;
  if (!(squared > 0.0)) {
    throw std::invalid_argument(describe("lead wheelbase lambda_l", lead_wheelbase_m,
                                         "must be < vehicle_wheelbase_m (eq. cornering_constr)"));
  }
  parameters.wheelbases_m[0] = std::sqrt(squared);  // eq. (cornering_constr)
  parameters.wheelbases_m[1] = lead_wheelbase_m;
  parameters.lead_curvature_bound = lead_curvature_bound;
  parameters.k_rob = k_rob;
  parameters.cornering_target = CorneringTarget::lead_wheel;
  parameters.validate();
  return parameters;
}

ControllerParameters ControllerParameters::paper_c0(double vehicle_wheelbase_m,
                                                    double front_curvature_bound, double k_rob) {
  ControllerParameters parameters;
  parameters.order = 1;
  parameters.vehicle_wheelbase_m = vehicle_wheelbase_m;
  parameters.wheelbases_m[0] = vehicle_wheelbase_m;
  parameters.lead_curvature_bound = front_curvature_bound;
  parameters.k_rob = k_rob;
  parameters.cornering_target = CorneringTarget::lead_wheel;
  parameters.validate();
  return parameters;
}

}  // namespace smoothsteer
