// Which limit the lead-wheel controller's command is at (SteeringController::active_limits):
// read from the controller's state after its step, against the bounds it was given; and the
// car's limits it was given, which the steering system's offset compensation keeps as well.

#include <cmath>
#include <string>

#include "smoothsteer/controller/active_limits.hpp"
#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/controller/steering_certificate.hpp"

namespace smoothsteer {
namespace {

//! A value counts as at its bound within this relative distance: the controller clamps to the
//! bound exactly, and the sub-steps' sums leave a few ulps.
constexpr double at_bound_tolerance = 1e-9;

bool at_bound(double value, double bound) noexcept {
  return std::isfinite(bound) && std::abs(value) >= bound * (1.0 - at_bound_tolerance);
}

}  // namespace

std::uint32_t LeadWheelController::active_limits(const ControllerOutput& output,
                                                 double speed_mps) const noexcept {
  const ControllerParameters& p = parameters();
  const double lead = output.diagnostics.lead_curvature;
  const double feedforward = output.diagnostics.feedforward_curvature;
  std::uint32_t limits = limit_none;
  if (at_bound(lead, p.chain.lead_curvature_bound)) limits |= limit_lead_curvature;
  if (p.feedforward.share > 0.0 && at_bound(feedforward, p.feedforward_curvature_bound())) {
    limits |= limit_feedforward_bound;
  }
  if (p.chain.order > 0 && p.friction_guard.enabled && speed_mps > 0.0) {
    // The guard's lead curvature (FrictionGuard::max_lateral_acceleration_mps2): the one
    // whose stationary rear-axle curvature is a_max / v^2.
    double chain_length_squared = 0.0;
    for (int i = 0; i < p.chain.order; ++i) {
      const double lambda = p.chain.wheelbases_m[static_cast<std::size_t>(i)];
      chain_length_squared += lambda * lambda;
    }
    const double guard = stationary_lead_curvature(
        p.friction_guard.max_lateral_acceleration_mps2 / (speed_mps * speed_mps),
        chain_length_squared);
    if (guard < p.chain.lead_curvature_bound &&
        (at_bound(lead, guard) || at_bound(feedforward, guard))) {
      limits |= limit_friction_guard;
    }
  }
  if (p.switching_curvature_bound() > 0.0 &&
      at_bound(lead - feedforward, p.switching_curvature_bound())) {
    limits |= limit_switching_bound;
  }
  if (p.chain.order > 0 && at_bound(chain_angles()[0], bounds().angle[0])) {
    limits |= limit_steering_angle;
  }
  return limits;
}

std::optional<SteeringLimits> LeadWheelController::car_steering_limits() const noexcept {
  const SteeringGovernor& governor = parameters().governor;
  return SteeringLimits{.angle_rad = governor.max_steering_angle_rad,
                        .rate_radps = governor.max_steering_rate_radps,
                        .acceleration_radps2 = governor.max_steering_acceleration_radps2};
}

std::string describe_active_limits(std::uint32_t limits) {
  const struct {
    ActiveLimit bit;
    const char* name;
  } names[] = {{limit_lead_curvature, "lead_curvature"},
               {limit_feedforward_bound, "feedforward_bound"},
               {limit_friction_guard, "friction_guard"},
               {limit_switching_bound, "switching_bound"},
               {limit_steering_angle, "steering_angle"},
               {limit_path_beyond_domain, "path_beyond_domain"},
               {limit_beyond_certified_speed, "beyond_certified_speed"}};
  std::string text;
  for (const auto& entry : names) {
    if ((limits & entry.bit) == 0) continue;
    if (!text.empty()) text += '|';
    text += entry.name;
  }
  return text.empty() ? "none" : text;
}

}  // namespace smoothsteer
