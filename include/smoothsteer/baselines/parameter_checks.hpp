#pragma once
//! \file parameter_checks.hpp
//! Set-up-time checks shared by the comparison controllers and the evaluation module: every
//! message has the form "<owner>: <field> = <value> <rule>".

#include <cmath>
#include <string>

#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer::detail {

//! Throws std::invalid_argument "<owner>: <field> = <value> <rule>" (validation.hpp) unless `ok`;
//! for set-up checks outside a parameter struct's first_violation().
inline void require(bool ok, const char* owner, const char* field, double value,
                    const std::string& rule) {
  if (!ok) throw_if_violated(Violation{owner, "", field, value, rule.c_str()});
}

//! The parameters of the extended system x_ext (eq. x_ext) with C1 and C2, shared by HOSM and the
//! optimal reaching problem: lambda > 0, delta-bar in (0, pi/2), delta-bar' > 0.
inline void require_x_ext_limits(RuleChecker& check, double wheelbase_m,
                                 double steering_angle_bound_rad,
                                 double steering_rate_bound_per_m) noexcept {
  check.require_positive({{"wheelbase_m", wheelbase_m}});
  check.require(positive_finite(steering_angle_bound_rad) && steering_angle_bound_rad < pi / 2.0,
                "steering_angle_bound_rad", steering_angle_bound_rad, "must be in (0, pi/2)");
  check.require_positive({{"steering_rate_bound_per_m", steering_rate_bound_per_m}});
}

}  // namespace smoothsteer::detail
