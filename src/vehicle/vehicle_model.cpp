#include "smoothsteer/vehicle/vehicle_model.hpp"

#include <algorithm>
#include <cmath>

namespace smoothsteer {

double side_slip_angle(const VehicleState& state) noexcept {
  // At rest (a cusp of a parking manoeuvre) the relaxing vy leaves no meaningful angle.
  if (std::abs(state.vx_mps) < 1e-6) return 0.0;
  // atan(vy / vx) for vx > 0, atan(vy / |vx|) in reverse.
  return std::atan2(state.vy_mps, std::abs(state.vx_mps));
}

double rear_axle_side_slip_angle(const VehicleState& state,
                                 const VehicleParameters& vehicle) noexcept {
  if (std::abs(state.vx_mps) < 1e-6) return 0.0;
  return std::atan((state.vy_mps - vehicle.cg_to_rear_axle_m * state.yaw_rate_radps) /
                   state.vx_mps);
}

Pose2 rear_axle_pose(const VehicleState& state, const VehicleParameters& vehicle) noexcept {
  const Vec2 cg{state.x_m, state.y_m};
  return {cg - vehicle.cg_to_rear_axle_m * unit_from_heading(state.heading_rad), state.heading_rad};
}

Vec2 front_axle_position(const VehicleState& state, const VehicleParameters& vehicle) noexcept {
  return Vec2{state.x_m, state.y_m} +
         vehicle.cg_to_front_axle_m * unit_from_heading(state.heading_rad);
}

VehicleState state_from_rear_axle(const Pose2& rear, double speed_mps,
                                  const VehicleParameters& vehicle) noexcept {
  const Vec2 cg = rear.position + vehicle.cg_to_rear_axle_m * unit_from_heading(rear.heading_rad);
  return {cg.x, cg.y, rear.heading_rad, speed_mps, 0.0, 0.0};
}

VehicleModel::VehicleModel(const VehicleParameters& parameters) : parameters_(parameters) {
  parameters_.validate();
}

namespace {

//! Kinematic yaw rate and lateral CG velocity for vx and delta (eq. kappar).
struct KinematicLateral {
  double yaw_rate = 0.0;
  double vy = 0.0;
};
KinematicLateral kinematic_lateral(const VehicleParameters& p, double vx, double delta) noexcept {
  const double yaw_rate = vx * std::tan(delta) / p.wheelbase_m();
  return {yaw_rate, p.cg_to_rear_axle_m * yaw_rate};
}

VehicleState planar_motion(const VehicleState& s, double yaw_rate, double vy) noexcept {
  const double c = std::cos(s.heading_rad);
  const double sn = std::sin(s.heading_rad);
  VehicleState d;
  d.x_m = s.vx_mps * c - vy * sn;
  d.y_m = s.vx_mps * sn + vy * c;
  d.heading_rad = yaw_rate;
  return d;
}

//! The Magic Formula's argument B a - E (B a - atan(B a)): Fy = D sin(C atan(.)).
double magic_formula_argument(const TireParameters& tire, double slip_angle_rad) noexcept {
  const double b_alpha = tire.stiffness_factor_b * slip_angle_rad;
  return b_alpha - tire.curvature_factor_e * (b_alpha - std::atan(b_alpha));
}

}  // namespace

VehicleState KinematicVehicleModel::derivative(
    const VehicleState& state, double steering_angle_rad,
    double longitudinal_acceleration_mps2) const noexcept {
  const KinematicLateral k = kinematic_lateral(parameters_, state.vx_mps, steering_angle_rad);
  VehicleState d = planar_motion(state, k.yaw_rate, k.vy);
  d.vx_mps = longitudinal_acceleration_mps2;
  return d;  // vy and r are algebraic: constrain() sets them
}

void KinematicVehicleModel::constrain(VehicleState& state,
                                      double steering_angle_rad) const noexcept {
  const KinematicLateral k = kinematic_lateral(parameters_, state.vx_mps, steering_angle_rad);
  state.yaw_rate_radps = k.yaw_rate;
  state.vy_mps = k.vy;
}

double DynamicSingleTrack::lateral_force(const TireParameters& tire, double slip_angle_rad,
                                         double vertical_load_n) noexcept {
  const double inner = magic_formula_argument(tire, slip_angle_rad);
  return tire.friction_mu * vertical_load_n * std::sin(tire.shape_factor_c * std::atan(inner));
}

double DynamicSingleTrack::lateral_force_slope(const TireParameters& tire, double slip_angle_rad,
                                               double vertical_load_n) noexcept {
  const double b = tire.stiffness_factor_b, c = tire.shape_factor_c;
  const double b_alpha = b * slip_angle_rad;
  const double inner = magic_formula_argument(tire, slip_angle_rad);
  const double d_inner = b - tire.curvature_factor_e * (b - b / (1.0 + b_alpha * b_alpha));
  return tire.friction_mu * vertical_load_n * std::cos(c * std::atan(inner)) * c /
         (1.0 + inner * inner) * d_inner;
}

DynamicSingleTrack::SlipAngles DynamicSingleTrack::slip_angles(const VehicleState& s,
                                                               double delta) const noexcept {
  const double vx = std::max(s.vx_mps, parameters_.kinematic_below_mps);
  const double lf = parameters_.cg_to_front_axle_m;
  const double lr = parameters_.cg_to_rear_axle_m;
  return {delta - std::atan2(s.vy_mps + lf * s.yaw_rate_radps, vx),
          -std::atan2(s.vy_mps - lr * s.yaw_rate_radps, vx)};
}

VehicleState DynamicSingleTrack::derivative(const VehicleState& s, double delta,
                                            double ax) const noexcept {
  const VehicleParameters& p = parameters_;
  // Blend weight: 0 = kinematic, 1 = kinetic.
  const double w = std::clamp(
      (s.vx_mps - p.kinematic_below_mps) / (p.kinetic_above_mps - p.kinematic_below_mps), 0.0, 1.0);
  VehicleState d = planar_motion(s, s.yaw_rate_radps, s.vy_mps);
  d.vx_mps = ax;  // prescribed by the speed profile
  double dvy = 0.0;
  double dr = 0.0;
  if (w > 0.0) {
    const SlipAngles alpha = slip_angles(s, delta);
    const double fy_front = lateral_force(p.front_tire, alpha.front_rad, p.front_axle_load_n(ax));
    const double fy_rear = lateral_force(p.rear_tire, alpha.rear_rad, p.rear_axle_load_n(ax));
    const double cos_delta = std::cos(delta);
    // m (dvy/dt + vx r) = Fy_r + Fy_f cos(delta);  Iz dr/dt = lf Fy_f cos(delta) - lr Fy_r
    dvy += w * ((fy_rear + fy_front * cos_delta) / p.mass_kg - s.vx_mps * s.yaw_rate_radps);
    dr += w * (p.cg_to_front_axle_m * fy_front * cos_delta - p.cg_to_rear_axle_m * fy_rear) /
          p.yaw_inertia_kgm2;
  }
  if (w < 1.0) {
    const KinematicLateral k = kinematic_lateral(p, s.vx_mps, delta);
    dvy += (1.0 - w) * (k.vy - s.vy_mps) / p.kinematic_relaxation_s;
    dr += (1.0 - w) * (k.yaw_rate - s.yaw_rate_radps) / p.kinematic_relaxation_s;
  }
  d.vy_mps = dvy;
  d.yaw_rate_radps = dr;
  return d;
}

}  // namespace smoothsteer
