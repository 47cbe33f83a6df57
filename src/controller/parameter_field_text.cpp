// The field table as text. The rule of each row is derived from the row's range: the range is
// stated once, in the table, and validate(), the docs' table and Python all print this text. A
// field's value and default read as the docs show them, and the docs' parameter table
// (docs/controller.md) is generated from the rows.

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "smoothsteer/controller/parameter_fields.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {
namespace {

//! "+inf", "pi/2", "0.3": a bound or a value as the rules and the docs' table print it.
std::string number_text(double value) {
  if (std::isinf(value)) return value > 0 ? "+inf" : "-inf";
  if (value == std::numbers::pi / 2.0) return "pi/2";
  return exact_number(value);
}

std::string with_unit(std::string text, std::string_view unit) {
  if (!unit.empty()) text.append(" ").append(unit);
  return text;
}

//! "a, b or c".
std::string listing(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t k = 0; k < items.size(); ++k) {
    if (k > 0) text += k + 1 == items.size() ? " or " : ", ";
    text += items[k];
  }
  return text;
}

//! "in [0, 1)", "finite and > 0", ">= 0": the interval as the rule states it.
std::string interval_text(const ValueRange& range, std::string_view unit) {
  const bool has_min = std::isfinite(range.min), has_max = std::isfinite(range.max);
  if (has_min && has_max) {
    return with_unit(std::string("in ") + (range.min_open ? "(" : "[") + number_text(range.min) +
                         ", " + number_text(range.max) + (range.max_open ? ")" : "]"),
                     unit);
  }
  if (has_min) {
    const std::string comparison = (range.min_open ? "> " : ">= ") + number_text(range.min);
    return with_unit(range.max_open ? "finite and " + comparison : comparison, unit);
  }
  const std::string comparison = (range.max_open ? "< " : "<= ") + number_text(range.max);
  return with_unit(range.min_open ? "finite and " + comparison : comparison, unit);
}

std::string values_text(const ParameterField& field) {
  const FieldRange& range = field.range;
  if (field.kind == FieldKind::choice) {
    std::istringstream words{std::string(field.choices)};
    std::vector<std::string> items;
    std::string name;
    for (int k = 0; words >> name; ++k) items.push_back(std::to_string(k) + " (" + name + ")");
    return listing(items);
  }
  if (field.kind == FieldKind::integer && !range.min_open && !range.max_open &&
      range.max - range.min <= 2.0) {
    std::vector<std::string> items;
    for (double v = range.min; v <= range.max; v += 1.0) items.push_back(number_text(v));
    return listing(items);
  }
  if (std::isnan(range.off)) return interval_text(range, field.unit);
  // An off value at an open end of the interval closes it: [0, 1] s rather than "0 or (0, 1]".
  if ((range.off == range.min && range.min_open) || (range.off == range.max && range.max_open)) {
    return interval_text(range.hull(), field.unit);
  }
  return number_text(range.off) + " (off) or " + interval_text(range, field.unit);
}

}  // namespace

bool field_has_rule(const ParameterField& field) noexcept {
  return field.kind != FieldKind::boolean &&
         (std::isfinite(field.range.min) || std::isfinite(field.range.max));
}

std::string field_rule_text(const ParameterField& field) {
  if (!field_has_rule(field)) return "";
  return "must be " + values_text(field) + std::string(field.rule_reason);
}

std::string field_value_text(const ParameterField& field, const ControllerParameters& p) {
  if (field.kind == FieldKind::wheelbases) {
    std::string text;
    for (int i = 0; i < 3; ++i) {
      text += number_text(p.chain.wheelbases_m[static_cast<std::size_t>(i)]) + ", ";
    }
    return text + "...";
  }
  const double value = field.get(p);
  if (field.kind == FieldKind::boolean) return value != 0.0 ? "true" : "false";
  if (field.kind == FieldKind::choice) {
    std::istringstream names{std::string(field.choices)};
    std::string name;
    for (int k = 0; names >> name; ++k) {
      if (k == static_cast<int>(value)) return name;
    }
    return exact_number(value);
  }
  return number_text(value);
}

std::string field_default_text(const ParameterField& field) {
  return field_value_text(field, ControllerParameters{});
}

std::string parameter_table_markdown() {
  std::string table =
      "| field (scenario key, Python keyword) | member | default | unit | meaning | rule "
      "(checked by `validate()`) |\n|---|---|---|---|---|---|\n";
  auto escape = [](std::string_view text) {
    std::string out;
    for (const char c : text) {
      if (c == '|') out += '\\';
      out += c;
    }
    return out;
  };
  for (const ParameterField& field : controller_parameter_fields()) {
    std::string doc = escape(field.doc);
    if (field.scenario == ScenarioKey::derived) {
      doc += " (scenario files: " + std::string(field.scenario_note) + ")";
    }
    table += "| `" + std::string(field.name) + "` | `" + std::string(field.member) + "` | " +
             field_default_text(field) + " | " + std::string(field.unit) + " | " + doc + " | " +
             escape(field_rule_text(field)) + " |\n";
  }
  return table;
}

}  // namespace smoothsteer
