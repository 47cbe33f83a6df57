#pragma once
//! \file validation.hpp
//! One validation shape for every parameter struct (one message formatter instead of a copy per
//! struct): the struct states its rules once, in `first_violation() noexcept`, which returns the
//! first rule broken as a Violation (plain data, no allocation), and offers
//!   bool is_valid() const noexcept;          // real-time use: no allocation, no throw
//!   std::string validation_error() const;     // "" when valid, else the message
//!   void validate() const;                    // throws std::invalid_argument(message)
//! (the three written inline on first_violation(), which checks its rules with RuleChecker).
//! The message is always "<Struct>: <field> = <value> <rule>", values printed exactly
//! (shortest round-trip form: 0.0200001 stays 0.0200001).

#include <charconv>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace smoothsteer {

struct Violation {
  const char* owner = "";   //!< the struct, e.g. "VehicleParameters"
  const char* prefix = "";  //!< a nested struct's field, e.g. "front_tire.", or ""
  const char* field = "";
  double value = 0.0;
  const char* rule = "";  //!< e.g. "must be finite and > 0"
  //! A number the rule refers to, appended after it (NaN: none).
  double reference = std::numeric_limits<double>::quiet_NaN();
};

//! Shortest text that reads back as exactly `value`.
inline std::string exact_number(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

//! "<owner>: <prefix><field> = <value> <rule>[ <reference>]".
inline std::string describe(const Violation& v) {
  // Appended piece by piece: GCC 12 reports a false -Wrestrict on chains of operator+.
  std::string message(v.owner);
  message.append(": ").append(v.prefix).append(v.field).append(" = ");
  message.append(exact_number(v.value)).append(" ").append(v.rule);
  if (!std::isnan(v.reference)) message.append(" ").append(exact_number(v.reference));
  return message;
}

inline std::string describe(const std::optional<Violation>& v) {
  return v ? describe(*v) : std::string();
}

inline void throw_if_violated(const std::optional<Violation>& v) {
  if (v) throw std::invalid_argument(describe(*v));
}

inline bool positive_finite(double value) noexcept {
  return std::isfinite(value) && value > 0.0;
}
inline bool non_negative_finite(double value) noexcept {
  return std::isfinite(value) && value >= 0.0;
}

//! The shared helper behind every first_violation(): checks the rules in order and keeps the
//! first one broken. noexcept and allocation free, so is_valid() can run in real time.
class RuleChecker {
 public:
  explicit RuleChecker(const char* owner) noexcept : owner_(owner) {}
  //! Records "<field> = <value> <rule>[ <reference>]" unless `ok` or a rule failed before.
  void require(bool ok, const char* field, double value, const char* rule,
               double reference = std::numeric_limits<double>::quiet_NaN()) noexcept {
    if (!ok && !first_) first_ = Violation{owner_, "", field, value, rule, reference};
  }
  //! A field's name and value, for the rules that name a list of fields.
  struct Field {
    const char* name;
    double value;
  };
  //! The two rules most fields follow, each message stated once here; the fields are checked
  //! in the order given.
  void require_positive(std::initializer_list<Field> fields) noexcept {
    for (const Field& f : fields) {
      require(positive_finite(f.value), f.name, f.value, "must be finite and > 0");
    }
  }
  void require_non_negative(std::initializer_list<Field> fields) noexcept {
    for (const Field& f : fields) {
      require(non_negative_finite(f.value), f.name, f.value, "must be finite and >= 0");
    }
  }
  //! A nested struct's first violation, with its own owner.
  void include(const std::optional<Violation>& nested) noexcept {
    if (nested && !first_) first_ = nested;
  }
  //! A member struct's first violation, named as this owner's field `<prefix><field>` (e.g.
  //! "SteeringSystemParameters: observer.mass_kg = ...").
  void include_member(std::optional<Violation> nested, const char* prefix) noexcept {
    if (nested) {
      nested->owner = owner_;
      nested->prefix = prefix;
    }
    include(nested);
  }
  const std::optional<Violation>& first() const noexcept { return first_; }

 private:
  const char* owner_;
  std::optional<Violation> first_;
};

}  // namespace smoothsteer
