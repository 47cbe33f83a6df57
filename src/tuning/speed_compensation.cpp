#include "smoothsteer/tuning/speed_compensation.hpp"

#include <algorithm>
#include <cmath>

#include "smoothsteer/controller/controller_parameters.hpp"

namespace smoothsteer {

double SpeedCompensation::friction_usage(double speed_mps) const noexcept {
  const double v2 = speed_mps * speed_mps;
  return std::clamp(v2 * design_curvature_per_m / friction_limit_mps2, 0.0, 1.0);
}

double SpeedCompensation::delay_s(double speed_mps) const noexcept {
  const double tire_lag =
      tire_lag_share * slip_gradient_sum_s2pm * std::abs(speed_mps) * friction_usage(speed_mps);
  // The controller's Smith predictor accepts at most max_actuator_delay_s.
  return std::min(actuator_group_delay_s + tire_lag, ControllerParameters::max_actuator_delay_s);
}

double SpeedCompensation::catch_up(double speed_mps) const noexcept {
  return friction_usage(speed_mps) >= catch_up_usage ? catch_up_gain : 0.0;
}

std::optional<Violation> SpeedCompensation::first_violation() const noexcept {
  RuleChecker check("SpeedCompensation");
  check.require(std::isfinite(actuator_group_delay_s) && actuator_group_delay_s >= 0.0 &&
                    actuator_group_delay_s <= ControllerParameters::max_actuator_delay_s,
                "actuator_group_delay_s", actuator_group_delay_s,
                "must be in [0, ControllerParameters::max_actuator_delay_s =",
                ControllerParameters::max_actuator_delay_s);
  check.require(std::isfinite(slip_gradient_sum_s2pm) && slip_gradient_sum_s2pm >= 0.0 &&
                    slip_gradient_sum_s2pm <= 2.0 * ControllerParameters::max_slip_gradient_s2pm,
                "slip_gradient_sum_s2pm", slip_gradient_sum_s2pm,
                "must be in [0, 2 ControllerParameters::max_slip_gradient_s2pm =",
                2.0 * ControllerParameters::max_slip_gradient_s2pm);
  check.require(std::isfinite(design_curvature_per_m) && design_curvature_per_m >= 0.0,
                "design_curvature_per_m", design_curvature_per_m, "must be finite and >= 0");
  check.require(std::isfinite(friction_limit_mps2) && friction_limit_mps2 > 0.0,
                "friction_limit_mps2", friction_limit_mps2, "must be finite and > 0");
  return check.first();
}

}  // namespace smoothsteer
