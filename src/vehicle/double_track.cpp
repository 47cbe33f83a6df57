// Double-track model with roll, load transfer and combined slip (double_track.hpp).

#include "smoothsteer/vehicle/double_track.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace smoothsteer {
namespace {

constexpr int wheels = 4;

std::size_t at(int i) noexcept {
  return static_cast<std::size_t>(i);
}

bool front(int i) noexcept {
  return i < 2;
}

}  // namespace

DoubleTrack::DoubleTrack(const VehicleParameters& parameters) : VehicleModel(parameters) {
  if (!parameters_.double_track) {
    throw std::invalid_argument(
        "VehicleParameters: double_track is absent; the double_track model needs it (vehicle "
        "file key 'double_track': tracks, roll inertia, roll stiffness and damping, ...)");
  }
  body_ = *parameters_.double_track;
  const double lf = parameters_.cg_to_front_axle_m, lr = parameters_.cg_to_rear_axle_m;
  x_ = {lf, lf, -lr, -lr};
  y_ = {0.5 * body_.front_track_m, -0.5 * body_.front_track_m, 0.5 * body_.rear_track_m,
        -0.5 * body_.rear_track_m};
  const double front_load = 0.5 * parameters_.front_axle_load_n();
  const double rear_load = 0.5 * parameters_.rear_axle_load_n();
  static_load_n_ = {front_load, front_load, rear_load, rear_load};
  const double h = parameters_.cg_height_m;
  roll_axis_inertia_kgm2_ = body_.roll_inertia_kgm2 + parameters_.mass_kg * h * h;
}

std::array<double, 2> DoubleTrack::front_wheel_angles(double delta) const noexcept {
  const double share = body_.ackermann_share;
  if (share == 0.0) return {delta, delta};
  // Full Ackermann about the single-track angle: tan(delta_left) = L t / (L - T_f t / 2) with
  // t = tan(delta), so that cot(delta_outer) - cot(delta_inner) = T_f / L (Gillespie, Fundamentals
  // of Vehicle Dynamics, ch. 6, low-speed turning).
  const double wheelbase = parameters_.wheelbase_m();
  const double t = std::tan(delta);
  const double half = 0.5 * body_.front_track_m;
  const double left = std::atan2(wheelbase * t, wheelbase - half * t);
  const double right = std::atan2(wheelbase * t, wheelbase + half * t);
  return {delta + share * (left - delta), delta + share * (right - delta)};
}

DoubleTrack::WheelForces DoubleTrack::forces(const VehicleState& s, double delta,
                                             Longitudinal input) const noexcept {
  const VehicleParameters& p = parameters_;
  const double m = p.mass_kg, h = p.cg_height_m;
  WheelForces w;
  const std::array<double, 2> angles = front_wheel_angles(delta);
  w.steering_angle_rad = {angles[0], angles[1], 0.0, 0.0};
  std::array<double, wheels> sin_delta{}, cos_delta{};
  for (int i = 0; i < wheels; ++i) {
    sin_delta[at(i)] = std::sin(w.steering_angle_rad[at(i)]);
    cos_delta[at(i)] = std::cos(w.steering_angle_rad[at(i)]);
  }

  // Vertical loads: static, the drive force's pitch moment F h over the wheelbase, and the roll
  // moment each axle's springs and dampers carry, over its track (double_track.hpp).
  const double pitch_force = input.is_force ? input.value : m * input.value;
  const double pitch_transfer = 0.5 * pitch_force * h / p.wheelbase_m();
  const double front_roll = (body_.front_roll_stiffness_nmprad * s.roll_rad +
                             body_.front_roll_damping_nmsprad * s.roll_rate_radps) /
                            body_.front_track_m;
  const double rear_roll = (body_.rear_roll_stiffness_nmprad * s.roll_rad +
                            body_.rear_roll_damping_nmsprad * s.roll_rate_radps) /
                           body_.rear_track_m;
  const std::array<double, wheels> transfer{-pitch_transfer - front_roll,
                                            -pitch_transfer + front_roll,
                                            pitch_transfer - rear_roll, pitch_transfer + rear_roll};
  std::array<double, wheels> pure_lateral{};
  const double vx_floor = p.kinematic_below_mps;
  for (int i = 0; i < wheels; ++i) {
    const std::size_t k = at(i);
    const double load = std::max(0.0, static_load_n_[k] + transfer[k]);
    w.vertical_n[k] = load;
    // mu (1 + s dfz) Fz (Pacejka 2002 mu_y = p_Dy1 + p_Dy2 dfz), never below 0.
    const double sensitivity =
        std::max(0.0, 1.0 + body_.friction_load_sensitivity * (load - static_load_n_[k]) /
                                static_load_n_[k]);
    const double effective_load = load * sensitivity;
    const TireParameters& tire = front(i) ? p.front_tire : p.rear_tire;
    w.lateral_friction_n[k] = tire.friction_mu * effective_load;
    w.longitudinal_friction_n[k] = body_.longitudinal_friction_mu * effective_load;
    const double forward = std::max(s.vx_mps - s.yaw_rate_radps * y_[k], vx_floor);
    const double sideways = s.vy_mps + s.yaw_rate_radps * x_[k];
    w.slip_angle_rad[k] = w.steering_angle_rad[k] - std::atan2(sideways, forward);
    pure_lateral[k] = DynamicSingleTrack::lateral_force(tire, w.slip_angle_rad[k], effective_load);
  }

  // Longitudinal forces: the drive force split between the axles and equally left and right,
  // each clipped to its wheel's friction; the side force shrinks to the friction ellipse.
  auto shares = [this](double force) {
    const double f = force >= 0.0 ? body_.drive_share_front : body_.brake_share_front;
    return std::array<double, wheels>{0.5 * f, 0.5 * f, 0.5 * (1.0 - f), 0.5 * (1.0 - f)};
  };
  auto longitudinal = [&w](double share, double force, std::size_t k) {
    return std::clamp(share * force, -w.longitudinal_friction_n[k], w.longitudinal_friction_n[k]);
  };
  auto lateral = [&w, &pure_lateral](double fx, std::size_t k) {
    const double capacity = w.longitudinal_friction_n[k];
    const double used = capacity > 0.0 ? fx / capacity : 1.0;
    return pure_lateral[k] * std::sqrt(std::max(0.0, 1.0 - used * used));
  };
  double force = input.value;
  if (!input.is_force) {
    // The force that makes vx' = ax in equation (x), neglecting its m h sin(phi) r' term:
    // sum_i (Fx_i cos(delta_i) - Fy_i sin(delta_i)) = m (ax - vy r) + 2 m h cos(phi) phi' r.
    // Fy_i depends on Fx_i through the ellipse: two fixed-point passes (the second changes the
    // force by well under 1 N on the shipped scenarios).
    const double target = m * (input.value - s.vy_mps * s.yaw_rate_radps) +
                          2.0 * m * h * std::cos(s.roll_rad) * s.roll_rate_radps * s.yaw_rate_radps;
    force = target;
    for (int pass = 0; pass < 2; ++pass) {
      const std::array<double, wheels> share = shares(force);
      double numerator = target, denominator = 0.0;
      for (int i = 0; i < wheels; ++i) {
        const std::size_t k = at(i);
        numerator += lateral(longitudinal(share[k], force, k), k) * sin_delta[k];
        denominator += share[k] * cos_delta[k];
      }
      // The shares' cosines add to > 0.1 unless full Ackermann turns an inner wheel past 84 deg
      // (|delta| near 1.5 rad on a short wheelbase); there the steering correction is dropped.
      force = denominator > 0.1 ? numerator / denominator : numerator;
    }
  }
  w.drive_force_n = force;
  const std::array<double, wheels> share = shares(force);
  for (int i = 0; i < wheels; ++i) {
    const std::size_t k = at(i);
    w.longitudinal_n[k] = longitudinal(share[k], force, k);
    w.lateral_n[k] = lateral(w.longitudinal_n[k], k);
  }
  return w;
}

DoubleTrack::WheelForces DoubleTrack::wheel_forces(const VehicleState& state, double delta,
                                                   double acceleration) const noexcept {
  return forces(state, delta, {acceleration, false});
}

DoubleTrack::WheelForces DoubleTrack::wheel_forces_with_drive_force(const VehicleState& state,
                                                                    double delta,
                                                                    double force) const noexcept {
  return forces(state, delta, {force, true});
}

VehicleState DoubleTrack::derivative(const VehicleState& state, double delta,
                                     double acceleration) const noexcept {
  return evaluate(state, delta, {acceleration, false});
}

VehicleState DoubleTrack::derivative_with_drive_force(const VehicleState& state, double delta,
                                                      double force) const noexcept {
  return evaluate(state, delta, {force, true});
}

VehicleState DoubleTrack::evaluate(const VehicleState& s, double delta,
                                   Longitudinal input) const noexcept {
  const VehicleParameters& p = parameters_;
  const double m = p.mass_kg, h = p.cg_height_m, g = p.gravity_mps2;
  const double iz = p.yaw_inertia_kgm2, i_phi = roll_axis_inertia_kgm2_;
  const double sin_phi = std::sin(s.roll_rad), cos_phi = std::cos(s.roll_rad);
  const double mh = m * h;
  const double r = s.yaw_rate_radps, phi_rate = s.roll_rate_radps;
  const double roll_moment =
      -body_.roll_stiffness_nmprad() * s.roll_rad -
      (body_.front_roll_damping_nmsprad + body_.rear_roll_damping_nmsprad) * phi_rate +
      m * g * h * sin_phi;

  VehicleState d;
  const double c = std::cos(s.heading_rad), sn = std::sin(s.heading_rad);
  d.x_m = s.vx_mps * c - s.vy_mps * sn;
  d.y_m = s.vx_mps * sn + s.vy_mps * c;
  d.heading_rad = r;
  d.roll_rad = phi_rate;

  const double w = std::clamp(
      (s.vx_mps - p.kinematic_below_mps) / (p.kinetic_above_mps - p.kinematic_below_mps), 0.0, 1.0);
  if (w > 0.0) {
    const WheelForces f = forces(s, delta, input);
    double fx = 0.0, fy = 0.0, yaw_moment = 0.0;
    for (int i = 0; i < wheels; ++i) {
      const std::size_t k = at(i);
      const double sd = std::sin(f.steering_angle_rad[k]), cd = std::cos(f.steering_angle_rad[k]);
      const double body_x = f.longitudinal_n[k] * cd - f.lateral_n[k] * sd;
      const double body_y = f.longitudinal_n[k] * sd + f.lateral_n[k] * cd;
      fx += body_x;
      fy += body_y;
      yaw_moment += x_[k] * body_y - y_[k] * body_x;
    }
    // Equations (x) and (yaw), then (y) and (roll): two 2x2 systems (double_track.hpp).
    const double b_x = fx + m * s.vy_mps * r - 2.0 * mh * cos_phi * phi_rate * r;
    const double b_yaw = yaw_moment + mh * sin_phi * s.vy_mps * r;
    const double coupling_x = mh * sin_phi;
    const double det_x = m * iz - coupling_x * coupling_x;
    const double b_y = fy - m * s.vx_mps * r - mh * sin_phi * (phi_rate * phi_rate + r * r);
    const double b_roll = mh * cos_phi * s.vx_mps * r + roll_moment;
    const double coupling_y = mh * cos_phi;
    const double det_y = m * i_phi - coupling_y * coupling_y;  // = m I_xx + (m h sin phi)^2 > 0
    d.vx_mps = w * (b_x * iz - coupling_x * b_yaw) / det_x;
    d.yaw_rate_radps = w * (m * b_yaw - coupling_x * b_x) / det_x;
    d.vy_mps = w * (b_y * i_phi + coupling_y * b_roll) / det_y;
    d.roll_rate_radps = w * (m * b_roll + coupling_y * b_y) / det_y;
  }
  if (w < 1.0) {
    // Kinematic below kinetic_above_mps, as DynamicSingleTrack: vy, r relax to eq. (kappar);
    // the body rolls under the resulting lateral acceleration by equation (roll).
    const double yaw_rate = s.vx_mps * std::tan(delta) / p.wheelbase_m();
    const double dvy = (p.cg_to_rear_axle_m * yaw_rate - s.vy_mps) / p.kinematic_relaxation_s;
    const double ddphi = (mh * cos_phi * (dvy + s.vx_mps * r) + roll_moment) / i_phi;
    const double dvx = input.is_force ? input.value / m : input.value;
    d.vx_mps += (1.0 - w) * dvx;
    d.vy_mps += (1.0 - w) * dvy;
    d.yaw_rate_radps += (1.0 - w) * (yaw_rate - r) / p.kinematic_relaxation_s;
    d.roll_rate_radps += (1.0 - w) * ddphi;
  }
  return d;
}

double DoubleTrack::mechanical_energy(const VehicleState& s) const noexcept {
  const VehicleParameters& p = parameters_;
  const double m = p.mass_kg, h = p.cg_height_m;
  const double sin_phi = std::sin(s.roll_rad), cos_phi = std::cos(s.roll_rad);
  const double kinetic =
      0.5 * m * (s.vx_mps * s.vx_mps + s.vy_mps * s.vy_mps) +
      0.5 * p.yaw_inertia_kgm2 * s.yaw_rate_radps * s.yaw_rate_radps +
      0.5 * roll_axis_inertia_kgm2_ * s.roll_rate_radps * s.roll_rate_radps +
      m * h * (sin_phi * s.vx_mps * s.yaw_rate_radps - cos_phi * s.vy_mps * s.roll_rate_radps);
  const double potential = 0.5 * body_.roll_stiffness_nmprad() * s.roll_rad * s.roll_rad +
                           m * p.gravity_mps2 * h * (cos_phi - 1.0);
  return kinetic + potential;
}

}  // namespace smoothsteer
