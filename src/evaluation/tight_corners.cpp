// Tight corners (tight_corners.hpp): the engagement family's runs, started on the path, on the
// corners where the car's steering is asked the most, and the kinetic reference of each.

#include "smoothsteer/evaluation/tight_corners.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "smoothsteer/baselines/parameter_checks.hpp"
#include "smoothsteer/runner/sweep.hpp"

namespace smoothsteer {

namespace {

constexpr double bound_factor = 1.5;  // the target: certified <= 1.5x the reference
// Below this the reference is the transcription's own error (its re-simulation on the 0.04 s
// grid differs by up to 8 mm on the shipped corners): a ratio to it says nothing.
constexpr double resolved_reference_m = 0.01;

EngagementStudyOptions case_options(const TightCornerOptions& options) {
  EngagementStudyOptions study;
  for (const TightCorner& corner : options.corners) study.scenario_files.push_back(corner.file);
  study.offsets_m = {0.0};
  study.headings_rad = {0.0};
  study.baselines = options.baselines;
  study.bound_time_step_s = options.bound_time_step_s;
  study.threads = options.threads;
  return study;
}

//! The kinetic reference of a corner: the engagement bound's path, start, speed and horizon.
//! On its own grid (0.02 s, the control period), not the kinematic one's.
void solve_kinetic_case(const TightCorner& corner, const EngagementCase& c, EngagementRun& run,
                        KineticReferenceCheck& check) {
  run.controller = "kinetic_reference";
  run.reaching_distance_m = std::nan("");
  run.max_abs_e_m = std::nan("");
  try {
    const runner::Scenario scenario =
        runner::load_scenario(corner.file, engagement_case_overrides(c));
    if (scenario.plan) {
      run.note = "no reference: the path changes gear";
      return;
    }
    const EngagementBoundProblem bound = engagement_bound_problem(scenario);
    KineticReferenceProblem problem;
    problem.path = scenario.path;
    problem.vehicle = scenario.vehicle;
    problem.speed_mps = bound.speed_mps;
    problem.start_arc_length_m = engagement_start(bound).arc_length_m;
    problem.duration_s = bound.duration_s;
    const KineticReference reference = solve_kinetic_reference(problem);
    check = resimulate_kinetic_reference(problem, reference);
    run.max_abs_e_m = reference.max_abs_lateral_error_m;
    run.diverged = !reference.converged;
    run.note = reference.solver_status +
               " resimulated=" + ResultsTable::number(check.max_abs_lateral_error_m, 4);
  } catch (const std::exception& error) {
    run.diverged = true;
    run.note = error.what();
  }
}

}  // namespace

std::vector<TightCorner> shipped_tight_corners(const std::string& scenario_directory) {
  const std::string hairpin = scenario_directory + "/hairpin.yaml";
  const std::string roads = scenario_directory + "/roads/";
  return {{hairpin, 7.0},
          {hairpin, 0.0},
          {hairpin, 10.0},
          {roads + "urban_turn.yaml", 0.0},
          {roads + "mountain_hairpins.yaml", 0.0},
          {roads + "parking_lot.yaml", 0.0}};
}

void TightCornerOptions::validate() const {
  const char* owner = "TightCornerOptions";
  detail::require(!corners.empty(), owner, "corners", 0.0, "must not be empty");
  for (const TightCorner& corner : corners) {
    detail::require(
        std::isfinite(corner.speed_mps) && corner.speed_mps >= 0.0 && corner.speed_mps <= 100.0,
        owner, "corners.speed_mps", corner.speed_mps,
        "must be in [0, 100] (0: the file's own speed)");
  }
  // The rest as the engagement family checks it (baselines, grid, threads).
  case_options(*this).validate();
}

TightCornerResult run_tight_corner_study(const TightCornerOptions& input) {
  TightCornerResult result;
  result.options = input;
  if (result.options.baselines.empty()) result.options.baselines = default_study_baselines();
  const TightCornerOptions& options = result.options;
  options.validate();
  const auto begin = std::chrono::steady_clock::now();
  const EngagementStudyOptions study = case_options(options);
  for (const TightCorner& corner : options.corners) {
    const runner::Scenario scenario = runner::load_scenario(corner.file);
    EngagementCase c;
    c.scenario = scenario.name;
    c.speed_overridden = corner.speed_mps > 0.0;
    c.speed_mps = c.speed_overridden ? corner.speed_mps : scenario.speed.initial_speed_mps;
    SpeedProfile speed = scenario.speed;
    if (c.speed_overridden) speed.initial_speed_mps = c.speed_mps;
    result.bound_speeds_mps.push_back(bound_speed_mps(speed));
    result.cases.push_back(std::move(c));
  }
  result.kinetic_references.resize(result.cases.size());
  result.kinetic_checks.resize(result.cases.size());
  runner::run_parallel(result.cases.size(), options.threads, [&](std::size_t i) {
    run_engagement_case(options.corners[i].file, study, result.cases[i]);
    solve_kinetic_case(options.corners[i], result.cases[i], result.kinetic_references[i],
                       result.kinetic_checks[i]);
  });
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  return result;
}

ResultsTable TightCornerResult::table() const {
  ResultsTable table;
  table.title = "Tight corners: every controller";
  table.header = {"scenario",          "speed_mps", "controller", "max_abs_e_m",
                  "held_above_limits", "diverged",  "note"};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const EngagementCase& c = cases[i];
    auto add = [&](const EngagementRun& run, bool is_bound) {
      table.rows.push_back({c.scenario, ResultsTable::number(c.speed_mps, 2), run.controller,
                            ResultsTable::number(run.max_abs_e_m, 4),
                            is_bound ? "" : std::to_string(run.held_above_limits),
                            run.diverged ? "1" : "0", run.note});
    };
    add(c.certified, false);
    for (const EngagementRun& run : c.baselines) add(run, false);
    add(c.bound, true);
    add(kinetic_references[i], true);
  }
  return table;
}

ResultsTable TightCornerResult::summary() const {
  ResultsTable table;
  table.title = "Tight corners: the certified route against the best baseline and the references";
  table.header = {
      "scenario",         "speed_mps",       "reference_speed_mps",   "certified_m",
      "best_baseline",    "best_baseline_m", "kinematic_reference_m", "kinetic_reference_m",
      "to_best_baseline", "to_reference",    "at_most_best",          "within_1.5x_reference",
      "held_above_limits"};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const EngagementCase& c = cases[i];
    const EngagementRun& best = c.baselines[c.best_baseline()];
    long held = c.certified.held_above_limits;
    for (const EngagementRun& run : c.baselines) held += run.held_above_limits;
    // The larger of the two references: each is a lower estimate of what the plant allows.
    const double reference = std::max(c.bound.max_abs_e_m, kinetic_references[i].max_abs_e_m);
    const double to_bound =
        reference >= resolved_reference_m ? c.certified.max_abs_e_m / reference : std::nan("");
    table.rows.push_back({c.scenario, ResultsTable::number(c.speed_mps, 2),
                          ResultsTable::number(bound_speeds_mps[i], 2),
                          ResultsTable::number(c.certified.max_abs_e_m), best.controller,
                          ResultsTable::number(best.max_abs_e_m),
                          ResultsTable::number(c.bound.max_abs_e_m),
                          ResultsTable::number(kinetic_references[i].max_abs_e_m),
                          ResultsTable::number(c.ratio_to_best_baseline(), 2),
                          std::isnan(to_bound) ? "" : ResultsTable::number(to_bound, 2),
                          c.certified.max_abs_e_m <= best.max_abs_e_m ? "yes" : "no",
                          std::isnan(to_bound) ? "" : (to_bound <= bound_factor ? "yes" : "no"),
                          std::to_string(held)});
  }
  table.notes = {
      "max |e|: rear axle, whole run, each controller from the path at the file's start. "
      "Baselines: the lane-change comparison's construction, held to the car's angle, rate and "
      "acceleration limits. The references: the least max |e| any steering reaches under the "
      "same limits at the reference speed held constant, on the kinematic single track and on "
      "the linear kinetic single track (Ipopt, docs/corners.md); both leave out the tires' "
      "saturation and the actuator's lag. to_reference: certified / the larger reference, left "
      "blank where both are below 1 cm (the transcriptions' own resolution) and for the parking "
      "lot, which changes gear. held_above_limits: held-command samples above the car's limits, "
      "the certified route and every baseline together."};
  return table;
}

}  // namespace smoothsteer
