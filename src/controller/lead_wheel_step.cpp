// The control step of LeadWheelController as its stages, in the order they run
// (docs/controller.md, "The control step in stages").

#include <algorithm>
#include <cmath>

#include "smoothsteer/controller/actuator_inversion.hpp"
#include "smoothsteer/controller/chain_stepper.hpp"
#include "smoothsteer/controller/feedforward_split.hpp"
#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/controller/near_law_layer.hpp"
#include "smoothsteer/controller/steering_governor.hpp"
#include "smoothsteer/math/angles.hpp"

namespace smoothsteer {
namespace {

bool finite(double value) noexcept {
  return std::isfinite(value);
}

bool valid_input(const ControllerInput& input) noexcept {
  return finite(input.rear_axle_position.x) && finite(input.rear_axle_position.y) &&
         finite(input.heading_rad) && finite(input.speed_mps) && finite(input.acceleration_mps2) &&
         finite(input.period_s) && input.period_s > 0.0 &&
         std::abs(input.rear_axle_side_slip_rad) <= ControllerInput::max_side_slip_rad;
}

bool finite(const SteeringCommand& command) noexcept {
  return finite(command.steering_rad) && finite(command.rate_radps) &&
         finite(command.acceleration_radps2);
}

}  // namespace

Status LeadWheelController::compute_command(const ControllerInput& input,
                                            ControllerOutput& output) noexcept {
  if (!valid_input(input)) return Status::invalid_input;
  if (!path_) return Status::not_configured;
  follow_direction_of_travel(input.speed_mps);
  const Pose2 law_pose = predict_law_pose(input);
  ChainStepper stepper;
  const PeriodPlan plan = begin_period(input, law_pose, stepper);
  LeadWheelState first{};
  double lead_curvature = 0.0;
  for (int step = 0; step < stepper.steps(); ++step) {
    lead_curvature = substep(plan, step == 0, stepper, first);
  }
  governor_.end_period();
  const SteeringCommand command =
      chain_command(plan.speed_magnitude, input.acceleration_mps2, lead_curvature);
  if (!finite(command)) {
    initialise_chain(last_steering_angle_);
    return Status::numerical_error;
  }
  last_steering_angle_ = command.steering_rad;
  delay_.record(command.steering_rad, input.period_s);
  send_command(command, plan.speed_magnitude, input.period_s, output);
  write_diagnostics(input, first, lead_curvature, output);
  return Status::ok;
}

void LeadWheelController::follow_direction_of_travel(double speed_mps) noexcept {
  // Reversing: the chain is mirrored so that it always points along the direction of travel
  // (paper Sec. II end: lambda_i < 0 for ds/dt < 0). Switching direction re-initialises the chain
  // at the current steering angle, which keeps delta_veh continuous.
  if (speed_mps != 0.0 && sign(speed_mps) != direction_) {
    direction_ = sign(speed_mps);
    initialise_chain(last_steering_angle_);
  }
}

Pose2 LeadWheelController::predict_law_pose(const ControllerInput& input) noexcept {
  const double wheelbase = parameters_.chain.vehicle_wheelbase_m;
  // Stage 1, the single-track inversion: where and how strongly the feedforward reads the path.
  dynamics_.update(parameters_.single_track, input.speed_mps, wheelbase, input.acceleration_mps2,
                   input.slip_gradient_scale);
  // Stage 2, the disturbance estimate, from the course turned since the last period.
  estimate_disturbance(input);
  // Stage 3, the delay prediction: with a known actuator delay and pose age the law acts on the
  // pose at which this command will take effect. The commands issued over the last (delay + age)
  // seconds are the ones in effect from the pose's time to then. The law steers the rear axle's
  // course psi + beta_r (the kinematic model's heading).
  return delay_.predict(
      {input.rear_axle_position, input.heading_rad + input.rear_axle_side_slip_rad},
      prediction_horizon_s(input), input.speed_mps, wheelbase, disturbance_.estimate());
}

void LeadWheelController::estimate_disturbance(const ControllerInput& input) noexcept {
  const DisturbanceEstimator::Context context{
      .enabled = parameters_.disturbance_estimation.enabled,
      .length_m = parameters_.disturbance_estimation.length_m,
      .direction = direction_,
      .delay_s = prediction_horizon_s(input),
      .dynamics = dynamics_,
      .wheelbase_m = parameters_.chain.vehicle_wheelbase_m,
      .feedforward_bound = parameters_.feedforward_curvature_bound()};
  disturbance_.update(input, context, delay_);
}

LeadWheelController::PeriodPlan LeadWheelController::begin_period(const ControllerInput& input,
                                                                  const Pose2& law_pose,
                                                                  ChainStepper& stepper) noexcept {
  const double speed_magnitude = std::abs(input.speed_mps);
  stepper.begin_period(law_pose.position, travel_heading(law_pose.heading_rad),
                       speed_magnitude * input.period_s, largest_substep_m_,
                       parameters_.chain.max_substeps, parameters_.chain.order);
  const double step_length = stepper.step_length();
  governor_.begin_period(parameters_, {.speed_magnitude = speed_magnitude,
                                       .acceleration_mps2 = input.acceleration_mps2,
                                       .period_s = input.period_s,
                                       .step_length_m = step_length});
  PeriodPlan plan;
  plan.speed_magnitude = speed_magnitude;
  // Friction guard: the lead curvature whose stationary rear-axle curvature is a_max / v^2.
  plan.guard = friction_guard_curvature(speed_magnitude);
  plan.feedforward_bound = std::min(parameters_.feedforward_curvature_bound(), plan.guard);
  plan.feedforward_step = step_length > 0.0 ? governor_.feedforward_rate() * step_length : 0.0;
  return plan;
}

double LeadWheelController::substep(const PeriodPlan& plan, bool first_substep,
                                    ChainStepper& stepper, LeadWheelState& first) noexcept {
  const GovernorStage::Authority authority =
      governor_.authority(parameters_, feedforward_curvature_);
  const double catch_up = parameters_.feedforward.catch_up * authority.bound;
  LeadWheelState lead =
      evaluate_lead_wheel(stepper.position(), stepper.heading(), first_substep, authority.bound,
                          authority.layer, governor_.feedforward_rate());
  const NearLawLayer::PathAhead ahead =
      first_substep && governor_.governed()
          ? NearLawLayer::path_ahead(*path_, lead.projection.arc_length_m,
                                     NearLawLayer::reversal_lookahead_s * plan.speed_magnitude,
                                     plan.speed_magnitude)
          : NearLawLayer::PathAhead{};
  lead.law.curvature = governor_.blend(parameters_,
                                       {.path_curvature = lead.projection.curvature,
                                        .lateral_error_m = lead.lateral_error,
                                        .relative_heading = lead.relative_heading,
                                        .far_law_curvature = lead.law.curvature,
                                        .slip_lag_m = dynamics_.slip_lag_m,
                                        .ahead = ahead},
                                       first_substep);
  if (first_substep) first = lead;
  // Stage 4, the split: kappa_ff moves towards its target at L_ff, linearly within the
  // sub-step; kappa_sw is the law with the catch-up and the friction guard.
  const double feedforward_start = feedforward_curvature_;
  const double wanted = step_feedforward(feedforward_curvature_, lead.feedforward_target,
                                         plan.feedforward_bound, plan.feedforward_step);
  const double switching = switching_curvature(
      lead.law.curvature, authority.bound, wanted, feedforward_curvature_, catch_up,
      matched_disturbance_, plan.guard, parameters_.chain.lead_curvature_bound);
  double lead_curvature = feedforward_curvature_ + switching;
  const int n = parameters_.chain.order;
  if (n == 0 || stepper.step_length() <= 0.0) return lead_curvature;
  double start_curvature = feedforward_start + switching;
  if (governor_.governed()) {
    lead_curvature = governor_.clamp(lead_curvature, angles_, parameters_, direction_);
    start_curvature = lead_curvature;
  }
  stepper.advance(angles_, parameters_.chain.wheelbases_m.data(), n, start_curvature,
                  lead_curvature, bounds_.angle, disturbance_.estimate());
  governor_.end_substep(angles_, parameters_, direction_, lead_curvature);
  return lead_curvature;
}

SteeringCommand LeadWheelController::chain_command(double speed_magnitude, double acceleration_mps2,
                                                   double lead_curvature) const noexcept {
  // delta_veh and its time derivatives (d/dt = v d/ds, d2/dt2 = v^2 d2/ds2 + a d/ds).
  const int n = parameters_.chain.order;
  if (n == 0) {
    return {.steering_rad =
                direction_ * std::atan(parameters_.chain.vehicle_wheelbase_m * lead_curvature)};
  }
  const CommandDerivatives d = steering_derivatives(
      angles_, parameters_, direction_, speed_magnitude, acceleration_mps2, lead_curvature);
  return {.steering_rad = vehicle_steering_angle(angles_[0]),
          .rate_radps = d.rate_radps,
          .acceleration_radps2 = d.acceleration_radps2,
          .derivatives = n >= 2 ? 2 : 1};
}

void LeadWheelController::send_command(SteeringCommand command, double speed_magnitude,
                                       double period_s, ControllerOutput& output) noexcept {
  // Stage 5, the actuator inversion: the command leads the chain's delta_veh, which the
  // actuator then reproduces. The history and the re-initialisation keep the chain's own
  // delta_veh: that is what the actuator delivers.
  invert_actuator(parameters_.actuator_inversion, parameters_.chain.order, command);
  // After a reset beyond the invariant set, the command as sent approaches the chain's within
  // the rate limit (the history keeps the chain's, the state the approach converges to).
  approach_step(speed_magnitude, period_s, command.steering_rad, command.rate_radps,
                command.acceleration_radps2);
  output.steering_angle_rad = command.steering_rad;
  output.steering_rate_radps = command.rate_radps;
  output.steering_acceleration_radps2 = command.acceleration_radps2;
  output.derivatives_available = command.derivatives;
}

void LeadWheelController::write_diagnostics(const ControllerInput& input,
                                            const LeadWheelState& first, double lead_curvature,
                                            ControllerOutput& output) noexcept {
  // The real axles' errors; the rear axle's path also gates the disturbance estimate.
  // Far from the path the lead wheel's projection, just made, bounds the axles' global searches.
  const Path::ProjectionOptions near_lead{.nearby = &lead_hint_};
  const PathProjection rear_projection =
      path_->project(input.rear_axle_position, rear_hint_, near_lead);
  disturbance_.set_rear_path(rear_projection.curvature, rear_projection.lateral_error_m);
  const Vec2 front_axle = input.rear_axle_position + parameters_.chain.vehicle_wheelbase_m *
                                                         unit_from_heading(input.heading_rad);
  const PathProjection front_projection = path_->project(front_axle, front_hint_, near_lead);
  TrackingDiagnostics& diagnostics = output.diagnostics;
  diagnostics.lateral_error_m = rear_projection.lateral_error_m;
  diagnostics.heading_error_rad =
      wrap_angle(travel_heading(input.heading_rad) - rear_projection.heading_rad);
  diagnostics.front_lateral_error_m = front_projection.lateral_error_m;
  diagnostics.lead_lateral_error_m = first.projection.lateral_error_m;
  diagnostics.lead_heading_error_rad = first.relative_heading;
  diagnostics.sliding_variable = first.law.sliding_variable;
  diagnostics.lead_curvature = lead_curvature;
  diagnostics.feedforward_curvature = feedforward_curvature_;
  diagnostics.path_arc_length_m = rear_projection.arc_length_m;
  diagnostics.path_curvature = rear_projection.curvature;
  diagnostics.fictive_steering_angle_rad =
      parameters_.chain.order > 0 ? angles_[0] : output.steering_angle_rad;
  diagnostics.disturbance_curvature = disturbance_.estimate();
}

}  // namespace smoothsteer
