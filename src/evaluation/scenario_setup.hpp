#pragma once
// The comparison set-up of a scenario (internal): its path and wheelbase, its speed as the
// nominal speed, and the limits the simulated actuator enforces plus the car's steering
// acceleration limit, so that every controller of a comparison runs under the same C1, C2 and
// acceleration limit. The MPC's steering model gets a first-order lag of
// the dead time plus 3 / (2 pi f_b) (48 ms at 10 Hz). That is twice the three-pole low-pass's
// own group delay 3 / w_p (24 ms, w_p = ActuatorParameters::pole_radps) and equals the Smith
// delay the shipped scenarios give the lead-wheel controller (actuator_delay_s 0.048 s: the
// group delay plus the lag the feedforward leaves), so both model-based controllers get the same
// lag. The actuator's own 24 ms makes the tuned MPC worse (docs/baselines.md). Autoware sets
// vehicle_model_steer_tau per vehicle; its default 0.3 s is for another steering system.

#include <cmath>
#include <numbers>
#include <string>

#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/runner/scenario.hpp"

namespace smoothsteer::detail {

inline ComparisonSetup comparison_setup_for(const runner::Scenario& scenario) {
  ComparisonSetup setup;
  setup.path = scenario.path;
  setup.wheelbase_m = scenario.vehicle.wheelbase_m();
  setup.nominal_speed_mps = std::abs(scenario.speed.initial_speed_mps);  // < 0: reversing
  setup.limits = {scenario.actuator.max_angle_rad, scenario.actuator.max_rate_radps,
                  scenario.vehicle.max_steering_acceleration_radps2};
  if (!scenario.actuator.ideal && scenario.actuator.bandwidth_hz > 0.0) {
    setup.mpc.steering_time_constant_s =
        scenario.actuator.dead_time_s +
        3.0 / (2.0 * std::numbers::pi * scenario.actuator.bandwidth_hz);
  }
  return setup;
}

//! The name of a comparison's row for the scenario's own controller (its certified route).
inline constexpr const char* certified_controller = "certified";

//! Runs `scenario` with its own controller ("certified") or the named comparison controller, set
//! up by comparison_setup_for().
inline runner::RunResult run_with_controller(const runner::Scenario& scenario,
                                             const std::string& controller) {
  if (controller == certified_controller) return runner::run_scenario(scenario);
  auto baseline = make_comparison_controller(controller, comparison_setup_for(scenario));
  return runner::run_scenario(scenario, *baseline);
}

}  // namespace smoothsteer::detail
