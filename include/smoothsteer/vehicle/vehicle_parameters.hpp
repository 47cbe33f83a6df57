#pragma once
//! \file vehicle_parameters.hpp
//! Parameters of the single-track vehicle models (kinematic and kinetic) and of the Pacejka
//! Magic Formula lateral tire (paper_notes §9; Rajamani, Vehicle Dynamics and Control, ch. 2, 13).
//! Defaults: CommonRoad vehicle models, "vehicle 2" (BMW 320i), see vehicles/passenger_car.yaml.

#include <algorithm>
#include <limits>
#include <optional>
#include <string>

#include "smoothsteer/validation.hpp"
#include "smoothsteer/vehicle/double_track_parameters.hpp"

namespace smoothsteer {

//! Lateral Magic Formula of one axle: Fy = D sin(C atan(B a - E (B a - atan(B a)))), D = mu Fz.
struct TireParameters {
  double stiffness_factor_b = 15.47;       //!< B [1/rad]
  double shape_factor_c = 1.3507;          //!< C [-]
  double friction_mu = 1.0489;             //!< D / Fz [-]
  double curvature_factor_e = -0.0074722;  //!< E [-]

  //! Cornering stiffness per unit load, dFy/dalpha / Fz at alpha = 0: B C mu [1/rad].
  double normalized_cornering_stiffness() const noexcept {
    return stiffness_factor_b * shape_factor_c * friction_mu;
  }
};

//! The first rule the tire breaks, reported as `owner`.`prefix`field (validation.hpp).
std::optional<Violation> tire_violation(const char* owner, const char* prefix,
                                        const TireParameters& tire) noexcept;

//! Physical ranges beyond "finite and > 0" (validation): values outside them describe no car
//! and make the plant stiff, so that the adaptive integrators take 10 s per simulated second
//! (mass 1e9 kg, Iz 0.01 kg m^2, B 1e6). Wide enough for a 1/10-scale model car and a mining
//! truck. The dynamic index Iz / (m lf lr) is about 1 for cars (Rajamani, ch. 2).
struct VehiclePhysicalRange {
  static constexpr double min_mass_kg = 1.0;
  static constexpr double max_mass_kg = 1e6;
  static constexpr double min_dynamic_index = 0.1;
  static constexpr double max_dynamic_index = 10.0;
  static constexpr double min_wheelbase_m = 0.01;  //!< lf + lr, as ControllerParameters
  static constexpr double max_wheelbase_m = 100.0;
  static constexpr double max_gravity_mps2 = 100.0;
  static constexpr double max_stiffness_factor_b = 100.0;  //!< Pacejka B [1/rad]; cars 5-30
  static constexpr double max_friction_mu = 3.0;           //!< racing slicks reach about 2
};

struct VehicleParameters {
  double mass_kg = 1093.3;            //!< m [kg]
  double yaw_inertia_kgm2 = 1791.6;   //!< Iz [kg m^2]
  double cg_to_front_axle_m = 1.156;  //!< lf [m]
  double cg_to_rear_axle_m = 1.422;   //!< lr [m]
  //! h [m]: the axle loads shift with the longitudinal acceleration about it (both kinetic
  //! models); the double-track model also rolls about it.
  double cg_height_m = 0.614;
  double gravity_mps2 = 9.81;             //!< g [m/s^2]
  TireParameters front_tire;              //!< lumped front axle
  TireParameters rear_tire;               //!< lumped rear axle
  double max_steering_angle_rad = 1.066;  //!< |delta| limit of the steering system [rad]
  double max_steering_rate_radps = 0.4;   //!< |d delta/dt| limit of the steering system [rad/s]
  //! |d2 delta/dt2| limit of the steering system [rad/s^2]; +inf = none given. Not enforced by
  //! the simulated actuator (a low-pass): it is what the tuner certifies and the metrics count.
  double max_steering_acceleration_radps2 = std::numeric_limits<double>::infinity();
  //! Below this speed the kinetic model is purely kinematic [m/s] (no slip angles at v -> 0).
  double kinematic_below_mps = 1.0;
  //! Above this speed the kinetic model is purely kinetic [m/s]; linear blend in between.
  double kinetic_above_mps = 2.0;
  //! Time constant [s] with which vy and r relax to their kinematic values in the blend region.
  double kinematic_relaxation_s = 0.02;
  //! What the double-track model needs besides (double_track_parameters.hpp); absent: the
  //! vehicle runs on the single-track models only.
  std::optional<DoubleTrackParameters> double_track;

  double wheelbase_m() const noexcept { return cg_to_front_axle_m + cg_to_rear_axle_m; }
  //! Axle loads at longitudinal acceleration a_x [N]: the static Fz_f = m g lr / L and
  //! Fz_r = m g lf / L, shifted by the pitch moment m a_x h / L (Rajamani, Vehicle Dynamics and
  //! Control, eqs. 4.17-4.18, with the aerodynamic and grade terms left out; CommonRoad's
  //! single-track model does the same). Never below 0.
  double front_axle_load_n(double longitudinal_acceleration_mps2 = 0.0) const noexcept {
    return std::max(0.0, mass_kg * gravity_mps2 * cg_to_rear_axle_m / wheelbase_m() -
                             longitudinal_load_shift_n(longitudinal_acceleration_mps2));
  }
  double rear_axle_load_n(double longitudinal_acceleration_mps2 = 0.0) const noexcept {
    return std::max(0.0, mass_kg * gravity_mps2 * cg_to_front_axle_m / wheelbase_m() +
                             longitudinal_load_shift_n(longitudinal_acceleration_mps2));
  }
  //! m a_x h / L [N]: the load the rear axle gains from the front one under acceleration a_x.
  double longitudinal_load_shift_n(double longitudinal_acceleration_mps2) const noexcept {
    return mass_kg * longitudinal_acceleration_mps2 * cg_height_m / wheelbase_m();
  }
  //! Understeer gradient of the linearized model, K = m/L (lr/Cf - lf/Cr) [rad s^2/m], with the
  //! axle cornering stiffnesses Cf, Cr = B C D (Rajamani eq. 3.23 written per axle).
  double understeer_gradient() const noexcept;
  //! Axle cornering stiffnesses Cf, Cr = B C D at the static loads [N/rad].
  double front_cornering_stiffness_npr() const noexcept;
  double rear_cornering_stiffness_npr() const noexcept;
  //! K_r = m lf / (L Cr) [rad / (m/s^2)]: stationary rear-axle side slip per lateral
  //! acceleration of the linear model, beta_r = -K_r a_y (the rear tire carries m a_y lf / L).
  double rear_slip_gradient() const noexcept;
  //! K_f = m lr / (L Cf) [s^2/m]: the front axle's slip angle per lateral acceleration.
  double front_slip_gradient() const noexcept;
  //! Friction limit of the lateral acceleration, min(mu_f, mu_r) g [m/s^2].
  double friction_limit_mps2() const noexcept;

  //! The first rule broken (validation.hpp); is_valid(), validation_error(), validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else the message naming the field, its value and the rule.
  std::string validation_error() const;
  //! Throws std::invalid_argument with validation_error().
  void validate() const;
};

}  // namespace smoothsteer
