#include "smoothsteer/controller/lead_wheel_controller.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "smoothsteer/controller/feedforward.hpp"
#include "smoothsteer/controller/steering_governor.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"

namespace smoothsteer {
namespace {

//! A reset angle this close to the chain's is inside the set (the chain's round trip through
//! atan and tan moves it by rounding only) [rad].
constexpr double kApproachTolerance = 1e-9;

}  // namespace

LeadWheelController::LeadWheelController(const ControllerParameters& parameters,
                                         std::shared_ptr<const Path> path)
    : path_(std::move(path)) {
  parameters.validate();
  if (!path_) throw std::invalid_argument("LeadWheelController: path is null; a path is required");
  apply_parameters(parameters);
  (void)reset(0.0);
}

LeadWheelController::LeadWheelController(const ControllerParameters& parameters, PathLater) {
  parameters.validate();
  apply_parameters(parameters);
  (void)reset(0.0);
}

void LeadWheelController::apply_parameters(const ControllerParameters& parameters) noexcept {
  parameters_ = parameters;
  bounds_ = compute_chain_bounds(parameters_);
  certificate_ = feedforward_certificate(parameters_, bounds_);
  chain_length_squared_ = 0.0;
  chain_reach_ = chain_reach(parameters_.chain.wheelbases_m.data(), parameters_.chain.order);
  double shortest = parameters_.chain.order > 0 ? parameters_.chain.wheelbases_m[0] : 0.0;
  for (int i = 0; i < parameters_.chain.order; ++i) {
    const double lambda = parameters_.chain.wheelbases_m[static_cast<std::size_t>(i)];
    chain_length_squared_ += lambda * lambda;
    shortest = std::min(shortest, lambda);
  }
  largest_substep_m_ = parameters_.chain.max_substep_fraction * shortest;
}

double LeadWheelController::travel_heading(double heading) const noexcept {
  return heading + (direction_ < 0.0 ? pi : 0.0);
}

double LeadWheelController::vehicle_steering_angle(double front_angle) const noexcept {
  if (parameters_.chain.order == 0) return front_angle;
  const double ratio = parameters_.chain.vehicle_wheelbase_m / parameters_.chain.wheelbases_m[0];
  return direction_ * std::atan(ratio * std::tan(front_angle));
}

double LeadWheelController::front_angle_from_vehicle(double vehicle_steering_angle) const noexcept {
  const double ratio = parameters_.chain.wheelbases_m[0] / parameters_.chain.vehicle_wheelbase_m;
  return std::atan(ratio * std::tan(direction_ * vehicle_steering_angle));
}

void LeadWheelController::initialise_chain(double vehicle_steering_angle) noexcept {
  const int n = parameters_.chain.order;
  if (n == 0) {
    angles_.fill(0.0);
    feedforward_curvature_ = 0.0;
    last_steering_angle_ = vehicle_steering_angle;
    return;
  }
  // The chain restarts in stationary cornering at the steering the car holds, so that delta_veh
  // continues through a reset and a change of direction (at a cusp the rate v d delta / ds is
  // zero on both sides). Only an angle outside the invariant set is clamped into it.
  const double front = std::clamp(front_angle_from_vehicle(vehicle_steering_angle),
                                  -bounds_.angle[0], bounds_.angle[0]);
  stationary_chain(front, parameters_.chain.wheelbases_m.data(), n, angles_);
  for (int i = 1; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    angles_[k] = std::clamp(angles_[k], -bounds_.angle[k], bounds_.angle[k]);
  }
  // The split certificate (steering_certificate.hpp) holds from a state whose switching response
  // is within kbar_sw: kappa_ff takes the chain's stationary lead curvature, saturated at
  // kbar_ff, and the rest, |kappa_n - kappa_ff| <= kbar_n - kbar_ff, is the switching part's.
  const double rear_curvature = std::tan(front) / parameters_.chain.wheelbases_m[0];
  const double bound = parameters_.feedforward_curvature_bound();
  feedforward_curvature_ =
      std::clamp(stationary_lead_curvature(rear_curvature, chain_length_squared_), -bound, bound);
  last_steering_angle_ = vehicle_steering_angle_of_chain();
  governor_.restart(feedforward_curvature_);
}

Status LeadWheelController::retune(const ControllerParameters& parameters) noexcept {
  if (!parameters.is_valid() || parameters.chain.order != parameters_.chain.order) {
    return Status::invalid_input;
  }
  const int n = parameters.chain.order;
  const double steering = n > 0 ? vehicle_steering_angle_of_chain() : last_steering_angle_;
  // For n >= 2, d delta_veh / ds depends on (delta_1, delta_2) only: keep it too, so that the
  // command stays C^1 across retunes and a gain schedule adds no steering-acceleration spikes.
  // (For n >= 2, delta_1' does not depend on the lead curvature, so 0 is as good as any.)
  double rate_per_meter = 0.0;
  if (n >= 2) {
    const double* old_wheelbases = parameters_.chain.wheelbases_m.data();
    rate_per_meter =
        vehicle_angle_gain(angles_[0], parameters_.chain.vehicle_wheelbase_m / old_wheelbases[0]) *
        front_angle_derivatives(angles_, old_wheelbases, n, 0.0).first;
  }
  apply_parameters(parameters);
  const double feedforward_bound = parameters_.feedforward_curvature_bound();
  feedforward_curvature_ =
      std::clamp(feedforward_curvature_, -feedforward_bound, feedforward_bound);
  // No clamping into the new sets: a jump of the state would be a kink in delta_veh. A state
  // outside a shrunken set returns under the chain's flow (integrate_chain never pushes it out).
  if (n > 0) angles_[0] = front_angle_from_vehicle(steering);
  if (n >= 2) {
    // delta_1' = tan(delta_2) / (lambda_2 cos delta_1) - tan(delta_1) / lambda_1, solved for
    // delta_2.
    const double* wheelbases = parameters_.chain.wheelbases_m.data();
    const double front_rate =
        rate_per_meter /
        vehicle_angle_gain(angles_[0], parameters_.chain.vehicle_wheelbase_m / wheelbases[0]);
    angles_[1] = std::atan(wheelbases[1] * std::cos(angles_[0]) *
                           (front_rate + std::tan(angles_[0]) / wheelbases[0]));
  }
  return Status::ok;
}

Status LeadWheelController::reset(double measured_steering_angle_rad) noexcept {
  if (!valid_reset_angle(measured_steering_angle_rad,
                         parameters_.governor.max_steering_angle_rad)) {
    return Status::invalid_input;
  }
  direction_ = 1.0;
  governor_.forget_speed();
  disturbance_.reset();
  delay_.reset();
  rear_hint_.reset();
  front_hint_.reset();
  lead_hint_.reset();
  initialise_chain(measured_steering_angle_rad);
  // Beyond the invariant set the chain starts at its bound; the command leaves the wheel's angle
  // towards it within the rate limit instead of jumping there (approach_step()).
  approach_angle_ = measured_steering_angle_rad;
  approaching_ = std::abs(measured_steering_angle_rad - last_steering_angle_) > kApproachTolerance;
  return Status::ok;
}

double LeadWheelController::approach_rate_radps(double speed) const noexcept {
  // The car's rate limit where the parameters know it, else the rate the chain is certified
  // to, else its box bound: the approach is never faster than the chain may steer.
  const SteeringGovernor& governor = parameters_.governor;
  if (std::isfinite(governor.max_steering_rate_radps)) {
    return governor.max_steering_rate_radps * (1.0 - governor.margin);
  }
  const double certified = certificate_.rate_radps(speed);
  if (std::isfinite(certified)) return certified;
  return speed * bounds_.steering_rate_per_meter;
}

void LeadWheelController::approach_step(double speed, double period_s, double& steering,
                                        double& rate, double& acceleration) noexcept {
  if (!approaching_) return;
  const double step = approach_rate_radps(speed) * period_s;
  if (!std::isfinite(step)) {  // no rate bound at all (order 0): nothing to respect
    approaching_ = false;
    return;
  }
  const double next = std::clamp(steering, approach_angle_ - step, approach_angle_ + step);
  if (next == steering) {
    approaching_ = false;  // met the chain: its command from here on
  } else {
    rate = (next - approach_angle_) / period_s;
    acceleration = 0.0;
    steering = next;
  }
  approach_angle_ = next;
}

double LeadWheelController::friction_guard_curvature(double speed) const noexcept {
  const FrictionGuard& guard = parameters_.friction_guard;
  const double limit = guard.max_lateral_acceleration_mps2;
  if (!guard.enabled || speed <= 0.0 || parameters_.chain.order == 0) {
    return std::numeric_limits<double>::infinity();
  }
  return stationary_lead_curvature(limit / (speed * speed), chain_length_squared_);
}

double LeadWheelController::vehicle_steering_angle_of_chain() const noexcept {
  return vehicle_steering_angle(angles_[0]);
}

}  // namespace smoothsteer
