// The field table (parameter_fields.hpp) is the one source of ControllerParameters' names,
// ranges and docs: every rule it states gives its own message, every combination validate()
// rejects names both fields, and docs/controller.md's table is the table's rendering.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>

#include "smoothsteer/controller/parameter_fields.hpp"
#include "smoothsteer/validation.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

void expect_message(const ControllerParameters& p, const std::string& expected) {
  EXPECT_EQ(p.validation_error(), "ControllerParameters: " + expected);
  EXPECT_FALSE(p.is_valid());
}

ControllerParameters with(const char* name, double value, ControllerParameters p = {}) {
  const ParameterField* field = find_parameter_field(name);
  EXPECT_NE(field, nullptr) << name;
  if (field) field->set(p, value);
  return p;
}

// A value outside the field's range: below it, above it, or NaN for an unbounded real.
double out_of_range(const ParameterField& field) {
  const FieldRange& r = field.range;
  const bool whole = field.kind != FieldKind::real;
  const double step = whole ? 1.0 : 0.5;
  for (const double candidate : {r.min - step, r.max + step}) {
    if (std::isfinite(candidate) && !r.contains(candidate)) return candidate;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

TEST(ParameterFields, EveryFieldHasOneRowAndAUniqueName) {
  std::set<std::string> names, members;
  for (const ParameterField& field : controller_parameter_fields()) {
    EXPECT_TRUE(names.insert(std::string(field.name)).second) << field.name;
    EXPECT_TRUE(members.insert(std::string(field.member)).second) << field.member;
    EXPECT_FALSE(field.doc.empty()) << field.name;
    EXPECT_EQ(find_parameter_field(field.name), &field);
    if (field.kind != FieldKind::wheelbases) {
      ASSERT_NE(field.get, nullptr) << field.name;
      // The default is in range (the governor's limits have none that holds: the vehicle gives
      // them once it is enabled), and setting it back changes nothing.
      const ControllerParameters defaults;
      const double value = field.get(defaults);
      if (field_has_rule(field) && field.group != ParameterGroup::governor) {
        EXPECT_TRUE(field.range.contains(value)) << field.name;
      }
      ControllerParameters p;
      field.set(p, value);
      EXPECT_EQ(p.validation_error(), "") << field.name;
    }
  }
  EXPECT_EQ(find_parameter_field("kbar"), nullptr);
}

// Every rule of the table, broken on its own, gives "<name> = <value> <rule>".
TEST(ParameterFields, EveryRuleHasItsOwnMessage) {
  int checked = 0;
  for (const ParameterField& field : controller_parameter_fields()) {
    if (!field_has_rule(field) || field.kind == FieldKind::wheelbases) continue;
    ControllerParameters p;
    if (field.group == ParameterGroup::governor) {
      p.governor.enabled = true;
      p.governor.max_steering_rate_radps = 0.5;
      p.governor.max_steering_acceleration_radps2 = 2.0;
    }
    const double value = out_of_range(field);
    field.set(p, value);
    expect_message(p, std::string(field.name) + " = " + exact_number(field.get(p)) + " " +
                          field_rule_text(field));
    ++checked;
  }
  EXPECT_GE(checked, 25);
}

// The rule texts come from the ranges: each shape of range reads as validate() states it.
TEST(ParameterFields, RuleTextsAreDerivedFromTheRanges) {
  auto rule = [](const char* name) { return field_rule_text(*find_parameter_field(name)); };
  EXPECT_EQ(rule("k_rob"), "must be in [0, 1) (eq. sigma divides by 1 - k_rob)");
  EXPECT_EQ(rule("lead_curvature_bound"), "must be finite and > 0 1/m");
  EXPECT_EQ(rule("feedforward_curvature_rate"), "must be >= 0 1/m^2 (+inf: no rate limit)");
  EXPECT_EQ(rule("actuator_delay_s"), "must be in [0, 1] s");  // off closes the open end
  EXPECT_EQ(rule("disturbance_estimation_length_m"), "must be 0 (off) or in [1, 1000] m");
  EXPECT_EQ(rule("max_lateral_acceleration_mps2"), "must be > 0 m/s^2 (+inf: no friction guard)");
  EXPECT_EQ(rule("actuator_lag_count"), "must be 1, 2 or 3");
  EXPECT_EQ(rule("surface"), "must be 0 (global) or 1 (paper)");
  EXPECT_EQ(rule("approach_angle_rad"), "must be in (0, pi/2] rad");
  EXPECT_EQ(rule("slip_preview_second_order"), "");
  EXPECT_EQ(rule("governor.max_steering_angle_rad"), "must be > 0 rad (+inf: none)");
  EXPECT_EQ(rule("governor.near_law_switching_bound"), "must be > 0 1/m");
}

TEST(ParameterFields, FlatFieldsSwitchTheirGroup) {
  ControllerParameters p = with("actuator_delay_s", 0.05);
  EXPECT_TRUE(p.delay_compensation.enabled);
  EXPECT_EQ(p.delay_compensation.actuator_delay_s, 0.05);
  p = with("actuator_delay_s", 0.0, p);
  EXPECT_FALSE(p.delay_compensation.enabled);
  p = with("max_lateral_acceleration_mps2", 8.0);
  EXPECT_TRUE(p.friction_guard.enabled);
  p = with("max_lateral_acceleration_mps2", inf, p);
  EXPECT_FALSE(p.friction_guard.enabled);
  p = with("rear_slip_gradient_s2pm", 0.004);
  EXPECT_TRUE(p.single_track.enabled);
  p = with("front_slip_gradient_s2pm", 0.003, p);
  p = with("rear_slip_gradient_s2pm", 0.0, p);
  EXPECT_TRUE(p.single_track.enabled) << "the front gradient keeps it on";
  p = with("disturbance_estimation_length_m", 20.0);
  EXPECT_TRUE(p.disturbance_estimation.enabled);
  p = with("actuator_time_constant_s", 0.01);
  EXPECT_TRUE(p.actuator_inversion.enabled);
  EXPECT_EQ(p.validation_error(), "");
}

// A field of a switched-off group does nothing: rejected, naming the group's switch.
TEST(ParameterFields, FieldsOfASwitchedOffGroupAreRejected) {
  expect_message(with("actuator_lag_count", 2),
                 "actuator_lag_count = 2 has no effect while actuator_inversion.enabled is false "
                 "(the inversion needs actuator_time_constant_s > 0)");
  expect_message(with("preview_time_s", 0.05),
                 "preview_time_s = 0.05 has no effect while single_track.enabled is false (the "
                 "inversion needs rear_slip_gradient_s2pm or front_slip_gradient_s2pm > 0)");
  expect_message(with("slip_preview_second_order", 0.0),
                 "slip_preview_second_order = 0 has no effect while single_track.enabled is false "
                 "(the inversion needs rear_slip_gradient_s2pm or front_slip_gradient_s2pm > 0)");
  ControllerParameters p;
  p.delay_compensation.actuator_delay_s = 0.05;  // the member set, the group left off
  expect_message(p,
                 "actuator_delay_s = 0.05 has no effect while delay_compensation.enabled is "
                 "false (the compensation needs actuator_delay_s > 0)");
  p = {};
  p.disturbance_estimation.length_m = 20.0;
  expect_message(p,
                 "disturbance_estimation_length_m = 20 has no effect while "
                 "disturbance_estimation.enabled is false (the estimation needs "
                 "disturbance_estimation_length_m > 0)");
  p = {};
  p.friction_guard.max_lateral_acceleration_mps2 = 8.0;
  expect_message(p,
                 "max_lateral_acceleration_mps2 = 8 has no effect while "
                 "friction_guard.enabled is false (the guard needs a finite "
                 "max_lateral_acceleration_mps2)");
  p = {};
  p.actuator_inversion.time_constant_s = 0.01;
  expect_message(p,
                 "actuator_time_constant_s = 0.01 has no effect while "
                 "actuator_inversion.enabled is false (the inversion needs "
                 "actuator_time_constant_s > 0)");
  p = {};
  p.single_track.rear_slip_gradient_s2pm = 0.004;
  expect_message(p,
                 "rear_slip_gradient_s2pm = 0.004 has no effect while single_track.enabled "
                 "is false (the inversion needs rear_slip_gradient_s2pm or "
                 "front_slip_gradient_s2pm > 0)");
}

// A group switched on with its "off" value would do nothing.
TEST(ParameterFields, AGroupOnWithItsOffValueIsRejected) {
  ControllerParameters p;
  p.delay_compensation.enabled = true;
  expect_message(p,
                 "actuator_delay_s = 0 switches delay_compensation.enabled off: with "
                 "enabled = true it must be in (0, 1]");
  p = {};
  p.disturbance_estimation.enabled = true;
  expect_message(p,
                 "disturbance_estimation_length_m = 0 switches "
                 "disturbance_estimation.enabled off: with enabled = true it must be in "
                 "[1, 1000]");
  p = {};
  p.friction_guard.enabled = true;
  expect_message(p,
                 "max_lateral_acceleration_mps2 = inf switches friction_guard.enabled off: "
                 "with enabled = true it must be in (0, inf)");
  p = {};
  p.actuator_inversion.enabled = true;
  expect_message(p,
                 "actuator_time_constant_s = 0 switches actuator_inversion.enabled off: with "
                 "enabled = true it must be in (0, 0.5]");
  p = {};
  p.single_track.enabled = true;
  expect_message(p,
                 "rear_slip_gradient_s2pm = 0 and front_slip_gradient_s2pm = 0 with "
                 "single_track.enabled = true: the inversion needs a slip gradient > 0");
}

// Combinations where one field makes the other inert, or that conflict: both are named.
TEST(ParameterFields, InertAndConflictingCombinationsNameBothFields) {
  ControllerParameters first_order;
  first_order.chain.order = 1;
  expect_message(with("actuator_time_constant_s", 0.01, first_order),
                 "actuator_time_constant_s = 0.01 needs order >= 2, not order = 1 (the "
                 "inversion leads the command with the chain's derivatives up to n - 1)");
  ControllerParameters paper_law;
  paper_law.feedforward.share = 0.0;
  expect_message(with("feedforward_catch_up", 0.5, paper_law),
                 "feedforward_catch_up = 0.5 has no effect with feedforward_share = 0 (without a "
                 "feedforward there is no gap to catch up)");
  expect_message(with("disturbance_estimation_length_m", 20.0, paper_law),
                 "disturbance_estimation_length_m = 20 has no effect with feedforward_share = 0 "
                 "(the estimate enters through kappa_ff, which kbar_ff = 0 clamps)");
  ControllerParameters dubins;
  dubins.chain.order = 0;
  expect_message(with("max_lateral_acceleration_mps2", 8.0, dubins),
                 "max_lateral_acceleration_mps2 = 8 has no effect with order = 0 (the guard "
                 "bounds the chain's lead curvature)");
  ControllerParameters governed = with("actuator_time_constant_s", 0.01);
  governed.governor.enabled = true;
  governed.governor.max_steering_rate_radps = 0.5;
  governed.governor.max_steering_acceleration_radps2 = 2.0;
  expect_message(governed,
                 "actuator_time_constant_s = 0.01 must be 0 with the governor (it bounds the "
                 "chain's command, not the actuator-inverted one)");
  ControllerParameters third_order_governed = governed;
  third_order_governed.chain.order = 3;
  expect_message(third_order_governed,
                 "order = 3 must be 1 or 2 with governor.enabled = true (the command's "
                 "acceleration, resp. rate, is affine in the lead curvature only there)");
  ControllerParameters planned;
  planned.feedforward.curvature_preview = CurvaturePreview::planned_jumps;
  expect_message(planned,
                 "curvature_preview (1 = planned_jumps) = 1 planned_jumps needs cornering_target "
                 "rear_axle_exact (the plan is the rear axle's curvature, which only the chain's "
                 "inverse turns into a target)");
  planned.feedforward.cornering_target = CorneringTarget::rear_axle_exact;
  expect_message(planned,
                 "curvature_preview (1 = planned_jumps) = 1 planned_jumps needs a finite "
                 "feedforward_curvature_rate > 0 (the plan ramps at it)");
  planned.feedforward.curvature_rate = 0.02;
  planned.chain.order = 3;
  expect_message(planned,
                 "curvature_preview (1 = planned_jumps) = 1 planned_jumps needs order 1 or 2 (the "
                 "plan's lags are simulated for those)");
}

// A setting another field leaves without effect is refused, naming that field; the same setting
// where it acts passes.
TEST(ParameterFields, InertSettingsNameTheFieldThatMakesThemInert) {
  ControllerParameters ungoverned;
  ungoverned.governor.margin = 0.05;
  expect_message(ungoverned,
                 "governor.margin = 0.05 has no effect while governor.enabled is false");
  ControllerParameters governed = ungoverned;
  governed.governor.enabled = true;
  governed.governor.max_steering_rate_radps = 0.5;
  governed.governor.max_steering_acceleration_radps2 = 2.0;
  EXPECT_EQ(governed.validation_error(), "");

  ControllerParameters paper_surface = with("approach_angle_rad", 1.0);
  EXPECT_EQ(paper_surface.validation_error(), "");
  paper_surface.law.surface = SlidingSurface::paper;
  expect_message(paper_surface,
                 "approach_angle_rad = 1 has no effect with surface = paper (psi_max shapes the "
                 "global law's reference heading only)");

  ControllerParameters unbounded = with("feedforward_catch_up", 0.5);
  expect_message(unbounded,
                 "feedforward_catch_up = 0.5 has no effect with feedforward_curvature_rate = +inf "
                 "(an unlimited feedforward leaves no gap to catch up)");
  unbounded.feedforward.curvature_rate = 0.01;
  EXPECT_EQ(unbounded.validation_error(), "");
}

std::string between(const std::string& text, const std::string& begin, const std::string& end) {
  const auto start = text.find(begin);
  if (start == std::string::npos) return "";
  const auto from = start + begin.size();
  const auto stop = text.find(end, from);
  return stop == std::string::npos ? "" : text.substr(from, stop - from);
}

// docs/controller.md's parameter table is parameter_table_markdown(). With
// SMOOTHSTEER_UPDATE_DOCS=1 the test rewrites it instead.
TEST(ParameterFields, DocsTableIsTheFieldTable) {
  const auto path = testing::source_dir() / "docs/controller.md";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const std::string begin = "<!-- parameter table: generated from parameter_fields.cpp -->\n";
  const std::string end = "<!-- end of parameter table -->";
  const std::string table = parameter_table_markdown();
  const std::string documented = between(text, begin, end);
  const char* update = std::getenv("SMOOTHSTEER_UPDATE_DOCS");
  const bool marked = text.find(begin) != std::string::npos && text.find(end) != std::string::npos;
  ASSERT_TRUE(marked) << path << " lacks the markers " << begin << " and " << end;
  if (update && std::string(update) == "1" && documented != table) {
    const auto at = text.find(begin) + begin.size();
    std::ofstream(path) << text.substr(0, at) << table << text.substr(at + documented.size());
    GTEST_SKIP() << "rewrote " << path;
  }
  EXPECT_EQ(documented, table) << "docs/controller.md's parameter table differs from the field "
                                  "table; rerun with SMOOTHSTEER_UPDATE_DOCS=1 to regenerate";
}

}  // namespace
}  // namespace smoothsteer
