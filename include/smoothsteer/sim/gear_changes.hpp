#pragma once
//! \file gear_changes.hpp
//! Where a signed speed profile (SpeedProfile::signed_speeds) changes the direction of travel:
//! it comes to rest (a knot at 0 m/s), stays there, and moves off with the other sign. The
//! closed loop on a PathPlan (simulation.hpp) hands the next piece to the controller at the
//! first control instant of each rest.

#include <vector>

#include "smoothsteer/path/path_plan.hpp"
#include "smoothsteer/sim/speed_profile.hpp"

namespace smoothsteer {

struct GearChange {
  double stop_time_s = 0.0;    //!< the first knot at 0 m/s before the sign changes [s]
  double resume_time_s = 0.0;  //!< the last knot at 0 m/s before the sign changes [s]
};

//! The gear changes of a tabulated profile, in time order (empty for a ramp or an unsigned
//! profile). Throws std::invalid_argument naming the knot if the speed changes sign between two
//! knots without a knot at rest.
std::vector<GearChange> gear_changes(const SpeedProfile& speed);

//! Checks that `speed` drives `plan`: signed knots, the first moving knot with the first piece's
//! gear, one gear change per cusp, every cusp between pieces of opposite gears, and each rest at
//! least `control_period_s` long (so that a control instant falls inside it). Throws
//! std::invalid_argument naming the field and the rule.
void check_gear_changes(const PathPlan& plan, const SpeedProfile& speed, double control_period_s);

}  // namespace smoothsteer
