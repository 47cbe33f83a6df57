#pragma once
//! \file value_range.hpp
//! The one range type of the library's settings: the field table of ControllerParameters
//! (controller/parameter_fields.hpp) and the scenario reader (io/config_section.hpp) state their
//! ranges in it, so that a range written in one reads the same in the other.

#include <limits>

namespace smoothsteer {

//! Values a number accepts: [min, max] with open ends as flagged. A closed infinite end admits
//! that infinity (feedforward_curvature_rate = +inf: no limit); NaN is never in range. A
//! scenario file's numbers must be finite as well (io::ConfigSection checks that first).
struct ValueRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;
  bool max_open = false;

  //! (0, +inf]
  static constexpr ValueRange positive() noexcept {
    return {0.0, std::numeric_limits<double>::infinity(), true, false};
  }
  //! [0, +inf]
  static constexpr ValueRange non_negative() noexcept {
    return {0.0, std::numeric_limits<double>::infinity(), false, false};
  }
  constexpr bool contains(double value) const noexcept {
    if (value != value) return false;  // NaN
    const bool above = min_open ? value > min : value >= min;
    const bool below = max_open ? value < max : value <= max;
    return above && below;
  }
};

}  // namespace smoothsteer
