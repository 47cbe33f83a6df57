#include "smoothsteer/controller/governor_stage.hpp"

#include <algorithm>
#include <cmath>

#include "smoothsteer/controller/dubins_switching_law.hpp"

namespace smoothsteer {

void GovernorStage::restart(double feedforward_curvature) noexcept {
  rate_radps_ = 0.0;  // stationary cornering
  feedforward_envelope_ = std::abs(feedforward_curvature);
  far_share_ = 0.0;
  heading_envelope_ = 0.0;
  near_layer_.reset();
}

void GovernorStage::begin_period(const ControllerParameters& parameters,
                                 const Period& period) noexcept {
  const SteeringGovernor& governor = parameters.governor;
  const double speed = period.speed_magnitude;
  const double step_length = period.step_length_m;
  governed_ = governor.enabled && parameters.chain.order > 0 && step_length > 0.0;
  speed_magnitude_ = speed;
  travelled_m_ = speed * period.period_s;
  step_length_m_ = step_length;
  // Under the governor kappa_ff may move as fast as the car's rate limit can steer it, eq.
  // (governed_feedforward_rate); the planned jumps keep the certified L_ff they were shaped with.
  feedforward_rate_ = governed_ ? std::max(parameters.feedforward.curvature_rate,
                                           governed_feedforward_rate(parameters, speed))
                                : parameters.feedforward.curvature_rate;
  step_ = {};
  if (governed_) {
    const double period_speed_change =
        previous_speed_ >= 0.0 ? std::abs(speed - previous_speed_) / period.period_s : 0.0;
    step_ = {.speed_magnitude = speed,
             .longitudinal_acceleration =
                 std::max({std::abs(period.acceleration_mps2), period_speed_change,
                           governor.max_longitudinal_acceleration_mps2}),
             .duration_s = step_length / speed,
             .previous_rate_radps = rate_radps_};
  }
  previous_speed_ = speed;
  reversal_bound_ = governed_ ? governed_reversal_curvature(parameters, speed) : 0.0;
  heading_decay_ = governed_ ? std::exp(-step_length / SteeringGovernor::far_law_memory_m) : 1.0;
  switching_bound_ = parameters.switching_curvature_bound();
  near_bound_ = std::min(governor.near_law_switching_bound, switching_bound_);
}

GovernorStage::Authority GovernorStage::authority(const ControllerParameters& parameters,
                                                  double feedforward_curvature) noexcept {
  if (!governed_) return {switching_bound_, parameters.law.boundary_layer};
  // The far law's authority is what the feedforward's recent demand leaves of kbar_n: an
  // envelope of |kappa_ff| that forgets over SteeringGovernor::demand_memory_m, so that a
  // reversal of the path's curvature does not hand the law the friction the car still uses.
  const double lead_bound = parameters.chain.lead_curvature_bound;
  feedforward_envelope_ = std::max(
      std::abs(feedforward_curvature),
      feedforward_envelope_ - lead_bound * step_length_m_ / SteeringGovernor::demand_memory_m);
  const double bound =
      std::max(std::min(lead_bound - feedforward_envelope_, reversal_bound_), near_bound_);
  // Eq. (governed_law_length) at the envelope of the lead wheel's heading error, unless the
  // parameters fix the length. The layer epsilon = l kbar_sw / 2 keeps the law's linear zone
  // kappa_sw = -e / l^2 - 2 psi / l whatever the authority.
  const double length = far_law_length(parameters, speed_magnitude_, heading_envelope_);
  return {bound, 0.5 * length * bound};
}

double GovernorStage::blend(const ControllerParameters& parameters, const LeadWheelError& error,
                            bool first_substep) noexcept {
  if (!governed_) return error.far_law_curvature;
  // Near the path the certified law steers (its authority and boundary layer, as the split
  // certificate tuned them). The decisive far law takes over as the certified law's sliding
  // variable leaves its boundary layer, fully at twice its width, and keeps the lead until
  // the error is gone: its share decays over SteeringGovernor::far_law_memory_m, so that the
  // slow near-path surface does not finish an engagement (docs/governor.md).
  // Stiff on steady stretches, the certified layer while the path moves, and on a tight corner
  // without a reversal at most NearLawLayer::single_corner_layer (near_law_layer.hpp).
  if (first_substep) {
    near_layer_.observe(error.path_curvature, travelled_m_, speed_magnitude_);
    near_layer_.observe_ahead(error.ahead, travelled_m_);
  }
  const double layer = near_layer_.certified_layer(parameters.law.boundary_layer);
  const double near_layer = near_layer_.layer(layer, near_bound_, speed_magnitude_);
  const SwitchingResult near = dubins_switching_law(error.lateral_error_m, error.relative_heading,
                                                    near_bound_, near_layer, parameters);
  // The far law also takes the lead from an error the near law's long linear zone would leave
  // standing (SteeringGovernor::far_law_slip_lag_share).
  const double handover_error =
      std::max(layer, SteeringGovernor::far_law_slip_lag_share * error.slip_lag_m);
  const double wanted =
      layer > 0.0 ? std::clamp(std::max(std::abs(near.sliding_variable) / layer,
                                        std::abs(error.lateral_error_m) / handover_error) -
                                   1.0,
                               0.0, 1.0)
                  : 1.0;
  far_share_ = std::max(wanted, far_share_ - step_length_m_ / SteeringGovernor::far_law_memory_m);
  const double curvature =
      far_share_ * error.far_law_curvature + (1.0 - far_share_) * near.curvature;
  // The heading envelope forgets over the far law's memory, as its share does.
  heading_envelope_ =
      std::max(std::abs(error.relative_heading), heading_envelope_ * heading_decay_);
  return curvature;
}

double GovernorStage::clamp(double lead_curvature, const ChainAngles& angles,
                            const ControllerParameters& parameters,
                            double direction) const noexcept {
  // Eq. (governor_interval), inside |kappa_n| <= kbar_n (the invariant sets come first: the
  // angle limit is the car's too). kappa_n is held over the sub-step, as the interval assumes.
  const CurvatureInterval allowed =
      governed_lead_curvature_interval(angles, parameters, direction, step_);
  const double bound = parameters.chain.lead_curvature_bound;
  const double low = std::max(allowed.low, -bound);
  const double high = std::min(allowed.high, bound);
  return low <= high ? std::clamp(lead_curvature, low, high)
                     : (allowed.high < -bound ? -bound : bound);
}

void GovernorStage::end_substep(const ChainAngles& angles, const ControllerParameters& parameters,
                                double direction, double lead_curvature) noexcept {
  // Only n = 1 bounds the rate's change from one sub-step to the next (for n = 2 the
  // interval reads the rate from the chain's state).
  if (!governed_ || parameters.chain.order != 1) return;
  step_.previous_rate_radps =
      steering_derivatives(angles, parameters, direction, speed_magnitude_, 0.0, lead_curvature)
          .rate_radps;
}

void GovernorStage::end_period() noexcept {
  if (governed_) rate_radps_ = step_.previous_rate_radps;
}

}  // namespace smoothsteer
