#include "smoothsteer/evaluation/road_suite_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include "car_schedule.hpp"
#include "parallel_cases.hpp"
#include "scenario_setup.hpp"
#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/io/vehicle_file.hpp"
#include "smoothsteer/runner/scenario.hpp"

namespace smoothsteer {
namespace {

constexpr const char* certified = detail::certified_controller;

struct Case {
  std::string road_file, vehicle_file, model, controller;
  double jitter = 0.0;
};

struct Outcome {
  std::string road, car, model, controller, stop;
  double jitter = 0.0;
  double max_e = 0.0, rms_e = 0.0, max_heading = 0.0, max_slip = 0.0;
  long above = 0;
  bool wide = false, spun = false;
};

std::string stem(const std::string& file) {
  return std::filesystem::path(file).stem().string();
}

void write_trace(const std::string& file, const std::vector<TraceSample>& trace) {
  std::filesystem::create_directories(std::filesystem::path(file).parent_path());
  std::ofstream out(file, std::ios::binary);
  out << "t,s,x,y,e,delta_cmd\n";
  char line[160];
  for (const TraceSample& r : trace) {
    std::snprintf(line, sizeof line, "%.3f,%.4f,%.4f,%.4f,%.5f,%.5f\n", r.time_s, r.distance_m,
                  r.rear_axle.position.x, r.rear_axle.position.y, r.lateral_error_m,
                  r.steering_command_rad);
    out << line;
  }
  if (!out) throw std::runtime_error("road suite: writing " + file + " failed");
}

//! The road's path (every piece of a plan) as x,y rows every 0.25 m, beside the traces; written
//! to a file of its own and renamed, so that runs of the same road in parallel cannot mix it.
void write_path(const std::string& directory, const runner::Scenario& scenario, std::size_t id) {
  std::filesystem::create_directories(directory);
  const std::string file = directory + "/path.csv";
  const std::string part = file + "." + std::to_string(id);
  {
    std::ofstream out(part, std::ios::binary);
    out << "x,y\n";
    const std::size_t pieces = scenario.plan ? scenario.plan->piece_count() : 1;
    char line[64];
    for (std::size_t p = 0; p < pieces; ++p) {
      const Path& path = scenario.plan ? *scenario.plan->piece(p).path : *scenario.path;
      const double count = std::ceil(path.length() / 0.25);
      for (double i = 0.0; i <= count; i += 1.0) {
        const Vec2 at = path.evaluate(path.length() * i / count).position;
        std::snprintf(line, sizeof line, "%.4f,%.4f\n", at.x, at.y);
        out << line;
      }
    }
    if (!out) throw std::runtime_error("road suite: writing " + part + " failed");
  }
  std::filesystem::rename(part, file);
}

std::string text(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

//! The scenario keys of the planner's windows with `jitter` (none when the planner is off).
std::vector<std::string> planner_overrides(const PlannerWindows& planner, double jitter) {
  if (!planner.active()) return {};
  const std::string key = "simulation.planner.";
  std::vector<std::string> keys{
      key + "period_s=" + text(planner.period_s), key + "behind_m=" + text(planner.behind_m),
      key + "ahead_m=" + text(planner.ahead_m), key + "spacing_m=" + text(planner.spacing_m),
      key + "jitter_std_m=" + text(jitter)};
  if (planner.smoothing_tolerance_m) {
    keys.push_back(key + "smoothing_tolerance_m=" + text(*planner.smoothing_tolerance_m));
  }
  return keys;
}

Outcome run_case(const Case& c, const RoadSuiteOptions& options, std::size_t id) {
  const std::string vehicle = std::filesystem::absolute(c.vehicle_file).string();
  std::vector<std::string> overrides{"vehicle.file=" + vehicle, "model=" + c.model};
  if (c.controller == certified) {
    for (std::string& o : detail::car_schedule(c.road_file, stem(c.vehicle_file))) {
      overrides.push_back(o);
    }
  } else if (c.controller == road_suite_car_system) {
    overrides.push_back("controller={type: steering_system}");
  }
  for (std::string& o : planner_overrides(options.planner, c.jitter)) overrides.push_back(o);
  const runner::Scenario scenario = runner::load_scenario(c.road_file, overrides);
  const runner::RunResult run = detail::run_with_controller(
      scenario, c.controller == road_suite_car_system ? certified : c.controller);
  Outcome o;
  o.jitter = c.jitter;
  o.road = scenario.name;
  o.car = stem(c.vehicle_file);
  o.model = c.model;
  o.controller = c.controller;
  o.stop = run.simulation.stop_reason;
  const Metrics& m = run.metrics;
  o.max_e = m.max_abs_rear_error_m;
  o.rms_e = m.rms_rear_error_m;
  o.above = static_cast<long>(m.angle_violations) + m.held_rate_violations +
            m.held_acceleration_violations;
  for (const TraceSample& r : run.simulation.trace) {
    o.max_heading = std::max(o.max_heading, std::abs(r.heading_error_rad));
    o.max_slip = std::max(o.max_slip, std::abs(r.rear_side_slip_rad));
  }
  o.wide = !(o.max_e <= road_suite_wide_error_m);
  o.spun = o.max_heading > road_suite_spin_heading_error_rad ||
           o.max_slip > road_suite_spin_side_slip_rad || run.simulation.non_finite;
  if (const std::string& traces = options.trace_directory; !traces.empty()) {
    write_path(traces + "/" + o.road, scenario, id);
    const std::string jitter = options.planner.active() ? "_jitter" + text(c.jitter) : "";
    write_trace(
        traces + "/" + o.road + "/" + o.car + "_" + o.model + "_" + o.controller + jitter + ".csv",
        run.simulation.trace);
  }
  return o;
}

std::string plant_name(const std::string& model) {
  return model == "double_track" ? "double-track" : model == "dynamic" ? "single-track" : model;
}

}  // namespace

std::vector<std::string> road_suite_controller_names() {
  std::vector<std::string> names{certified};
  for (const std::string& name : comparison_controller_names()) names.push_back(name);
  return names;
}

namespace {

//! Every name `controllers` may hold: the default list and the car's system.
std::vector<std::string> known_controller_names() {
  std::vector<std::string> names = road_suite_controller_names();
  names.insert(names.begin() + 1, road_suite_car_system);
  return names;
}

}  // namespace

void RoadSuiteOptions::validate() const {
  if (road_files.empty()) throw std::invalid_argument("RoadSuiteOptions: road_files is empty");
  if (vehicle_files.empty()) {
    throw std::invalid_argument("RoadSuiteOptions: vehicle_files is empty");
  }
  // Each car's own error, before any run: a broken file used to surface only as a missing
  // schedule of the certified route.
  for (const std::string& vehicle : vehicle_files) {
    try {
      io::load_vehicle_file(vehicle);
    } catch (const std::exception& error) {
      throw std::invalid_argument("RoadSuiteOptions: vehicle_files (--vehicles) " + vehicle +
                                  " cannot be read: " + error.what());
    }
  }
  if (models.empty()) throw std::invalid_argument("RoadSuiteOptions: models is empty");
  for (const std::string& model : models) {
    if (model != "dynamic" && model != "double_track" && model != "kinematic") {
      throw std::invalid_argument("RoadSuiteOptions: models contains '" + model +
                                  "'; expected dynamic, double_track or kinematic");
    }
  }
  if (controllers.empty()) throw std::invalid_argument("RoadSuiteOptions: controllers is empty");
  const std::vector<std::string> known = known_controller_names();
  for (const std::string& name : controllers) {
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      throw std::invalid_argument("RoadSuiteOptions: controllers contains '" + name +
                                  "', which is neither 'certified', 'steering_system' nor a "
                                  "comparison controller");
    }
  }
  SimulationParameters windows;  // the planner's own rules, at the default control period
  windows.planner = planner;
  if (const std::string error = windows.validation_error(); !error.empty()) {
    throw std::invalid_argument("RoadSuiteOptions: planner: " + error);
  }
  if (jitters_m.empty()) throw std::invalid_argument("RoadSuiteOptions: jitters_m is empty");
  for (const double jitter : jitters_m) {
    if (!(jitter >= 0.0 && jitter <= 1.0)) {
      throw std::invalid_argument("RoadSuiteOptions: jitters_m contains " + text(jitter) +
                                  "; each must be in [0, 1] m");
    }
  }
  if (threads < 1 || threads > 256) {
    throw std::invalid_argument("RoadSuiteOptions: threads = " + std::to_string(threads) +
                                " must be in [1, 256]");
  }
}

RoadSuiteResult run_road_suite_comparison(const RoadSuiteOptions& options) {
  options.validate();
  const bool stack = options.planner.active();
  const std::vector<double> jitters = stack ? options.jitters_m : std::vector<double>{0.0};
  std::vector<Case> cases;
  for (const std::string& road : options.road_files) {
    for (const std::string& vehicle : options.vehicle_files) {
      for (const std::string& model : options.models) {
        for (const double jitter : jitters) {
          for (const std::string& controller : options.controllers) {
            cases.push_back({road, vehicle, model, controller, jitter});
          }
        }
      }
    }
  }
  std::vector<Outcome> outcomes(cases.size());
  detail::run_cases_in_parallel(cases.size(), options.threads, "road suite", [&](std::size_t i) {
    outcomes[i] = run_case(cases[i], options, i);
  });

  RoadSuiteResult result;
  ResultsTable& runs = result.runs;
  runs.title = stack ? "Road suite as a driving stack drives it: planner windows x jitter x cars "
                       "x plants x controllers (rear axle, the whole run)"
                     : "Road suite x cars x plants x controllers (rear axle, the whole run)";
  runs.header = {"road", "car", "plant"};
  if (stack) runs.header.push_back("jitter_m");
  for (const char* column :
       {"controller", "max_abs_e_m", "rms_e_m", "held_above_limits", "wide", "spun", "stop"}) {
    runs.header.push_back(column);
  }
  // Per plant (and jitter) and controller: runs, wide, spun, held above, worst and mean max |e|,
  // best-of.
  struct Totals {
    int runs = 0, wide = 0, spun = 0, best = 0;
    long above = 0;
    double worst = 0.0, sum_max = 0.0, sum_rms = 0.0;
  };
  auto group_of = [](const std::string& model, double jitter) {
    return model + "|" + ResultsTable::number(jitter);
  };
  std::map<std::pair<std::string, std::string>, Totals> totals;
  std::map<std::string, std::pair<double, std::string>> best;  // road|car|group -> best
  for (const Outcome& o : outcomes) {
    std::vector<std::string> row{o.road, o.car, plant_name(o.model)};
    if (stack) row.push_back(ResultsTable::number(o.jitter));
    for (std::string cell :
         {o.controller, ResultsTable::number(o.max_e), ResultsTable::number(o.rms_e),
          std::to_string(o.above), std::string(o.wide ? "wide" : ""),
          std::string(o.spun ? "spun" : ""), o.stop}) {
      row.push_back(std::move(cell));
    }
    runs.rows.push_back(std::move(row));
    const std::string group = group_of(o.model, o.jitter);
    Totals& t = totals[{group, o.controller}];
    ++t.runs;
    t.wide += o.wide ? 1 : 0;
    t.spun += o.spun ? 1 : 0;
    t.above += o.above;
    t.worst = std::max(t.worst, o.max_e);
    t.sum_max += o.max_e;
    t.sum_rms += o.rms_e;
    const std::string key = o.road + "|" + o.car + "|" + group;
    const auto found = best.find(key);
    if (found == best.end() || o.max_e < found->second.first) best[key] = {o.max_e, o.controller};
  }
  for (const auto& [key, value] : best) {
    const std::size_t plant_at = key.find('|', key.find('|') + 1) + 1;
    ++totals[{key.substr(plant_at), value.second}].best;
  }
  const std::string controllers_note =
      "certified: the road file's own controller (the scheduled lead-wheel controller with the "
      "governor and the schedule `smoothsteer tune` gives for that car, "
      "schedules/<car>_*.csv); " +
      std::string(std::find(options.controllers.begin(), options.controllers.end(),
                            road_suite_car_system) != options.controllers.end()
                      ? "steering_system: the car's system built from the car alone, with no "
                        "schedule file (docs/steering_system.md); "
                      : "") +
      "every other row is a baseline behind the second-order limiter "
      "(docs/baselines.md). Cars: vehicles/*.yaml (CommonRoad vehicles 1-3); plants: the "
      "single-track model (model: dynamic) and the held-out double-track model.";
  runs.notes = {
      "max_abs_e_m, rms_e_m: the rear axle's lateral error over the whole run (on a path with "
      "gear changes, against the active piece). held_above_limits: held-command samples above "
      "the car's angle, rate or acceleration limit. wide: max |e| > 1 m; spun: |heading error| "
      "> 1 rad or |rear-axle side slip| > 0.5 rad (the rear axle slides; at parking speed the CG's "
      "kinematic slip atan(lr tan(delta) / L) reaches 0.6 rad without any sliding). stop: path_end "
      "(the run reached the end of its path) or "
      "duration. " +
      controllers_note};
  if (stack) {
    runs.notes.push_back(
        "Stack mode (docs/simulation.md): every " + ResultsTable::number(options.planner.period_s) +
        " s the controller gets by set_path() a window of the road from " +
        ResultsTable::number(options.planner.behind_m) + " m behind to " +
        ResultsTable::number(options.planner.ahead_m) + " m ahead, waypoints " +
        ResultsTable::number(options.planner.spacing_m) +
        " m apart with Gaussian jitter jitter_m per coordinate, fitted by Path::from_waypoints "
        "(smoothing tolerance jitter_m sqrt(2) unless set); e is against the road itself.");
  }

  ResultsTable& summary = result.summary;
  summary.title = stack ? "Road suite as a stack drives it: totals per plant, jitter and controller"
                        : "Road suite: totals per plant and controller over every road and car";
  summary.header = {"plant"};
  if (stack) summary.header.push_back("jitter_m");
  for (const char* column : {"controller", "runs", "wide", "spun", "held_above", "worst_max_e_m",
                             "mean_max_e_m", "mean_rms_e_m", "best_of"}) {
    summary.header.push_back(column);
  }
  for (const std::string& model : options.models) {
    for (const double jitter : jitters) {
      for (const std::string& controller : options.controllers) {
        const Totals& t = totals[{group_of(model, jitter), controller}];
        const double n = std::max(1, t.runs);
        std::vector<std::string> row{plant_name(model)};
        if (stack) row.push_back(ResultsTable::number(jitter));
        for (std::string cell : {controller, std::to_string(t.runs), std::to_string(t.wide),
                                 std::to_string(t.spun), std::to_string(t.above),
                                 ResultsTable::number(t.worst), ResultsTable::number(t.sum_max / n),
                                 ResultsTable::number(t.sum_rms / n), std::to_string(t.best)}) {
          row.push_back(std::move(cell));
        }
        summary.rows.push_back(std::move(row));
      }
    }
  }
  summary.notes = {
      "Over every road and car of " + std::string(stack ? "road_suite_stack.md" : "road_suite.md") +
      ": wide and spun runs, held samples above the "
      "limits, the worst and the mean of the runs' max |e|, the mean RMS |e|, and best_of: on how "
      "many road x car pairs of that plant" +
      std::string(stack ? " and jitter" : "") + " the controller had the smallest max |e|."};
  return result;
}

}  // namespace smoothsteer
