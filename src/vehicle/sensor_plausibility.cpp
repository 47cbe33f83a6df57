// The plausibility layer of the sensor fault gate and its rules (sensor_fault_gate.hpp).

#include <algorithm>
#include <cmath>

#include "smoothsteer/vehicle/sensor_fault_gate.hpp"
#include "smoothsteer/vehicle/side_slip_observer.hpp"

namespace smoothsteer {
namespace {

//! The shortest time in which a tire builds up its whole force [s]: its relaxation length
//! (about 0.5 m) at 10 m/s. Bounds the lateral jerk at a_max over this time.
constexpr double kForceBuildUpTime = 0.05;

}  // namespace

std::optional<Violation> SideSlipFaultGate::first_violation(const char* owner,
                                                            const char* prefix) const noexcept {
  RuleChecker check(owner);
  // Below 9 (3 sigma) a healthy filter would reject one sample in 370.
  check.require(std::isfinite(innovation_gate) && innovation_gate >= 9.0, "innovation_gate",
                innovation_gate, "must be finite and >= 9 (3 sigma)");
  check.require(std::isfinite(friction_margin) && friction_margin >= 0.0 && friction_margin <= 10.0,
                "friction_margin", friction_margin, "must be in [0, 10]");
  check.require(std::isfinite(noise_margin) && noise_margin >= 3.0 && noise_margin <= 100.0,
                "noise_margin", noise_margin, "must be in [3, 100]");
  check.require(max_side_slip_rad > 0.0 && max_side_slip_rad <= 0.5, "max_side_slip_rad",
                max_side_slip_rad, "must be in (0, 0.5] rad (ControllerInput::max_side_slip_rad)");
  const struct {
    const char* field;
    double value;
  } durations[] = {{"saturated_restart_s", saturated_restart_s},
                   {"uncorrected_untrusted_s", uncorrected_untrusted_s},
                   {"uncorrected_restart_s", uncorrected_restart_s}};
  for (const auto& entry : durations) {
    check.require(std::isfinite(entry.value) && entry.value >= 0.0 && entry.value <= 1e3,
                  entry.field, entry.value, "must be in [0, 1000] s");
  }
  check.require(uncorrected_restart_s >= uncorrected_untrusted_s, "uncorrected_restart_s",
                uncorrected_restart_s, "must be >= uncorrected_untrusted_s");
  std::optional<Violation> first = check.first();
  if (first) first->prefix = prefix;
  return first;
}

SensorPlausibility::SensorPlausibility(const SideSlipObserverParameters& p) noexcept
    : wheelbase_(p.cg_to_front_axle_m + p.cg_to_rear_axle_m), min_speed_(p.min_speed_mps) {
  const double mu = std::max(p.front_tire.friction_mu, p.rear_tire.friction_mu);
  max_lateral_acceleration_ = (1.0 + p.fault_gate.friction_margin) * mu * p.gravity_mps2;
  // Both axles at a_max turning the car about the CG: the front's load m g lr / L on the arm lf,
  // the rear's m g lf / L on lr.
  const double lf = p.cg_to_front_axle_m, lr = p.cg_to_rear_axle_m;
  max_yaw_acceleration_ =
      2.0 * max_lateral_acceleration_ * p.mass_kg * lf * lr / (wheelbase_ * p.yaw_inertia_kgm2);
  max_lateral_jerk_ = max_lateral_acceleration_ / kForceBuildUpTime;
  yaw_rate_noise_ = p.fault_gate.noise_margin * p.yaw_rate_noise_std_radps;
  lateral_acceleration_noise_ = p.fault_gate.noise_margin * p.lateral_acceleration_noise_std_mps2;
}

void SensorPlausibility::reset() noexcept {
  yaw_rate_ = lateral_acceleration_ = Channel{};
  yaw_rate_freeze_ = lateral_acceleration_freeze_ = Freeze{};
}

bool SensorPlausibility::frozen(Freeze& freeze, double value, double reference,
                                double noise) noexcept {
  const bool repeated = freeze.known && value == freeze.last;
  if (!repeated) freeze = {value, reference, true};
  return repeated && std::abs(reference - freeze.reference) > noise;
}

bool SensorPlausibility::plausible(Channel& channel, double value, double bound, double rate,
                                   double noise, double period_s) noexcept {
  channel.elapsed_s += period_s;
  if (!(std::abs(value) <= bound + noise)) return false;
  // Two samples' noise apart at most (sqrt 2 of one).
  if (channel.known &&
      !(std::abs(value - channel.value) <= rate * channel.elapsed_s + std::sqrt(2.0) * noise)) {
    return false;
  }
  channel = {value, 0.0, true};
  return true;
}

SensorPlausibility::Verdict SensorPlausibility::check(const SideSlipMeasurement& m,
                                                      double period_s) noexcept {
  Verdict verdict;
  const double speed = std::abs(m.speed_mps);
  // Turning faster than the wheels point needs slip, and slip needs force: a_max / v at most.
  const double kinematic_yaw_rate =
      m.speed_mps * std::tan(std::clamp(m.steering_angle_rad, -1.5, 1.5)) / wheelbase_;
  if (!std::isfinite(m.yaw_rate_radps)) {
    verdict.faults |= fault_yaw_rate_dropped;
    yaw_rate_.elapsed_s += period_s;
  } else {
    const double friction = max_lateral_acceleration_ / std::max(speed, min_speed_);
    verdict.use_yaw_rate =
        !frozen(yaw_rate_freeze_, m.yaw_rate_radps, kinematic_yaw_rate, yaw_rate_noise_) &&
        plausible(yaw_rate_, m.yaw_rate_radps, std::max(std::abs(kinematic_yaw_rate), friction),
                  max_yaw_acceleration_, yaw_rate_noise_, period_s);
    if (!verdict.use_yaw_rate) verdict.faults |= fault_yaw_rate_implausible;
  }
  if (!std::isfinite(m.lateral_acceleration_mps2)) {
    verdict.faults |= fault_lateral_acceleration_dropped;
    lateral_acceleration_.elapsed_s += period_s;
  } else {
    verdict.use_lateral_acceleration =
        !frozen(lateral_acceleration_freeze_, m.lateral_acceleration_mps2,
                m.speed_mps * kinematic_yaw_rate, lateral_acceleration_noise_) &&
        plausible(lateral_acceleration_, m.lateral_acceleration_mps2, max_lateral_acceleration_,
                  max_lateral_jerk_, lateral_acceleration_noise_, period_s);
    if (!verdict.use_lateral_acceleration) verdict.faults |= fault_lateral_acceleration_implausible;
  }
  return verdict;
}

}  // namespace smoothsteer
