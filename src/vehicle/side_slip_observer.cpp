#include "smoothsteer/vehicle/side_slip_observer.hpp"

#include <algorithm>
#include <cmath>

#include "smoothsteer/vehicle/vehicle_model.hpp"

namespace smoothsteer {
namespace {

//! Initial standard deviations of vy [m/s] and r [rad/s]; the steering offset starts at half its
//! bound.
constexpr double kInitialLateralVelocityStd = 0.5;
constexpr double kInitialYawRateStd = 0.1;

using Matrix2 = double[2][2];
//! The filter's state: x = (vy, r, delta_o), delta_o the steering offset.
constexpr int kStates = 3;
using Covariance = double[kStates][kStates];

//! e^{A t} of a 2 x 2 matrix (Cayley-Hamilton: e^{At} = e^{mu t} (c I + s (A - mu I)) with mu the
//! mean eigenvalue and c, s from q^2 = ((a11 - a22) / 2)^2 + a12 a21).
void matrix_exponential(const Matrix2& a, double t, Matrix2& out) noexcept {
  const double mu = 0.5 * (a[0][0] + a[1][1]);
  const double half_difference = 0.5 * (a[0][0] - a[1][1]);
  const double q2 = half_difference * half_difference + a[0][1] * a[1][0];
  double c = 1.0, s = t;
  if (q2 * t * t > 1e-12) {
    const double q = std::sqrt(q2);
    c = std::cosh(q * t);
    s = std::sinh(q * t) / q;
  } else if (q2 * t * t < -1e-12) {
    const double q = std::sqrt(-q2);
    c = std::cos(q * t);
    s = std::sin(q * t) / q;
  }
  const double scale = std::exp(mu * t);
  out[0][0] = scale * (c + s * (a[0][0] - mu));
  out[0][1] = scale * s * a[0][1];
  out[1][0] = scale * s * a[1][0];
  out[1][1] = scale * (c + s * (a[1][1] - mu));
}

//! The response over t of x' = A x + b u to a held unit input: gamma = int_0^t e^{A s} ds b
//! = A^-1 (e^{At} - I) b, by Simpson's rule where A is (nearly) singular.
void input_response(const Matrix2& a, const Matrix2& phi, const double b[2], double t,
                    double gamma[2]) noexcept {
  const double det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
  if (std::abs(det) * t * t > 1e-9) {
    const double r0 = (phi[0][0] - 1.0) * b[0] + phi[0][1] * b[1];
    const double r1 = phi[1][0] * b[0] + (phi[1][1] - 1.0) * b[1];
    gamma[0] = (a[1][1] * r0 - a[0][1] * r1) / det;
    gamma[1] = (-a[1][0] * r0 + a[0][0] * r1) / det;
    return;
  }
  Matrix2 half;
  matrix_exponential(a, 0.5 * t, half);
  for (int i = 0; i < 2; ++i) {
    gamma[i] = t / 6.0 *
               ((1.0 + 4.0 * half[i][i] + phi[i][i]) * b[i] +
                (4.0 * half[i][1 - i] + phi[i][1 - i]) * b[1 - i]);
  }
}

//! Scalar Kalman correction of (x, P) with y = h x + noise of variance r, unless the normalised
//! innovation nu^2 / S exceeds `gate` (then nothing changes and it returns false). Without
//! `learn_offset` the offset is a considered state (Schmidt): its gain is zero, its uncertainty
//! still weighs the others'. Joseph's form keeps P symmetric and positive for any gain.
bool correct(double x[kStates], Covariance& p, const double h[kStates], double innovation, double r,
             double gate, bool learn_offset) noexcept {
  double ph[kStates];
  for (int i = 0; i < kStates; ++i) {
    ph[i] = 0.0;
    for (int j = 0; j < kStates; ++j) ph[i] += p[i][j] * h[j];
  }
  double s = r;
  for (int i = 0; i < kStates; ++i) s += h[i] * ph[i];
  if (!(innovation * innovation <= gate * s)) return false;
  double k[kStates];
  for (int i = 0; i < kStates; ++i) k[i] = ph[i] / s;
  if (!learn_offset) k[2] = 0.0;
  for (int i = 0; i < kStates; ++i) x[i] += k[i] * innovation;
  // P+ = (I - k h) P (I - k h)^T + k r k^T
  Covariance m{};
  for (int i = 0; i < kStates; ++i) {
    for (int j = 0; j < kStates; ++j) m[i][j] = (i == j ? 1.0 : 0.0) - k[i] * h[j];
  }
  Covariance mp{};
  for (int i = 0; i < kStates; ++i) {
    for (int j = 0; j < kStates; ++j) {
      for (int l = 0; l < kStates; ++l) mp[i][j] += m[i][l] * p[l][j];
    }
  }
  for (int i = 0; i < kStates; ++i) {
    for (int j = i; j < kStates; ++j) {
      double sum = k[i] * r * k[j];
      for (int l = 0; l < kStates; ++l) sum += mp[i][l] * m[j][l];
      p[i][j] = p[j][i] = sum;
    }
  }
  return true;
}

//! The single-track model's lateral dynamics at x = (vy, r): d x / dt, its Jacobian A, the
//! accelerometer a_y = d vy / dt + v r, and their derivatives along the steering angle.
struct LateralModel {
  double rate[2];
  Matrix2 jacobian;
  double lateral_acceleration;
  double rate_steering[2];               //!< d (d x / dt) / d delta
  double lateral_acceleration_steering;  //!< d a_y / d delta [m/s^2/rad]
};

//! One axle's force: linear (the slope at zero) or the Magic Formula of the same slope.
struct AxleForce {
  double force, slope;  //!< Fy [N], dFy / dalpha [N/rad]
};

//! One axle of the model, derived from the parameters once per update: its cornering stiffness,
//! and for magic_formula its curve scaled to that stiffness (B = C_alpha / (C D)) at the static
//! load Fz (front m g lr / L, rear m g lf / L).
struct Axle {
  double cornering_stiffness;
  TireParameters curve;
  double load;

  AxleForce force(bool linear, double slip_angle) const noexcept {
    if (linear) return {cornering_stiffness * slip_angle, cornering_stiffness};
    return {DynamicSingleTrack::lateral_force(curve, slip_angle, load),
            DynamicSingleTrack::lateral_force_slope(curve, slip_angle, load)};
  }
};

struct Axles {
  bool linear;
  Axle front, rear;
};

Axle make_axle(double cornering_stiffness, const TireParameters& shape, double load) noexcept {
  TireParameters curve = shape;
  curve.stiffness_factor_b =
      cornering_stiffness / (shape.shape_factor_c * shape.friction_mu * load);
  return {cornering_stiffness, curve, load};
}

Axles make_axles(const SideSlipObserverParameters& p) noexcept {
  const double lf = p.cg_to_front_axle_m, lr = p.cg_to_rear_axle_m;
  const double weight_per_length = p.mass_kg * p.gravity_mps2 / (lf + lr);
  return {p.tire_model == ObserverTireModel::linear,
          make_axle(p.front_cornering_stiffness_npr, p.front_tire, weight_per_length * lr),
          make_axle(p.rear_cornering_stiffness_npr, p.rear_tire, weight_per_length * lf)};
}

//! Rajamani eqs. 2.31 and 2.45 per axle: m (d vy / dt + v r) = Fyr + Fyf cos(delta),
//! Iz d r / dt = lf Fyf cos(delta) - lr Fyr. The linear model takes the slip angles to first
//! order and cos(delta) = 1 (the header's matrices); magic_formula keeps them as the plant does.
LateralModel lateral_model(const SideSlipObserverParameters& p, const Axles& axles, double v,
                           double delta, const double x[2]) noexcept {
  const double lf = p.cg_to_front_axle_m, lr = p.cg_to_rear_axle_m;
  const bool linear = axles.linear;
  const double front_lateral = x[0] + lf * x[1], rear_lateral = x[0] - lr * x[1];
  // Slip angles and their derivatives along vy (d alpha / d r = lf, -lr times these).
  const double front_alpha =
      linear ? delta - front_lateral / v : delta - std::atan(front_lateral / v);
  const double rear_alpha = linear ? -rear_lateral / v : -std::atan(rear_lateral / v);
  const double front_gain = linear ? -1.0 / v : -v / (v * v + front_lateral * front_lateral);
  const double rear_gain = linear ? -1.0 / v : -v / (v * v + rear_lateral * rear_lateral);
  const AxleForce front = axles.front.force(linear, front_alpha);
  const AxleForce rear = axles.rear.force(linear, rear_alpha);
  const double cos_delta = linear ? 1.0 : std::cos(delta);
  const double front_y = front.force * cos_delta, front_slope = front.slope * cos_delta;
  LateralModel model{};
  model.lateral_acceleration = (rear.force + front_y) / p.mass_kg;
  model.rate[0] = model.lateral_acceleration - v * x[1];
  model.rate[1] = (lf * front_y - lr * rear.force) / p.yaw_inertia_kgm2;
  // d (Fyf cos delta) / d delta: the slip angle grows with delta one for one.
  const double front_steering =
      linear ? front.slope : front.slope * cos_delta - front.force * std::sin(delta);
  model.lateral_acceleration_steering = front_steering / p.mass_kg;
  model.rate_steering[0] = model.lateral_acceleration_steering;
  model.rate_steering[1] = lf * front_steering / p.yaw_inertia_kgm2;
  const double front_vy = front_slope * front_gain, rear_vy = rear.slope * rear_gain;
  model.jacobian[0][0] = (front_vy + rear_vy) / p.mass_kg;
  model.jacobian[0][1] = (lf * front_vy - lr * rear_vy) / p.mass_kg - v;
  model.jacobian[1][0] = (lf * front_vy - lr * rear_vy) / p.yaw_inertia_kgm2;
  model.jacobian[1][1] = (lf * lf * front_vy + lr * lr * rear_vy) / p.yaw_inertia_kgm2;
  return model;
}

//! Sub-steps of the Magic Formula's RK4 prediction: at most half the fastest time constant each.
constexpr int kMaxPredictionSubsteps = 16;

}  // namespace

SideSlipObserver::SideSlipObserver(const SideSlipObserverParameters& parameters)
    : parameters_(parameters), plausibility_((parameters.validate(), parameters)) {
  forget_steering_offset();
  reset();
}

void SideSlipObserver::reset() noexcept {
  reset_estimate();
  plausibility_.reset();
  health_ = {};
}

void SideSlipObserver::forget_steering_offset() noexcept {
  steering_offset_ = 0.0;
  const double initial_std = 0.5 * parameters_.max_steering_offset_rad;
  for (int i = 0; i < kStates; ++i) covariance_[i][2] = covariance_[2][i] = 0.0;
  covariance_[2][2] = initial_std * initial_std;
}

double SideSlipObserver::steering_offset_std_rad() const noexcept {
  return std::sqrt(std::max(covariance_[2][2], 0.0));
}

void SideSlipObserver::reset_estimate() noexcept {
  lateral_velocity_ = yaw_rate_ = side_slip_ = rear_side_slip_ = speed_ = 0.0;
  previous_steering_ = 0.0;
  has_previous_ = false;
  // The steering offset is the car's, not the engagement's: it and its variance stay.
  const double offset_variance = covariance_[2][2];
  for (auto& row : covariance_) {
    for (double& entry : row) entry = 0.0;
  }
  covariance_[0][0] = kInitialLateralVelocityStd * kInitialLateralVelocityStd;
  covariance_[1][1] = kInitialYawRateStd * kInitialYawRateStd;
  covariance_[2][2] = offset_variance;
}

void SideSlipObserver::restart_from_model(double v, double yaw_rate) noexcept {
  const double held = previous_steering_;
  const bool has_previous = has_previous_;
  reset_estimate();
  previous_steering_ = held;
  has_previous_ = has_previous;
  speed_ = v;
  yaw_rate_ = yaw_rate;
  lateral_velocity_ = parameters_.cg_to_rear_axle_m * yaw_rate;
  side_slip_ = v > 0.0 ? std::atan(lateral_velocity_ / v) : 0.0;
}

void SideSlipObserver::judge_estimate(bool corrected, double v, double restart_yaw_rate,
                                      double period_s, std::uint32_t& faults) noexcept {
  const SideSlipFaultGate& gate = parameters_.fault_gate;
  // A duration is reached within a rounding of the periods that sum to it.
  auto reached = [](double elapsed, double limit) { return elapsed >= limit * (1.0 - 1e-9); };
  health_.saturated_s =
      std::abs(rear_side_slip_) > gate.max_side_slip_rad ? health_.saturated_s + period_s : 0.0;
  health_.uncorrected_s = corrected ? 0.0 : health_.uncorrected_s + period_s;
  if (health_.saturated_s > 0.0) faults |= fault_estimate_saturated;
  if (reached(health_.uncorrected_s, gate.uncorrected_untrusted_s)) faults |= fault_uncorrected;
  if ((health_.saturated_s > 0.0 && reached(health_.saturated_s, gate.saturated_restart_s)) ||
      reached(health_.uncorrected_s, gate.uncorrected_restart_s)) {
    restart_from_model(v, restart_yaw_rate);
    health_.saturated_s = health_.uncorrected_s = 0.0;
    ++health_.restarts;
    faults |= fault_restarted;
  }
  health_.trusted =
      health_.saturated_s == 0.0 && !reached(health_.uncorrected_s, gate.uncorrected_untrusted_s);
}

Status SideSlipObserver::update(const SideSlipMeasurement& m, double period_s) noexcept {
  if (!std::isfinite(m.speed_mps) || !std::isfinite(m.steering_angle_rad) ||
      !positive_finite(period_s) || period_s > 1.0) {
    return Status::invalid_input;
  }
  const SideSlipObserverParameters& p = parameters_;
  const double v = m.speed_mps;
  if (has_previous_ && speed_ >= p.min_speed_mps) plausibility_.anchor_yaw_rate(yaw_rate_);
  const SensorPlausibility::Verdict verdict = plausibility_.check(m, period_s);
  std::uint32_t faults = verdict.faults;
  if (faults & fault_yaw_rate_dropped) ++health_.yaw_rate_dropped;
  if (faults & fault_yaw_rate_implausible) ++health_.yaw_rate_rejected;
  if (faults & fault_lateral_acceleration_dropped) ++health_.lateral_acceleration_dropped;
  if (faults & fault_lateral_acceleration_implausible) ++health_.lateral_acceleration_rejected;
  // Without a usable gyro sample the kinematic model's yaw rate stands in.
  const double kinematic_yaw_rate = v * std::tan(m.steering_angle_rad + steering_offset_) /
                                    (p.cg_to_front_axle_m + p.cg_to_rear_axle_m);
  speed_ = v;
  if (v < p.min_speed_mps) {
    // Kinematic rolling: the rear axle does not slip.
    restart_from_model(v, verdict.use_yaw_rate ? m.yaw_rate_radps : kinematic_yaw_rate);
    previous_steering_ = m.steering_angle_rad;
    has_previous_ = true;
    health_.saturated_s = health_.uncorrected_s = 0.0;
    health_.trusted = true;
    health_.last_period = faults;
    return Status::ok;
  }
  const double lr = p.cg_to_rear_axle_m;
  // The road wheels steer the measured angle plus the offset (the state delta_o, constant over
  // the period).
  const double offset = steering_offset_;
  const double held_steering = (has_previous_ ? previous_steering_ : m.steering_angle_rad) + offset;
  previous_steering_ = m.steering_angle_rad;
  has_previous_ = true;
  double x[kStates] = {lateral_velocity_, yaw_rate_, offset};
  const Axles axles = make_axles(p);
  const LateralModel start = lateral_model(p, axles, v, held_steering, x);
  const Matrix2& a = start.jacobian;
  Matrix2 phi;  // the covariance's transition, e^{A period} at the prior estimate
  matrix_exponential(a, period_s, phi);
  double gamma[2];  // the response to the held steering angle, and so to the offset
  input_response(a, phi, start.rate_steering, period_s, gamma);
  if (p.tire_model == ObserverTireModel::linear) {
    // Exact for the linear model: x+ = Phi x + Gamma delta.
    const double vy = x[0], r = x[1];
    x[0] = phi[0][0] * vy + phi[0][1] * r + gamma[0] * held_steering;
    x[1] = phi[1][0] * vy + phi[1][1] * r + gamma[1] * held_steering;
  } else {
    // RK4 in sub-steps of at most half the fastest time constant at the prior estimate.
    const double fastest = std::abs(a[0][0]) + std::abs(a[1][1]);
    const int substeps = std::clamp(static_cast<int>(std::ceil(2.0 * fastest * period_s)), 1,
                                    kMaxPredictionSubsteps);
    const double h = period_s / substeps;
    for (int step = 0; step < substeps; ++step) {
      double k[4][2], probe[2];
      const double weights[4] = {0.0, 0.5, 0.5, 1.0};
      for (int stage = 0; stage < 4; ++stage) {
        for (int i = 0; i < 2; ++i) {
          probe[i] = x[i] + (stage == 0 ? 0.0 : weights[stage] * h * k[stage - 1][i]);
        }
        const LateralModel model = lateral_model(p, axles, v, held_steering, probe);
        k[stage][0] = model.rate[0];
        k[stage][1] = model.rate[1];
      }
      for (int i = 0; i < 2; ++i) {
        x[i] += h / 6.0 * (k[0][i] + 2.0 * k[1][i] + 2.0 * k[2][i] + k[3][i]);
      }
    }
  }
  // The covariance's transition: (vy, r) by Phi and the offset through Gamma; the offset a
  // random walk.
  const double transition[kStates][kStates] = {
      {phi[0][0], phi[0][1], gamma[0]}, {phi[1][0], phi[1][1], gamma[1]}, {0.0, 0.0, 1.0}};
  Covariance predicted{};
  for (int i = 0; i < kStates; ++i) {
    for (int j = 0; j < kStates; ++j) {
      double sum = 0.0;
      for (int k = 0; k < kStates; ++k) {
        for (int l = 0; l < kStates; ++l) {
          sum += transition[i][k] * covariance_[k][l] * transition[j][l];
        }
      }
      predicted[i][j] = sum;
    }
  }
  predicted[0][0] += p.lateral_process_std_mps2 * p.lateral_process_std_mps2 * period_s;
  predicted[1][1] += p.yaw_process_std_radps2 * p.yaw_process_std_radps2 * period_s;
  if (p.max_steering_offset_rad > 0.0) {
    predicted[2][2] +=
        p.steering_offset_process_std_radps * p.steering_offset_process_std_radps * period_s;
  }

  // Corrections: the gyro (r), then the accelerometer (a_y, linearised at the prediction), each
  // only with a plausible sample whose innovation passes the gate. The offset learns only where
  // the model is trusted: at speed, in the tires' linear range.
  const double gate = p.fault_gate.innovation_gate;
  const bool learn_offset =
      p.max_steering_offset_rad > 0.0 && v >= p.offset_learning_min_speed_mps &&
      verdict.use_lateral_acceleration &&
      std::abs(m.lateral_acceleration_mps2) <= p.offset_learning_max_lateral_acceleration_mps2;
  bool corrected = false;
  bool yaw_rate_accepted = false;
  if (verdict.use_yaw_rate) {
    const double h_yaw[kStates] = {0.0, 1.0, 0.0};
    yaw_rate_accepted =
        correct(x, predicted, h_yaw, m.yaw_rate_radps - x[1],
                p.yaw_rate_noise_std_radps * p.yaw_rate_noise_std_radps, gate, learn_offset);
    if (!yaw_rate_accepted) {
      faults |= fault_yaw_rate_innovation;
      ++health_.yaw_rate_rejected;
    }
    corrected = yaw_rate_accepted;
  }
  if (verdict.use_lateral_acceleration) {
    const LateralModel at_prediction = lateral_model(p, axles, v, m.steering_angle_rad + x[2], x);
    const double h_lateral[kStates] = {at_prediction.jacobian[0][0],
                                       at_prediction.jacobian[0][1] + v,
                                       at_prediction.lateral_acceleration_steering};
    if (correct(x, predicted, h_lateral,
                m.lateral_acceleration_mps2 - at_prediction.lateral_acceleration,
                p.lateral_acceleration_noise_std_mps2 * p.lateral_acceleration_noise_std_mps2, gate,
                learn_offset)) {
      corrected = true;
    } else {
      faults |= fault_lateral_acceleration_innovation;
      ++health_.lateral_acceleration_rejected;
    }
  }

  if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) {
    // The committed offset was finite; the restarted covariance forgets its correlations.
    reset_estimate();
    health_.last_period = faults;
    return Status::numerical_error;
  }
  lateral_velocity_ = x[0];
  yaw_rate_ = x[1];
  steering_offset_ = std::clamp(x[2], -p.max_steering_offset_rad, p.max_steering_offset_rad);
  for (int i = 0; i < kStates; ++i) {
    for (int j = 0; j < kStates; ++j) covariance_[i][j] = predicted[i][j];
  }
  side_slip_ = std::atan(lateral_velocity_ / v);
  rear_side_slip_ = std::atan((lateral_velocity_ - lr * yaw_rate_) / v);
  judge_estimate(corrected, v, yaw_rate_accepted ? m.yaw_rate_radps : kinematic_yaw_rate, period_s,
                 faults);
  health_.last_period = faults;
  return Status::ok;
}

}  // namespace smoothsteer
