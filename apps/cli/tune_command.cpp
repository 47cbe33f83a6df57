// `smoothsteer tune`: velocity-dependent controller parameters from a vehicle's steering limits
// (paper Sec. III; docs/tuning.md).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "progress_reporter.hpp"
#include "smoothsteer/io/atomic_output.hpp"
#include "smoothsteer/io/config_section.hpp"
#include "smoothsteer/io/schedule_files.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "smoothsteer/tuning/gain_schedule.hpp"
#include "smoothsteer/tuning/path_demand.hpp"

namespace smoothsteer::cli {
namespace {

struct TuneArguments {
  std::string vehicle_file;
  std::string speeds = "1:30:0.5";
  std::string out;
  int order = 2;
  double max_steering_acceleration = std::numeric_limits<double>::quiet_NaN();
  double max_steering_rate = std::numeric_limits<double>::quiet_NaN();
  double max_lateral_acceleration = std::numeric_limits<double>::quiet_NaN();
  std::string path_file;
  std::string certificate = "feedforward";
  TuningOptions options;
  bool quiet = false;  //!< --quiet: no progress on stderr
};

//! Most speeds one schedule may hold.
constexpr int max_speeds = 10'000;

std::vector<double> parse_speeds(const std::string& text) {
  double first = 0, last = 0, step = 0;
  char a = 0, b = 0;
  std::istringstream in(text);
  if (!(in >> first >> a >> last >> b >> step) || a != ':' || b != ':' || !in.eof()) {
    in.clear();
    throw std::invalid_argument("--speeds '" + text +
                                "' must be FIRST:LAST:STEP in m/s, e.g. 1:30:0.5");
  }
  // Count before building the grid: 1:1e300:1e-300 would convert inf to an integer
  // (converting inf to an integer is undefined behaviour).
  if (!std::isfinite(first) || !std::isfinite(last) || !std::isfinite(step) || !(step > 0.0)) {
    throw std::invalid_argument("--speeds '" + text + "': FIRST, LAST and STEP must be finite, " +
                                "STEP > 0");
  }
  const double count = (last - first) / step + 1.0;
  if (!(count >= 1.0) || count > max_speeds) {
    throw std::invalid_argument(
        "--speeds '" + text + "': gives " + std::to_string(static_cast<long double>(count)) +
        " speeds; between 1 and " + std::to_string(max_speeds) + " are allowed");
  }
  return speed_grid(first, last, step);
}

void print_summary(const GainSchedule& schedule, std::ostream& out) {
  const auto& entries = schedule.entries();
  out << "velocity regions (paper Sec. III):\n";
  for (std::size_t begin = 0; begin < entries.size();) {
    std::size_t end = begin;
    while (end + 1 < entries.size() && entries[end + 1].region == entries[begin].region) ++end;
    const ScheduleEntry& a = entries[begin];
    const ScheduleEntry& b = entries[end];
    char line[256];
    std::snprintf(line, sizeof line,
                  "  %5.2f-%5.2f m/s  region %-42s lambda_l %.3f-%.3f m  lead radius %.2f-%.2f m\n",
                  a.speed_mps, b.speed_mps, to_string(a.region), a.lead_wheelbase_m,
                  b.lead_wheelbase_m, 1.0 / a.lead_curvature_bound, 1.0 / b.lead_curvature_bound);
    out << line;
    begin = end + 1;
  }
}

//! The path of a YAML file: a scenario file (its `path:` section) or a bare path section, in any
//! of the scenario path forms (docs/scenarios.md).
std::shared_ptr<const Path> load_path_file(const std::string& file) {
  // Regular files only, bounded size and alias expansion, as every scenario file.
  const YAML::Node root = io::load_yaml_file(file);
  if (!root.IsMap()) throw std::invalid_argument(file + ": a path file must be a YAML map");
  const bool scenario = static_cast<bool>(root["path"]);
  io::ConfigSection section(scenario ? root["path"] : root, scenario ? "path" : "", file);
  const auto slash = file.find_last_of('/');
  const std::string directory = slash == std::string::npos ? "." : file.substr(0, slash);
  auto path = runner::make_path(section, directory);
  section.finish();
  return path;
}

void run_tune(const TuneArguments& arguments) {
  VehicleLimits vehicle = io::load_vehicle_limits(arguments.vehicle_file);
  if (!std::isnan(arguments.max_steering_rate)) {
    vehicle.max_steering_rate_radps = arguments.max_steering_rate;
  }
  if (!std::isnan(arguments.max_steering_acceleration)) {
    vehicle.max_steering_acceleration_radps2 = arguments.max_steering_acceleration;
  }
  if (!std::isnan(arguments.max_lateral_acceleration)) {
    vehicle.max_lateral_acceleration_mps2 = arguments.max_lateral_acceleration;
  }
  TuningOptions options = arguments.options;
  options.order = arguments.order;
  options.certificate =
      arguments.certificate == "box" ? Certificate::box : Certificate::feedforward;
  if (!arguments.path_file.empty()) {
    const PathDemand demand = apply_path_demand(options, load_path_file(arguments.path_file));
    std::cout << "path " << arguments.path_file << ": max |kappa| " << demand.max_curvature
              << " 1/m, max |d kappa/ds| " << demand.max_curvature_rate << " 1/m^2\n";
  }
  const std::vector<double> speeds = parse_speeds(arguments.speeds);
  // The schedule writer renames its file into place: never over a device or a link.
  io::require_regular_file_or_absent(arguments.out, "--out");
  GainSchedule schedule;
  {
    // One count per grid speed; an interrupt stops between two speeds and writes nothing.
    const LongCommand progress("tune", arguments.quiet, "speeds");
    runner::progress_expect(speeds.size());
    const SpeedSolved speed_solved = [] {
      runner::progress_case_done();
      runner::throw_if_interrupted("tune");
    };
    if (options.certificate == Certificate::feedforward) {
      schedule = compute_feedforward_schedule(vehicle, options, speeds, speed_solved);
    } else {
      StaticMapOptions map_options;
      map_options.max_steering_angle_rad = std::max(map_options.max_steering_angle_rad,
                                                    std::min(1.49, vehicle.max_steering_angle_rad));
      schedule =
          compute_gain_schedule(vehicle, options, speeds, StaticMap(map_options), speed_solved);
    }
  }
  io::write_schedule_csv(schedule, arguments.out);
  std::cout << "vehicle " << arguments.vehicle_file << ": lambda_veh " << vehicle.wheelbase_m
            << " m, limits " << vehicle.max_steering_angle_rad << " rad, "
            << vehicle.max_steering_rate_radps << " rad/s, "
            << vehicle.max_steering_acceleration_radps2 << " rad/s^2, lateral acceleration "
            << vehicle.max_lateral_acceleration_mps2 << " m/s^2; order n = " << options.order
            << ", certificate " << arguments.certificate << "\n";
  print_summary(schedule, std::cout);
  std::cout << "wrote " << schedule.entries().size() << " speeds to " << arguments.out << "\n";
}

}  // namespace

void add_tune_command(CLI::App& app) {
  auto arguments = std::make_shared<TuneArguments>();
  CLI::App* tune = app.add_subcommand(
      "tune",
      "Velocity-dependent controller parameters from the vehicle's steering limits "
      "(paper Sec. III); writes the gain schedule as CSV");
  tune->add_option("--vehicle", arguments->vehicle_file, "vehicle YAML (vehicles/NAME.yaml)")
      ->required();
  tune->add_option("--speeds", arguments->speeds, "FIRST:LAST:STEP in m/s")->capture_default_str();
  tune->add_option("--out", arguments->out, "schedule CSV to write")->required();
  tune->add_option("--order", arguments->order, "n: 1 (C0) or 2 (C1)")->capture_default_str();
  tune->add_flag("-q,--quiet", arguments->quiet, "no progress or summary line on stderr");
  tune->add_option("--max-steering-rate", arguments->max_steering_rate,
                   "steering rate limit [rad/s]; overrides the vehicle file");
  tune->add_option("--max-steering-acceleration", arguments->max_steering_acceleration,
                   "steering acceleration limit [rad/s^2]; overrides the vehicle file");
  tune->add_option("--certificate", arguments->certificate,
                   "feedforward (curvature feedforward, tight certificate) or box (the paper's "
                   "worst case over the invariant box)")
      ->check(CLI::IsMember({"feedforward", "box"}))
      ->capture_default_str();
  tune->add_option("--path", arguments->path_file,
                   "scenario or path YAML whose path sets --path-curvature and "
                   "--path-curvature-rate");
  tune->add_option("--path-curvature-rate", arguments->options.path_curvature_rate_bound,
                   "largest |d kappa/ds| of the path [1/m^2] (default: unknown, inf)");
  tune->add_option("--max-lateral-acceleration", arguments->max_lateral_acceleration,
                   "friction limit mu g [m/s^2]; default from the vehicle file's tires");
  // The TuningOptions fields set from the command line, each shown with its default.
  TuningOptions& o = arguments->options;
  const struct {
    const char* flag;
    double& value;
    const char* help;
  } tuning_options[] = {
      {"--max-longitudinal-acceleration", o.max_longitudinal_acceleration_mps2,
       "largest |dv/dt| to cover [m/s^2] (adds |dv/dt| delta' to d2(delta)/dt2)"},
      {"--min-lead-curvature", o.min_lead_curvature_bound, "smallest admissible kbar_l [1/m]"},
      {"--path-curvature", o.path_curvature_bound,
       "largest reference-path curvature [1/m]: the feedforward covers it (box: k_rob covers it)"},
      {"--feedforward-headroom", o.feedforward_headroom,
       "kbar_ff = this times the path's peak curvature, in [1, 3]: room for the rear-axle target "
       "and the dynamics preview"},
      {"--feedforward-rate-share", o.feedforward_rate_share,
       "largest share of the certified rate budget the feedforward's curvature rate may take "
       "(the switching part gets the rest)"},
      {"--disturbance", o.matched_disturbance_curvature,
       "matched disturbance kappa_d k_rob must cover [1/m]"},
  };
  for (const auto& option : tuning_options) {
    tune->add_option(option.flag, option.value, option.help)->capture_default_str();
  }
  tune->callback([arguments] { run_tune(*arguments); });
}

}  // namespace smoothsteer::cli
