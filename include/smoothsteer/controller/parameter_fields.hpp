#pragma once
//! \file parameter_fields.hpp
//! The one table of ControllerParameters' fields (docs/controller.md, "Parameters"). Each row
//! names a field once: its flat name (validation messages, the scenario key under `controller.`,
//! the Python keyword and attribute), its member in the grouped struct, its range, unit and
//! documentation. validate(), the scenario reader, the Python binding and the docs' parameter
//! table all read it, so that they cannot drift apart.

#include <limits>
#include <span>
#include <string>
#include <string_view>

#include "smoothsteer/controller/controller_parameters.hpp"
#include "smoothsteer/value_range.hpp"

namespace smoothsteer {

enum class FieldKind { real, integer, boolean, choice, wheelbases };

//! The optional compensations: a group is on exactly when its `enabled` is true.
enum class ParameterGroup {
  none,
  delay_compensation,
  single_track,
  disturbance_estimation,
  friction_guard,
  actuator_inversion,
  governor,
};

//! Values a field accepts on its own: the interval (value_range.hpp), or `off`.
struct FieldRange : ValueRange {
  //! The flat value that switches an optional group off (0 or +inf); NaN: none.
  double off = std::numeric_limits<double>::quiet_NaN();
  bool contains(double value) const noexcept;
  //! The smallest interval that holds the range and `off` (the scenario keys' range).
  ValueRange hull() const noexcept;
};

//! How a scenario file sets the field (src/runner/controller_registry.cpp).
enum class ScenarioKey {
  direct,   //!< `controller.<name>` sets it as it is
  derived,  //!< set from the vehicle file by the key in `scenario_note`
};

struct ParameterField {
  std::string_view name;    //!< flat name: messages, scenario key, Python keyword
  std::string_view member;  //!< member path in ControllerParameters, e.g. "law.k_rob"
  FieldKind kind = FieldKind::real;
  FieldRange range{};
  std::string_view unit;  //!< SI unit, "" for pure numbers
  //! Why the range is what it is, appended to the rule text field_rule_text() derives from the
  //! range (" (eq. sigma divides by 1 - k_rob)"); "" for none.
  std::string_view rule_reason;
  std::string_view doc;
  //! kind choice: the enumerators' names in the order of their values, space separated.
  std::string_view choices;
  ParameterGroup group = ParameterGroup::none;
  //! Setting the flat field switches its group: on, unless the value is range.off.
  bool switches_group = false;
  ScenarioKey scenario = ScenarioKey::direct;
  std::string_view scenario_note;  //!< for derived fields: which key sets it
  //! The member as a double (enumerations and integers convert exactly). Null for wheelbases.
  double (*get)(const ControllerParameters&) noexcept = nullptr;
  //! Sets the member; a field that switches its group sets `enabled` too.
  void (*set)(ControllerParameters&, double) noexcept = nullptr;
};

//! Every field, in the order of the docs' table and of validate()'s per-field checks.
std::span<const ParameterField> controller_parameter_fields() noexcept;
//! The row named `name` (flat name, e.g. "k_rob" or "governor.margin"), or nullptr.
const ParameterField* find_parameter_field(std::string_view name) noexcept;

//! Name of an optional group's switch ("delay_compensation.enabled"), "" for none.
std::string_view group_switch_name(ParameterGroup group) noexcept;
bool group_enabled(const ControllerParameters& p, ParameterGroup group) noexcept;

//! The default as the docs show it: "0.3", "+inf", "true", "global", "2.5, 1.0, ...".
std::string field_default_text(const ParameterField& field);
//! The value of `field` in `p` as text (choice names, true/false).
std::string field_value_text(const ParameterField& field, const ControllerParameters& p);
//! Whether validate() checks the field's range on its own (not booleans, not unbounded fields).
bool field_has_rule(const ParameterField& field) noexcept;
//! The rule as validate() states it, derived from the range and unit, then the reason:
//! "must be in [0, 1) (eq. sigma divides by 1 - k_rob)", "must be 0 (off) or in [1, 1000] m".
//! "" for a field without a rule of its own.
std::string field_rule_text(const ParameterField& field);
//! The docs' parameter table (Markdown), generated from the field table.
std::string parameter_table_markdown();

}  // namespace smoothsteer
