// The lead wheel's state in one sub-step: where it is on the path, the curve it tracks there
// and the switching law's answer (paper Sec. II end, paper_notes §6; feedforward.hpp).

#include <algorithm>
#include <cmath>

#include "smoothsteer/controller/feedforward.hpp"
#include "smoothsteer/controller/jump_plan.hpp"
#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/math/angles.hpp"

namespace smoothsteer {

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
  const double gain = dynamics_.gain_at(jet.value, parameters_.chain.vehicle_wheelbase_m);
  jet.value = gain * jet.value + dynamics_.bend_m2 * jet.bend;
  jet.slope *= gain;
  jet.bend *= gain;
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

}  // namespace smoothsteer
