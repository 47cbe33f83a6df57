// `smoothsteer compare <benchmark>`: runs one comparison benchmark (docs/baselines.md) and writes
// its table as CSV and Markdown into --out (default compare_out/, untracked). The committed tables
// in docs/results/ come from `--out docs/results` (docs/results/README.md); they are the same on
// every rerun, since wall-clock times go to a separate *_timings file, which is not committed.
//   roc           Tab. roc_vx: optimal (Ipopt) vs proposed (n = 1) vs HOSM reaching distance
//   lane-change   every controller on scenarios/lane_change_{10,15,19}.yaml
//   parameters    circle_sections_paper.yaml with the four settings of Sec. IV-A
//   tuning        every controller tuned by one rule on training scenarios, reported held-out
//                 (the study of docs/baselines.md; scenario NAME@V: NAME at V m/s)
//   engagement    the lane changes started off the path: certified vs baselines vs the
//                 optimal-control lower bound (docs/engagement.md)
//   road-suite    every controller on the road suite x the three cars x both plants
//                 (docs/results/road_suite.md; with --stack-period, as a driving stack drives
//                 it: docs/results/road_suite_stack.md)
//   robustness    every controller under a car's imperfections, acting on the plant only
//                 (docs/results/robustness.md)
//   corners       the tight corners where the steering rate binds: certified vs baselines vs
//                 the optimal-control reference (docs/corners.md)
// --plant dynamic|double_track sets the plant of the reported runs (lane-change, the tuning
// study's held-out scenarios; the training keeps its scenarios' plant: the held-out plant).
// Options of `compare` work before or after the sub-command (`compare parameters -o DIR`).

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.hpp"
#include "progress_reporter.hpp"
#include "smoothsteer/evaluation/engagement_study.hpp"
#include "smoothsteer/evaluation/paper_figures.hpp"
#include "smoothsteer/evaluation/reaching_benchmark.hpp"
#include "smoothsteer/evaluation/road_suite_comparison.hpp"
#include "smoothsteer/evaluation/robustness_comparison.hpp"
#include "smoothsteer/evaluation/scenario_comparison.hpp"
#include "smoothsteer/evaluation/tight_corners.hpp"
#include "smoothsteer/evaluation/tuning_rule.hpp"
#include "smoothsteer/io/atomic_output.hpp"
#include "worker_threads.hpp"

namespace smoothsteer::cli {

namespace {

struct CompareOptions {
  std::string output_directory = "compare_out";
  std::string scenario_directory = "scenarios";
  std::string paper_figures_file = "data/paper_figures.csv";
  double lateral_tolerance_m = 0.01;
  double heading_tolerance_rad = 0.01;
  int intervals = 150;
  int budget = 16;
  // The study (docs/baselines.md "Tuning rule"): chosen on the lane change at 12 and 17 m/s and
  // on the S-curve spline at 8 m/s, reported at the lane change's shipped speeds and on another
  // path (circle_sections).
  std::vector<std::string> training{"lane_change_15@12", "lane_change_15@17", "waypoints_s_curve"};
  std::vector<std::string> held_out{"lane_change_10", "lane_change_15", "lane_change_19",
                                    "circle_sections"};
  std::vector<std::string> controllers = study_controller_names();
  //! The plant of the reported runs: empty (each scenario's own model), dynamic, double_track.
  std::string plant;
  RoadSuiteOptions road_suite;   // road_files: roads/*.yaml and hairpin.yaml of --scenarios
  RobustnessOptions robustness;  // scenarios: from robustness_files
  //! `compare robustness --files`: FILE or FILE@T (max |e| from T s on; circle_sections starts
  //! off the path).
  std::vector<std::string> robustness_files{"lane_change_10.yaml", "lane_change_15.yaml",
                                            "lane_change_19.yaml", "circle_sections.yaml@8",
                                            "hairpin.yaml"};
  EngagementStudyOptions engagement;  // scenario_files: lane_change_{10,15,19} of --scenarios
  TightCornerOptions corners;         // corners: shipped_tight_corners() of --scenarios
  bool quiet = false;                 //!< --quiet: no progress on stderr
  int jobs = -1;  //!< -j: worker threads of the threaded benchmarks (0: all cores; -1: unset)
};

void emit(const ResultsTable& table, const CompareOptions& options, const std::string& stem) {
  table.write(options.output_directory, stem);
  std::printf("%s\nwritten: %s/%s.csv and .md\n", table.to_markdown().c_str(),
              options.output_directory.c_str(), stem.c_str());
}

//! NAME is scenarios/NAME.yaml; NAME@V the same file at the constant speed V m/s, named so.
//! The override of --plant (none without it).
std::vector<std::string> plant_overrides(const std::string& plant) {
  if (plant.empty()) return {};
  return {"model=" + plant};
}

std::vector<runner::Scenario> load_scenarios(const CompareOptions& options,
                                             const std::vector<std::string>& names,
                                             const std::string& plant = "") {
  std::vector<runner::Scenario> scenarios;
  for (const std::string& spec : names) {
    const std::size_t at = spec.find('@');
    const std::string file = options.scenario_directory + "/" + spec.substr(0, at) + ".yaml";
    std::vector<std::string> overrides = plant_overrides(plant);
    if (at == std::string::npos) {
      scenarios.push_back(runner::load_scenario(file, overrides));
      continue;
    }
    const std::string speed = spec.substr(at + 1);
    overrides.push_back("speed={initial_mps: " + speed + ", final_mps: " + speed + "}");
    runner::Scenario scenario = runner::load_scenario(file, overrides);
    scenario.name = spec;
    scenarios.push_back(std::move(scenario));
  }
  return scenarios;
}

PaperFigures paper_figures(const CompareOptions& options) {
  return options.paper_figures_file.empty() ? PaperFigures{}
                                            : PaperFigures::load(options.paper_figures_file);
}

void add_engagement_command(CLI::App& compare, const std::shared_ptr<CompareOptions>& options) {
  CLI::App* engagement = compare.add_subcommand(
      "engagement", "the lane changes started off the path, against the optimal lower bound");
  EngagementStudyOptions& defaults = options->engagement;
  engagement->add_option("--offsets", defaults.offsets_m, "start offsets start.y_m [m]")
      ->capture_default_str();
  engagement
      ->add_option("--headings", defaults.headings_rad, "heading errors start.heading_rad [rad]")
      ->capture_default_str();
  engagement->add_option("--baselines", defaults.baselines,
                         "baselines (default: the tuning study's)");
  engagement->add_option("--bound-step", defaults.bound_time_step_s, "lower bound's time grid [s]")
      ->capture_default_str()
      ->check(CLI::Range(1e-3, 0.05));
  engagement->add_option("--threads", defaults.threads, "worker threads")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  engagement->callback([options] {
    const LongCommand progress("engagement", options->quiet);
    EngagementStudyOptions study = options->engagement;
    study.threads = worker_threads(options->jobs, study.threads);
    study.scenario_files.clear();
    for (const char* speed : {"10", "15", "19"}) {
      study.scenario_files.push_back(options->scenario_directory + "/lane_change_" + speed +
                                     ".yaml");
    }
    const EngagementStudyResult result = run_engagement_study(study);
    const std::string summary = result.summary_markdown();
    std::filesystem::create_directories(options->output_directory);
    const std::string stem = options->output_directory + "/engagement";
    io::write_file_atomically(stem + ".csv", result.table().to_csv(), "--out");
    io::write_file_atomically(stem + ".md", summary, "--out");
    double solve_time = 0.0;
    for (const EngagementCase& c : result.cases) solve_time += c.bound_solve_time_s;
    std::printf(
        "%s\nwritten: %s.csv and .md\n%zu cases in %.1f s on %d threads (lower bounds: "
        "%.1f s of Ipopt)\n",
        summary.c_str(), stem.c_str(), result.cases.size(), result.wall_time_s, study.threads,
        solve_time);
  });
}

void add_road_suite_command(CLI::App& compare, const std::shared_ptr<CompareOptions>& options) {
  CLI::App* road = compare.add_subcommand(
      "road-suite", "every controller on the road suite x the three cars x both plants");
  RoadSuiteOptions& defaults = options->road_suite;
  defaults.vehicle_files = {"vehicles/ford_escort.yaml", "vehicles/bmw_320i.yaml",
                            "vehicles/vw_vanagon.yaml"};
  defaults.controllers = road_suite_controller_names();
  road->add_option("--roads", defaults.road_files,
                   "road scenario files (default: <scenarios>/roads/*.yaml and hairpin.yaml)");
  road->add_option("--vehicles", defaults.vehicle_files, "vehicle files")->capture_default_str();
  road->add_option("--plants", defaults.models, "plants (scenario models)")
      ->capture_default_str()
      ->check(CLI::IsMember({"dynamic", "double_track", "kinematic"}));
  road->add_option("--controllers", defaults.controllers,
                   "certified, steering_system and baseline names")
      ->capture_default_str();
  road->add_option("--stack-period", defaults.planner.period_s,
                   "stack mode: a planner window by set_path() every this many seconds (0: the "
                   "whole road; docs/simulation.md)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 10.0));
  road->add_option("--stack-behind", defaults.planner.behind_m, "window start behind the car [m]")
      ->capture_default_str();
  road->add_option("--stack-ahead", defaults.planner.ahead_m, "window end ahead of the car [m]")
      ->capture_default_str();
  road->add_option("--stack-spacing", defaults.planner.spacing_m, "waypoint spacing [m]")
      ->capture_default_str();
  road->add_option("--jitters", defaults.jitters_m,
                   "stack mode: Gaussian jitter std per waypoint coordinate [m], one set of runs "
                   "each")
      ->capture_default_str();
  road->add_option("--traces", defaults.trace_directory,
                   "write each run's trace here (scripts/road_suite_figures.py)");
  road->add_option("--threads", defaults.threads, "worker threads")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  road->callback([options] {
    const LongCommand progress("road suite", options->quiet);
    RoadSuiteOptions suite = options->road_suite;
    suite.threads = worker_threads(options->jobs, suite.threads);
    if (!options->plant.empty()) suite.models = {options->plant};
    if (suite.road_files.empty()) {
      const std::filesystem::path roads =
          std::filesystem::path(options->scenario_directory) / "roads";
      for (const auto& entry : std::filesystem::directory_iterator(roads)) {
        if (entry.path().extension() == ".yaml") suite.road_files.push_back(entry.path().string());
      }
      std::sort(suite.road_files.begin(), suite.road_files.end());
      suite.road_files.push_back(options->scenario_directory + "/hairpin.yaml");
    }
    const RoadSuiteResult result = run_road_suite_comparison(suite);
    const std::string stem = suite.planner.active() ? "road_suite_stack" : "road_suite";
    emit(result.runs, *options, stem);
    emit(result.summary, *options, stem + "_summary");
  });
}

//! "lane_change_15.yaml" or "circle_sections.yaml@8" (max |e| from 8 s on), in --files.
RobustnessScenario robustness_scenario(const std::string& entry, const std::string& directory) {
  RobustnessScenario scenario;
  const std::size_t at = entry.rfind('@');
  scenario.file = entry.substr(0, at);
  if (at != std::string::npos) {
    const std::string settle = entry.substr(at + 1);
    std::size_t used = 0;
    try {
      scenario.settle_time_s = std::stod(settle, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != settle.size()) {
      throw CLI::ValidationError("--scenarios", "'" + entry +
                                                    "': the part after '@' must be a settle "
                                                    "time in seconds, e.g. circle_sections.yaml@8");
    }
  }
  if (std::filesystem::path(scenario.file).is_relative() &&
      !std::filesystem::exists(scenario.file)) {
    scenario.file = (std::filesystem::path(directory) / scenario.file).string();
  }
  return scenario;
}

void add_robustness_command(CLI::App& compare, const std::shared_ptr<CompareOptions>& options) {
  CLI::App* robustness = compare.add_subcommand(
      "robustness", "every controller under a car's imperfections, acting on the plant only");
  RobustnessOptions& defaults = options->robustness;
  defaults.vehicle_files = {"vehicles/passenger_car.yaml"};
  defaults.controllers = road_suite_controller_names();
  robustness
      ->add_option(
          "--files", options->robustness_files,
          "scenario files (in --scenarios unless found as given); FILE@T: max |e| from T s on")
      ->capture_default_str();
  robustness->add_option("--vehicles", defaults.vehicle_files, "vehicle files")
      ->capture_default_str();
  robustness->add_option("--plants", defaults.models, "plants (scenario models)")
      ->capture_default_str()
      ->check(CLI::IsMember({"dynamic", "double_track"}));
  robustness->add_option("--controllers", defaults.controllers, "certified and baseline names")
      ->capture_default_str();
  robustness->add_option("--threads", defaults.threads, "worker threads")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  robustness->callback([options] {
    const LongCommand progress("robustness", options->quiet);
    RobustnessOptions study = options->robustness;
    study.threads = worker_threads(options->jobs, study.threads);
    if (!options->plant.empty()) study.models = {options->plant};
    for (const std::string& entry : options->robustness_files) {
      study.scenarios.push_back(robustness_scenario(entry, options->scenario_directory));
    }
    const RobustnessResult result = run_robustness_comparison(study);
    emit(result.runs, *options, "robustness");
    emit(result.summary, *options, "robustness_summary");
  });
}

void add_corners_command(CLI::App& compare, const std::shared_ptr<CompareOptions>& options) {
  CLI::App* corners = compare.add_subcommand(
      "corners", "the tight corners against the best baseline and the optimal-control reference");
  TightCornerOptions& defaults = options->corners;
  corners->add_option("--baselines", defaults.baselines, "baselines (default: the tuning study's)");
  corners->add_option("--bound-step", defaults.bound_time_step_s, "reference's time grid [s]")
      ->capture_default_str()
      ->check(CLI::Range(1e-3, 0.05));
  corners->add_option("--threads", defaults.threads, "worker threads")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  corners->callback([options] {
    const LongCommand progress("corners", options->quiet);
    TightCornerOptions study = options->corners;
    study.threads = worker_threads(options->jobs, study.threads);
    study.corners = shipped_tight_corners(options->scenario_directory);
    const TightCornerResult result = run_tight_corner_study(study);
    emit(result.table(), *options, "tight_corners");
    emit(result.summary(), *options, "tight_corners_summary");
  });
}

}  // namespace

void add_compare_command(CLI::App& app) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* compare = app.add_subcommand("compare", "run a comparison benchmark, write its table");
  compare->require_subcommand(1);
  // Sub-commands pass options they do not know to `compare`, so -o works after them too.
  compare->fallthrough();
  compare->add_option("-o,--out,--output", options->output_directory, "directory of the tables")
      ->capture_default_str();
  compare->add_option("--scenarios", options->scenario_directory, "directory of scenario files")
      ->capture_default_str();
  compare
      ->add_option("--plant", options->plant,
                   "plant of the reported runs: dynamic (single-track) or double_track; default: "
                   "each scenario's own")
      ->check(CLI::IsMember({"dynamic", "double_track", "kinematic"}));
  compare->add_flag("-q,--quiet", options->quiet, "no progress or summary line on stderr");
  compare
      ->add_option(
          "-j,--jobs", options->jobs,
          "worker threads of engagement, road-suite, robustness and corners (their --threads); 0: "
          "all cores; the other benchmarks run on one")
      ->check(CLI::Range(0, 256));
  compare
      ->add_option("--paper-figures", options->paper_figures_file,
                   "the paper's published figures (CSV); empty: none")
      ->capture_default_str();

  CLI::App* roc = compare->add_subcommand("roc", "Tab. roc_vx: reaching distance vs the optimum");
  roc->add_option("--tol-e", options->lateral_tolerance_m, "reached: |e| below this [m]")
      ->capture_default_str();
  roc->add_option("--tol-psi", options->heading_tolerance_rad, "reached: |psi| below [rad]")
      ->capture_default_str();
  roc->add_option("--intervals", options->intervals, "collocation intervals")
      ->capture_default_str()
      ->check(CLI::Range(10, 5000));
  roc->callback([options] {
    const LongCommand progress("roc", options->quiet);
    ReachingBenchmarkOptions benchmark;
    benchmark.lateral_tolerance_m = options->lateral_tolerance_m;
    benchmark.heading_tolerance_rad = options->heading_tolerance_rad;
    benchmark.intervals = options->intervals;
    const ReachingBenchmarkResult result = run_reaching_benchmark(benchmark);
    emit(result.table(paper_figures(*options)), *options, "roc_vx");
    emit(result.timings_table(), *options, "roc_vx_timings");
  });

  CLI::App* lane = compare->add_subcommand("lane-change", "every controller on the lane change");
  lane->callback([options] {
    const LongCommand progress("lane change", options->quiet);
    std::vector<std::string> files;
    for (const char* speed : {"10", "15", "19"}) {
      files.push_back(options->scenario_directory + "/lane_change_" + speed + ".yaml");
    }
    ResultsTable table =
        run_lane_change_comparison(files, paper_figures(*options), plant_overrides(options->plant));
    if (!options->plant.empty()) table.title += " (plant: model " + options->plant + ")";
    emit(table, *options, options->plant.empty() ? "lane_change" : "lane_change_" + options->plant);
  });
  CLI::App* parameters =
      compare->add_subcommand("parameters", "circle_sections with the settings of Sec. IV-A");
  parameters->callback([options] {
    const LongCommand progress("parameters", options->quiet);
    emit(run_parameter_comparison(options->scenario_directory + "/circle_sections_paper.yaml"),
         *options, "parameter_radar");
  });
  CLI::App* tuning = compare->add_subcommand(
      "tuning", "every controller tuned by one rule, reported on held-out scenarios");
  tuning->add_option("--budget", options->budget, "configurations per controller (power of 2)")
      ->capture_default_str();
  tuning->add_option("--train", options->training, "scenario names the gains are chosen on")
      ->capture_default_str();
  tuning->add_option("--held-out", options->held_out, "scenario names the table reports")
      ->capture_default_str();
  tuning->add_option("--controllers", options->controllers, "controllers of the study")
      ->capture_default_str();
  tuning->callback([options] {
    const LongCommand progress("tuning study", options->quiet);
    TuningRuleOptions rule;
    rule.budget = options->budget;
    rule.controllers = options->controllers;
    const TuningRuleResult result =
        run_tuning_rule(load_scenarios(*options, options->training),
                        load_scenarios(*options, options->held_out, options->plant), rule);
    const std::string stem =
        options->plant.empty() ? "tuning_rule" : "tuning_rule_" + options->plant;
    ResultsTable table = result.table();
    if (!options->plant.empty()) table.title += " (held-out plant: model " + options->plant + ")";
    emit(table, *options, stem);
    emit(result.timings_table(), *options, stem + "_timings");
  });
  add_engagement_command(*compare, options);
  add_road_suite_command(*compare, options);
  add_robustness_command(*compare, options);
  add_corners_command(*compare, options);
}

}  // namespace smoothsteer::cli
