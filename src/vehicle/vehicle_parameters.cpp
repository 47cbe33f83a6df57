#include "smoothsteer/vehicle/vehicle_parameters.hpp"

#include <algorithm>

#include <cmath>
#include <stdexcept>

namespace smoothsteer {
namespace {

constexpr const char* owner = "VehicleParameters";

bool positive(double value) {
  return std::isfinite(value) && value > 0.0;
}

}  // namespace

std::optional<Violation> tire_violation(const char* owner_name, const char* prefix,
                                        const TireParameters& tire) noexcept {
  auto bad = [owner_name, prefix](const char* field, double value, const char* rule) {
    return Violation{owner_name, prefix, field, value, rule};
  };
  if (!positive(tire.stiffness_factor_b)) {
    return bad("stiffness_factor_b", tire.stiffness_factor_b, "must be finite and > 0");
  }
  if (tire.stiffness_factor_b > VehiclePhysicalRange::max_stiffness_factor_b) {
    return bad("stiffness_factor_b", tire.stiffness_factor_b,
               "must be <= 100 1/rad (VehiclePhysicalRange; a stiffer tire makes the plant stiff)");
  }
  if (!positive(tire.shape_factor_c) || tire.shape_factor_c >= 2.0) {
    return bad("shape_factor_c", tire.shape_factor_c,
               "must be in (0, 2) (lateral Magic Formula shape)");
  }
  if (!positive(tire.friction_mu)) {
    return bad("friction_mu", tire.friction_mu, "must be finite and > 0");
  }
  if (tire.friction_mu > VehiclePhysicalRange::max_friction_mu) {
    return bad("friction_mu", tire.friction_mu, "must be <= 3 (VehiclePhysicalRange)");
  }
  if (!std::isfinite(tire.curvature_factor_e) || tire.curvature_factor_e > 1.0) {
    return bad("curvature_factor_e", tire.curvature_factor_e,
               "must be finite and <= 1 (Pacejka: E <= 1)");
  }
  return std::nullopt;
}

double VehicleParameters::front_cornering_stiffness_npr() const noexcept {
  return front_tire.normalized_cornering_stiffness() * front_axle_load_n();
}

double VehicleParameters::rear_cornering_stiffness_npr() const noexcept {
  return rear_tire.normalized_cornering_stiffness() * rear_axle_load_n();
}

double VehicleParameters::understeer_gradient() const noexcept {
  return mass_kg / wheelbase_m() *
         (cg_to_rear_axle_m / front_cornering_stiffness_npr() -
          cg_to_front_axle_m / rear_cornering_stiffness_npr());
}

double VehicleParameters::friction_limit_mps2() const noexcept {
  return std::min(front_tire.friction_mu, rear_tire.friction_mu) * gravity_mps2;
}

double VehicleParameters::rear_slip_gradient() const noexcept {
  return mass_kg * cg_to_front_axle_m / (wheelbase_m() * rear_cornering_stiffness_npr());
}

double VehicleParameters::front_slip_gradient() const noexcept {
  return mass_kg * cg_to_rear_axle_m / (wheelbase_m() * front_cornering_stiffness_npr());
}

std::optional<Violation> VehicleParameters::first_violation() const noexcept {
  auto bad = [](const char* field, double value, const char* rule) {
    return Violation{owner, "", field, value, rule};
  };
  if (!positive(mass_kg)) return bad("mass_kg", mass_kg, "must be finite and > 0");
  if (!positive(yaw_inertia_kgm2)) {
    return bad("yaw_inertia_kgm2", yaw_inertia_kgm2, "must be finite and > 0");
  }
  if (!positive(cg_to_front_axle_m)) {
    return bad("cg_to_front_axle_m", cg_to_front_axle_m, "must be finite and > 0");
  }
  if (!positive(cg_to_rear_axle_m)) {
    return bad("cg_to_rear_axle_m", cg_to_rear_axle_m, "must be finite and > 0");
  }
  if (!std::isfinite(cg_height_m) || cg_height_m < 0.0) {
    return bad("cg_height_m", cg_height_m, "must be finite and >= 0");
  }
  if (!positive(gravity_mps2)) return bad("gravity_mps2", gravity_mps2, "must be finite and > 0");
  using Range = VehiclePhysicalRange;
  if (mass_kg < Range::min_mass_kg || mass_kg > Range::max_mass_kg) {
    return bad("mass_kg", mass_kg, "must be in [1, 1e6] kg (VehiclePhysicalRange)");
  }
  if (wheelbase_m() < Range::min_wheelbase_m || wheelbase_m() > Range::max_wheelbase_m) {
    return bad("cg_to_front_axle_m", cg_to_front_axle_m,
               "gives, with cg_to_rear_axle_m, a wheelbase outside [0.01, 100] m "
               "(VehiclePhysicalRange)");
  }
  const double dynamic_index =
      yaw_inertia_kgm2 / (mass_kg * cg_to_front_axle_m * cg_to_rear_axle_m);
  if (!(dynamic_index >= Range::min_dynamic_index && dynamic_index <= Range::max_dynamic_index)) {
    return bad("yaw_inertia_kgm2", yaw_inertia_kgm2,
               "must give a dynamic index Iz / (mass_kg lf lr) in [0.1, 10] (VehiclePhysicalRange; "
               "cars have about 1)");
  }
  if (gravity_mps2 > Range::max_gravity_mps2) {
    return bad("gravity_mps2", gravity_mps2, "must be <= 100 m/s^2 (VehiclePhysicalRange)");
  }
  if (auto v = tire_violation(owner, "front_tire.", front_tire)) return v;
  if (auto v = tire_violation(owner, "rear_tire.", rear_tire)) return v;
  if (!positive(max_steering_angle_rad) || max_steering_angle_rad >= 1.5) {
    return bad("max_steering_angle_rad", max_steering_angle_rad, "must be in (0, 1.5)");
  }
  if (!positive(max_steering_rate_radps)) {
    return bad("max_steering_rate_radps", max_steering_rate_radps, "must be finite and > 0");
  }
  if (std::isnan(max_steering_acceleration_radps2) || max_steering_acceleration_radps2 <= 0.0) {
    return bad("max_steering_acceleration_radps2", max_steering_acceleration_radps2,
               "must be > 0 (+inf: none)");
  }
  if (!std::isfinite(kinematic_below_mps) || kinematic_below_mps < 0.1) {
    return bad("kinematic_below_mps", kinematic_below_mps,
               "must be >= 0.1 (slip angles are singular at v = 0)");
  }
  if (!std::isfinite(kinetic_above_mps) || kinetic_above_mps <= kinematic_below_mps) {
    return bad("kinetic_above_mps", kinetic_above_mps, "must be finite and > kinematic_below_mps");
  }
  if (!positive(kinematic_relaxation_s)) {
    return bad("kinematic_relaxation_s", kinematic_relaxation_s, "must be finite and > 0");
  }
  if (double_track) {
    if (auto v = double_track->first_violation(owner, "double_track.", mass_kg, gravity_mps2,
                                               cg_height_m)) {
      return v;
    }
  }
  return std::nullopt;
}

std::string VehicleParameters::validation_error() const {
  return describe(first_violation());
}

void VehicleParameters::validate() const {
  throw_if_violated(first_violation());
}

}  // namespace smoothsteer
