#include "smoothsteer/vehicle/side_slip_observer.hpp"

#include <cmath>

namespace smoothsteer {
namespace {

constexpr const char* owner = "SideSlipObserverParameters";
//! Initial standard deviations of vy [m/s] and r [rad/s].
constexpr double kInitialLateralVelocityStd = 0.5;
constexpr double kInitialYawRateStd = 0.1;

using Matrix2 = double[2][2];

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

//! Scalar Kalman correction of (x, P) with y = h x + noise of variance r.
void correct(double x[2], Matrix2& p, const double h[2], double innovation, double r) noexcept {
  const double ph0 = p[0][0] * h[0] + p[0][1] * h[1];
  const double ph1 = p[1][0] * h[0] + p[1][1] * h[1];
  const double s = h[0] * ph0 + h[1] * ph1 + r;
  const double k0 = ph0 / s, k1 = ph1 / s;
  x[0] += k0 * innovation;
  x[1] += k1 * innovation;
  const double p00 = p[0][0] - k0 * ph0, p01 = p[0][1] - k0 * ph1;
  const double p11 = p[1][1] - k1 * ph1;
  p[0][0] = p00;
  p[0][1] = p[1][0] = p01;
  p[1][1] = p11;
}

}  // namespace

SideSlipObserverParameters SideSlipObserverParameters::from_vehicle(
    const VehicleParameters& vehicle, double cornering_stiffness_scale, double mass_scale) {
  SideSlipObserverParameters p;
  p.mass_kg = vehicle.mass_kg * mass_scale;
  p.yaw_inertia_kgm2 = vehicle.yaw_inertia_kgm2 * mass_scale;
  p.cg_to_front_axle_m = vehicle.cg_to_front_axle_m;
  p.cg_to_rear_axle_m = vehicle.cg_to_rear_axle_m;
  p.front_cornering_stiffness_npr =
      cornering_stiffness_scale * vehicle.front_cornering_stiffness_npr();
  p.rear_cornering_stiffness_npr =
      cornering_stiffness_scale * vehicle.rear_cornering_stiffness_npr();
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
  return check.first();
}

std::string SideSlipObserverParameters::validation_error() const {
  return describe(first_violation());
}

void SideSlipObserverParameters::validate() const {
  throw_if_violated(first_violation());
}

SideSlipObserver::SideSlipObserver(const SideSlipObserverParameters& parameters)
    : parameters_(parameters) {
  parameters_.validate();
  reset();
}

void SideSlipObserver::reset() noexcept {
  lateral_velocity_ = yaw_rate_ = side_slip_ = rear_side_slip_ = speed_ = 0.0;
  previous_steering_ = 0.0;
  has_previous_ = false;
  covariance_[0][0] = kInitialLateralVelocityStd * kInitialLateralVelocityStd;
  covariance_[1][1] = kInitialYawRateStd * kInitialYawRateStd;
  covariance_[0][1] = covariance_[1][0] = 0.0;
}

Status SideSlipObserver::update(const SideSlipMeasurement& m, double period_s) noexcept {
  if (!std::isfinite(m.speed_mps) || !std::isfinite(m.yaw_rate_radps) ||
      !std::isfinite(m.lateral_acceleration_mps2) || !std::isfinite(m.steering_angle_rad) ||
      !positive_finite(period_s) || period_s > 1.0) {
    return Status::invalid_input;
  }
  const SideSlipObserverParameters& p = parameters_;
  const double v = m.speed_mps;
  speed_ = v;
  if (v < p.min_speed_mps) {
    // Kinematic rolling: the rear axle does not slip.
    reset();
    speed_ = v;
    previous_steering_ = m.steering_angle_rad;
    has_previous_ = true;
    yaw_rate_ = m.yaw_rate_radps;
    lateral_velocity_ = p.cg_to_rear_axle_m * yaw_rate_;
    side_slip_ = v > 0.0 ? std::atan(lateral_velocity_ / v) : 0.0;
    return Status::ok;
  }
  const double cf = p.front_cornering_stiffness_npr, cr = p.rear_cornering_stiffness_npr;
  const double lf = p.cg_to_front_axle_m, lr = p.cg_to_rear_axle_m;
  const double m_v = p.mass_kg * v, i_v = p.yaw_inertia_kgm2 * v;
  // Linear single-track model (header): d x / dt = A x + b delta.
  const Matrix2 a{{-(cf + cr) / m_v, -v - (cf * lf - cr * lr) / m_v},
                  {-(cf * lf - cr * lr) / i_v, -(cf * lf * lf + cr * lr * lr) / i_v}};
  const double b[2] = {cf / p.mass_kg, cf * lf / p.yaw_inertia_kgm2};

  // Prediction with the steering angle held since the last measurement: x+ = Phi x + Gamma
  // delta, Gamma = A^-1 (Phi - I) b.
  const double held_steering = has_previous_ ? previous_steering_ : m.steering_angle_rad;
  previous_steering_ = m.steering_angle_rad;
  has_previous_ = true;
  Matrix2 phi;
  matrix_exponential(a, period_s, phi);
  const double det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
  double gamma[2];
  if (std::abs(det) * period_s * period_s > 1e-9) {
    const double r0 = (phi[0][0] - 1.0) * b[0] + phi[0][1] * b[1];
    const double r1 = phi[1][0] * b[0] + (phi[1][1] - 1.0) * b[1];
    gamma[0] = (a[1][1] * r0 - a[0][1] * r1) / det;
    gamma[1] = (-a[1][0] * r0 + a[0][0] * r1) / det;
  } else {  // A (nearly) singular: Simpson's rule for the integral of e^{A t} b
    Matrix2 half;
    matrix_exponential(a, 0.5 * period_s, half);
    for (int i = 0; i < 2; ++i) {
      gamma[i] = period_s / 6.0 *
                 ((1.0 + 4.0 * half[i][i] + phi[i][i]) * b[i] +
                  (4.0 * half[i][1 - i] + phi[i][1 - i]) * b[1 - i]);
    }
  }
  double x[2] = {phi[0][0] * lateral_velocity_ + phi[0][1] * yaw_rate_ + gamma[0] * held_steering,
                 phi[1][0] * lateral_velocity_ + phi[1][1] * yaw_rate_ + gamma[1] * held_steering};
  Matrix2 predicted{};
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      double sum = 0.0;
      for (int k = 0; k < 2; ++k) {
        for (int l = 0; l < 2; ++l) sum += phi[i][k] * covariance_[k][l] * phi[j][l];
      }
      predicted[i][j] = sum;
    }
  }
  predicted[0][0] += p.lateral_process_std_mps2 * p.lateral_process_std_mps2 * period_s;
  predicted[1][1] += p.yaw_process_std_radps2 * p.yaw_process_std_radps2 * period_s;

  // Corrections: the gyro (r), then the accelerometer (a_y = h x + Cf / m delta).
  const double h_yaw[2] = {0.0, 1.0};
  correct(x, predicted, h_yaw, m.yaw_rate_radps - x[1],
          p.yaw_rate_noise_std_radps * p.yaw_rate_noise_std_radps);
  const double h_lateral[2] = {a[0][0], a[0][1] + v};
  const double predicted_lateral =
      h_lateral[0] * x[0] + h_lateral[1] * x[1] + b[0] * m.steering_angle_rad;
  correct(x, predicted, h_lateral, m.lateral_acceleration_mps2 - predicted_lateral,
          p.lateral_acceleration_noise_std_mps2 * p.lateral_acceleration_noise_std_mps2);

  if (!std::isfinite(x[0]) || !std::isfinite(x[1])) {
    reset();
    return Status::numerical_error;
  }
  lateral_velocity_ = x[0];
  yaw_rate_ = x[1];
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) covariance_[i][j] = predicted[i][j];
  }
  side_slip_ = std::atan(lateral_velocity_ / v);
  rear_side_slip_ = std::atan((lateral_velocity_ - lr * yaw_rate_) / v);
  return Status::ok;
}

}  // namespace smoothsteer
