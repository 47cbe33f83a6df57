// Plant-only scales of the vehicle and the actuator, crossfall (plant_imperfections.hpp).

#include "smoothsteer/sim/plant_imperfections.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace smoothsteer {
namespace {

[[noreturn]] void refuse(const std::string& field, double value, const std::string& rule) {
  throw std::invalid_argument("SimulationParameters: " + field + " = " + exact_number(value) + " " +
                              rule);
}

}  // namespace

VehicleParameters scaled_plant_vehicle(const VehicleParameters& truth, const PlantScales& scales) {
  VehicleParameters plant = truth;
  plant.mass_kg *= scales.mass;
  plant.yaw_inertia_kgm2 *= scales.yaw_inertia;
  const double wheelbase = truth.wheelbase_m();
  plant.cg_to_front_axle_m -= scales.cg_position * wheelbase;
  plant.cg_to_rear_axle_m += scales.cg_position * wheelbase;
  if (!(plant.cg_to_front_axle_m > 0.0 && plant.cg_to_rear_axle_m > 0.0)) {
    refuse("plant_scales.cg_position", scales.cg_position,
           "moves the CG onto or beyond an axle (lf and lr must stay > 0); lf / L of the "
           "vehicle =" +
               std::string(" ") + exact_number(truth.cg_to_front_axle_m / wheelbase));
  }
  // B carries the stiffness factor; the mass and friction factors are taken out of it again so
  // that each key changes what its name says (C_alpha = B C mu Fz, Fz proportional to m).
  for (TireParameters* tire : {&plant.front_tire, &plant.rear_tire}) {
    tire->friction_mu *= scales.friction;
    tire->stiffness_factor_b *= scales.cornering_stiffness / (scales.mass * scales.friction);
  }
  if (plant.double_track) plant.double_track->longitudinal_friction_mu *= scales.friction;
  if (const std::string error = plant.validation_error(); !error.empty()) {
    throw std::invalid_argument(
        "SimulationParameters: plant_scales give a plant vehicle that breaks its rules: " + error);
  }
  return plant;
}

ActuatorParameters scaled_plant_actuator(const ActuatorParameters& told,
                                         const PlantActuatorScales& scales, double substep_s) {
  ActuatorParameters plant = told;
  plant.bandwidth_hz *= scales.bandwidth;
  plant.dead_time_s = std::round(told.dead_time_s * scales.dead_time / substep_s) * substep_s;
  if (const std::string error = plant.validation_error(substep_s); !error.empty()) {
    throw std::invalid_argument(
        "SimulationParameters: plant_actuator_scales give an actuator that breaks its rules: " +
        error);
  }
  return plant;
}

double crossfall_lateral_acceleration(double grade, double gravity_mps2) noexcept {
  // sin(atan(grade)) without the two transcendental calls.
  return -gravity_mps2 * grade / std::sqrt(1.0 + grade * grade);
}

const VehicleModel& plant_model(const VehicleModel& given, const PlantScales& scales,
                                std::unique_ptr<VehicleModel>& storage) {
  if (scales.identity()) return given;
  storage = given.with_parameters(scaled_plant_vehicle(given.parameters(), scales));
  if (!storage) {
    throw std::invalid_argument(
        std::string("SimulationParameters: plant_scales apply to the kinetic single-track and "
                    "the double-track plants; the ") +
        given.name() +
        " plant has no masses or tires to scale (set every scale to 1 and "
        "cg_position to 0)");
  }
  return *storage;
}

}  // namespace smoothsteer
