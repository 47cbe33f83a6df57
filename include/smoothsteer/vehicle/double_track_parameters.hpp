#pragma once
//! \file double_track_parameters.hpp
//! What the double-track model (double_track.hpp) needs beyond the single-track parameters: the
//! track widths, the body's roll inertia, the roll stiffness and damping of each axle, the split
//! of the drive and brake forces, the tires' longitudinal friction and load sensitivity, and the
//! Ackermann share of the steering linkage. Sources: the CommonRoad multi-body model's parameter
//! sets (M. Althoff, "CommonRoad: Vehicle Models", version 2019b, parameters from Allen et al.
//! 1992, appendix A), the roll model of Rajamani, Vehicle Dynamics and Control (2nd ed.), chapter
//! "Roll Dynamics and Rollover Prevention", and the Magic Formula of Pacejka, Tire and Vehicle
//! Dynamics (3rd ed.), ch. 4. The vehicle files in vehicles/ derive the values and say which are
//! assumed; the defaults are those of CommonRoad vehicle 2 (BMW 320i, vehicles/bmw_320i.yaml).

#include <optional>

#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct DoubleTrackParameters {
  double front_track_m = 1.3868;  //!< T_f, distance between the front wheels' centres [m]
  double rear_track_m = 1.3640;   //!< T_r [m]
  //! Roll inertia of the body about the longitudinal axis through its CG, I_xx [kg m^2]; the
  //! model adds m h^2 for the roll axis, I_phi = I_xx + m h^2 (on the ground, CommonRoad h_raf =
  //! h_rar = 0).
  double roll_inertia_kgm2 = 207.27;
  //! Roll stiffness of each axle, K_phi,i: roll moment per roll angle that the axle's springs
  //! and anti-roll bar carry to its wheels [N m/rad].
  double front_roll_stiffness_nmprad = 25361.0;
  double rear_roll_stiffness_nmprad = 18309.0;
  //! Roll damping of each axle, D_phi,i [N m s/rad].
  double front_roll_damping_nmsprad = 1717.8;
  double rear_roll_damping_nmsprad = 1534.0;
  //! Share of the drive force on the front wheels (1: front-wheel drive; CommonRoad T_se) [-].
  double drive_share_front = 0.0;
  //! Share of the brake force on the front wheels (CommonRoad T_sb) [-].
  double brake_share_front = 0.66;
  //! Longitudinal friction coefficient of the tires, the friction ellipse's other half-axis
  //! (Pacejka 2002 p_Dx1) [-]. The lateral one is the single-track tire's friction_mu.
  double longitudinal_friction_mu = 1.1739;
  //! Load sensitivity of the friction, mu(Fz) = mu (1 + s dfz), dfz = (Fz - Fz0) / Fz0 with Fz0
  //! the wheel's static load (Pacejka 2002: s = p_Dy2 / p_Dy1). s < 0: an axle's grip and
  //! cornering stiffness fall as load transfers across it [-].
  double friction_load_sensitivity = -0.1;
  //! 0: both front wheels at the road-wheel angle delta (parallel steer); 1: full Ackermann,
  //! cot(delta_outer) - cot(delta_inner) = T_f / L around delta; in between, linear [-].
  double ackermann_share = 0.0;

  double roll_stiffness_nmprad() const noexcept {
    return front_roll_stiffness_nmprad + rear_roll_stiffness_nmprad;
  }
  //! Front share of the roll stiffness, K_phi,f / K_phi: the front axle's share of the lateral
  //! load transfer through the springs in steady cornering.
  double front_roll_stiffness_share() const noexcept {
    return front_roll_stiffness_nmprad / roll_stiffness_nmprad();
  }

  //! The first rule broken, reported as `owner`.`prefix`field (validation.hpp). `mass_kg` and
  //! `roll_arm_m` (the CG height) are the vehicle's: the body must not tip over on its springs,
  //! K_phi > m g h.
  std::optional<Violation> first_violation(const char* owner, const char* prefix, double mass_kg,
                                           double gravity_mps2, double roll_arm_m) const noexcept;
};

}  // namespace smoothsteer
