// `smoothsteer compare <benchmark>`: runs one comparison benchmark (issue "Comparison") and
// writes its table as CSV and Markdown into the output directory (default docs/results).
//   roc           Tab. roc_vx: optimal (Ipopt) vs proposed (n = 1) vs HOSM reaching distance
//   lane-change   every controller on scenarios/lane_change_{10,15,19}.yaml
//   parameters    circle_sections.yaml with the four settings of Sec. IV-A

#include <cstdio>
#include <string>
#include <vector>

#include "commands.hpp"
#include "smoothsteer/baselines/reaching_benchmark.hpp"
#include "smoothsteer/baselines/scenario_comparison.hpp"

namespace smoothsteer::cli {

namespace {

struct CompareOptions {
  std::string output_directory = "docs/results";
  std::string scenario_directory = "scenarios";
  double lateral_tolerance_m = 0.01;
  double heading_tolerance_rad = 0.01;
  int intervals = 150;
};

void emit(const ResultsTable& table, const CompareOptions& options, const std::string& stem) {
  table.write(options.output_directory, stem);
  std::printf("%s\nwritten: %s/%s.csv and .md\n", table.to_markdown().c_str(),
              options.output_directory.c_str(), stem.c_str());
}

}  // namespace

void add_compare_command(CLI::App& app) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* compare = app.add_subcommand("compare", "run a comparison benchmark, write its table");
  compare->require_subcommand(1);
  compare->add_option("-o,--output", options->output_directory, "directory of the tables")
      ->capture_default_str();
  compare->add_option("--scenarios", options->scenario_directory, "directory of scenario files")
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
    emit(run_reaching_benchmark(benchmark).table(), *options, "roc_vx");
  });

#ifdef SMOOTHSTEER_HAS_io
  CLI::App* lane = compare->add_subcommand("lane-change", "every controller on the lane change");
  lane->callback([options] {
    std::vector<std::string> files;
    for (const char* speed : {"10", "15", "19"}) {
      files.push_back(options->scenario_directory + "/lane_change_" + speed + ".yaml");
    }
    emit(run_lane_change_comparison(files), *options, "lane_change");
  });
  CLI::App* parameters =
      compare->add_subcommand("parameters", "circle_sections with the settings of Sec. IV-A");
  parameters->callback([options] {
    emit(run_parameter_comparison(options->scenario_directory + "/circle_sections.yaml"), *options,
         "parameter_radar");
  });
#endif
}

}  // namespace smoothsteer::cli
