// Example 5: delay compensation. The 15 m/s lane change with 50 ms of dead time in front of the
// steering actuator, once without the controller's delay compensation (no Smith predictor) and
// once with it: the file's derived_compensation takes the actuator block's dead time into the
// Smith predictor's delay, with the low-pass's group delay and the tires' lag over speed.
#include <smoothsteer/runner/scenario.hpp>

#include <cstdio>
#include <string>
#include <vector>

int main() {
  using namespace smoothsteer;
  const std::string file = "scenarios/lane_change_15.yaml";
  const std::vector<std::pair<const char*, std::vector<std::string>>> variants = {
      {"without", {"controller.derived_compensation=false"}},
      {"with", {}},
  };
  for (const auto& [label, overrides] : variants) {
    std::vector<std::string> all = overrides;
    all.push_back("actuator.dead_time_s=0.05");
    const runner::Scenario scenario = runner::load_scenario(file, all);
    const runner::RunResult run = runner::run_scenario(scenario);
    std::printf("dead time 50 ms, %-7s delay compensation: max |e| %.3f m, stop: %s\n", label,
                run.metrics.max_abs_rear_error_m, run.simulation.stop_reason.c_str());
  }
  return 0;
}
