// One configuration of one study controller on one scenario (tuning_rule.hpp): the run, its
// metrics (sim/metrics.hpp, the held_* and actual_* figures of docs/metrics.md), the clamps of
// the saturation, and the wall-clock cost per update for the timings table.

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "scenario_setup.hpp"
#include "smoothsteer/evaluation/certified_route.hpp"
#include "smoothsteer/evaluation/tuning_rule.hpp"
#include "timed_controller.hpp"

namespace smoothsteer {

long ScenarioScore::held_above_limits() const noexcept {
  return static_cast<long>(metrics.angle_violations) + metrics.held_rate_violations +
         metrics.held_acceleration_violations;
}

long ScenarioScore::actual_above_limits() const noexcept {
  return static_cast<long>(metrics.actual_rate_violations) + metrics.actual_acceleration_violations;
}

bool ScenarioScore::admissible() const noexcept {
  return !infeasible && !diverged && held_above_limits() == 0;
}

ScenarioScore score_configuration(const runner::Scenario& scenario, const std::string& controller,
                                  const std::vector<std::pair<std::string, double>>& gains,
                                  double divergence_m) {
  ScenarioScore result;
  result.scenario = scenario.name;
  const ComparisonSetup setup_template = detail::comparison_setup_for(scenario);
  std::unique_ptr<SaturatedController> saturated;
  if (controller == certified_controller_name) {
    try {
      // The same saturation as every baseline: it must never clamp a certified command.
      saturated = std::make_unique<SaturatedController>(make_certified_controller(scenario, gains),
                                                        setup_template.limits, controller);
    } catch (const InfeasibleLimits&) {
      result.infeasible = true;
      result.diverged = true;
      result.metrics.max_abs_rear_error_m = HUGE_VAL;
      return result;
    }
  } else {
    ComparisonSetup setup = setup_template;
    for (const auto& [key, value] : gains) apply_gain(controller, key, value, setup);
    saturated = make_comparison_controller(controller, setup);
  }
  SaturatedController& limited = *saturated;
  detail::TimedController timed(std::move(saturated));
  const runner::RunResult run = runner::run_scenario(scenario, timed);
  const Metrics& m = run.metrics;
  result.metrics = m;
  result.clamped_updates = limited.saturation().limited;
  result.diverged = !std::isfinite(m.max_abs_rear_error_m) ||
                    m.max_abs_rear_error_m > divergence_m || m.non_finite_values > 0;
  result.updates = timed.updates();
  result.mean_update_us = timed.mean_us();
  result.max_update_us = timed.max_us();
  return result;
}

}  // namespace smoothsteer
