#pragma once
// The comparison set-up of a scenario (internal): its path and wheelbase, its speed as the
// nominal speed, and the limits the simulated actuator enforces, so that every controller of
// a comparison runs under the same C1 and C2.

#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/io/scenario.hpp"

namespace smoothsteer::detail {

inline ComparisonSetup comparison_setup_for(const io::Scenario& scenario) {
  ComparisonSetup setup;
  setup.path = scenario.path;
  setup.wheelbase_m = scenario.vehicle.wheelbase_m();
  setup.nominal_speed_mps = scenario.speed.initial_speed_mps;
  setup.limits = {scenario.actuator.max_angle_rad, scenario.actuator.max_rate_radps};
  return setup;
}

}  // namespace smoothsteer::detail
