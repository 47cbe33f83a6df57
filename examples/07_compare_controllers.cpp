// Example 7: compare controllers on the 15 m/s lane change: the scenario's certified lead-wheel
// controller and every comparison controller (docs/baselines.md) on the same kinetic car and
// actuator. `smoothsteer compare lane-change` makes the full table (docs/results/).
#include <smoothsteer/baselines/comparison_controllers.hpp>
#include <smoothsteer/evaluation/controller_registration.hpp>
#include <smoothsteer/runner/scenario.hpp>

#include <cstdio>
#include <string>
#include <vector>

int main() {
  using namespace smoothsteer;
  register_comparison_controllers();         // scenario files may name them as controller types
  std::vector<std::string> controllers{""};  // "" = the scenario's own controller
  for (const std::string& name : comparison_controller_names()) controllers.push_back(name);
  std::printf("%-22s %12s %16s %14s\n", "controller", "max |e| [m]", "max rate [rad/s]",
              "rate > 0.4 [%]");
  for (const std::string& name : controllers) {
    std::vector<std::string> overrides;
    if (!name.empty())
      overrides.push_back("controller={type: " + name + ", nominal_speed_mps: 15}");
    const runner::Scenario scenario =
        runner::load_scenario("scenarios/lane_change_15.yaml", overrides);
    const runner::RunResult run = runner::run_scenario(scenario);
    const Metrics& m = run.metrics;
    std::printf("%-22s %12.3f %16.3f %14.1f\n", run.controller_name.c_str(), m.max_abs_rear_error_m,
                m.held_rate_max_radps, 100.0 * m.held_rate_violations / m.steps);
  }
  return 0;
}
