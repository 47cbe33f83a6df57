#include "smoothsteer/baselines/hosm_controller.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "baseline_common.hpp"
#include "smoothsteer/baselines/triple_integrator.hpp"

namespace smoothsteer {

double HosmParameters::alpha() const noexcept {
  const double lower_g = std::cos(heading_bound_rad) / wheelbase_m;
  const double rear_curvature = std::tan(steering_angle_bound_rad) / wheelbase_m;
  const double upper_f = std::sin(heading_bound_rad) * rear_curvature * rear_curvature;
  return lower_g * steering_rate_bound_per_m - upper_f;
}

std::optional<Violation> HosmParameters::first_violation() const noexcept {
  RuleChecker check("HosmParameters");
  detail::require_x_ext_limits(check, wheelbase_m, steering_angle_bound_rad,
                               steering_rate_bound_per_m);
  check.require(positive_finite(heading_bound_rad) && heading_bound_rad < pi / 2.0,
                "heading_bound_rad", heading_bound_rad,
                "must be in (0, pi/2) so that G = cos(psi_bar)/lambda > 0");
  check.require(alpha() > 0.0, "heading_bound_rad", heading_bound_rad,
                "gives alpha = G delta_bar' - F <= 0 (lower psi_bar or delta_bar, or raise "
                "delta_bar'): alpha =",
                alpha());
  check.require_positive({{"substep_m", substep_m}});
  check.require(max_substeps >= 1 && max_substeps <= 10000, "max_substeps", max_substeps,
                "must be in [1, 10000]");
  return check.first();
}

HosmController::HosmController(const HosmParameters& parameters, std::shared_ptr<const Path> path)
    : PathTrackingBaseline(parameters, std::move(path), "HosmController") {
  alpha_ = parameters_.alpha();
  (void)reset(0.0);
}

Status HosmController::reset(double measured_steering_angle_rad) noexcept {
  if (!valid_reset_angle(measured_steering_angle_rad, parameters_.steering_angle_bound_rad)) {
    return Status::invalid_input;
  }
  restart(measured_steering_angle_rad, parameters_.steering_angle_bound_rad);
  return Status::ok;
}

double HosmController::steering_rate_per_meter(double lateral_error_m, double heading_error_rad,
                                               double steering_angle_rad) const noexcept {
  const double lambda = parameters_.wheelbase_m;
  const double rate_bound = parameters_.steering_rate_bound_per_m;
  const double sigma2 = std::sin(heading_error_rad);
  const double sigma3 = std::cos(heading_error_rad) * std::tan(steering_angle_rad) / lambda;
  const TripleIntegratorSwitching law =
      triple_integrator_switching(lateral_error_m, sigma2, sigma3, alpha_);
  // g changes sign with cos(psi): the same sigma3' needs the opposite delta'.
  double rate = rate_bound * law.control_sign * sign_nonzero(std::cos(heading_error_rad));
  // State constraint |psi| <= psi_bar: stop the heading from growing (sigma3 -> 0).
  if (std::abs(heading_error_rad) >= parameters_.heading_bound_rad &&
      sign(sigma3) == sign(heading_error_rad) && sigma3 != 0.0) {
    rate = -rate_bound * sign(sigma3);
  }
  // C1: delta is held at the bound rather than pushed beyond it.
  const double bound = parameters_.steering_angle_bound_rad;
  if ((steering_angle_rad >= bound && rate > 0.0) || (steering_angle_rad <= -bound && rate < 0.0)) {
    rate = 0.0;
  }
  return rate;
}

Status HosmController::compute_command(const ControllerInput& input,
                                       ControllerOutput& output) noexcept {
  if (!detail::valid_input(input)) return Status::invalid_input;
  const detail::RearTracking rear = detail::track_rear_axle(*path_, rear_hint_, input);
  // Forward driving only: in reverse (or at rest) the command is held.
  const double distance = std::max(0.0, input.speed_mps) * input.period_s;
  const int steps = distance > 0.0
                        ? std::clamp(static_cast<int>(std::ceil(distance / parameters_.substep_m)),
                                     1, parameters_.max_substeps)
                        : 0;
  const double h = steps > 0 ? distance / steps : 0.0;
  const double bound = parameters_.steering_angle_bound_rad;
  const double previous = steering_;
  double e = rear.projection.lateral_error_m;
  double psi = rear.heading_error_rad;
  double first_rate = 0.0;
  for (int step = 0; step < steps; ++step) {
    const double rate = steering_rate_per_meter(e, psi, steering_);
    if (step == 0) first_rate = rate;
    const double next = std::clamp(steering_ + rate * h, -bound, bound);
    // Kinematic prediction of x_ext along the sub-step (midpoint rule).
    const double curvature = std::tan(0.5 * (steering_ + next)) / parameters_.wheelbase_m;
    e += h * std::sin(psi + 0.5 * h * curvature);
    psi += h * curvature;
    steering_ = next;
  }
  if (!std::isfinite(steering_)) {
    steering_ = std::isfinite(previous) ? previous : 0.0;
    return Status::numerical_error;
  }
  detail::fill_output(*path_, front_hint_, input, rear, parameters_.wheelbase_m, steering_,
                      previous, rear.projection.lateral_error_m, output, 1);
  output.diagnostics.lead_curvature = first_rate;
  return Status::ok;
}

}  // namespace smoothsteer
