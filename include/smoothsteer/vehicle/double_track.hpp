#pragma once
//! \file double_track.hpp
//! Double-track (four-wheel) vehicle model with roll, load transfer and combined slip: the
//! held-out plant, built from published equations and not from the controller's single-track
//! model (docs/simulation.md, "Double-track model").
//!
//! Bodies and coordinates. One rigid body of mass m rolls by phi about a longitudinal roll axis
//! on the ground (CommonRoad's parameter sets put the roll axis there, h_raf = h_rar = 0), its CG
//! at height h above it; the unsprung masses are lumped into it. The state's (X, Y) is the roll
//! axis point below the CG at rest; vx, vy, r are its body-frame velocities (VehicleState).
//! Pitch is quasi-static: the longitudinal load transfer is the drive force's pitch moment.
//!
//! Kinetic energy (the yaw-roll model of Rajamani, Vehicle Dynamics and Control, 2nd ed.,
//! chapter "Roll Dynamics and Rollover Prevention", with the CG offset -h sin(phi) of the body):
//!   T = m (vx^2 + vy^2) / 2 + Iz r^2 / 2 + I_phi phi'^2 / 2
//!       + m h (sin(phi) vx r - cos(phi) vy phi')
//! with I_phi = I_xx + m h^2 about the roll axis; potential V = K_phi phi^2 / 2 + m g h cos(phi).
//! Its equations of motion in the body frame (Boltzmann-Hamel / Euler-Poincare form), exact for
//! this T and therefore conserving T + V up to the tire forces' and the dampers' power:
//!   (x)   m vx' + m h sin(phi) r'          = X + m vy r - 2 m h cos(phi) phi' r
//!   (y)   m vy' - m h cos(phi) phi''       = Y - m vx r - m h sin(phi) (phi'^2 + r^2)
//!   (yaw) m h sin(phi) vx' + Iz r'         = N + m h sin(phi) vy r
//!   (roll) -m h cos(phi) vy' + I_phi phi'' = m h cos(phi) vx r - K_phi phi - D_phi phi'
//!                                            + m g h sin(phi)
//! X, Y, N: the sums of the four tire forces and their yaw moment about the CG.
//!
//! Wheels i = front left, front right, rear left, rear right at (x_i, y_i) = (lf, +-T_f/2),
//! (-lr, +-T_r/2); front road-wheel angles delta_i (Ackermann share, double_track_parameters.hpp),
//! rear 0. Slip angle alpha_i = delta_i - atan2(vy + r x_i, vx - r y_i) (CommonRoad vehicle models
//! 2019b, multi-body model, "lateral slip angles", from Allen et al. 1992 eq. A42-A45).
//! Vertical load Fz_i = static -+ F h / (2 L) (front -, rear +; F the drive force, m a_x with
//! the acceleration input)
//!   -+ (K_phi,axle phi + D_phi,axle phi') / T_axle   (left -, right +),
//! so the springs of each axle carry their share K_phi,axle / K_phi of the roll moment and the
//! lateral load transfer per axle follows the roll stiffness distribution (Rajamani, roll
//! dynamics; Gillespie, Fundamentals of Vehicle Dynamics, ch. 6, lateral load transfer). A lifted
//! wheel carries Fz = 0. Tires: the lateral Magic Formula of the vehicle's axle tire (Pacejka, Tire
//! and Vehicle Dynamics, 3rd ed., ch. 4), D = mu (1 + s dfz) Fz with the load sensitivity s and dfz
//! = (Fz - Fz0) / Fz0 about the wheel's static load Fz0 (Pacejka 2002's mu_y = p_Dy1 + p_Dy2 dfz);
//! combined slip by the friction ellipse: with the longitudinal force Fx_i the side force is Fy_i =
//! Fy0_i sqrt(1 - (Fx_i / (mu_x Fz_i))^2), so (Fx/mu_x Fz)^2 + (Fy/mu Fz)^2 <= 1.
//!
//! Longitudinal input. derivative() takes the speed profile's acceleration, like the single-track
//! models: the drive force is the one that makes vx' = ax (the CommonRoad models' premise of an
//! underlying speed controller), split between the axles by drive_share_front or
//! brake_share_front and equally between left and right (an open differential), and clipped to
//! the friction ellipse, where the car then falls behind the profile.
//! derivative_with_drive_force() takes the force itself (0: coasting).
//! Low speed: blended to the kinematic model exactly as DynamicSingleTrack does.

#include <array>

#include "smoothsteer/vehicle/vehicle_model.hpp"

namespace smoothsteer {

class DoubleTrack final : public VehicleModel {
 public:
  //! Validates; throws std::invalid_argument if the vehicle has no double_track group.
  explicit DoubleTrack(const VehicleParameters& parameters);

  VehicleState derivative(const VehicleState& state, double steering_angle_rad,
                          double longitudinal_acceleration_mps2) const noexcept override;
  //! The same with the total drive force at the wheels given [N] (negative: braking).
  VehicleState derivative_with_drive_force(const VehicleState& state, double steering_angle_rad,
                                           double drive_force_n) const noexcept;
  const char* name() const noexcept override { return "double_track"; }
  std::unique_ptr<VehicleModel> with_parameters(
      const VehicleParameters& parameters) const override {
    return std::make_unique<DoubleTrack>(parameters);
  }

  //! Wheel order: front left, front right, rear left, rear right.
  struct WheelForces {
    std::array<double, 4> vertical_n{};               //!< Fz_i [N]
    std::array<double, 4> longitudinal_n{};           //!< Fx_i in the wheel frame [N]
    std::array<double, 4> lateral_n{};                //!< Fy_i in the wheel frame [N]
    std::array<double, 4> slip_angle_rad{};           //!< alpha_i [rad]
    std::array<double, 4> steering_angle_rad{};       //!< delta_i [rad]
    std::array<double, 4> lateral_friction_n{};       //!< mu(Fz_i) Fz_i: the ellipse's lateral axis
    std::array<double, 4> longitudinal_friction_n{};  //!< mu_x(Fz_i) Fz_i
    double drive_force_n = 0.0;                       //!< the total drive force used [N]
  };
  //! The tire forces derivative() uses (for tests and diagnostics).
  WheelForces wheel_forces(const VehicleState& state, double steering_angle_rad,
                           double longitudinal_acceleration_mps2) const noexcept;
  WheelForces wheel_forces_with_drive_force(const VehicleState& state, double steering_angle_rad,
                                            double drive_force_n) const noexcept;
  //! T + V of the class comment [J] (V = 0 upright at rest).
  double mechanical_energy(const VehicleState& state) const noexcept;
  //! Front road-wheel angles (left, right) for the road-wheel angle delta.
  std::array<double, 2> front_wheel_angles(double steering_angle_rad) const noexcept;

 private:
  struct Longitudinal {
    double value = 0.0;
    bool is_force = false;  //!< value is the drive force [N], else the acceleration [m/s^2]
  };
  WheelForces forces(const VehicleState& s, double delta, Longitudinal input) const noexcept;
  VehicleState evaluate(const VehicleState& s, double delta, Longitudinal input) const noexcept;

  DoubleTrackParameters body_;
  std::array<double, 4> x_{}, y_{};        //!< wheel positions from the CG [m]
  std::array<double, 4> static_load_n_{};  //!< Fz0_i [N]
  double roll_axis_inertia_kgm2_ = 0.0;    //!< I_phi = I_xx + m h^2
};

}  // namespace smoothsteer
