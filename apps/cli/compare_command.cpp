// `smoothsteer compare <benchmark>`: runs one comparison benchmark (docs/baselines.md) and writes
// its table as CSV and Markdown into --out (default compare_out/, untracked). The committed tables
// in docs/results/ come from `--out docs/results` (docs/results/README.md); they are the same on
// every rerun, since wall-clock times go to a separate *_timings file, which is not committed.
//   roc           Tab. roc_vx: optimal (Ipopt) vs proposed (n = 1) vs HOSM reaching distance
//   lane-change   every controller on scenarios/lane_change_{10,15,19}.yaml
//   parameters    circle_sections.yaml with the four settings of Sec. IV-A
//   tuning        every controller tuned by one rule on training scenarios, reported held-out
//                 (the study of docs/baselines.md; scenario NAME@V: NAME at V m/s)
//   engagement    the lane changes started off the path: certified vs baselines vs the
//                 optimal-control lower bound (docs/engagement.md)
// Options of `compare` work before or after the sub-command (`compare parameters -o DIR`).

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.hpp"
#include "smoothsteer/evaluation/engagement_study.hpp"
#include "smoothsteer/evaluation/paper_figures.hpp"
#include "smoothsteer/evaluation/reaching_benchmark.hpp"
#include "smoothsteer/evaluation/scenario_comparison.hpp"
#include "smoothsteer/evaluation/tuning_rule.hpp"
#include "smoothsteer/io/atomic_output.hpp"

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
  EngagementStudyOptions engagement;  // scenario_files: lane_change_{10,15,19} of --scenarios
};

void emit(const ResultsTable& table, const CompareOptions& options, const std::string& stem) {
  table.write(options.output_directory, stem);
  std::printf("%s\nwritten: %s/%s.csv and .md\n", table.to_markdown().c_str(),
              options.output_directory.c_str(), stem.c_str());
}

//! NAME is scenarios/NAME.yaml; NAME@V the same file at the constant speed V m/s, named so.
std::vector<io::Scenario> load_scenarios(const CompareOptions& options,
                                         const std::vector<std::string>& names) {
  std::vector<io::Scenario> scenarios;
  for (const std::string& spec : names) {
    const std::size_t at = spec.find('@');
    const std::string file = options.scenario_directory + "/" + spec.substr(0, at) + ".yaml";
    if (at == std::string::npos) {
      scenarios.push_back(io::load_scenario(file));
      continue;
    }
    const std::string speed = spec.substr(at + 1);
    io::Scenario scenario =
        io::load_scenario(file, {"speed={initial_mps: " + speed + ", final_mps: " + speed + "}"});
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
    EngagementStudyOptions study = options->engagement;
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
    std::vector<std::string> files;
    for (const char* speed : {"10", "15", "19"}) {
      files.push_back(options->scenario_directory + "/lane_change_" + speed + ".yaml");
    }
    emit(run_lane_change_comparison(files, paper_figures(*options)), *options, "lane_change");
  });
  CLI::App* parameters =
      compare->add_subcommand("parameters", "circle_sections with the settings of Sec. IV-A");
  parameters->callback([options] {
    emit(run_parameter_comparison(options->scenario_directory + "/circle_sections.yaml"), *options,
         "parameter_radar");
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
    TuningRuleOptions rule;
    rule.budget = options->budget;
    rule.controllers = options->controllers;
    const TuningRuleResult result =
        run_tuning_rule(load_scenarios(*options, options->training),
                        load_scenarios(*options, options->held_out), rule);
    emit(result.table(), *options, "tuning_rule");
    emit(result.timings_table(), *options, "tuning_rule_timings");
  });
  add_engagement_command(*compare, options);
}

}  // namespace smoothsteer::cli
