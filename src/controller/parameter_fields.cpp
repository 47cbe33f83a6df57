#include "smoothsteer/controller/parameter_fields.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace smoothsteer {
namespace {

using P = ControllerParameters;
constexpr double inf = std::numeric_limits<double>::infinity();

// Accessors of a member given by its path: the table stays one line per field. The member is
// read and written as a double; integers, booleans and enumerations convert exactly.
template <typename T>
constexpr T from_double(double value) noexcept {
  if constexpr (std::is_same_v<T, bool>) {
    return value != 0.0;
  } else if constexpr (std::is_enum_v<T>) {
    return static_cast<T>(static_cast<int>(value));
  } else if constexpr (std::is_integral_v<T>) {
    // Out-of-range doubles are clamped first: a cast of one is undefined behaviour.
    return static_cast<T>(std::isnan(value) ? -1.0 : std::fmax(-1e9, std::fmin(value, 1e9)));
  } else {
    return value;
  }
}

template <typename T>
constexpr double to_double(T value) noexcept {
  if constexpr (std::is_enum_v<T>) {
    return static_cast<double>(static_cast<int>(value));
  } else {
    return static_cast<double>(value);
  }
}

#define SMOOTHSTEER_GET(path) [](const P& p) noexcept { return to_double(p.path); }
#define SMOOTHSTEER_SET(path) \
  [](P& p, double v) noexcept { p.path = from_double<decltype(p.path)>(v); }
// A flat field that switches its optional group: on unless the value is the range's `off`.
#define SMOOTHSTEER_SWITCH(group, path, off)   \
  [](P& p, double v) noexcept {                \
    p.path = from_double<decltype(p.path)>(v); \
    p.group.enabled = v != (off);              \
  }

// The far law's length through its flat field: a length fixes it, 0 leaves it derived.
#define SMOOTHSTEER_FIX_LAW_LENGTH          \
  [](P& p, double v) noexcept {             \
    p.governor.law_length_m = v;            \
    p.governor.fixed_law_length = v != 0.0; \
  }

// The single-track inversion is on while either slip gradient is.
#define SMOOTHSTEER_SLIP(path)                                                \
  [](P& p, double v) noexcept {                                               \
    p.path = v;                                                               \
    p.single_track.enabled = p.single_track.rear_slip_gradient_s2pm != 0.0 || \
                             p.single_track.front_slip_gradient_s2pm != 0.0;  \
  }

constexpr FieldRange closed(double min, double max) noexcept {
  return {{min, max, false, false}};
}
constexpr FieldRange right_open(double min, double max) noexcept {
  return {{min, max, false, true}};
}
constexpr FieldRange left_open(double min, double max) noexcept {
  return {{min, max, true, false}};
}
constexpr FieldRange positive() noexcept {
  return {{0.0, inf, true, true}};
}

using K = FieldKind;
using G = ParameterGroup;

// clang-format off
const std::array fields{
  // The chain (paper Sec. II-C/D).
  ParameterField{"order", "chain.order", K::integer, closed(0, P::max_order), "",
    "", "n, the number of fictive wheels; the command is C^(n-1)", "",
    G::none, false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(chain.order), SMOOTHSTEER_SET(chain.order)},
  ParameterField{"vehicle_wheelbase_m", "chain.vehicle_wheelbase_m", K::real,
    closed(P::min_wheelbase_m, P::max_wheelbase_m), "m",
    " (min_wheelbase_m, max_wheelbase_m)",
    "lambda_veh, the real vehicle's wheelbase", "", G::none, false, ScenarioKey::derived,
    "the vehicle file's lf + lr",
    SMOOTHSTEER_GET(chain.vehicle_wheelbase_m), SMOOTHSTEER_SET(chain.vehicle_wheelbase_m)},
  ParameterField{"wheelbases_m", "chain.wheelbases_m", K::wheelbases,
    closed(P::min_wheelbase_m, P::max_wheelbase_m), "m",
    "; lambda_i < lambda_veh for i >= 2 (eq. cornering_constr)",
    "lambda_1 (fictive lambda) .. lambda_n (lead lambda_l); the first n are used", "",
    G::none, false, ScenarioKey::direct, "", nullptr, nullptr},
  ParameterField{"lead_curvature_bound", "chain.lead_curvature_bound", K::real, positive(), "1/m",
    "", "kbar_n (eq. kappan); kbar_i lambda_i < 1 down the chain "
    "(eq. kappal_constr)", "", G::none, false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(chain.lead_curvature_bound), SMOOTHSTEER_SET(chain.lead_curvature_bound)},
  ParameterField{"max_substep_fraction", "chain.max_substep_fraction", K::real, left_open(0, 1), "",
    "", "chain RK4 sub-step over the shortest wheelbase; times min lambda_i "
    ">= min_substep_m = 1 mm", "", G::none, false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(chain.max_substep_fraction), SMOOTHSTEER_SET(chain.max_substep_fraction)},
  ParameterField{"max_substeps", "chain.max_substeps", K::integer, closed(1, 10000), "",
    "", "most sub-steps per control period", "", G::none, false,
    ScenarioKey::direct, "",
    SMOOTHSTEER_GET(chain.max_substeps), SMOOTHSTEER_SET(chain.max_substeps)},
  // The switching law.
  ParameterField{"surface", "law.surface", K::choice, closed(0, 1), "",
    "", "`global` (converges from any pose) or `paper` (printed "
    "eq. sigma, local)", "global paper", G::none, false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(law.surface), SMOOTHSTEER_SET(law.surface)},
  ParameterField{"k_rob", "law.k_rob", K::real, right_open(0, 1), "",
    " (eq. sigma divides by 1 - k_rob)",
    "robustness margin: the law rejects matched disturbances |kappa_d| <= k_rob kbar_sw "
    "(eq. sigma; paper_notes §5: the paper's k_rob = 3 is 0.3)", "", G::none, false,
    ScenarioKey::direct, "", SMOOTHSTEER_GET(law.k_rob), SMOOTHSTEER_SET(law.k_rob)},
  ParameterField{"approach_angle_rad", "law.approach_angle_rad", K::real,
    left_open(0, std::numbers::pi / 2.0), "rad", "",
    "psi_max of the global law", "", G::none, false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(law.approach_angle_rad), SMOOTHSTEER_SET(law.approach_angle_rad)},
  ParameterField{"boundary_layer", "law.boundary_layer", K::real, right_open(0, inf), "",
    "", "epsilon: kbar sat(z/epsilon) instead of kbar sign(z) "
    "(rad for the global law, m for the paper's); 0 = the paper's law", "", G::none, false,
    ScenarioKey::direct, "",
    SMOOTHSTEER_GET(law.boundary_layer), SMOOTHSTEER_SET(law.boundary_layer)},
  // The feedforward.
  ParameterField{"feedforward_share", "feedforward.share", K::real, right_open(0, 1), "",
    " (the switching part needs kbar_n - kbar_ff > 0)",
    "kbar_ff / kbar_n, the feedforward's share of the authority (feedforward.md)", "", G::none,
    false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(feedforward.share), SMOOTHSTEER_SET(feedforward.share)},
  ParameterField{"feedforward_curvature_rate", "feedforward.curvature_rate", K::real,
    closed(0, inf), "1/m^2", " (+inf: no rate limit)",
    "L_ff, the largest d kappa_ff / ds; finite values make the rate certificate finite", "",
    G::none, false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(feedforward.curvature_rate), SMOOTHSTEER_SET(feedforward.curvature_rate)},
  ParameterField{"feedforward_catch_up", "feedforward.catch_up", K::real, closed(0, 1), "",
    "", "g: share of kbar_sw that closes the gap the rate limit leaves "
    "(feedforward.md section 4); 0 = off", "", G::none, false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(feedforward.catch_up), SMOOTHSTEER_SET(feedforward.catch_up)},
  ParameterField{"cornering_target", "feedforward.cornering_target", K::choice, closed(0, 2), "",
    "",
    "`rear_axle` (stationary offset), `rear_axle_exact` (the chain's inverse, feedforward.md "
    "section 3) or `lead_wheel` (paper)", "rear_axle rear_axle_exact lead_wheel", G::none, false,
    ScenarioKey::direct, "",
    SMOOTHSTEER_GET(feedforward.cornering_target), SMOOTHSTEER_SET(feedforward.cornering_target)},
  ParameterField{"curvature_preview", "feedforward.curvature_preview", K::choice, closed(0, 1), "",
    "", "`centred_ramp` or `planned_jumps` "
    "(feedforward.md section 2b; needs `rear_axle_exact`, order 1 or 2, a finite L_ff > 0)",
    "centred_ramp planned_jumps", G::none, false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(feedforward.curvature_preview),
    SMOOTHSTEER_SET(feedforward.curvature_preview)},
  // Delay compensation (Smith predictor).
  ParameterField{"actuator_delay_s", "delay_compensation.actuator_delay_s", K::real,
    {{0.0, P::max_actuator_delay_s, true, false}, 0.0}, "s", "",
    "known steering delay that the Smith predictor compensates; 0 = off", "",
    G::delay_compensation, true, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(delay_compensation.actuator_delay_s),
    SMOOTHSTEER_SWITCH(delay_compensation, delay_compensation.actuator_delay_s, 0.0)},
  // Single-track inversion.
  ParameterField{"rear_slip_gradient_s2pm", "single_track.rear_slip_gradient_s2pm", K::real,
    closed(0, P::max_slip_gradient_s2pm), "s^2/m", "",
    "K_r of the single-track inversion; with the front one 0 = off", "", G::single_track, true,
    ScenarioKey::derived, "`slip_preview: true` (the vehicle file's tires)",
    SMOOTHSTEER_GET(single_track.rear_slip_gradient_s2pm),
    SMOOTHSTEER_SLIP(single_track.rear_slip_gradient_s2pm)},
  ParameterField{"front_slip_gradient_s2pm", "single_track.front_slip_gradient_s2pm", K::real,
    closed(0, P::max_slip_gradient_s2pm), "s^2/m", "",
    "K_f of the single-track inversion", "", G::single_track, true, ScenarioKey::derived,
    "`slip_preview: true` (the vehicle file's tires)",
    SMOOTHSTEER_GET(single_track.front_slip_gradient_s2pm),
    SMOOTHSTEER_SLIP(single_track.front_slip_gradient_s2pm)},
  ParameterField{"front_load_transfer_s2pm", "single_track.front_load_transfer_s2pm", K::real,
    closed(0, 1), "s^2/m", "",
    "t_f = h / (g lr): the front slip gradient is K_f / (1 - a_x t_f) at acceleration a_x", "",
    G::single_track, false, ScenarioKey::derived,
    "`slip_preview: true` (the vehicle file's cg_height_m)",
    SMOOTHSTEER_GET(single_track.front_load_transfer_s2pm),
    SMOOTHSTEER_SET(single_track.front_load_transfer_s2pm)},
  ParameterField{"rear_load_transfer_s2pm", "single_track.rear_load_transfer_s2pm", K::real,
    closed(0, 1), "s^2/m", "",
    "t_r = h / (g lf): the rear slip gradient is K_r / (1 + a_x t_r) at acceleration a_x", "",
    G::single_track, false, ScenarioKey::derived,
    "`slip_preview: true` (the vehicle file's cg_height_m)",
    SMOOTHSTEER_GET(single_track.rear_load_transfer_s2pm),
    SMOOTHSTEER_SET(single_track.rear_load_transfer_s2pm)},
  ParameterField{"preview_time_s", "single_track.preview_time_s", K::real,
    closed(0, P::max_actuator_delay_s), "s", "",
    "extra preview of the inversion (vehicle_dynamics.md section 3)", "", G::single_track, false,
    ScenarioKey::direct, "",
    SMOOTHSTEER_GET(single_track.preview_time_s), SMOOTHSTEER_SET(single_track.preview_time_s)},
  ParameterField{"slip_preview_second_order", "single_track.second_order", K::boolean, closed(0, 1),
    "", "", "with the K_f K_r v^4 kappa'' term of the inversion", "", G::single_track, false,
    ScenarioKey::direct, "",
    SMOOTHSTEER_GET(single_track.second_order), SMOOTHSTEER_SET(single_track.second_order)},
  // Disturbance estimation.
  ParameterField{"disturbance_estimation_length_m", "disturbance_estimation.length_m", K::real,
    {{1.0, 1000.0, false, false}, 0.0}, "m", "",
    "low-pass length of the estimated plant curvature (understeer, bank, steering offset) that "
    "the feedforward subtracts; 0 = off", "", G::disturbance_estimation, true,
    ScenarioKey::direct, "",
    SMOOTHSTEER_GET(disturbance_estimation.length_m),
    SMOOTHSTEER_SWITCH(disturbance_estimation, disturbance_estimation.length_m, 0.0)},
  // Friction guard.
  ParameterField{"max_lateral_acceleration_mps2", "friction_guard.max_lateral_acceleration_mps2",
    K::real, {{0.0, inf, true, true}, inf}, "m/s^2", " (+inf: no friction guard)",
    "a_max: the lead curvature stays within a_max / v^2 at the rear axle; +inf = off", "",
    G::friction_guard, true, ScenarioKey::derived, "`friction_guard: true` (the vehicle's mu g)",
    SMOOTHSTEER_GET(friction_guard.max_lateral_acceleration_mps2),
    SMOOTHSTEER_SWITCH(friction_guard, friction_guard.max_lateral_acceleration_mps2, inf)},
  // Actuator inversion.
  ParameterField{"actuator_time_constant_s", "actuator_inversion.time_constant_s", K::real,
    {{0.0, 0.5, true, false}, 0.0}, "s", "",
    "T of the steering-actuator inversion (1 + T s)^m; 0 = off", "", G::actuator_inversion, true,
    ScenarioKey::direct, "",
    SMOOTHSTEER_GET(actuator_inversion.time_constant_s),
    SMOOTHSTEER_SWITCH(actuator_inversion, actuator_inversion.time_constant_s, 0.0)},
  ParameterField{"actuator_lag_count", "actuator_inversion.lag_count", K::integer, closed(1, 3), "",
    "", "m, the number of equal lags inverted", "", G::actuator_inversion,
    false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(actuator_inversion.lag_count), SMOOTHSTEER_SET(actuator_inversion.lag_count)},
  // The steering governor (docs/governor.md); its fields are checked while it is enabled.
  ParameterField{"governor.enabled", "governor.enabled", K::boolean, closed(0, 1), "",
    "", "the car's rate and acceleration limits held on the command inside the control step "
    "(needs order 1 or 2)", "", G::governor, false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(governor.enabled), SMOOTHSTEER_SET(governor.enabled)},
  ParameterField{"governor.max_steering_rate_radps", "governor.max_steering_rate_radps", K::real,
    positive(), "rad/s", "", "R, the steering rate the governor holds", "",
    G::governor, false, ScenarioKey::derived, "the vehicle file's max_steering_rate_radps",
    SMOOTHSTEER_GET(governor.max_steering_rate_radps),
    SMOOTHSTEER_SET(governor.max_steering_rate_radps)},
  ParameterField{"governor.max_steering_acceleration_radps2",
    "governor.max_steering_acceleration_radps2", K::real, positive(), "rad/s^2",
    "", "A, the steering acceleration the governor holds", "", G::governor,
    false, ScenarioKey::derived, "the vehicle file's max_steering_acceleration_radps2",
    SMOOTHSTEER_GET(governor.max_steering_acceleration_radps2),
    SMOOTHSTEER_SET(governor.max_steering_acceleration_radps2)},
  ParameterField{"governor.max_steering_angle_rad", "governor.max_steering_angle_rad", K::real,
    {{0.0, inf, true, true}, inf}, "rad", " (+inf: none)", "the car's angle limit: kbar_n widens to what it allows (`governed_parameters()`), and a "
    "reset refuses an angle beyond it", "",
    G::governor, false, ScenarioKey::derived, "the vehicle file's max_steering_angle_rad",
    SMOOTHSTEER_GET(governor.max_steering_angle_rad),
    SMOOTHSTEER_SET(governor.max_steering_angle_rad)},
  ParameterField{"governor.max_lateral_acceleration_mps2", "governor.max_lateral_acceleration_mps2",
    K::real, {{0.0, inf, true, true}, inf}, "m/s^2", " (+inf: none)",
    "the car's friction limit mu g: kbar_n widens to what it allows at the speed "
    "(`governed_parameters()`)", "",
    G::governor, false, ScenarioKey::derived, "the vehicle file's mu g",
    SMOOTHSTEER_GET(governor.max_lateral_acceleration_mps2),
    SMOOTHSTEER_SET(governor.max_lateral_acceleration_mps2)},
  ParameterField{"governor.max_longitudinal_acceleration_mps2",
    "governor.max_longitudinal_acceleration_mps2", K::real, closed(0, 50), "m/s^2",
    "", "|dv/dt| budgeted beyond the measured one", "", G::governor,
    false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(governor.max_longitudinal_acceleration_mps2),
    SMOOTHSTEER_SET(governor.max_longitudinal_acceleration_mps2)},
  ParameterField{"governor.law_length_m", "governor.law_length_m", K::real,
    {{0.0, 1000.0, true, false}, 0.0}, "m", "; > 0 with governor.fixed_law_length = true",
    "l, the far law's fixed length (used with governor.fixed_law_length): boundary layer "
    "epsilon = l kbar_sw / 2, a critically damped linear zone; setting this field fixes the "
    "length, 0 derives it", "", G::governor,
    false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(governor.law_length_m), SMOOTHSTEER_FIX_LAW_LENGTH},
  // After law_length_m: a scenario's `fixed_law_length` then overrides what law_length_m set.
  ParameterField{"governor.fixed_law_length", "governor.fixed_law_length", K::boolean,
    closed(0, 1), "", "", "the far law's length is governor.law_length_m; false = derived at "
    "every sub-step from the speed and the heading error (eq. governed_law_length)", "",
    G::governor, false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(governor.fixed_law_length), SMOOTHSTEER_SET(governor.fixed_law_length)},
  ParameterField{"governor.margin", "governor.margin", K::real, right_open(0, 0.5), "",
    "", "share of R and A kept for the chain's variation within a sub-step",
    "", G::governor, false, ScenarioKey::direct, "",
    SMOOTHSTEER_GET(governor.margin), SMOOTHSTEER_SET(governor.margin)},
  ParameterField{"governor.near_law_switching_bound", "governor.near_law_switching_bound",
    K::real, left_open(0, inf), "1/m", "",
    "the near-path law's authority: it steers with min(this, kbar_sw); +inf = the whole kbar_sw",
    "", G::governor, false, ScenarioKey::derived,
    "none, `governed_parameters()` lowers it to the certified kbar_sw",
    SMOOTHSTEER_GET(governor.near_law_switching_bound),
    SMOOTHSTEER_SET(governor.near_law_switching_bound)},
};
// clang-format on

#undef SMOOTHSTEER_GET
#undef SMOOTHSTEER_SET
#undef SMOOTHSTEER_SWITCH
#undef SMOOTHSTEER_SLIP
#undef SMOOTHSTEER_FIX_LAW_LENGTH

}  // namespace

bool FieldRange::contains(double value) const noexcept {
  return value == off || ValueRange::contains(value);
}

ValueRange FieldRange::hull() const noexcept {
  ValueRange h = *this;
  if (std::isnan(off)) return h;
  if (off <= min) {
    h.min = off;
    h.min_open = false;
  }
  if (off >= max) {
    h.max = off;
    h.max_open = false;
  }
  return h;
}

std::span<const ParameterField> controller_parameter_fields() noexcept {
  return fields;
}

const ParameterField* find_parameter_field(std::string_view name) noexcept {
  for (const ParameterField& field : fields) {
    if (field.name == name) return &field;
  }
  return nullptr;
}

std::string_view group_switch_name(ParameterGroup group) noexcept {
  switch (group) {
    case ParameterGroup::delay_compensation:
      return "delay_compensation.enabled";
    case ParameterGroup::single_track:
      return "single_track.enabled";
    case ParameterGroup::disturbance_estimation:
      return "disturbance_estimation.enabled";
    case ParameterGroup::friction_guard:
      return "friction_guard.enabled";
    case ParameterGroup::actuator_inversion:
      return "actuator_inversion.enabled";
    case ParameterGroup::governor:
      return "governor.enabled";
    case ParameterGroup::none:
      break;
  }
  return "";
}

bool group_enabled(const ControllerParameters& p, ParameterGroup group) noexcept {
  switch (group) {
    case ParameterGroup::delay_compensation:
      return p.delay_compensation.enabled;
    case ParameterGroup::single_track:
      return p.single_track.enabled;
    case ParameterGroup::disturbance_estimation:
      return p.disturbance_estimation.enabled;
    case ParameterGroup::friction_guard:
      return p.friction_guard.enabled;
    case ParameterGroup::actuator_inversion:
      return p.actuator_inversion.enabled;
    case ParameterGroup::governor:
      return p.governor.enabled;
    case ParameterGroup::none:
      break;
  }
  return true;
}

}  // namespace smoothsteer
