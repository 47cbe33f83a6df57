#pragma once
//! \file vehicle_model.hpp
//! Planar vehicle models behind one interface (the double-track model: double_track.hpp). The state
//! is that of the kinetic model (Rajamani ch. 2; paper_notes §9): position of the centre of gravity
//! (CG), heading, and the body-frame velocity and yaw rate. The kinematic model uses the same
//! state, with vy and r fixed algebraically by the steering angle, so the simulation and the
//! metrics treat both alike. Longitudinal speed is prescribed: d vx / dt is an input (the speed
//! profile), i.e. the longitudinal force is whatever the profile requires.

#include <array>
#include <memory>

#include "smoothsteer/math/vec2.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"
#include "smoothsteer/vehicle/vehicle_parameters.hpp"

namespace smoothsteer {

struct VehicleState {
  double x_m = 0.0;             //!< X of the CG [m]
  double y_m = 0.0;             //!< Y of the CG [m]
  double heading_rad = 0.0;     //!< psi [rad]
  double vx_mps = 0.0;          //!< longitudinal velocity in the body frame [m/s]
  double vy_mps = 0.0;          //!< lateral velocity of the CG in the body frame [m/s]
  double yaw_rate_radps = 0.0;  //!< r = d psi / dt [rad/s]
  //! Roll angle phi of the body about the roll axis, positive to the right (outward in a left
  //! turn) [rad]; the single-track models leave it and its rate at 0 (double_track.hpp).
  double roll_rad = 0.0;
  double roll_rate_radps = 0.0;  //!< d phi / dt [rad/s]

  static constexpr int size = 8;
  std::array<double, size> to_array() const noexcept {
    return {x_m, y_m, heading_rad, vx_mps, vy_mps, yaw_rate_radps, roll_rad, roll_rate_radps};
  }
  static VehicleState from_array(const std::array<double, size>& a) noexcept {
    return {a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7]};
  }
};

//! Side-slip angle of the CG, beta = atan(vy / vx) (0 at standstill) [rad].
double side_slip_angle(const VehicleState& state) noexcept;
//! Side slip of the rear axle, beta_r = atan((vy - lr r) / vx): the angle from the heading to the
//! rear axle's velocity (0 below 1e-6 m/s). What ControllerInput::rear_axle_side_slip_rad means.
double rear_axle_side_slip_angle(const VehicleState& state,
                                 const VehicleParameters& vehicle) noexcept;
//! Rear-axle pose, the controller's reference point: rear = CG - lr (cos psi, sin psi).
Pose2 rear_axle_pose(const VehicleState& state, const VehicleParameters& vehicle) noexcept;
//! Front-axle position: CG + lf (cos psi, sin psi).
Vec2 front_axle_position(const VehicleState& state, const VehicleParameters& vehicle) noexcept;
//! State at rest-free steady straight motion with the rear axle at `rear` and speed v.
VehicleState state_from_rear_axle(const Pose2& rear, double speed_mps,
                                  const VehicleParameters& vehicle) noexcept;

class VehicleModel {
 public:
  explicit VehicleModel(const VehicleParameters& parameters);  //!< validates (throws)
  virtual ~VehicleModel() = default;

  //! d state / dt for steering angle delta and longitudinal acceleration (real time: noexcept,
  //! allocation free).
  virtual VehicleState derivative(const VehicleState& state, double steering_angle_rad,
                                  double longitudinal_acceleration_mps2) const noexcept = 0;
  //! Enforces algebraic constraints after an integration step (the kinematic model sets vy, r).
  virtual void constrain(VehicleState& state, double steering_angle_rad) const noexcept {
    (void)state;
    (void)steering_angle_rad;
  }
  virtual const char* name() const noexcept = 0;
  //! The same model for other parameters (set-up: allocates, validates), so that a simulation
  //! can give the plant parameters the controller is not told; null for a model that cannot be
  //! rebuilt so.
  virtual std::unique_ptr<VehicleModel> with_parameters(const VehicleParameters& parameters) const {
    (void)parameters;
    return nullptr;
  }

  const VehicleParameters& parameters() const noexcept { return parameters_; }

 protected:
  VehicleParameters parameters_;
};

//! Kinematic single-track model (eq. kappar), rear axle rolling without slip:
//! r = vx tan(delta) / L, vy = lr r.
class KinematicVehicleModel final : public VehicleModel {
 public:
  using VehicleModel::VehicleModel;
  VehicleState derivative(const VehicleState& state, double steering_angle_rad,
                          double longitudinal_acceleration_mps2) const noexcept override;
  void constrain(VehicleState& state, double steering_angle_rad) const noexcept override;
  const char* name() const noexcept override { return "kinematic"; }
};

//! Kinetic single-track model with Pacejka lateral forces (paper_notes §9), blended linearly to
//! the kinematic model between kinematic_below_mps and kinetic_above_mps so that nothing divides
//! by a vanishing speed.
class DynamicSingleTrack final : public VehicleModel {
 public:
  using VehicleModel::VehicleModel;
  VehicleState derivative(const VehicleState& state, double steering_angle_rad,
                          double longitudinal_acceleration_mps2) const noexcept override;
  const char* name() const noexcept override { return "dynamic"; }
  std::unique_ptr<VehicleModel> with_parameters(
      const VehicleParameters& parameters) const override {
    return std::make_unique<DynamicSingleTrack>(parameters);
  }

  //! Lateral Magic Formula force [N] for slip angle alpha [rad] and vertical load Fz [N].
  static double lateral_force(const TireParameters& tire, double slip_angle_rad,
                              double vertical_load_n) noexcept;
  //! Its slope dFy / dalpha [N/rad] (B C D at alpha = 0: the cornering stiffness).
  static double lateral_force_slope(const TireParameters& tire, double slip_angle_rad,
                                    double vertical_load_n) noexcept;
  //! Front and rear slip angles [rad] (0 at standstill).
  struct SlipAngles {
    double front_rad = 0.0;
    double rear_rad = 0.0;
  };
  SlipAngles slip_angles(const VehicleState& state, double steering_angle_rad) const noexcept;
};

}  // namespace smoothsteer
