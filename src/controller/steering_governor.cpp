#include "smoothsteer/controller/steering_governor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "smoothsteer/controller/feedforward.hpp"
#include "smoothsteer/controller/steering_certificate.hpp"

namespace smoothsteer {

namespace {

//! What steering_derivatives() needs of a chain state, whatever the lead curvature: the
//! chain's trigonometry and d delta_veh / d delta_1 with its slope.
struct CommandJacobian {
  ChainTrigonometry trigonometry;
  double gain = 0.0;        //!< d delta_veh / d delta_1
  double gain_slope = 0.0;  //!< d gain / d delta_1 (n >= 2)
};

CommandJacobian command_jacobian(const ChainAngles& angles,
                                 const ControllerParameters& parameters) noexcept {
  const int n = parameters.chain.order;
  const double ratio = parameters.chain.vehicle_wheelbase_m / parameters.chain.wheelbases_m[0];
  CommandJacobian result;
  result.trigonometry = chain_trigonometry(angles, n);
  if (n >= 2) {
    // chain_trigonometry has cos and sin of delta_1 for n >= 2.
    result.gain =
        vehicle_angle_gain(result.trigonometry.front_cosine, result.trigonometry.front_sine, ratio);
    result.gain_slope = vehicle_angle_gain_slope(angles[0], ratio, result.gain);
  } else {
    result.gain = vehicle_angle_gain(angles[0], ratio);
  }
  return result;
}

CommandDerivatives command_derivatives(const CommandJacobian& jacobian,
                                       const ControllerParameters& parameters, double direction,
                                       double speed_magnitude, double acceleration_mps2,
                                       double lead_curvature) noexcept {
  CommandDerivatives result;
  const int n = parameters.chain.order;
  const FrontAngleDerivatives d = front_angle_derivatives(
      jacobian.trigonometry, parameters.chain.wheelbases_m.data(), n, lead_curvature);
  const double front_rate = speed_magnitude * d.first;
  result.rate_radps = direction * jacobian.gain * front_rate;
  if (n >= 2) {
    const double front_acceleration =
        speed_magnitude * speed_magnitude * d.second + direction * acceleration_mps2 * d.first;
    result.acceleration_radps2 = direction * (jacobian.gain_slope * front_rate * front_rate +
                                              jacobian.gain * front_acceleration);
  }
  return result;
}

}  // namespace

CommandDerivatives steering_derivatives(const ChainAngles& angles,
                                        const ControllerParameters& parameters, double direction,
                                        double speed_magnitude, double acceleration_mps2,
                                        double lead_curvature) noexcept {
  if (parameters.chain.order == 0) return {};
  return command_derivatives(command_jacobian(angles, parameters), parameters, direction,
                             speed_magnitude, acceleration_mps2, lead_curvature);
}

namespace {

constexpr double unbounded = std::numeric_limits<double>::infinity();

//! The kappa with value(kappa) = offset + slope kappa in [low, high], as an interval.
CurvatureInterval invert_affine(double offset, double slope, double low, double high) noexcept {
  // A slope this small means kappa_n does not reach the constrained quantity (a chain at its
  // singular pose); leaving it free is then exact to the margin.
  constexpr double negligible_slope = 1e-12;
  if (std::abs(slope) < negligible_slope) return {-unbounded, unbounded};
  const double a = (low - offset) / slope;
  const double b = (high - offset) / slope;
  return {std::min(a, b), std::max(a, b)};
}

}  // namespace

CurvatureInterval governed_lead_curvature_interval(const ChainAngles& angles,
                                                   const ControllerParameters& parameters,
                                                   double direction,
                                                   const GovernorStep& step) noexcept {
  const SteeringGovernor& governor = parameters.governor;
  const double v = step.speed_magnitude;
  const double h = step.duration_s;
  if (!(v > 0.0) || !(h > 0.0)) return {-unbounded, unbounded};
  const double keep = 1.0 - governor.margin;
  const double rate_limit = keep * governor.max_steering_rate_radps;
  const double acceleration_limit = keep * governor.max_steering_acceleration_radps2;
  // The command as a function of kappa_n at this state: two evaluations of an affine map, which
  // share the state's trigonometry.
  const CommandJacobian jacobian = command_jacobian(angles, parameters);
  const CommandDerivatives zero = command_derivatives(jacobian, parameters, direction, v, 0.0, 0.0);
  const CommandDerivatives one = command_derivatives(jacobian, parameters, direction, v, 0.0, 1.0);
  if (parameters.chain.order == 1) {
    // rate(kappa) = zero.rate + (one.rate - zero.rate) kappa; its change from the last sub-step
    // is bounded by (A - |dv/dt| |rate| / v) h.
    // Within the sub-step the rate drifts at held kappa_n as delta_1 moves:
    //   d rate / dt = v rate [gain'/gain delta_1' + (kappa_n sin delta_1 - 1 / lambda_1) / cos^2],
    // bounded with |kappa_n| <= kbar_n; that drift is budgeted like the speed change.
    const double previous = step.previous_rate_radps;
    const double front = angles[0];
    const double ratio = parameters.chain.vehicle_wheelbase_m / parameters.chain.wheelbases_m[0];
    const double gain = jacobian.gain;
    const double front_rate = std::abs(previous) / (v * gain);  // |delta_1'| [rad/m]
    const double cosine = std::cos(front);
    const double drift =
        v * (std::abs(vehicle_angle_gain_slope(front, ratio, gain)) / gain * front_rate +
             (parameters.chain.lead_curvature_bound * std::abs(std::sin(front)) +
              1.0 / parameters.chain.wheelbases_m[0]) /
                 (cosine * cosine));
    const double reserve = (step.longitudinal_acceleration / v + drift) * std::abs(previous);
    const double change = std::max(0.0, acceleration_limit - reserve) * h;
    double low = std::max(-rate_limit, previous - change);
    double high = std::min(rate_limit, previous + change);
    if (low > high) low = high = previous > 0.0 ? previous - change : previous + change;
    return invert_affine(zero.rate_radps, one.rate_radps - zero.rate_radps, low, high);
  }
  // n = 2: the rate is the state's; acceleration(kappa) is affine. Keep |rate| <= R at the end of
  // the sub-step (first order in h) and |acceleration| <= A less the speed-change share.
  const double rate = zero.rate_radps;
  const double reserve = step.longitudinal_acceleration * std::abs(rate) / v;
  const double limit = std::max(0.0, acceleration_limit - reserve);
  double low = std::max(-limit, (-rate_limit - rate) / h);
  double high = std::min(limit, (rate_limit - rate) / h);
  if (low > high) low = high = rate > 0.0 ? -limit : limit;
  return invert_affine(zero.acceleration_radps2, one.acceleration_radps2 - zero.acceleration_radps2,
                       low, high);
}

double governed_law_length(const ControllerParameters& parameters, double speed_mps,
                           double heading_error_rad) noexcept {
  // Eq. (governed_law_length): l = max(sum lambda_i, 1 m + 0.25 s |v|, sqrt(2 |v| lambda_veh |psi|
  // / R)). The law asks kappa_sw = 2 psi / l for a heading error psi; the rate limit R delivers the
  // steering lambda_veh kappa_sw within t = 2 lambda_veh |psi| / (l R), over which the car travels
  // |v| t. Keeping that travel below l stops the loop from overshooting into a limit cycle
  // against the rate limit, and no longer than that keeps a small heading error decisive. The
  // second term keeps the heading time constant l / (2 |v|) near 0.13 s at speed.
  const double v = std::abs(speed_mps);
  const double reach = chain_reach(parameters.chain.wheelbases_m.data(), parameters.chain.order);
  const double rate = parameters.governor.max_steering_rate_radps;
  const double rate_bound = std::isfinite(rate) && rate > 0.0
                                ? std::sqrt(2.0 * v * parameters.chain.vehicle_wheelbase_m *
                                            std::abs(heading_error_rad) / rate)
                                : 0.0;
  return std::max({reach, 1.0 + 0.25 * v, rate_bound});
}

double far_law_length(const ControllerParameters& parameters, double speed_mps,
                      double heading_error_rad) noexcept {
  return parameters.governor.fixed_law_length
             ? parameters.governor.law_length_m
             : governed_law_length(parameters, speed_mps, heading_error_rad);
}

double governed_reversal_curvature(const ControllerParameters& parameters,
                                   double speed_mps) noexcept {
  const double v = std::abs(speed_mps);
  const double rate = parameters.governor.max_steering_rate_radps;
  const double length = far_law_length(parameters, v, governed_reversal_heading_rad);
  if (!(v > 0.0) || !std::isfinite(rate)) return unbounded;
  // n = 1 reverses within half the law's length: its command follows kappa_n within a sub-step,
  // and at the full length a random closed loop (v = 18.7 m/s, R = 1.5 rad/s) kept a 0.29 m limit
  // cycle. n = 2 uses the whole length: its chain filters kappa_n once more.
  const double travel = parameters.chain.order == 1 ? 0.5 * length : length;
  return travel * rate / (2.0 * parameters.chain.vehicle_wheelbase_m * v);
}

double governed_feedforward_rate(const ControllerParameters& parameters,
                                 double speed_mps) noexcept {
  const double v = std::abs(speed_mps);
  const double rate = parameters.governor.max_steering_rate_radps;
  if (!(v > 0.0) || !std::isfinite(rate)) return unbounded;
  return rate / (parameters.chain.vehicle_wheelbase_m * v);
}

ControllerParameters governed_parameters(const ControllerParameters& certified,
                                         double speed_mps) noexcept {
  const SteeringGovernor& governor = certified.governor;
  if (!governor.enabled || certified.chain.order < 1) return certified;
  const double v = std::abs(speed_mps);
  double chain_length_squared = 0.0;
  for (int i = 0; i < certified.chain.order; ++i) {
    const double lambda = certified.chain.wheelbases_m[static_cast<std::size_t>(i)];
    chain_length_squared += lambda * lambda;
  }
  // Eq. (kappalmax) corrected (docs/tuning.md): kbar_n <= sin(dbar_veh) / lambda_veh; friction:
  // the rear axle's kbar_0 <= mu g / v^2, mapped to the lead wheel by stationary cornering.
  double bound = unbounded;
  if (std::isfinite(governor.max_steering_angle_rad)) {
    bound = std::sin(std::min(governor.max_steering_angle_rad, 1.5)) /
            certified.chain.vehicle_wheelbase_m;
  }
  if (std::isfinite(governor.max_lateral_acceleration_mps2) && v > 0.0) {
    bound =
        std::min(bound, stationary_lead_curvature(governor.max_lateral_acceleration_mps2 / (v * v),
                                                  chain_length_squared));
  }
  ControllerParameters p = certified;
  // The near-path law keeps the certified authority (docs/governor.md, section 4).
  p.governor.near_law_switching_bound =
      std::min(governor.near_law_switching_bound, certified.switching_curvature_bound());
  if (std::isfinite(bound) && bound > certified.chain.lead_curvature_bound) {
    const double feedforward =
        std::max(certified.feedforward_curvature_bound(), governed_feedforward_share * bound);
    p.chain.lead_curvature_bound = bound;
    p.feedforward.share = std::min(feedforward / bound, 0.95);
  }
  return p.is_valid() ? p : certified;
}

}  // namespace smoothsteer
