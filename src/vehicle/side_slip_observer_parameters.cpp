// SideSlipObserverParameters: from the vehicle file, and their rules (side_slip_observer.hpp).

#include <cmath>

#include "smoothsteer/vehicle/side_slip_observer.hpp"

namespace smoothsteer {
namespace {

constexpr const char* owner = "SideSlipObserverParameters";
// The rule texts below state these bounds.
static_assert(SideSlipObserverParameters::max_steering_offset_bound_rad == 0.2);
static_assert(SideSlipObserverParameters::max_steering_offset_process_std_radps == 0.1);

}  // namespace

SideSlipObserverParameters SideSlipObserverParameters::from_vehicle(
    const VehicleParameters& vehicle, double cornering_stiffness_scale, double mass_scale,
    ObserverTireModel tire_model) {
  SideSlipObserverParameters p;
  p.mass_kg = vehicle.mass_kg * mass_scale;
  p.yaw_inertia_kgm2 = vehicle.yaw_inertia_kgm2 * mass_scale;
  p.cg_to_front_axle_m = vehicle.cg_to_front_axle_m;
  p.cg_to_rear_axle_m = vehicle.cg_to_rear_axle_m;
  p.front_cornering_stiffness_npr =
      cornering_stiffness_scale * vehicle.front_cornering_stiffness_npr();
  p.rear_cornering_stiffness_npr =
      cornering_stiffness_scale * vehicle.rear_cornering_stiffness_npr();
  p.tire_model = tire_model;
  p.front_tire = vehicle.front_tire;
  p.rear_tire = vehicle.rear_tire;
  p.gravity_mps2 = vehicle.gravity_mps2;
  return p;
}

std::optional<Violation> SideSlipObserverParameters::first_violation() const noexcept {
  RuleChecker check(owner);
  const struct {
    const char* field;
    double value;
  } strictly_positive[] = {
      {"mass_kg", mass_kg},
      {"yaw_inertia_kgm2", yaw_inertia_kgm2},
      {"cg_to_front_axle_m", cg_to_front_axle_m},
      {"cg_to_rear_axle_m", cg_to_rear_axle_m},
      {"front_cornering_stiffness_npr", front_cornering_stiffness_npr},
      {"rear_cornering_stiffness_npr", rear_cornering_stiffness_npr},
      {"yaw_rate_noise_std_radps", yaw_rate_noise_std_radps},
      {"lateral_acceleration_noise_std_mps2", lateral_acceleration_noise_std_mps2},
      {"lateral_process_std_mps2", lateral_process_std_mps2},
      {"yaw_process_std_radps2", yaw_process_std_radps2},
  };
  for (const auto& entry : strictly_positive) {
    check.require(positive_finite(entry.value) && entry.value <= 1e12, entry.field, entry.value,
                  "must be finite, > 0 and <= 1e12");
  }
  check.require(std::isfinite(min_speed_mps) && min_speed_mps >= 0.5 && min_speed_mps <= 50.0,
                "min_speed_mps", min_speed_mps, "must be in [0.5, 50] m/s");
  check.require(std::isfinite(max_steering_offset_rad) && max_steering_offset_rad >= 0.0 &&
                    max_steering_offset_rad <= max_steering_offset_bound_rad,
                "max_steering_offset_rad", max_steering_offset_rad,
                "must be in [0, 0.2] rad (0: no offset state)");
  check.require(std::isfinite(steering_offset_process_std_radps) &&
                    steering_offset_process_std_radps >= 0.0 &&
                    steering_offset_process_std_radps <= max_steering_offset_process_std_radps,
                "steering_offset_process_std_radps", steering_offset_process_std_radps,
                "must be in [0, 0.1] rad/sqrt(s)");
  check.require(std::isfinite(offset_learning_min_speed_mps) &&
                    offset_learning_min_speed_mps >= min_speed_mps &&
                    offset_learning_min_speed_mps <= 100.0,
                "offset_learning_min_speed_mps", offset_learning_min_speed_mps,
                "must be in [min_speed_mps, 100] m/s");
  check.require(std::isfinite(offset_learning_max_lateral_acceleration_mps2) &&
                    offset_learning_max_lateral_acceleration_mps2 > 0.0 &&
                    offset_learning_max_lateral_acceleration_mps2 <= 20.0,
                "offset_learning_max_lateral_acceleration_mps2",
                offset_learning_max_lateral_acceleration_mps2, "must be in (0, 20] m/s^2");
  check.require(positive_finite(gravity_mps2) && gravity_mps2 <= 100.0, "gravity_mps2",
                gravity_mps2, "must be finite, > 0 and <= 100");
  check.require(
      tire_model == ObserverTireModel::linear || tire_model == ObserverTireModel::magic_formula,
      "tire_model", static_cast<double>(tire_model), "must be 0 (linear) or 1 (magic_formula)");
  check.include(fault_gate.first_violation(owner, "fault_gate."));
  check.include(tire_violation(owner, "front_tire.", front_tire));
  check.include(tire_violation(owner, "rear_tire.", rear_tire));
  return check.first();
}

std::string SideSlipObserverParameters::validation_error() const {
  return describe(first_violation());
}

void SideSlipObserverParameters::validate() const {
  throw_if_violated(first_violation());
}

}  // namespace smoothsteer
