// SteeringSaturator: a second-order limiter on the held command (docs/baselines.md, "The
// limiter").
//
// Notation. The held command u_k is held over the period h_k (the actual, possibly varying,
// control period); its rate is the difference quotient r_k = (u_k - u_{k-1}) / h_k and its
// acceleration (r_k - r_{k-1}) / h_k. Limits: D = angle_rad, R = rate_radps,
// A = acceleration_radps2. Each step knows (u_{k-1}, r_{k-1}) and h = h_k and picks r = r_k,
// u_k = u_{k-1} + h r.
//
// 1. Hard window [r_low, r_high] of r (every returned command lies in it):
//      (a) |u_{k-1} + h r| <= D,  (b) |r| <= R,  (c) |r - r_{k-1}| <= A h,
//      (d) braking: u_k + r |r| / (2A) in [-D, D].
//    (d) for r >= 0 reads u_{k-1} + h r + r^2 / (2A) <= D, i.e. r <= rho(D - u_{k-1}) with
//      rho(d) = -A h + sqrt(A^2 h^2 + 2 A d) = 2 d / (h + sqrt(h^2 + 2 d / A)),
//    and symmetrically r >= -rho(D + u_{k-1}); (d) implies (a).
//    Why r^2 / (2A), not a stopping distance at the current period: braking at the limit over
//    later periods h_1, h_2, ... (t_j = h_1 + ... + h_j) moves the command by
//      sum_j h_j max(r - A t_j, 0),
//    a right Riemann sum of the decreasing r - A t over [0, r / A], hence below its integral
//    r^2 / (2A) for every sequence of periods. At a constant period h it equals
//      S_h(r) = r^2 / (2A) - r h / 2 + A h^2 f (1 - f) / 2,  f = frac(r / (A h)),
//    which tends to r^2 / (2A) as the periods shrink: no smaller margin holds when the next
//    periods are unknown. The price: near the angle bound the limiter brakes up to r h / 2
//    earlier than a limiter that knew the periods would stay h.
//    Guarantee (recursive feasibility). Let |u| <= D, |r| <= R and u + r|r| / (2A) in [-D, D]
//    (the invariant set; reset() clamps the measured rate into it). For any next period h the
//    braking rate r' = sign(r) max(|r| - A h, 0) satisfies (a)-(d): for r' = r - A h > 0,
//      u + h r' + r'^2 / (2A) = u + r^2 / (2A) - A h^2 / 2 <= D
//    (the other side of (d) holds as the command moves away from -D); for r' = 0 the command
//    stays at u, inside [-D, D] with no stopping distance. So the window is never empty
//    (up to round-off, handled below by that braking rate), and the held command keeps the
//    angle, rate and acceleration limits at every sample, whatever the periods.
//
// 2. Approach to the target (soft: it only picks a point of the window). The target is the
//    raw command clamped to [-D, D] (the previous command if the raw one is not finite), moving
//    at its own rate v = (target_k - target_{k-1}) / h; a target faster than R is taken as a
//    jump (v = 0): it cannot be followed anyway, and a step must not be mistaken for motion,
//    which would carry the command past it. With the relative error e = target_k - u_{k-1} - h v
//    and the relative rate w = r - v, this step and the braking by A h per period after it, at
//    the current period h, travel (relative to the target)
//      F_h(w) = h sum_{i=0}^{n} (w - i A h),  n = floor(w / (A h)),
//    a continuous increasing piecewise-linear function with F_h(n A h) = A h^2 n (n + 1) / 2.
//    The desired rate is v + sign(e) W(|e|), W = F_h^{-1}: with q = |e| / (A h^2),
//      n = floor((sqrt(1 + 8 q) - 1) / 2),  W = (|e| / h + A h n (n + 1) / 2) / (n + 1),
//    the largest closing rate from which the command still stops on the target: the discrete
//    time-optimal approach (accelerate at A, cruise at R, brake at A). Guarantee: at a constant
//    period and a constant target that the state can still stop before (|e| >= S_h of the
//    closing rate), the command never passes the target: W(|e|) >= |r_{k-1}| - A h, so the lower
//    edge of (c) never forces an overshoot, and a rate below W keeps the stop possible.
//    For |e| <= A h^2 (n = 0) W = |e| / h, i.e. the desired command is the target itself: it is
//    returned exactly when it lies in the window. A raw command that keeps all four limits and
//    continues the previous one (previous command = previous raw command, the case while
//    nothing was clamped) has e = 0 and passes unchanged. The acceptance of the raw command uses
//    limits widened by relative_tolerance, so round-off of controllers that keep the limits by
//    construction is not clamped or counted.
//
// A = +infinity (no acceleration limit) gives (c) and (d) no content and W(e) = e / h: the
// limiter then clamps the angle, then the change to R h, as a first-order limiter does.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "smoothsteer/controller/command_limiter.hpp"

namespace smoothsteer {

namespace {

//! Relative tolerance of the acceptance and of the clamp counts.
constexpr double relative_tolerance = 1e-9;
//! Beyond q = |e| / (A h^2) = this, W takes its continuous limit sqrt(2 A |e|) (n > 4e7).
constexpr double continuous_approach_ratio = 1e15;

//! rho(d): the largest r with h r + max(r, 0)^2 / (2A) <= d (item 1, (d)); +inf without an
//! acceleration limit, where the angle bound is applied to the command itself.
double braking_rate(double room, double period, double acceleration) noexcept {
  if (std::isinf(acceleration)) return HUGE_VAL;
  if (room <= 0.0) return room / period;  // outside only by round-off: move back inside
  return 2.0 * room / (period + std::sqrt(period * period + 2.0 * room / acceleration));
}

//! W(e) = F_h^{-1}(e) for e >= 0 (item 2).
double approach_rate(double error, double period, double acceleration) noexcept {
  const double step = acceleration * period * period;
  if (!(error > step)) return error / period;  // n = 0 (also A = +inf): reach it this period
  const double q = error / step;
  if (q > continuous_approach_ratio) return std::sqrt(2.0 * acceleration * error);
  double n = std::floor((std::sqrt(1.0 + 8.0 * q) - 1.0) / 2.0);
  if ((n + 1.0) * (n + 2.0) / 2.0 <= q) n += 1.0;  // round-off of the square root
  if (n * (n + 1.0) / 2.0 > q) n -= 1.0;
  return (error / period + acceleration * period * n * (n + 1.0) / 2.0) / (n + 1.0);
}

struct Interval {
  double low = 0.0;
  double high = 0.0;
};

//! The window of u_k (item 1) for limits rate, acceleration and angle bound D.
Interval command_window(double previous, double previous_rate, double period, double angle,
                        double rate, double acceleration) noexcept {
  const double largest_change = acceleration * period;  // +inf without an acceleration limit
  const double high = std::min(
      {rate, previous_rate + largest_change, braking_rate(angle - previous, period, acceleration)});
  const double low = std::max({-rate, previous_rate - largest_change,
                               -braking_rate(angle + previous, period, acceleration)});
  const double command_low = std::max(-angle, previous + period * low);
  const double command_high = std::min(angle, previous + period * high);
  if (low > high || command_low > command_high) {
    // Only by round-off at the edge of the invariant set: the braking rate of item 1.
    const double braking =
        std::copysign(std::max(std::abs(previous_rate) - largest_change, 0.0), previous_rate);
    const double command =
        std::clamp(previous + period * std::clamp(braking, -rate, rate), -angle, angle);
    return {command, command};
  }
  return {command_low, command_high};
}

//! Counts a finite angle beyond the bound by more than the tolerance; true when it is.
bool count_angle_excess(double raw_angle_rad, double angle_bound,
                        SaturationStatistics& statistics) noexcept {
  const double excess = std::abs(raw_angle_rad) - angle_bound;
  if (!(excess > relative_tolerance * angle_bound)) return false;
  ++statistics.angle_limited;
  statistics.max_angle_excess_rad = std::max(statistics.max_angle_excess_rad, excess);
  return true;
}

}  // namespace

std::optional<Violation> SteeringLimits::first_violation() const noexcept {
  RuleChecker check("SteeringLimits");
  check.require(positive_finite(angle_rad) && angle_rad < std::numbers::pi / 2.0, "angle_rad",
                angle_rad, "must be in (0, pi/2)");
  check.require_positive({{"rate_radps", rate_radps}});
  check.require(!std::isnan(acceleration_radps2) && acceleration_radps2 > 0.0,
                "acceleration_radps2", acceleration_radps2, "must be > 0 (+inf: no limit)");
  return check.first();
}

double SaturationStatistics::limited_fraction() const noexcept {
  if (updates == 0) return 0.0;
  return std::min(1.0, static_cast<double>(limited) / static_cast<double>(updates));
}

SteeringSaturator::SteeringSaturator(const SteeringLimits& limits) : limits_(limits) {
  limits_.validate();
}

void SteeringSaturator::reset(double angle_rad, double rate_radps) noexcept {
  const double bound = limits_.angle_rad;
  previous_ = std::isfinite(angle_rad) ? std::clamp(angle_rad, -bound, bound) : 0.0;
  double rate = std::isfinite(rate_radps)
                    ? std::clamp(rate_radps, -limits_.rate_radps, limits_.rate_radps)
                    : 0.0;
  if (std::isfinite(limits_.acceleration_radps2)) {
    // Stopping distance r^2 / (2A) inside the angle bound (the invariant set of item 1).
    const double room = bound - std::copysign(1.0, rate) * previous_;
    const double largest = std::sqrt(2.0 * limits_.acceleration_radps2 * std::max(room, 0.0));
    rate = std::clamp(rate, -largest, largest);
  }
  previous_rate_ = rate;
  previous_target_ = previous_;
}

double SteeringSaturator::apply(double raw_angle_rad, double period_s, double& rate_radps,
                                double& acceleration_radps2) noexcept {
  const double previous_rate = previous_rate_;
  const double angle = apply(raw_angle_rad, period_s, rate_radps);
  const bool valid_period = std::isfinite(period_s) && period_s > 0.0;
  acceleration_radps2 = valid_period ? (rate_radps - previous_rate) / period_s : 0.0;
  return angle;
}

double SteeringSaturator::apply(double raw_angle_rad, double period_s,
                                double& rate_radps) noexcept {
  if (!std::isfinite(period_s) || !(period_s > 0.0)) {
    rate_radps = 0.0;
    return previous_;
  }
  const double h = period_s;
  const double angle_bound = limits_.angle_rad;
  const double rate_bound = limits_.rate_radps;
  const double acceleration_bound = limits_.acceleration_radps2;
  const double previous = previous_;
  ++statistics_.updates;

  // The first-order clamps, counted as before: angle, then the change to rate * dt.
  const bool finite = std::isfinite(raw_angle_rad);
  const double target = finite ? std::clamp(raw_angle_rad, -angle_bound, angle_bound) : previous;
  const bool angle_limited = finite && count_angle_excess(raw_angle_rad, angle_bound, statistics_);
  const double largest_change = rate_bound * h;
  const double change = target - previous;
  const bool rate_limited = std::abs(change) > largest_change * (1.0 + relative_tolerance);
  if (rate_limited) {
    ++statistics_.rate_limited;
    statistics_.max_rate_excess_radps =
        std::max(statistics_.max_rate_excess_radps, (std::abs(change) - largest_change) / h);
  }
  const double first_order =
      rate_limited ? previous + std::clamp(change, -largest_change, largest_change) : target;

  // Item 2: the target's own rate and the relative error.
  const double widened = 1.0 + relative_tolerance;
  const double raw_rate = (target - previous_target_) / h;
  const double target_rate = finite && std::abs(raw_rate) <= rate_bound * widened
                                 ? std::clamp(raw_rate, -rate_bound, rate_bound)
                                 : 0.0;
  const double relative_error = change - h * target_rate;
  const bool lands = std::abs(relative_error) <= acceleration_bound * widened * h * h;
  bool accepted = false;
  if (lands) {
    const Interval widened_window =
        command_window(previous, previous_rate_, h, angle_bound, rate_bound * widened,
                       acceleration_bound * widened);
    accepted = target >= widened_window.low && target <= widened_window.high;
  }
  double angle = target;
  if (!accepted) {
    const Interval window =
        command_window(previous, previous_rate_, h, angle_bound, rate_bound, acceleration_bound);
    const double desired =
        lands ? target
              : previous + h * (target_rate + std::copysign(approach_rate(std::abs(relative_error),
                                                                          h, acceleration_bound),
                                                            relative_error));
    angle = std::clamp(desired, window.low, window.high);
  }

  bool acceleration_limited = false;
  if (std::isfinite(acceleration_bound)) {
    const double first_order_rate = (first_order - previous) / h;
    const double excess = std::abs(first_order_rate - previous_rate_) / h - acceleration_bound;
    statistics_.max_acceleration_excess_radps2 =
        std::max(statistics_.max_acceleration_excess_radps2, excess);
    acceleration_limited =
        std::abs(angle - first_order) > relative_tolerance * acceleration_bound * h * h;
    if (acceleration_limited) ++statistics_.acceleration_limited;
  }
  if (angle_limited || rate_limited || acceleration_limited) ++statistics_.limited;

  rate_radps = (angle - previous) / h;
  previous_ = angle;
  previous_rate_ = rate_radps;
  previous_target_ = target;
  return angle;
}

}  // namespace smoothsteer
