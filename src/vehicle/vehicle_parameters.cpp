#include "smoothsteer/vehicle/vehicle_parameters.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace smoothsteer {
namespace {

std::string describe(const std::string& field, double value, const std::string& rule) {
  std::ostringstream message;
  message.precision(10);
  message << "VehicleParameters: " << field << " = " << value << " " << rule;
  return message.str();
}

bool positive(double value) {
  return std::isfinite(value) && value > 0.0;
}

std::string tire_error(const std::string& name, const TireParameters& tire) {
  if (!positive(tire.stiffness_factor_b)) {
    return describe(name + ".stiffness_factor_b", tire.stiffness_factor_b,
                    "must be finite and > 0");
  }
  if (!positive(tire.shape_factor_c) || tire.shape_factor_c >= 2.0) {
    return describe(name + ".shape_factor_c", tire.shape_factor_c,
                    "must be in (0, 2) (lateral Magic Formula shape)");
  }
  if (!positive(tire.friction_mu)) {
    return describe(name + ".friction_mu", tire.friction_mu, "must be finite and > 0");
  }
  if (!std::isfinite(tire.curvature_factor_e) || tire.curvature_factor_e > 1.0) {
    return describe(name + ".curvature_factor_e", tire.curvature_factor_e,
                    "must be finite and <= 1 (Pacejka: E <= 1)");
  }
  return {};
}

}  // namespace

double VehicleParameters::understeer_gradient() const noexcept {
  const double front = front_tire.normalized_cornering_stiffness() * front_axle_load_n();
  const double rear = rear_tire.normalized_cornering_stiffness() * rear_axle_load_n();
  return mass_kg / wheelbase_m() * (cg_to_rear_axle_m / front - cg_to_front_axle_m / rear);
}

std::string VehicleParameters::validation_error() const {
  if (!positive(mass_kg)) return describe("mass_kg", mass_kg, "must be finite and > 0");
  if (!positive(yaw_inertia_kgm2)) {
    return describe("yaw_inertia_kgm2", yaw_inertia_kgm2, "must be finite and > 0");
  }
  if (!positive(cg_to_front_axle_m)) {
    return describe("cg_to_front_axle_m", cg_to_front_axle_m, "must be finite and > 0");
  }
  if (!positive(cg_to_rear_axle_m)) {
    return describe("cg_to_rear_axle_m", cg_to_rear_axle_m, "must be finite and > 0");
  }
  if (!std::isfinite(cg_height_m) || cg_height_m < 0.0) {
    return describe("cg_height_m", cg_height_m, "must be finite and >= 0");
  }
  if (!positive(gravity_mps2))
    return describe("gravity_mps2", gravity_mps2, "must be finite and > 0");
  if (std::string e = tire_error("front_tire", front_tire); !e.empty()) return e;
  if (std::string e = tire_error("rear_tire", rear_tire); !e.empty()) return e;
  if (!positive(max_steering_angle_rad) || max_steering_angle_rad >= 1.5) {
    return describe("max_steering_angle_rad", max_steering_angle_rad, "must be in (0, 1.5)");
  }
  if (!positive(max_steering_rate_radps)) {
    return describe("max_steering_rate_radps", max_steering_rate_radps, "must be finite and > 0");
  }
  if (std::isnan(max_steering_acceleration_radps2) || max_steering_acceleration_radps2 <= 0.0) {
    return describe("max_steering_acceleration_radps2", max_steering_acceleration_radps2,
                    "must be > 0 (+inf: none)");
  }
  if (!std::isfinite(kinematic_below_mps) || kinematic_below_mps < 0.1) {
    return describe("kinematic_below_mps", kinematic_below_mps,
                    "must be >= 0.1 (slip angles are singular at v = 0)");
  }
  if (!std::isfinite(kinetic_above_mps) || kinetic_above_mps <= kinematic_below_mps) {
    return describe("kinetic_above_mps", kinetic_above_mps,
                    "must be finite and > kinematic_below_mps");
  }
  if (!positive(kinematic_relaxation_s)) {
    return describe("kinematic_relaxation_s", kinematic_relaxation_s, "must be finite and > 0");
  }
  return {};
}

void VehicleParameters::validate() const {
  const std::string error = validation_error();
  if (!error.empty()) throw std::invalid_argument(error);
}

}  // namespace smoothsteer
