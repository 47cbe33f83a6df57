// The engagement family (engagement_study.hpp): cases, runs and the lower bound of each case.

#include "smoothsteer/evaluation/engagement_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "scenario_setup.hpp"
#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/baselines/parameter_checks.hpp"
#include "smoothsteer/evaluation/certified_route.hpp"
#include "smoothsteer/evaluation/tuning_rule.hpp"
#include "smoothsteer/runner/sweep.hpp"

namespace smoothsteer {

double bound_speed_mps(const SpeedProfile& speed) noexcept {
  constexpr double moving_mps = 0.1;
  double slowest = HUGE_VAL;
  auto consider = [&](double v) {
    if (std::abs(v) >= moving_mps) slowest = std::min(slowest, std::abs(v));
  };
  if (speed.knots) {
    for (const SpeedKnot& knot : *speed.knots) consider(knot.speed_mps);
  } else {
    consider(speed.initial_speed_mps);
    if (speed.acceleration_mps2 > 0.0) consider(speed.final_speed_mps);
  }
  return std::isfinite(slowest) ? slowest : speed.initial_speed_mps;
}

EngagementBoundProblem engagement_bound_problem(const runner::Scenario& scenario,
                                                double time_step_s) {
  EngagementBoundProblem problem;
  problem.path = scenario.path;
  problem.speed_mps = bound_speed_mps(scenario.speed);
  problem.wheelbase_m = scenario.vehicle.wheelbase_m();
  problem.steering_angle_bound_rad = scenario.vehicle.max_steering_angle_rad;
  problem.steering_rate_bound_radps = scenario.vehicle.max_steering_rate_radps;
  problem.steering_acceleration_bound_radps2 = scenario.vehicle.max_steering_acceleration_radps2;
  problem.start = scenario.start;
  problem.time_step_s = time_step_s;
  problem.duration_s = scenario.simulation.duration_s;
  if (!scenario.path->is_closed()) {
    // Beyond its end an open path runs straight on: the shorter horizon can only lower the bound.
    const double s0 = engagement_start(problem).arc_length_m;
    const double remaining = (scenario.path->length() - s0) / problem.speed_mps;
    if (remaining > 10.0 * time_step_s)
      problem.duration_s = std::min(problem.duration_s, remaining);
  }
  return problem;
}

double rear_reaching_distance(const std::vector<TraceSample>& trace, double threshold_m) {
  if (trace.empty()) return -1.0;
  std::size_t first = 0;  // one past the last row at or above the threshold
  for (std::size_t k = 0; k < trace.size(); ++k) {
    if (!(std::abs(trace[k].lateral_error_m) < threshold_m)) first = k + 1;
  }
  if (first == trace.size()) return -1.0;
  return trace[first].distance_m - trace.front().distance_m;
}

void EngagementStudyOptions::validate() const {
  const char* owner = "EngagementStudyOptions";
  detail::require(!scenario_files.empty(), owner, "scenario_files", 0.0, "must not be empty");
  detail::require(!offsets_m.empty(), owner, "offsets_m", 0.0, "must not be empty");
  detail::require(!headings_rad.empty(), owner, "headings_rad", 0.0, "must not be empty");
  for (double offset : offsets_m) {
    detail::require(std::isfinite(offset) && std::abs(offset) <= 10.0, owner, "offsets_m", offset,
                    "must hold finite values in [-10, 10]");
  }
  for (double heading : headings_rad) {
    detail::require(std::isfinite(heading) && std::abs(heading) < 1.0, owner, "headings_rad",
                    heading, "must hold finite values in (-1, 1)");
  }
  const auto& known = comparison_controller_names();
  for (const std::string& name : baselines) {
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      throw std::invalid_argument("EngagementStudyOptions: baselines contains '" + name +
                                  "', which is not a comparison controller");
    }
  }
  detail::require(positive_finite(bound_time_step_s) && bound_time_step_s <= 0.05, owner,
                  "bound_time_step_s", bound_time_step_s, "must be in (0, 0.05]");
  detail::require(positive_finite(reaching_threshold_m), owner, "reaching_threshold_m",
                  reaching_threshold_m, "must be finite and > 0");
  detail::require(positive_finite(divergence_m), owner, "divergence_m", divergence_m,
                  "must be finite and > 0");
  detail::require(threads >= 1 && threads <= 256, owner, "threads", threads, "must be in [1, 256]");
}

namespace {

EngagementRun score_run(const std::string& name, const runner::RunResult& run,
                        const EngagementStudyOptions& options) {
  EngagementRun result;
  result.controller = name;
  const Metrics& m = run.metrics;
  result.max_abs_e_m = m.max_abs_rear_error_m;
  result.reaching_distance_m =
      rear_reaching_distance(run.simulation.trace, options.reaching_threshold_m);
  result.held_above_limits = static_cast<long>(m.angle_violations) + m.held_rate_violations +
                             m.held_acceleration_violations;
  result.diverged = !std::isfinite(m.max_abs_rear_error_m) ||
                    m.max_abs_rear_error_m > options.divergence_m || m.non_finite_values > 0 ||
                    run.simulation.non_finite || run.simulation.status != Status::ok;
  result.note = run.simulation.stop_reason;
  return result;
}

EngagementRun failed_run(const std::string& name, const std::string& error) {
  EngagementRun result;
  result.controller = name;
  result.max_abs_e_m = HUGE_VAL;
  result.diverged = true;
  result.note = error;
  return result;
}

}  // namespace

std::vector<std::string> engagement_case_overrides(const EngagementCase& c) {
  std::vector<std::string> overrides{"start.y_m=" + ResultsTable::number(c.offset_m, 6),
                                     "start.heading_rad=" + ResultsTable::number(c.heading_rad, 6)};
  if (c.speed_overridden) {
    overrides.push_back("speed.initial_mps=" + ResultsTable::number(c.speed_mps, 6));
  }
  return overrides;
}

void run_engagement_case(const std::string& file, const EngagementStudyOptions& options,
                         EngagementCase& out) {
  runner::Scenario scenario;
  try {
    scenario = runner::load_scenario(file, engagement_case_overrides(out));
  } catch (const std::exception& error) {
    // Every row stays in the table, marked failed.
    out.certified = failed_run("scenario", error.what());
    for (const std::string& name : options.baselines) {
      out.baselines.push_back(failed_run(name, error.what()));
    }
    out.bound = failed_run("lower_bound", error.what());
    return;
  }
  const std::string certified_name =
      "scenario (" + scenario.controller["type"].as<std::string>() + ")";
  try {
    out.certified = score_run(certified_name, runner::run_scenario(scenario), options);
  } catch (const std::exception& error) {
    out.certified = failed_run(certified_name, error.what());
  }
  for (const std::string& name : options.baselines) {
    try {
      // The lane-change comparison's construction: the limits the simulated actuator enforces.
      auto controller = make_comparison_controller(name, detail::comparison_setup_for(scenario));
      out.baselines.push_back(
          score_run(name, runner::run_scenario(scenario, *controller), options));
    } catch (const std::exception& error) {
      out.baselines.push_back(failed_run(name, error.what()));
    }
  }
  out.bound.controller = "lower_bound";
  out.bound.reaching_distance_m = std::nan("");
  if (scenario.plan) {
    // The transcription drives one way on one path; a change of gear is outside it.
    out.bound.max_abs_e_m = std::nan("");
    out.bound.note = "no bound: the path changes gear";
    return;
  }
  try {
    const EngagementBoundProblem problem =
        engagement_bound_problem(scenario, options.bound_time_step_s);
    const EngagementBound bound = solve_engagement_bound(problem);
    out.bound_converged = bound.converged;
    out.bound_solve_time_s = bound.solve_time_s;
    out.bound.max_abs_e_m = bound.max_abs_lateral_error_m;
    out.bound.diverged = !bound.converged;
    out.bound_check = resimulate_engagement_bound(problem, bound);
    out.bound.note = bound.solver_status + " resimulated=" +
                     ResultsTable::number(out.bound_check.max_abs_lateral_error_m, 4);
  } catch (const std::exception& error) {
    out.bound = failed_run("lower_bound", error.what());
  }
}

std::vector<std::string> default_study_baselines() {
  std::vector<std::string> names;
  for (const std::string& name : study_controller_names()) {
    if (name != certified_controller_name) names.push_back(name);
  }
  return names;
}

std::size_t EngagementCase::best_baseline() const noexcept {
  std::size_t best = 0;
  for (std::size_t i = 1; i < baselines.size(); ++i) {
    if (baselines[i].max_abs_e_m < baselines[best].max_abs_e_m) best = i;
  }
  return best;
}

double EngagementCase::ratio_to_best_baseline() const noexcept {
  if (baselines.empty()) return std::nan("");
  return certified.max_abs_e_m / baselines[best_baseline()].max_abs_e_m;
}

double EngagementCase::ratio_to_bound() const noexcept {
  return certified.max_abs_e_m / bound.max_abs_e_m;
}

EngagementStudyResult run_engagement_study(const EngagementStudyOptions& input) {
  EngagementStudyOptions options = input;
  if (options.baselines.empty()) options.baselines = default_study_baselines();
  options.validate();
  const auto begin = std::chrono::steady_clock::now();
  EngagementStudyResult result;
  result.options = options;
  std::vector<std::size_t> scenario_of_case;
  for (std::size_t f = 0; f < options.scenario_files.size(); ++f) {
    const runner::Scenario scenario = runner::load_scenario(options.scenario_files[f]);
    for (double offset : options.offsets_m) {
      for (double heading : options.headings_rad) {
        EngagementCase c;
        c.scenario = scenario.name;
        c.speed_mps = scenario.speed.initial_speed_mps;
        c.offset_m = offset;
        c.heading_rad = heading;
        result.cases.push_back(std::move(c));
        scenario_of_case.push_back(f);
      }
    }
  }
  runner::run_parallel(result.cases.size(), options.threads, [&](std::size_t i) {
    run_engagement_case(options.scenario_files[scenario_of_case[i]], options, result.cases[i]);
  });
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  return result;
}

}  // namespace smoothsteer
