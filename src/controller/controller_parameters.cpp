#include "smoothsteer/controller/controller_parameters.hpp"

#include "smoothsteer/controller/parameter_fields.hpp"
#include "smoothsteer/controller/steering_certificate.hpp"
#include "smoothsteer/validation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace smoothsteer {
namespace {

std::string describe(const std::string& field, double value, const std::string& rule) {
  return smoothsteer::describe(
      Violation{"ControllerParameters", "", field.c_str(), value, rule.c_str()});
}

std::string wheelbase_name(int index) {
  return "wheelbases_m[" + std::to_string(index) + "] (lambda_" + std::to_string(index + 1) + ")";
}

//! The hint an inert field of a switched-off group gets: what switches the group on.
const char* group_hint(ParameterGroup group) noexcept {
  switch (group) {
    case ParameterGroup::single_track:
      return " (the inversion needs rear_slip_gradient_s2pm or front_slip_gradient_s2pm > 0)";
    case ParameterGroup::actuator_inversion:
      return " (the inversion needs actuator_time_constant_s > 0)";
    case ParameterGroup::disturbance_estimation:
      return " (the estimation needs disturbance_estimation_length_m > 0)";
    case ParameterGroup::friction_guard:
      return " (the guard needs a finite max_lateral_acceleration_mps2)";
    case ParameterGroup::delay_compensation:
      return " (the compensation needs actuator_delay_s > 0)";
    default:
      return "";
  }
}

//! A rule text, built only when a rule fails.
auto text(const char* literal) {
  return [literal] { return std::string(literal); };
}

bool finite_positive(double x) noexcept {
  return std::isfinite(x) && x > 0.0;
}

// The rules in groups, in the order check_rules() applies them. Each calls `fail(field, value,
// rule)` for the first rule it finds broken and returns its result (false), else true.

template <typename Fail>
bool check_wheelbases(const ControllerParameters& p, Fail& fail) {
  constexpr double shortest = ControllerParameters::min_wheelbase_m;
  constexpr double longest = ControllerParameters::max_wheelbase_m;
  const ChainParameters& chain = p.chain;
  for (int i = 0; i < chain.order; ++i) {
    const double lambda = chain.wheelbases_m[static_cast<std::size_t>(i)];
    auto indexed = [i] { return wheelbase_name(i); };
    if (!finite_positive(lambda)) {
      return fail(indexed, lambda,
                  text("must be finite and > 0 (reversing is selected by v < 0, not by the "
                       "sign)"));
    }
    if (lambda < shortest || lambda > longest) {
      // The vehicle's wheelbase states the same range.
      return fail(indexed, lambda,
                  [] { return field_rule_text(*find_parameter_field("vehicle_wheelbase_m")); });
    }
    // Paper Sec. III item 3: lambda^2 = lambda_veh^2 - lambda_l^2 implies lambda_l <
    // lambda_veh.
    if (i >= 1 && lambda >= chain.vehicle_wheelbase_m) {
      return fail(indexed, lambda, [&p] {
        return "must be < vehicle_wheelbase_m = " + std::to_string(p.chain.vehicle_wheelbase_m) +
               " (eq. cornering_constr: lambda_l < lambda_veh)";
      });
    }
  }
  return true;
}

//! Each field on its own, as the field table (parameter_fields.hpp) states its range.
template <typename Fail>
bool check_fields(const ControllerParameters& p, Fail& fail) {
  const ChainParameters& chain = p.chain;
  for (const ParameterField& field : controller_parameter_fields()) {
    auto name = [&field] { return std::string(field.name); };
    if (field.kind == FieldKind::wheelbases) {
      if (!check_wheelbases(p, fail)) return false;
      continue;
    }
    if (field.group == ParameterGroup::governor && !p.governor.enabled) continue;
    if (field.name == "governor.enabled" && (chain.order < 1 || chain.order > 2)) {
      // Named as the order's rule, so that the message shows the order's value, not the flag's.
      return fail(text("order"), chain.order,
                  text("must be 1 or 2 with governor.enabled = true (the command's acceleration, "
                       "resp. rate, is affine in the lead curvature only there)"));
    }
    if (!field_has_rule(field)) continue;
    const double value = field.get(p);
    if (!field.range.contains(value)) {
      return fail(name, value, [&field] { return field_rule_text(field); });
    }
  }
  return true;
}

template <typename Fail>
bool check_substep(const ControllerParameters& p, Fail& fail) {
  const ChainParameters& chain = p.chain;
  double shortest_lambda = ControllerParameters::max_wheelbase_m;
  for (int i = 0; i < chain.order; ++i) {
    shortest_lambda = std::min(shortest_lambda, chain.wheelbases_m[static_cast<std::size_t>(i)]);
  }
  if (chain.order > 0 &&
      chain.max_substep_fraction * shortest_lambda < ControllerParameters::min_substep_m) {
    return fail(text("max_substep_fraction"), chain.max_substep_fraction, [shortest_lambda] {
      return "times the shortest wheelbase " + std::to_string(shortest_lambda) +
             " m must be >= min_substep_m = 0.001 m";
    });
  }
  return true;
}

template <typename Fail>
bool check_planned_jumps(const ControllerParameters& p, Fail& fail) {
  const FeedforwardParameters& ff = p.feedforward;
  if (ff.curvature_preview != CurvaturePreview::planned_jumps) return true;
  const int preview = static_cast<int>(ff.curvature_preview);
  if (ff.cornering_target != CorneringTarget::rear_axle_exact) {
    return fail(text("curvature_preview (1 = planned_jumps)"), preview,
                text("planned_jumps needs cornering_target rear_axle_exact (the plan is the "
                     "rear axle's curvature, which only the chain's inverse turns into a "
                     "target)"));
  }
  if (p.chain.order < 1 || p.chain.order > 2) {
    return fail(text("curvature_preview (1 = planned_jumps)"), preview,
                text("planned_jumps needs order 1 or 2 (the plan's lags are simulated for "
                     "those)"));
  }
  if (!std::isfinite(ff.curvature_rate) || !(ff.curvature_rate > 0.0)) {
    return fail(text("curvature_preview (1 = planned_jumps)"), preview,
                text("planned_jumps needs a finite feedforward_curvature_rate > 0 (the plan "
                     "ramps at it)"));
  }
  return true;
}

//! An optional group that is off must keep its fields at their defaults: a value set there
//! would do nothing, and silently so. One that is on must not hold its "off" value.
template <typename Fail>
bool check_group_switches(const ControllerParameters& p, Fail& fail) {
  static constexpr ControllerParameters defaults{};
  for (const ParameterField& field : controller_parameter_fields()) {
    if (field.group == ParameterGroup::none) continue;
    const double value = field.get(p);
    if (!group_enabled(p, field.group)) {
      if (value != field.get(defaults)) {
        return fail([&field] { return std::string(field.name); }, value,
                    [&field] {
                      return "has no effect while " + std::string(group_switch_name(field.group)) +
                             " is false" + group_hint(field.group);
                    });
      }
    } else if (field.switches_group && value == field.range.off &&
               field.group != ParameterGroup::single_track) {
      return fail([&field] { return std::string(field.name); }, value,
                  [&field] {
                    return "switches " + std::string(group_switch_name(field.group)) +
                           " off: with enabled = true it must be in " +
                           (field.range.min_open ? "(" : "[") + exact_number(field.range.min) +
                           ", " + exact_number(field.range.max) +
                           (field.range.max_open ? ")" : "]");
                  });
    }
  }
  return true;
}

//! Groups that are on but cannot act with the rest of the parameters.
template <typename Fail>
bool check_group_combinations(const ControllerParameters& p, Fail& fail) {
  const ChainParameters& chain = p.chain;
  const FeedforwardParameters& ff = p.feedforward;
  const SingleTrackInversion& slip = p.single_track;
  if (slip.enabled && slip.rear_slip_gradient_s2pm == 0.0 && slip.front_slip_gradient_s2pm == 0.0) {
    return fail(text("rear_slip_gradient_s2pm"), 0.0,
                text("and front_slip_gradient_s2pm = 0 with single_track.enabled = true: the "
                     "inversion needs a slip gradient > 0"));
  }
  const ActuatorInversion& inversion = p.actuator_inversion;
  if (inversion.enabled && chain.order < 2) {
    return fail(text("actuator_time_constant_s"), inversion.time_constant_s, [&chain] {
      return "needs order >= 2, not order = " + std::to_string(chain.order) +
             " (the inversion leads the command with the chain's derivatives up to n - 1)";
    });
  }
  if (inversion.enabled && p.governor.enabled) {
    return fail(text("actuator_time_constant_s"), inversion.time_constant_s,
                text("must be 0 with the governor (it bounds the chain's command, not the "
                     "actuator-inverted one)"));
  }
  if (ff.catch_up > 0.0 && ff.share == 0.0) {
    return fail(text("feedforward_catch_up"), ff.catch_up,
                text("has no effect with feedforward_share = 0 (without a feedforward there is "
                     "no gap to catch up)"));
  }
  if (p.disturbance_estimation.enabled && ff.share == 0.0) {
    return fail(text("disturbance_estimation_length_m"), p.disturbance_estimation.length_m,
                text("has no effect with feedforward_share = 0 (the estimate enters through "
                     "kappa_ff, which kbar_ff = 0 clamps)"));
  }
  if (p.friction_guard.enabled && chain.order == 0) {
    return fail(text("max_lateral_acceleration_mps2"),
                p.friction_guard.max_lateral_acceleration_mps2,
                text("has no effect with order = 0 (the guard bounds the chain's lead curvature)"));
  }
  return true;
}

//! Settings of the laws that the rest of the parameters leave without effect: each names the
//! field that makes it inert.
template <typename Fail>
bool check_inert_settings(const ControllerParameters& p, Fail& fail) {
  static constexpr ControllerParameters defaults{};
  if (p.law.surface == SlidingSurface::paper &&
      p.law.approach_angle_rad != defaults.law.approach_angle_rad) {
    return fail(text("approach_angle_rad"), p.law.approach_angle_rad,
                text("has no effect with surface = paper (psi_max shapes the global law's "
                     "reference heading only)"));
  }
  const SteeringGovernor& governor = p.governor;
  if (governor.enabled && governor.fixed_law_length && !(governor.law_length_m > 0.0)) {
    return fail(text("governor.law_length_m"), governor.law_length_m,
                text("must be > 0 m with governor.fixed_law_length = true (the far law's layer "
                     "l kbar_sw / 2 needs a length)"));
  }
  if (governor.enabled && !governor.fixed_law_length &&
      governor.law_length_m != defaults.governor.law_length_m) {
    return fail(text("governor.law_length_m"), governor.law_length_m,
                text("has no effect while governor.fixed_law_length is false (the length is "
                     "derived from the speed and the heading error, eq. governed_law_length)"));
  }
  if (p.feedforward.catch_up > 0.0 && std::isinf(p.feedforward.curvature_rate)) {
    return fail(text("feedforward_catch_up"), p.feedforward.catch_up,
                text("has no effect with feedforward_curvature_rate = +inf (an unlimited "
                     "feedforward leaves no gap to catch up)"));
  }
  return true;
}

//! Invariant sets down the chain (paper_notes §2): kbar_i lambda_i < 1 for every wheel.
template <typename Fail>
bool check_invariant_sets(const ControllerParameters& p, Fail& fail) {
  const ChainParameters& chain = p.chain;
  double kbar = chain.lead_curvature_bound;
  for (int i = chain.order; i >= 1; --i) {
    const double product = kbar * chain.wheelbases_m[static_cast<std::size_t>(i - 1)];
    if (product >= 1.0) {
      return fail([i] { return "kbar_" + std::to_string(i) + " * lambda_" + std::to_string(i); },
                  product,
                  [i] {
                    return "must be < 1 (invariant set |delta_" + std::to_string(i) +
                           "| <= asin(kbar lambda), eq. kappal_constr); reduce "
                           "lead_curvature_bound or the wheelbases";
                  });
    }
    kbar /= std::sqrt(1.0 - product * product);
  }
  return true;
}

//! Every rule of the parameters, once. `fail(field, value, rule)` is called for the first broken
//! rule with lazily evaluated field and rule texts; it returns false, and so does check_rules();
//! true means valid. is_valid() passes a no-op and so never builds a string; validation_error()
//! formats them. First each field on its own, as the field table (parameter_fields.hpp) states
//! its range, then the rules that relate two fields: each names both.
template <typename Fail>
bool check_rules(const ControllerParameters& p, Fail&& fail) {
  return check_fields(p, fail) && check_substep(p, fail) && check_planned_jumps(p, fail) &&
         check_group_switches(p, fail) && check_group_combinations(p, fail) &&
         check_inert_settings(p, fail) && check_invariant_sets(p, fail);
}

}  // namespace

std::string ControllerParameters::validation_error() const {
  std::string message;
  check_rules(*this, [&message](auto field, double value, auto rule) {
    message = describe(field(), value, rule());
    return false;
  });
  return message;
}

bool ControllerParameters::is_valid() const noexcept {
  return check_rules(*this, [](auto&&, double, auto&&) noexcept { return false; });
}

void ControllerParameters::validate() const {
  const std::string error = validation_error();
  if (!error.empty()) throw std::invalid_argument(error);
}

namespace {

//! What paper_c1 and paper_c0 share: the paper's law (Sec. II) on the given chain, the lead
//! wheel on the path, no feedforward and kappa_n = kbar_n sign(sigma); validated.
ControllerParameters with_paper_law(ControllerParameters parameters, double lead_curvature_bound,
                                    double k_rob) {
  parameters.chain.lead_curvature_bound = lead_curvature_bound;
  parameters.law.k_rob = k_rob;
  parameters.feedforward.cornering_target = CorneringTarget::lead_wheel;
  parameters.feedforward.share = 0.0;   // the paper's law: no feedforward
  parameters.law.boundary_layer = 0.0;  // and kappa_n = kbar_n sign(sigma)
  parameters.validate();
  return parameters;
}

}  // namespace

ControllerParameters ControllerParameters::paper_c1(double vehicle_wheelbase_m,
                                                    double lead_wheelbase_m,
                                                    double lead_curvature_bound, double k_rob) {
  ControllerParameters parameters;
  parameters.chain.order = 2;
  parameters.chain.vehicle_wheelbase_m = vehicle_wheelbase_m;
  parameters.chain.wheelbases_m[0] =
      cornering_front_wheelbase(vehicle_wheelbase_m, lead_wheelbase_m * lead_wheelbase_m);
  if (!(parameters.chain.wheelbases_m[0] > 0.0)) {
    throw std::invalid_argument(describe("lead wheelbase lambda_l", lead_wheelbase_m,
                                         "must be < vehicle_wheelbase_m (eq. cornering_constr)"));
  }
  parameters.chain.wheelbases_m[1] = lead_wheelbase_m;
  return with_paper_law(parameters, lead_curvature_bound, k_rob);
}

ControllerParameters ControllerParameters::paper_c0(double vehicle_wheelbase_m,
                                                    double front_curvature_bound, double k_rob) {
  ControllerParameters parameters;
  parameters.chain.order = 1;
  parameters.chain.vehicle_wheelbase_m = vehicle_wheelbase_m;
  parameters.chain.wheelbases_m[0] = vehicle_wheelbase_m;
  return with_paper_law(parameters, front_curvature_bound, k_rob);
}

}  // namespace smoothsteer
