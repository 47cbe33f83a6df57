// `smoothsteer run | list | sweep` (issue "Simulation"; docs/cli.md).

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "plotter.hpp"
#include "progress_reporter.hpp"
#include "smoothsteer/io/atomic_output.hpp"
#include "smoothsteer/runner/run_output.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "smoothsteer/runner/sweep.hpp"

namespace smoothsteer::cli {
namespace {

namespace fs = std::filesystem;

//! scenarios/ next to the binary's source tree: $SMOOTHSTEER_SCENARIOS, else ./scenarios.
std::string default_scenario_directory() {
  if (const char* env = std::getenv("SMOOTHSTEER_SCENARIOS")) return env;
  return "scenarios";
}

struct RunOptions {
  std::string scenario;
  std::string out;
  std::vector<std::string> overrides;
  bool plot = false;
};

void run(const RunOptions& options) {
  io::OutputDirectory out(options.out, "--out");
  const std::string script = options.plot ? find_plot_script() : std::string();
  const runner::Scenario scenario = runner::load_scenario(options.scenario, options.overrides);
  const runner::RunResult result = runner::run_scenario(scenario, out);
  const Metrics& m = result.metrics;
  std::printf("%s: %d steps, stop: %s, reached: %s (t = %.2f s, s = %.2f m)\n",
              scenario.name.c_str(), m.steps, result.simulation.stop_reason.c_str(),
              m.reached ? "yes" : "no", m.reaching_time_s, m.reaching_distance_m);
  std::printf(
      "  max |e| rear %.4f m, front %.4f m; after reaching: |e_lead| %.4f, front %.4f, rear %.4f "
      "m\n",
      m.max_abs_rear_error_m, m.max_abs_front_error_m, m.max_abs_lead_error_after_reaching_m,
      m.max_abs_front_error_after_reaching_m, m.max_abs_rear_error_after_reaching_m);
  std::printf("  max side slip %.4f rad, bound violations %d\n", m.max_abs_side_slip_rad,
              m.bound_violations);
  if (m.path_friction_exceedances > 0) {
    std::printf(
        "  warning: the path asks more than the tires can give: v^2 |kappa| up to %.2f m/s^2 "
        "against mu g = %.2f m/s^2 (%d steps)\n",
        m.max_path_lateral_acceleration_mps2, scenario.metrics.friction_limit_mps2,
        m.path_friction_exceedances);
  }
  const bool ok = result.simulation.status == Status::ok && !result.simulation.non_finite;
  if (options.plot && ok) {
    write_path_csv(*scenario.path, out.file("path.csv").string(), scenario.plan.get());
    run_plotter(script, out.file("trace.csv").string(), out.file("trace.png").string());
  }
  // Published even when the run stopped early: the trace shows where and why.
  out.commit();
  std::printf("wrote %s/trace.csv and summary.json%s\n", out.target().c_str(),
              options.plot && ok ? ", path.csv and trace.png" : "");
  if (!ok) {
    throw std::runtime_error("run stopped early: " + result.simulation.stop_reason + " (" +
                             result.simulation.stop_detail + ")");
  }
}

void list(const std::string& directory) {
  if (!fs::is_directory(directory))
    throw std::runtime_error("'" + directory + "' is not a directory");
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(directory)) {
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    try {
      const runner::Scenario s = runner::load_scenario(file.string());
      std::printf("%-28s %s\n", file.filename().string().c_str(), s.description.c_str());
    } catch (const std::exception& error) {
      std::printf("%-28s INVALID: %s\n", file.filename().string().c_str(), error.what());
    }
  }
}

struct SweepOptions {
  std::string scenario;
  std::string out;
  std::vector<std::string> overrides;
  std::vector<std::string> vary;
  bool paper = false;
  int jobs = 0;
  bool quiet = false;
};

void sweep(const SweepOptions& options) {
  std::vector<std::vector<std::string>> sets;
  if (options.paper) {
    sets = runner::paper_variations(runner::load_scenario(options.scenario, options.overrides));
  }
  if (!options.vary.empty()) {
    std::vector<runner::SweepAxis> axes;
    for (const std::string& v : options.vary) axes.push_back(runner::parse_sweep_axis(v));
    const auto grid = runner::sweep_grid(axes);
    sets.insert(sets.end(), grid.begin(), grid.end());
  }
  if (sets.empty()) throw std::runtime_error("sweep: give --vary key=v1,v2,... and/or --paper");
  if (sets.size() > runner::max_sweep_rows) {
    throw std::runtime_error("sweep: " + std::to_string(sets.size()) + " runs; at most " +
                             std::to_string(runner::max_sweep_rows));
  }
  io::require_regular_file_or_absent(options.out, "--out");
  std::vector<runner::SweepRow> rows;
  {
    const LongCommand progress("sweep", options.quiet);
    rows = runner::run_sweep(options.scenario, options.overrides, sets, options.jobs);
  }
  const fs::path out(options.out);
  if (out.has_parent_path()) fs::create_directories(out.parent_path());
  io::write_file_atomically(options.out, runner::sweep_csv(rows), "--out");
  std::size_t failed = 0;
  for (const auto& row : rows) failed += row.ok ? 0 : 1;
  std::printf("wrote %s (%zu runs, %zu failed)\n", options.out.c_str(), rows.size(), failed);
  if (failed == rows.size()) {
    throw std::runtime_error("sweep: every run failed; first error: " + rows.front().error);
  }
}

}  // namespace

void add_run_commands(CLI::App& app) {
  auto run_options = std::make_shared<RunOptions>();
  CLI::App* run_command =
      app.add_subcommand("run", "Simulate one scenario, write trace.csv and summary.json");
  run_command->add_option("scenario", run_options->scenario, "scenario YAML file")->required();
  run_command->add_option("--out", run_options->out, "output directory")->required();
  run_command->add_option("--set", run_options->overrides, "override: key.path=value (repeatable)");
  run_command->add_flag(
      "--plot", run_options->plot,
      "also write DIR/trace.png and the reference path DIR/path.csv (scripts/plot_trace.py)");
  run_command->callback([run_options] { run(*run_options); });

  auto directory = std::make_shared<std::string>(default_scenario_directory());
  CLI::App* list_command = app.add_subcommand("list", "List the scenarios of a directory");
  list_command->add_option("directory", *directory, "scenario directory (default: ./scenarios)");
  list_command->callback([directory] { list(*directory); });

  auto sweep_options = std::make_shared<SweepOptions>();
  CLI::App* sweep_command =
      app.add_subcommand("sweep", "Run a grid of parameter variations in parallel");
  sweep_command->add_option("scenario", sweep_options->scenario, "scenario YAML file")->required();
  sweep_command->add_option("--out", sweep_options->out, "output CSV table")->required();
  sweep_command->add_option("--set", sweep_options->overrides, "override applied to every run");
  sweep_command->add_option("--vary", sweep_options->vary,
                            "grid axis: key.path=v1,v2,... (repeatable)");
  sweep_command->add_flag("--paper", sweep_options->paper,
                          "the paper's variations: kbar_l -50%, lambda_l +300%, k_rob -33%");
  sweep_command->add_option("-j,--jobs", sweep_options->jobs, "worker threads (0 = all cores)");
  sweep_command->add_flag("-q,--quiet", sweep_options->quiet,
                          "no progress or summary line on stderr");
  sweep_command->callback([sweep_options] { sweep(*sweep_options); });
}

}  // namespace smoothsteer::cli
