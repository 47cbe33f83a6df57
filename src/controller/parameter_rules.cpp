// The rule text of each row of the field table, derived from the row's range: the range is
// stated once, in the table, and validate(), the docs' table and Python all print this text.

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "smoothsteer/controller/parameter_fields.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {
namespace {

std::string bound_text(double value) {
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
    return with_unit(std::string("in ") + (range.min_open ? "(" : "[") + bound_text(range.min) +
                         ", " + bound_text(range.max) + (range.max_open ? ")" : "]"),
                     unit);
  }
  if (has_min) {
    const std::string comparison = (range.min_open ? "> " : ">= ") + bound_text(range.min);
    return with_unit(range.max_open ? "finite and " + comparison : comparison, unit);
  }
  const std::string comparison = (range.max_open ? "< " : "<= ") + bound_text(range.max);
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
    for (double v = range.min; v <= range.max; v += 1.0) items.push_back(bound_text(v));
    return listing(items);
  }
  if (std::isnan(range.off)) return interval_text(range, field.unit);
  // An off value at an open end of the interval closes it: [0, 1] s rather than "0 or (0, 1]".
  if ((range.off == range.min && range.min_open) || (range.off == range.max && range.max_open)) {
    return interval_text(range.hull(), field.unit);
  }
  return bound_text(range.off) + " (off) or " + interval_text(range, field.unit);
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

}  // namespace smoothsteer
