#pragma once
// The comparison set-up of a scenario (internal): its path and wheelbase, its speed as the
// nominal speed, and the limits the simulated actuator enforces, so that every controller of
// a comparison runs under the same C1 and C2. The MPC's steering model gets the actuator's lag:
// its dead time plus the low-pass's group delay 3 / (2 pi f_b), the value the shipped scenarios
// give the lead-wheel controller as actuator_delay_s (Autoware sets vehicle_model_steer_tau per
// vehicle; its default 0.3 s is for another steering system).

#include <numbers>

#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/io/scenario.hpp"

namespace smoothsteer::detail {

inline ComparisonSetup comparison_setup_for(const io::Scenario& scenario) {
  ComparisonSetup setup;
  setup.path = scenario.path;
  setup.wheelbase_m = scenario.vehicle.wheelbase_m();
  setup.nominal_speed_mps = scenario.speed.initial_speed_mps;
  setup.limits = {scenario.actuator.max_angle_rad, scenario.actuator.max_rate_radps};
  if (!scenario.actuator.ideal && scenario.actuator.bandwidth_hz > 0.0) {
    setup.mpc.steering_time_constant_s =
        scenario.actuator.dead_time_s +
        3.0 / (2.0 * std::numbers::pi * scenario.actuator.bandwidth_hz);
  }
  return setup;
}

}  // namespace smoothsteer::detail
