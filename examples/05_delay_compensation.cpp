// Example 5: delay compensation. The 15 m/s lane change with 50 ms of dead time in front of the
// steering actuator, once without and once with the controller's delay compensation
// (ControllerParameters::actuator_delay_s, a Smith predictor on the kinematic model).
#include <smoothsteer/runner/scenario.hpp>

#include <cstdio>
#include <string>

int main() {
  using namespace smoothsteer;
  const std::string file = "scenarios/lane_change_15.yaml";
  for (const char* delay : {"0", "0.05"}) {
    const runner::Scenario scenario = runner::load_scenario(
        file, {"actuator.dead_time_s=0.05", std::string("controller.actuator_delay_s=") + delay});
    const runner::RunResult run = runner::run_scenario(scenario);
    std::printf("dead time 50 ms, actuator_delay_s = %-4s s: max |e| %.3f m, stop: %s\n", delay,
                run.metrics.max_abs_rear_error_m, run.simulation.stop_reason.c_str());
  }
  return 0;
}
