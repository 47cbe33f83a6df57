#include "smoothsteer/controller/jump_plan.hpp"

#include <algorithm>
#include <cmath>

namespace smoothsteer {
namespace {

//! The plan's shape for a jump of height a > 0, starting at 0: 0 -> -o1 -> a + o2 -> a at
//! slope `rate`.
struct Shape {
  double x[4];
  double value[4];
};

Shape plan_shape(double a, double o1, double o2, double rate) noexcept {
  const double x1 = o1 / rate;
  const double x2 = x1 + (a + o1 + o2) / rate;
  return {{0.0, x1, x2, x2 + o2 / rate}, {0.0, -o1, a + o2, a}};
}

//! Integral and first moment of a shape over [x[0], x[3]] (exact for piecewise linear).
void shape_moments(const Shape& s, double& area, double& first) noexcept {
  area = first = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double a = s.x[i], b = s.x[i + 1], pa = s.value[i], pb = s.value[i + 1];
    area += 0.5 * (b - a) * (pa + pb);
    first += (b - a) / 6.0 * (pa * (2.0 * a + b) + pb * (a + 2.0 * b));
  }
}

//! First-order lag y' = (u - y) / lambda over one step h for u linear from u0 to u1, exact;
//! decay = exp(-h / lambda).
double lag_step(double y, double u0, double u1, double lambda, double h, double decay) noexcept {
  const double drift = lambda * (u1 - u0) / h;
  return u1 - drift + (y - u0 + drift) * decay;
}

//! The average over [s - width / 2, s + width / 2] of the path's curvature samples joined by
//! straight lines (exact for that polyline; O(width / spacing)).
double sampled_curvature_average(const Path& path, double s, double width) noexcept {
  const double spacing = path.curvature_sample_spacing_m();
  const double from = s - 0.5 * width, to = s + 0.5 * width;
  auto value = [&](double at) {
    const double index = std::floor(at / spacing);
    const auto i = static_cast<long>(index);
    const double k0 = path.curvature_sample(i);
    return k0 + (path.curvature_sample(i + 1) - k0) * (at / spacing - index);
  };
  double total = 0.0, a = from, ka = value(from);
  while (a < to) {
    const double b = std::min(to, (std::floor(a / spacing) + 1.0) * spacing);
    const double kb = value(b);
    total += 0.5 * (b - a) * (ka + kb);
    a = b;
    ka = kb;
  }
  return total / width;
}

}  // namespace

JumpPlan plan_jump(const Path::CurvatureJump& jump, double rate, double bound, double chain_reach,
                   double chain_length_squared) noexcept {
  JumpPlan plan;
  plan.at_m = jump.arc_length_m;
  const double step = jump.after - jump.before;
  plan.sign = step < 0.0 ? -1.0 : 1.0;
  const double a = std::abs(step);
  plan.height = a;
  if (!(a > 0.0) || !(rate > 0.0) || !std::isfinite(rate)) {
    for (int i = 0; i < 4; ++i) plan.value[i] = i >= 2 ? a : 0.0;
    return plan;
  }
  // Room beyond `before` (counter-steer) and beyond `after` (overshoot) within +-bound.
  const double counter_room = std::max(0.0, bound + plan.sign * jump.before);
  const double overshoot_room = std::max(0.0, bound - plan.sign * jump.after);
  const double o1 = std::min(jump_plan_counter_share * a, counter_room);
  const double m = chain_reach, variance = chain_length_squared;
  // D = shape(x - c) - a H(x) over x >= x0 (c < 0): integral area - a (c + l), first moment
  // first + c area - a (c + l)^2 / 2, with l the shape's length. The first condition gives c;
  // `residual` is what the second leaves.
  auto residual = [&](double o2, double& c) {
    const Shape s = plan_shape(a, o1, o2, rate);
    double area, first;
    shape_moments(s, area, first);
    const double l = s.x[3];
    c = (area - m * a) / a - l;
    return first + c * area - 0.5 * a * (c + l) * (c + l) - 0.5 * (variance - m * m) * a;
  };
  double c = 0.0;
  double low = 0.0, high = overshoot_room;
  const double at_low = residual(low, c), at_high = residual(high, c);
  double o2 = std::abs(at_low) <= std::abs(at_high) ? low : high;
  if ((at_low < 0.0) != (at_high < 0.0)) {
    for (int i = 0; i < 30; ++i) {
      const double middle = 0.5 * (low + high);
      ((residual(middle, c) < 0.0) == (at_low < 0.0) ? low : high) = middle;
    }
    o2 = 0.5 * (low + high);
    plan.balanced = true;
  }
  residual(o2, c);
  const Shape s = plan_shape(a, o1, o2, rate);
  for (int i = 0; i < 4; ++i) {
    plan.x[i] = s.x[i] + c;
    plan.value[i] = s.value[i];
  }
  return plan;
}

double jump_plan_deviation(const JumpPlan& plan, double arc_length_m) noexcept {
  const double x = arc_length_m - plan.at_m;
  double value = plan.value[3];
  if (x <= plan.x[0]) {
    value = 0.0;
  } else if (x < plan.x[3]) {
    int i = 0;
    while (i < 2 && x > plan.x[i + 1]) ++i;
    const double width = plan.x[i + 1] - plan.x[i];
    const double t = width > 0.0 ? (x - plan.x[i]) / width : 1.0;
    value = plan.value[i] + t * (plan.value[i + 1] - plan.value[i]);
  }
  return plan.sign * (value - (x >= 0.0 ? plan.height : 0.0));
}

double kink_rounding(double slope_step, double width_m, double offset_m) noexcept {
  const double half = 0.5 * width_m;
  if (!(width_m > 0.0) || std::abs(offset_m) >= half) return 0.0;
  // The average of slope_step * max(x, 0) over [x - w / 2, x + w / 2], minus the kink itself.
  const double reach = offset_m + half;
  return slope_step * (reach * reach / (2.0 * width_m) - std::max(offset_m, 0.0));
}

namespace {

//! The chain's first one or two wheels, whose lags the plan simulates.
struct PlanChain {
  int stages = 1;
  double longest = 0.0;         //!< max lambda_i [m]
  double reach = 0.0;           //!< m = sum lambda_i [m]
  double length_squared = 0.0;  //!< V = sum lambda_i^2 [m^2]
};

PlanChain plan_chain(const double* wheelbases, int order) noexcept {
  PlanChain chain;
  chain.stages = std::clamp(order, 1, 2);
  for (int i = 0; i < chain.stages; ++i) {
    chain.longest = std::max(chain.longest, wheelbases[i]);
    chain.reach += wheelbases[i];
    chain.length_squared += wheelbases[i] * wheelbases[i];
  }
  return chain;
}

//! The jumps planned within reach of one arc length.
struct PlannedJumps {
  JumpPlan plans[max_planned_jumps];
  int count = 0;

  //! The planned jumps' steps at or before s [1/m].
  double steps_at(double s) const noexcept {
    double total = 0.0;
    for (int p = 0; p < count; ++p) {
      if (s >= plans[p].at_m) total += plans[p].sign * plans[p].height;
    }
    return total;
  }
  //! The jumps' part of the plan at s (plan - before: step plus deviation) [1/m].
  double part(double s) const noexcept {
    double deviation = 0.0;
    for (int p = 0; p < count; ++p) deviation += jump_plan_deviation(plans[p], s);
    return steps_at(s) + deviation;
  }
};

//! Plans the path's jumps in [first, last] for the query at arc length `at`; a closed path's
//! jumps repeat every length.
void plan_jumps(const Path& path, double at, double first, double last, double rate, double bound,
                const PlanChain& chain, PlannedJumps& planned) noexcept {
  const auto& jumps = path.curvature_jumps();
  const double length = path.length();
  const int laps = path.is_closed() ? 1 : 0;
  for (int lap = -laps; lap <= laps; ++lap) {
    const double shift = lap * length;
    auto it =
        std::lower_bound(jumps.begin(), jumps.end(), first - shift,
                         [](const Path::CurvatureJump& j, double s) { return j.arc_length_m < s; });
    for (;
         it != jumps.end() && it->arc_length_m + shift <= last && planned.count < max_planned_jumps;
         ++it) {
      // An open path's start against the straight extension behind it is a jump only for a car
      // that comes along the extension (at = arc length of the query, < 0); a planner's window
      // starts behind the car, whose past it does not describe.
      if (!path.is_closed() && it->arc_length_m == 0.0 && at >= 0.0) continue;
      Path::CurvatureJump shifted = *it;
      shifted.arc_length_m += shift;
      planned.plans[planned.count++] =
          plan_jump(shifted, rate, bound, chain.reach, chain.length_squared);
    }
  }
}

//! The smooth part of the path's curvature: the samples, stepping exactly at each planned jump,
//! minus those steps, with every kink rounded (kink_rounding()). The planned kinks: a step D of
//! the curvature's slope makes the chain inverse's lead curvature step by about m D (m = sum
//! lambda_i), which the feedforward can only ramp at `rate`. The smooth part is therefore
//! rounded over w = m |D| / rate around each kink, centred on it: its average over a window of
//! width w. Outside +-w / 2 the path is unchanged.
class SmoothPart {
 public:
  SmoothPart(const Path& path, const PlannedJumps& planned, double reach,
             double rounding_rate) noexcept
      : path_(path),
        planned_(planned),
        reach_(reach),
        rounding_rate_(rounding_rate),
        half_window_(0.5 * reach * path.max_abs_curvature_kink() / rounding_rate),
        spline_width_(
            std::min(reach * path.max_abs_spline_kink() / rounding_rate, max_spline_rounding_m)),
        spacing_(path.curvature_sample_spacing_m()),
        length_(path.length()),
        laps_(path.is_closed() ? 1 : 0) {}

  double operator()(double s) const noexcept {
    // Within an open path: its straight extensions are no road a planner sent.
    const double width =
        laps_ == 1 ? spline_width_ : std::min(spline_width_, 2.0 * std::min(s, length_ - s));
    if (width > spacing_) return sampled_curvature_average(path_, s, width) - planned_.steps_at(s);
    const double index = std::floor(s / spacing_);
    const auto i = static_cast<long>(index);
    const double s0 = index * spacing_, s1 = s0 + spacing_;
    const double k0 = path_.curvature_sample(i), k1 = path_.curvature_sample(i + 1);
    double k = k0 + (k1 - k0) * (s - s0) / spacing_;
    for (int p = 0; p < planned_.count; ++p) {
      const double at = planned_.plans[p].at_m;
      if (at > s0 && at <= s1) k = s < at ? k0 : k1;
    }
    return k - planned_.steps_at(s) + rounding(s);
  }

 private:
  double rounding(double s) const noexcept {
    double total = 0.0;
    const auto& kinks = path_.curvature_kinks();
    if (kinks.empty()) return total;
    for (int lap = -laps_; lap <= laps_; ++lap) {
      const double shift = lap * length_;
      auto it = std::lower_bound(
          kinks.begin(), kinks.end(), s - half_window_ - shift,
          [](const Path::CurvatureKink& k, double at) { return k.arc_length_m < at; });
      for (; it != kinks.end() && it->arc_length_m + shift <= s + half_window_; ++it) {
        const double step = it->after - it->before;
        total += kink_rounding(step, reach_ * std::abs(step) / rounding_rate_,
                               s - (it->arc_length_m + shift));
      }
    }
    return total;
  }

  const Path& path_;
  const PlannedJumps& planned_;
  double reach_, rounding_rate_, half_window_;
  //! A spline spreads a kink over a knot or two and lists none: its curvature is averaged over
  //! the width a listed kink of its size would be rounded over (m |D| / rate, D =
  //! Path::max_abs_spline_kink()), which ramps the chain inverse's lead curvature at `rate`
  //! through it as kink_rounding() does.
  double spline_width_;
  double spacing_, length_;
  int laps_;
};

//! Adds to `jet` the rear axle's response to the planned jumps' part: the chain's linearised
//! lags simulated over the last `history` metres before arc_length_m from a stationary start.
void add_lagged_jumps(CurvatureJet& jet, const PlannedJumps& planned, const PlanChain& chain,
                      const double* wheelbases, double arc_length_m, double history) noexcept {
  constexpr double step = 0.25;
  const int steps = std::max(1, static_cast<int>(std::ceil(history / step)));
  const double h = history / steps;
  const double decay_front = std::exp(-h / wheelbases[0]);
  const double decay_lead = chain.stages == 2 ? std::exp(-h / wheelbases[1]) : 0.0;
  const double start = arc_length_m - history;
  double input = planned.part(start);
  double lead_stage = input, rear = input;  // stationary start
  for (int k = 1; k <= steps; ++k) {
    const double next = planned.part(start + k * h);
    if (chain.stages == 2) {
      const double stage = lag_step(lead_stage, input, next, wheelbases[1], h, decay_lead);
      rear = lag_step(rear, lead_stage, stage, wheelbases[0], h, decay_front);
      lead_stage = stage;
    } else {
      rear = lag_step(rear, input, next, wheelbases[0], h, decay_front);
    }
    input = next;
  }
  // sigma_0' = (kappa_1 - sigma_0) / lambda_1 and its derivative (paper_notes §1).
  jet.value += rear;
  if (chain.stages == 2) {
    const double slope = (lead_stage - rear) / wheelbases[0];
    jet.slope += slope;
    jet.bend += ((input - lead_stage) / wheelbases[1] - slope) / wheelbases[0];
  } else {
    const double slope = (input - rear) / wheelbases[0];
    const double input_slope =
        (planned.part(arc_length_m + step) - planned.part(arc_length_m - step)) / (2 * step);
    jet.slope += slope;
    jet.bend += (input_slope - slope) / wheelbases[0];
  }
}

}  // namespace

CurvatureJet planned_rear_curvature_jet(const Path& path, double arc_length_m,
                                        double feedforward_rate, double feedforward_bound,
                                        const double* wheelbases, int order,
                                        double kink_rate) noexcept {
  const double rate = jump_plan_rate_margin * feedforward_rate;
  const double bound = jump_plan_bound_margin * feedforward_bound;
  const PlanChain chain = plan_chain(wheelbases, order);
  // The lags forget their start within 8 max lambda (e^-8); a plan reaches at most this far
  // from its jump: the largest jump (twice the larger of the path's curvature and kbar_ff) with
  // its counter-steer and overshoot, at `rate`, plus the chain's mean delay.
  const double history = 8.0 * chain.longest;
  const double largest_jump = 2.0 * std::max(bound, path.max_abs_curvature());
  const double plan_reach = 4.0 * largest_jump / std::max(rate, 1e-9) + chain.reach;
  PlannedJumps planned;
  plan_jumps(path, arc_length_m, arc_length_m - history - plan_reach, arc_length_m + plan_reach,
             rate, bound, chain, planned);

  // The path's curvature splits into a smooth part and the planned jumps (plan - before: step
  // plus deviation). The lags pass the smooth part through unchanged when the lead wheel follows
  // its chain inverse (section 3), so only the jumps' part needs the lag simulation; the rear
  // axle's jet is the sum of the smooth part's jet and the lagged jumps' jet.
  const double rounding_rate =
      std::max(jump_plan_rate_margin *
                   (std::isfinite(kink_rate) && kink_rate > 0.0 ? kink_rate : feedforward_rate),
               1e-9);
  const SmoothPart smooth(path, planned, chain.reach, rounding_rate);
  // The smooth part's jet by central differences, as for the centred ramp.
  const double jet_step = curvature_jet_step_m;
  CurvatureJet jet = curvature_jet(smooth(arc_length_m - jet_step), smooth(arc_length_m),
                                   smooth(arc_length_m + jet_step));
  if (planned.count == 0) return jet;
  add_lagged_jumps(jet, planned, chain, wheelbases, arc_length_m, history);
  return jet;
}

}  // namespace smoothsteer
