#include "smoothsteer/controller/controller_parameters.hpp"

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

//! Every rule of the parameters, once. `fail(field, value, rule)` is called for the first broken
//! rule with lazily evaluated field and rule texts, and its result returned; true means valid.
//! is_valid() passes a no-op and so never builds a string; validation_error() formats them.
template <typename Fail>
bool check_rules(const ControllerParameters& p, Fail&& fail) {
  auto text = [](const char* literal) { return [literal] { return std::string(literal); }; };
  auto finite_positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  constexpr int max_order = ControllerParameters::max_order;
  if (p.order < 0 || p.order > max_order) {
    return fail(text("order"), p.order,
                [] { return "must be in [0, " + std::to_string(max_order) + "]"; });
  }
  // Enumerations set from an int (bindings, casts) must hold one of their values.
  if (p.surface != SlidingSurface::global && p.surface != SlidingSurface::paper) {
    return fail(text("surface"), static_cast<int>(p.surface),
                text("must be 0 (global) or 1 (paper)"));
  }
  if (p.cornering_target != CorneringTarget::rear_axle &&
      p.cornering_target != CorneringTarget::rear_axle_exact &&
      p.cornering_target != CorneringTarget::lead_wheel) {
    return fail(text("cornering_target"), static_cast<int>(p.cornering_target),
                text("must be 0 (rear_axle), 1 (rear_axle_exact) or 2 (lead_wheel)"));
  }
  if (p.curvature_preview != CurvaturePreview::centred_ramp &&
      p.curvature_preview != CurvaturePreview::planned_jumps) {
    return fail(text("curvature_preview"), static_cast<int>(p.curvature_preview),
                text("must be 0 (centred_ramp) or 1 (planned_jumps)"));
  }
  constexpr double shortest = ControllerParameters::min_wheelbase_m;
  constexpr double longest = ControllerParameters::max_wheelbase_m;
  auto wheelbase_rule = [] {
    return "must be in [0.01, 100] m (min_wheelbase_m, max_wheelbase_m)";
  };
  if (!finite_positive(p.vehicle_wheelbase_m)) {
    return fail(text("vehicle_wheelbase_m"), p.vehicle_wheelbase_m, text("must be finite and > 0"));
  }
  if (p.vehicle_wheelbase_m < shortest || p.vehicle_wheelbase_m > longest) {
    return fail(text("vehicle_wheelbase_m"), p.vehicle_wheelbase_m, wheelbase_rule);
  }
  double shortest_lambda = longest;
  for (int i = 0; i < p.order; ++i) {
    const double lambda = p.wheelbases_m[static_cast<std::size_t>(i)];
    auto name = [i] { return wheelbase_name(i); };
    if (!finite_positive(lambda)) {
      return fail(name, lambda,
                  text("must be finite and > 0 (reversing is selected by v < 0, not by the sign)"));
    }
    if (lambda < shortest || lambda > longest) return fail(name, lambda, wheelbase_rule);
    shortest_lambda = std::min(shortest_lambda, lambda);
    // Paper Sec. III item 3: lambda^2 = lambda_veh^2 - lambda_l^2 implies lambda_l < lambda_veh.
    if (i >= 1 && lambda >= p.vehicle_wheelbase_m) {
      return fail(name, lambda, [&p] {
        return "must be < vehicle_wheelbase_m = " + std::to_string(p.vehicle_wheelbase_m) +
               " (eq. cornering_constr: lambda_l < lambda_veh)";
      });
    }
  }
  if (!finite_positive(p.lead_curvature_bound)) {
    return fail(text("lead_curvature_bound"), p.lead_curvature_bound,
                text("must be finite and > 0"));
  }
  if (!std::isfinite(p.k_rob) || p.k_rob < 0.0 || p.k_rob >= 1.0) {
    return fail(text("k_rob"), p.k_rob, text("must be in [0, 1) (eq. sigma divides by 1 - k_rob)"));
  }
  if (!std::isfinite(p.feedforward_share) || p.feedforward_share < 0.0 ||
      p.feedforward_share >= 1.0) {
    return fail(text("feedforward_share"), p.feedforward_share,
                text("must be in [0, 1) (the switching part needs kbar_n - kbar_ff > 0)"));
  }
  if (std::isnan(p.feedforward_curvature_rate) || p.feedforward_curvature_rate < 0.0) {
    return fail(text("feedforward_curvature_rate"), p.feedforward_curvature_rate,
                text("must be >= 0 (+inf: no rate limit)"));
  }
  if (!std::isfinite(p.feedforward_catch_up) || p.feedforward_catch_up < 0.0 ||
      p.feedforward_catch_up > 1.0) {
    return fail(text("feedforward_catch_up"), p.feedforward_catch_up, text("must be in [0, 1]"));
  }
  if (p.curvature_preview == CurvaturePreview::planned_jumps) {
    const int preview = static_cast<int>(p.curvature_preview);
    if (p.cornering_target != CorneringTarget::rear_axle_exact) {
      return fail(text("curvature_preview (1 = planned_jumps)"), preview,
                  text("planned_jumps needs cornering_target rear_axle_exact (the plan is the "
                       "rear axle's curvature, which only the chain's inverse turns into a "
                       "target)"));
    }
    if (p.order < 1 || p.order > 2) {
      return fail(text("curvature_preview (1 = planned_jumps)"), preview,
                  text("planned_jumps needs order 1 or 2 (the plan's lags are simulated for "
                       "those)"));
    }
    if (!std::isfinite(p.feedforward_curvature_rate) || !(p.feedforward_curvature_rate > 0.0)) {
      return fail(text("curvature_preview (1 = planned_jumps)"), preview,
                  text("planned_jumps needs a finite feedforward_curvature_rate > 0 (the plan "
                       "ramps at it)"));
    }
  }
  if (!std::isfinite(p.boundary_layer) || p.boundary_layer < 0.0) {
    return fail(text("boundary_layer"), p.boundary_layer, text("must be finite and >= 0"));
  }
  if (!std::isfinite(p.actuator_delay_s) || p.actuator_delay_s < 0.0 ||
      p.actuator_delay_s > ControllerParameters::max_actuator_delay_s) {
    return fail(text("actuator_delay_s"), p.actuator_delay_s, text("must be in [0, 1] s"));
  }
  if (!std::isfinite(p.preview_time_s) || p.preview_time_s < 0.0 ||
      p.preview_time_s > ControllerParameters::max_actuator_delay_s) {
    return fail(text("preview_time_s"), p.preview_time_s, text("must be in [0, 1] s"));
  }
  const std::pair<const char*, double> slip_gradients[] = {
      {"rear_slip_gradient_s2pm", p.rear_slip_gradient_s2pm},
      {"front_slip_gradient_s2pm", p.front_slip_gradient_s2pm}};
  for (const auto& [name, value] : slip_gradients) {
    if (!std::isfinite(value) || value < 0.0 ||
        value > ControllerParameters::max_slip_gradient_s2pm) {
      return fail(text(name), value, text("must be in [0, 0.1] s^2/m"));
    }
  }
  if (!std::isfinite(p.disturbance_estimation_length_m) ||
      (p.disturbance_estimation_length_m != 0.0 &&
       (p.disturbance_estimation_length_m < 1.0 || p.disturbance_estimation_length_m > 1000.0))) {
    return fail(text("disturbance_estimation_length_m"), p.disturbance_estimation_length_m,
                text("must be 0 (off) or in [1, 1000] m"));
  }
  if (std::isnan(p.max_lateral_acceleration_mps2) || p.max_lateral_acceleration_mps2 <= 0.0) {
    return fail(text("max_lateral_acceleration_mps2"), p.max_lateral_acceleration_mps2,
                text("must be > 0 m/s^2 (+inf: no friction guard)"));
  }
  if (!std::isfinite(p.actuator_time_constant_s) || p.actuator_time_constant_s < 0.0 ||
      p.actuator_time_constant_s > 0.5) {
    return fail(text("actuator_time_constant_s"), p.actuator_time_constant_s,
                text("must be in [0, 0.5] s"));
  }
  if (p.actuator_lag_count < 1 || p.actuator_lag_count > 3) {
    return fail(text("actuator_lag_count"), p.actuator_lag_count, text("must be 1, 2 or 3"));
  }
  if (!finite_positive(p.approach_angle_rad) ||
      p.approach_angle_rad > std::numbers::pi / 2.0 + 1e-12) {
    return fail(text("approach_angle_rad"), p.approach_angle_rad, text("must be in (0, pi/2]"));
  }
  if (!finite_positive(p.max_substep_fraction) || p.max_substep_fraction > 1.0) {
    return fail(text("max_substep_fraction"), p.max_substep_fraction, text("must be in (0, 1]"));
  }
  if (p.order > 0 &&
      p.max_substep_fraction * shortest_lambda < ControllerParameters::min_substep_m) {
    return fail(text("max_substep_fraction"), p.max_substep_fraction, [shortest_lambda] {
      return "times the shortest wheelbase " + std::to_string(shortest_lambda) +
             " m must be >= min_substep_m = 0.001 m";
    });
  }
  if (p.max_substeps < 1 || p.max_substeps > 10000) {
    return fail(text("max_substeps"), p.max_substeps, text("must be in [1, 10000]"));
  }
  if (p.governor.enabled) {
    const SteeringGovernor& g = p.governor;
    if (p.order < 1 || p.order > 2) {
      return fail(text("governor.enabled"), p.order,
                  text("the governor needs order 1 or 2 (the command's acceleration, resp. "
                       "rate, is affine in the lead curvature only there)"));
    }
    if (!finite_positive(g.max_steering_rate_radps)) {
      return fail(text("governor.max_steering_rate_radps"), g.max_steering_rate_radps,
                  text("must be finite and > 0"));
    }
    if (!finite_positive(g.max_steering_acceleration_radps2)) {
      return fail(text("governor.max_steering_acceleration_radps2"),
                  g.max_steering_acceleration_radps2, text("must be finite and > 0"));
    }
    if (!std::isfinite(g.max_longitudinal_acceleration_mps2) ||
        g.max_longitudinal_acceleration_mps2 < 0.0 || g.max_longitudinal_acceleration_mps2 > 50.0) {
      return fail(text("governor.max_longitudinal_acceleration_mps2"),
                  g.max_longitudinal_acceleration_mps2, text("must be in [0, 50] m/s^2"));
    }
    if (!std::isfinite(g.law_length_m) || g.law_length_m < 0.0 || g.law_length_m > 1000.0) {
      return fail(text("governor.law_length_m"), g.law_length_m,
                  text("must be 0 (keep boundary_layer) or in (0, 1000] m"));
    }
    if (!std::isfinite(g.margin) || g.margin < 0.0 || g.margin >= 0.5) {
      return fail(text("governor.margin"), g.margin, text("must be in [0, 0.5)"));
    }
    if (p.actuator_time_constant_s > 0.0) {
      return fail(text("actuator_time_constant_s"), p.actuator_time_constant_s,
                  text("must be 0 with the governor (it bounds the chain's command, not the "
                       "actuator-inverted one)"));
    }
  }
  // Invariant sets down the chain (paper_notes §2): kbar_i lambda_i < 1 for every wheel.
  double kbar = p.lead_curvature_bound;
  for (int i = p.order; i >= 1; --i) {
    const double product = kbar * p.wheelbases_m[static_cast<std::size_t>(i - 1)];
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

ControllerParameters ControllerParameters::paper_c1(double vehicle_wheelbase_m,
                                                    double lead_wheelbase_m,
                                                    double lead_curvature_bound, double k_rob) {
  ControllerParameters parameters;
  parameters.order = 2;
  parameters.vehicle_wheelbase_m = vehicle_wheelbase_m;
  parameters.wheelbases_m[0] =
      cornering_front_wheelbase(vehicle_wheelbase_m, lead_wheelbase_m * lead_wheelbase_m);
  if (!(parameters.wheelbases_m[0] > 0.0)) {
    throw std::invalid_argument(describe("lead wheelbase lambda_l", lead_wheelbase_m,
                                         "must be < vehicle_wheelbase_m (eq. cornering_constr)"));
  }
  parameters.wheelbases_m[1] = lead_wheelbase_m;
  parameters.lead_curvature_bound = lead_curvature_bound;
  parameters.k_rob = k_rob;
  parameters.cornering_target = CorneringTarget::lead_wheel;
  parameters.feedforward_share = 0.0;  // the paper's law: no feedforward
  parameters.boundary_layer = 0.0;     // and kappa_n = kbar_n sign(sigma)
  parameters.validate();
  return parameters;
}

ControllerParameters ControllerParameters::paper_c0(double vehicle_wheelbase_m,
                                                    double front_curvature_bound, double k_rob) {
  ControllerParameters parameters;
  parameters.order = 1;
  parameters.vehicle_wheelbase_m = vehicle_wheelbase_m;
  parameters.wheelbases_m[0] = vehicle_wheelbase_m;
  parameters.lead_curvature_bound = front_curvature_bound;
  parameters.k_rob = k_rob;
  parameters.cornering_target = CorneringTarget::lead_wheel;
  parameters.feedforward_share = 0.0;  // the paper's law: no feedforward
  parameters.boundary_layer = 0.0;     // and kappa_n = kbar_n sign(sigma)
  parameters.validate();
  return parameters;
}

}  // namespace smoothsteer
