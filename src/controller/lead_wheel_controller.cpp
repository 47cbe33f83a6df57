#include "smoothsteer/controller/lead_wheel_controller.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "smoothsteer/controller/actuator_inversion.hpp"
#include "smoothsteer/controller/dubins_switching_law.hpp"
#include "smoothsteer/controller/feedforward.hpp"
#include "smoothsteer/controller/feedforward_split.hpp"
#include "smoothsteer/controller/jump_plan.hpp"
#include "smoothsteer/controller/steering_governor.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"

namespace smoothsteer {
namespace {

//! A reset angle this close to the chain's is inside the set (the chain's round trip through
//! atan and tan moves it by rounding only) [rad].
constexpr double kApproachTolerance = 1e-9;

bool finite(double value) noexcept {
  return std::isfinite(value);
}

bool valid_input(const ControllerInput& input) noexcept {
  return finite(input.rear_axle_position.x) && finite(input.rear_axle_position.y) &&
         finite(input.heading_rad) && finite(input.speed_mps) && finite(input.acceleration_mps2) &&
         finite(input.period_s) && input.period_s > 0.0 &&
         std::abs(input.rear_axle_side_slip_rad) <= ControllerInput::max_side_slip_rad;
}

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
  governor_rate_ = 0.0;  // stationary cornering
  feedforward_envelope_ = std::abs(feedforward_curvature_);
  far_share_ = 0.0;
  heading_envelope_ = 0.0;
  near_layer_.reset();
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
  previous_speed_ = -1.0;
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

TargetCurve LeadWheelController::target_curve(const PathProjection& lead,
                                              double feedforward_rate) const noexcept {
  // The path's curvature as the rate-limited feedforward should see it (feedforward.hpp): with a
  // finite L_ff the previewed samples (a jump becomes a ramp centred on it), else the path at s
  // and +- one step. The exact rear-axle target reads it at the rear axle, a chain's reach
  // behind the lead wheel; the others at the lead wheel. All read `dynamics_.preview_m` ahead.
  const double rate = parameters_.feedforward.curvature_rate;
  const CorneringTarget kind = parameters_.feedforward.cornering_target;
  const bool exact = kind == CorneringTarget::rear_axle_exact;
  const double s = lead.arc_length_m + dynamics_.preview_m - (exact ? chain_reach_ : 0.0);
  const bool limited = std::isfinite(rate) && rate > 0.0;
  PreviewedCurvature curvature{lead.curvature, lead.curvature, lead.curvature};
  const bool planned = exact && limited &&
                       parameters_.feedforward.curvature_preview == CurvaturePreview::planned_jumps;
  if (planned) {
    // The jet comes from the plan's lagged response below (jump_plan.hpp).
  } else if (exact) {
    // The exact target needs the curvature's first two derivatives, so a jump always becomes a
    // centred ramp: at L_ff, or without a rate limit over the chain's reach. The samples keep
    // the path's own magnitude; the feedforward is clamped to kbar_ff afterwards.
    const double bound = std::max(path_->max_abs_curvature(), 1e-12);
    const double ramp_rate = limited ? rate : bound / std::max(chain_reach_, curvature_jet_step_m);
    curvature = preview_curvature(*path_, s, curvature_jet_step_m, ramp_rate, bound);
  } else if (limited) {
    const double bound = std::max(parameters_.feedforward_curvature_bound(), 1e-12);
    curvature = preview_curvature(*path_, s, curvature_jet_step_m, rate, bound);
  } else if (kind == CorneringTarget::rear_axle || dynamics_.preview_m > 0.0) {
    curvature.at = path_->evaluate(s).curvature;
    curvature.before = path_->evaluate(s - curvature_jet_step_m).curvature;
    curvature.after = path_->evaluate(s + curvature_jet_step_m).curvature;
  }
  // The single-track inversion (ControllerParameters::single_track): gain and second-order
  // correction on top of the preview; then, with a plant disturbance kappa_d, the chain runs on
  // kappa - kappa_d while the rear axle follows kappa (docs/feedforward.md, "disturbances on the
  // vehicle").
  CurvatureJet jet = planned ? planned_rear_curvature_jet(*path_, s, rate,
                                                          parameters_.feedforward_curvature_bound(),
                                                          parameters_.chain.wheelbases_m.data(),
                                                          parameters_.chain.order, feedforward_rate)
                             : curvature_jet(curvature.before, curvature.at, curvature.after);
  jet.value = dynamics_.gain * jet.value + dynamics_.bend_m2 * jet.bend;
  jet.slope *= dynamics_.gain;
  jet.bend *= dynamics_.gain;
  if (kind == CorneringTarget::lead_wheel) return {0.0, 0.0, jet.value};
  const double d = disturbance_.estimate();
  TargetCurve target;
  if (exact) {
    // The chain's angles come from kappa - kappa_d, the lead wheel's position from the path's
    // own geometry, so its curve bends by kappa_d more than the chain's input.
    jet.value -= d;
    target = rear_axle_target_curve(*path_, lead, jet, parameters_.chain.wheelbases_m.data(),
                                    parameters_.chain.order);
  } else {
    // The chain's stationary shape on kappa - kappa_d, minus the path's extra bend over the
    // chain's reach l = sum lambda_i, kappa_d l^2 / 2.
    constexpr double h = curvature_jet_step_m;
    const double before = jet.value - h * jet.slope + 0.5 * h * h * jet.bend;
    const double after = jet.value + h * jet.slope + 0.5 * h * h * jet.bend;
    target = stationary_rear_axle_target_curve(before - d, jet.value - d, after - d, h,
                                               chain_length_squared_);
    target.offset -= 0.5 * d * chain_reach_ * chain_reach_;
    // The same bend turns the path's tangent by kappa_d l more than the chain's lead wheel,
    // which in this steady state points that much across its own track (exact to O(kappa_d)).
    target.heading -= d * chain_reach_;
  }
  target.curvature += d;
  return target;
}

LeadWheelController::LeadWheelState LeadWheelController::evaluate_lead_wheel(
    Vec2 rear_position, double rear_travel_heading, bool refresh_target, double switching_bound,
    double boundary_layer, double feedforward_rate) noexcept {
  // Lead-wheel state from projecting its own position (paper Sec. II end, paper_notes §6).
  const int n = parameters_.chain.order;
  ChainGeometry geometry;
  chain_geometry(rear_position, rear_travel_heading, angles_, parameters_.chain.wheelbases_m.data(),
                 n, geometry);
  const auto lead = static_cast<std::size_t>(n);
  LeadWheelState state;
  // The target curve is refreshed once per period, which needs the arc length of the closest
  // point; the other sub-steps only need e and the heading (and skip the quadrature on splines).
  const Path::ProjectionOptions lead_options{.compute_arc_length = refresh_target};
  state.projection = path_->project(geometry.position[lead], lead_hint_, lead_options);
  if (refresh_target) target_ = target_curve(state.projection, feedforward_rate);
  const double path_heading = wrap_angle(geometry.heading[lead] - state.projection.heading_rad);
  const double error = state.projection.lateral_error_m - target_.offset;
  state.relative_heading = wrap_angle(path_heading - target_.heading);
  state.lateral_error = error;
  // The plant adds kappa_d to every curvature of the chain: the lead wheel asks that much less.
  state.feedforward_target =
      frenet_feedforward_curvature(target_.curvature, error, state.relative_heading) -
      disturbance_.estimate();
  state.law = dubins_switching_law(error, state.relative_heading, switching_bound, boundary_layer,
                                   parameters_);
  return state;
}

Status LeadWheelController::compute_command(const ControllerInput& input,
                                            ControllerOutput& output) noexcept {
  if (!valid_input(input)) return Status::invalid_input;
  if (!path_) return Status::not_configured;
  const int n = parameters_.chain.order;
  const double* wheelbases = parameters_.chain.wheelbases_m.data();

  // Reversing: the chain is mirrored so that it always points along the direction of travel
  // (paper Sec. II end: lambda_i < 0 for ds/dt < 0). Switching direction re-initialises the chain
  // at the current steering angle, which keeps delta_veh continuous.
  if (input.speed_mps != 0.0 && sign(input.speed_mps) != direction_) {
    direction_ = sign(input.speed_mps);
    initialise_chain(last_steering_angle_);
  }
  const double speed_magnitude = std::abs(input.speed_mps);
  const double wheelbase = parameters_.chain.vehicle_wheelbase_m;
  // Stage 1, the single-track inversion: where and how strongly the feedforward reads the path.
  dynamics_.update(parameters_.single_track, speed_magnitude, wheelbase);
  // Stage 2, the disturbance estimate, from the course turned since the last period.
  const DisturbanceEstimator::Context estimation{
      .enabled = parameters_.disturbance_estimation.enabled,
      .length_m = parameters_.disturbance_estimation.length_m,
      .direction = direction_,
      .delay_s = prediction_horizon_s(input),
      .slip_lag_m = dynamics_.slip_lag_m,
      .dynamics_gain = dynamics_.gain,
      .wheelbase_m = wheelbase,
      .feedforward_bound = parameters_.feedforward_curvature_bound()};
  disturbance_.update(input, estimation, delay_);
  // Stage 3, the delay prediction: with a known actuator delay and pose age the law acts on the
  // pose at which this command will take effect. The commands issued over the last (delay + age)
  // seconds are the ones in effect from the pose's time to then. The law steers the rear axle's
  // course psi + beta_r (the kinematic model's heading).
  const Pose2 law_pose = delay_.predict(
      {input.rear_axle_position, input.heading_rad + input.rear_axle_side_slip_rad},
      prediction_horizon_s(input), input.speed_mps, wheelbase, disturbance_.estimate());

  // One control period: the switching law is re-evaluated at every RK4 sub-step of the chain.
  // The first sub-step uses law_pose (measured, or predicted over the actuator delay); later ones
  // the rear-axle pose predicted by the chain's own kinematics (rear curvature
  // tan(delta_1) / lambda_1). This keeps the discrete sliding band of the lead wheel at
  // O(kbar h^2) for the sub-step h instead of O(kbar (v dt)^2).
  const double distance = speed_magnitude * input.period_s;
  int steps = 1;
  if (n > 0 && distance > 0.0) {
    steps = std::clamp(static_cast<int>(std::ceil(distance / largest_substep_m_)), 1,
                       parameters_.chain.max_substeps);
  }
  const double step_length = distance / steps;
  Vec2 position = law_pose.position;
  double heading = travel_heading(law_pose.heading_rad);
  LeadWheelState first{};
  double applied_curvature = 0.0;
  // Friction guard: the lead curvature whose stationary rear-axle curvature is a_max / v^2.
  const double guard = friction_guard_curvature(speed_magnitude);
  const double feedforward_bound = std::min(parameters_.feedforward_curvature_bound(), guard);
  const double switching_bound = parameters_.switching_curvature_bound();
  // The governor (steering_governor.hpp) holds the car's limits itself, so the split follows the
  // feedforward along s: the switching part gets what kappa_ff leaves of kbar_n, and with
  // law_length_m its boundary layer scales with it (epsilon = l kbar_sw / 2), which keeps the
  // law's linear zone kappa_sw = -e / l^2 - 2 psi / l whatever the authority.
  const SteeringGovernor& governor = parameters_.governor;
  const bool governed = governor.enabled && n > 0 && step_length > 0.0;
  // Under the governor kappa_ff may move as fast as the car's rate limit can steer it, eq.
  // (governed_feedforward_rate); the planned jumps keep the certified L_ff they were shaped with.
  const double feedforward_rate =
      governed ? std::max(parameters_.feedforward.curvature_rate,
                          governed_feedforward_rate(parameters_, speed_magnitude))
               : parameters_.feedforward.curvature_rate;
  const double feedforward_step = step_length > 0.0 ? feedforward_rate * step_length : 0.0;
  GovernorStep governor_step;
  if (governed) {
    const double period_speed_change =
        previous_speed_ >= 0.0 ? std::abs(speed_magnitude - previous_speed_) / input.period_s : 0.0;
    governor_step = {.speed_magnitude = speed_magnitude,
                     .longitudinal_acceleration =
                         std::max({std::abs(input.acceleration_mps2), period_speed_change,
                                   governor.max_longitudinal_acceleration_mps2}),
                     .duration_s = step_length / speed_magnitude,
                     .previous_rate_radps = governor_rate_};
  }
  previous_speed_ = speed_magnitude;
  const double far_law_reversal_bound =
      governed ? governed_reversal_curvature(parameters_, speed_magnitude) : 0.0;
  const double heading_decay =
      governed ? std::exp(-step_length / SteeringGovernor::far_law_memory_m) : 1.0;
  // The near-path law's authority: the certified kbar_sw (governed_parameters() keeps it).
  const double near_bound = governor.certified_switching_bound > 0.0
                                ? std::min(governor.certified_switching_bound, switching_bound)
                                : switching_bound;
  for (int step = 0; step < steps; ++step) {
    // The far law's authority is what the feedforward's recent demand leaves of kbar_n: an
    // envelope of |kappa_ff| that forgets over SteeringGovernor::demand_memory_m, so that a
    // reversal of the path's curvature does not hand the law the friction the car still uses.
    if (governed) {
      feedforward_envelope_ =
          std::max(std::abs(feedforward_curvature_),
                   feedforward_envelope_ - parameters_.chain.lead_curvature_bound * step_length /
                                               SteeringGovernor::demand_memory_m);
    }
    const double law_bound =
        governed ? std::max(std::min(parameters_.chain.lead_curvature_bound - feedforward_envelope_,
                                     far_law_reversal_bound),
                            near_bound)
                 : switching_bound;
    // Eq. (governed_law_length) at the envelope of the lead wheel's heading error, unless the
    // parameters fix the length.
    const double law_length =
        !governed ? 0.0
        : governor.law_length_m > 0.0
            ? governor.law_length_m
            : governed_law_length(parameters_, speed_magnitude, heading_envelope_);
    const double law_layer =
        governed ? 0.5 * law_length * law_bound : parameters_.law.boundary_layer;
    const double catch_up = parameters_.feedforward.catch_up * law_bound;
    LeadWheelState lead =
        evaluate_lead_wheel(position, heading, step == 0, law_bound, law_layer, feedforward_rate);
    if (governed) {
      // Near the path the certified law steers (its authority and boundary layer, as the split
      // certificate tuned them). The decisive far law takes over as the certified law's sliding
      // variable leaves its boundary layer, fully at twice its width, and keeps the lead until
      // the error is gone: its share decays over SteeringGovernor::far_law_memory_m, so that the
      // slow near-path surface does not finish an engagement (docs/governor.md).
      const double layer = parameters_.law.boundary_layer;
      // Stiff on steady stretches, the certified layer while the path moves (near_law_layer.hpp).
      if (step == 0)
        near_layer_.observe(lead.projection.curvature, speed_magnitude * input.period_s,
                            speed_magnitude);
      const double near_layer = near_layer_.layer(layer, near_bound, speed_magnitude);
      const SwitchingResult near = dubins_switching_law(lead.lateral_error, lead.relative_heading,
                                                        near_bound, near_layer, parameters_);
      const double wanted =
          layer > 0.0 ? std::clamp(std::abs(near.sliding_variable) / layer - 1.0, 0.0, 1.0) : 1.0;
      far_share_ = std::max(wanted, far_share_ - step_length / SteeringGovernor::far_law_memory_m);
      lead.law.curvature = far_share_ * lead.law.curvature + (1.0 - far_share_) * near.curvature;
      // The heading envelope forgets over the far law's memory, as its share does.
      heading_envelope_ =
          std::max(std::abs(lead.relative_heading), heading_envelope_ * heading_decay);
    }
    if (step == 0) first = lead;
    // Stage 4, the split: kappa_ff moves towards its target at L_ff, linearly within the
    // sub-step; kappa_sw is the law with the catch-up and the friction guard.
    const double feedforward_start = feedforward_curvature_;
    const double wanted = step_feedforward(feedforward_curvature_, lead.feedforward_target,
                                           feedforward_bound, feedforward_step);
    const double switching =
        switching_curvature(lead.law.curvature, law_bound, wanted, feedforward_curvature_, catch_up,
                            matched_disturbance_, guard, parameters_.chain.lead_curvature_bound);
    applied_curvature = feedforward_curvature_ + switching;
    if (n == 0 || step_length <= 0.0) break;
    double start_curvature = feedforward_start + switching;
    if (governed) {
      // Eq. (governor_interval), inside |kappa_n| <= kbar_n (the invariant sets come first: the
      // angle limit is the car's too). kappa_n is held over the sub-step, as the interval assumes.
      const CurvatureInterval allowed =
          governed_lead_curvature_interval(angles_, parameters_, direction_, governor_step);
      const double bound = parameters_.chain.lead_curvature_bound;
      const double low = std::max(allowed.low, -bound);
      const double high = std::min(allowed.high, bound);
      applied_curvature = low <= high ? std::clamp(applied_curvature, low, high)
                                      : (allowed.high < -bound ? -bound : bound);
      start_curvature = applied_curvature;
    }
    const double front_before = angles_[0];
    integrate_chain(angles_, wheelbases, n, start_curvature, applied_curvature, step_length,
                    bounds_.angle);
    if (governed && n == 1) {
      // Only n = 1 bounds the rate's change from one sub-step to the next (for n = 2 the
      // interval reads the rate from the chain's state).
      governor_step.previous_rate_radps =
          steering_derivatives(angles_, parameters_, direction_, speed_magnitude, 0.0,
                               applied_curvature)
              .rate_radps;
    }
    // Rear-axle prediction along an arc of the mean chain curvature over the sub-step, plus the
    // plant's estimated disturbance.
    const double curvature = 0.5 * (std::tan(front_before) + std::tan(angles_[0])) / wheelbases[0] +
                             disturbance_.estimate();
    const double half_turn = 0.5 * curvature * step_length;
    position = position + step_length * unit_from_heading(heading + half_turn);
    heading += 2.0 * half_turn;
  }
  const SwitchingResult& law = first.law;
  if (governed) governor_rate_ = governor_step.previous_rate_radps;

  // Output: delta_veh and its time derivatives (d/dt = v d/ds, d2/dt2 = v^2 d2/ds2 + a d/ds).
  double steering = 0.0, rate = 0.0, acceleration = 0.0;
  int derivatives = 0;
  if (n == 0) {
    steering = direction_ * std::atan(parameters_.chain.vehicle_wheelbase_m * applied_curvature);
  } else {
    const CommandDerivatives d =
        steering_derivatives(angles_, parameters_, direction_, speed_magnitude,
                             input.acceleration_mps2, applied_curvature);
    steering = vehicle_steering_angle(angles_[0]);
    rate = d.rate_radps;
    acceleration = d.acceleration_radps2;
    derivatives = n >= 2 ? 2 : 1;
  }
  if (!finite(steering) || !finite(rate) || !finite(acceleration)) {
    initialise_chain(last_steering_angle_);
    return Status::numerical_error;
  }
  last_steering_angle_ = steering;
  delay_.record(steering, input.period_s);

  // Diagnostics of the real axles.
  const PathProjection rear_projection = path_->project(input.rear_axle_position, rear_hint_);
  disturbance_.set_rear_path(rear_projection.curvature, rear_projection.lateral_error_m);
  const Vec2 front_axle = input.rear_axle_position + parameters_.chain.vehicle_wheelbase_m *
                                                         unit_from_heading(input.heading_rad);
  const PathProjection front_projection = path_->project(front_axle, front_hint_);

  // Stage 5, the actuator inversion: the command leads the chain's delta_veh, which the
  // actuator then reproduces. The history and the re-initialisation keep the chain's own
  // delta_veh: that is what the actuator delivers.
  SteeringCommand command{steering, rate, acceleration, derivatives};
  invert_actuator(parameters_.actuator_inversion, n, command);
  steering = command.steering_rad;
  rate = command.rate_radps;
  acceleration = command.acceleration_radps2;
  derivatives = command.derivatives;
  // After a reset beyond the invariant set, the command as sent approaches the chain's within
  // the rate limit (the history keeps the chain's, the state the approach converges to).
  approach_step(speed_magnitude, input.period_s, steering, rate, acceleration);
  output.steering_angle_rad = steering;
  output.steering_rate_radps = rate;
  output.steering_acceleration_radps2 = acceleration;
  output.derivatives_available = derivatives;
  TrackingDiagnostics& diagnostics = output.diagnostics;
  diagnostics.lateral_error_m = rear_projection.lateral_error_m;
  diagnostics.heading_error_rad =
      wrap_angle(travel_heading(input.heading_rad) - rear_projection.heading_rad);
  diagnostics.front_lateral_error_m = front_projection.lateral_error_m;
  diagnostics.lead_lateral_error_m = first.projection.lateral_error_m;
  diagnostics.lead_heading_error_rad = first.relative_heading;
  diagnostics.sliding_variable = law.sliding_variable;
  diagnostics.lead_curvature = applied_curvature;
  diagnostics.feedforward_curvature = feedforward_curvature_;
  diagnostics.path_arc_length_m = rear_projection.arc_length_m;
  diagnostics.path_curvature = rear_projection.curvature;
  diagnostics.fictive_steering_angle_rad = n > 0 ? angles_[0] : steering;
  diagnostics.disturbance_curvature = disturbance_.estimate();
  return Status::ok;
}

}  // namespace smoothsteer
