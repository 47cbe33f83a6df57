#include "smoothsteer/evaluation/robustness_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <stdexcept>
#include <tuple>

#include "car_schedule.hpp"
#include "parallel_cases.hpp"
#include "scenario_setup.hpp"
#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/evaluation/road_suite_comparison.hpp"
#include "smoothsteer/runner/scenario.hpp"

namespace smoothsteer {
namespace {

constexpr const char* certified = detail::certified_controller;
constexpr const char* nominal = "nominal";

//! What the targets allow: max |e| <= factor x the nominal figure + margin (docs/results/
//! robustness.md).
constexpr double target_factor = 1.2;
constexpr double target_margin_m = 0.02;

struct Case {
  const RobustnessScenario* scenario = nullptr;
  std::string vehicle_file, model, controller;
  const Imperfection* imperfection = nullptr;  //!< nullptr: the nominal run
};

struct Outcome {
  std::string scenario, car, model, controller, imperfection, group, stop;
  double max_e = 0.0;
  long above = 0;
};

std::string stem(const std::string& file) {
  return std::filesystem::path(file).stem().string();
}

std::string plant_name(const std::string& model) {
  return model == "double_track" ? "double-track" : model == "dynamic" ? "single-track" : model;
}

Outcome run_case(const Case& c) {
  const std::string& file = c.scenario->file;
  const double settle_time_s = c.scenario->settle_time_s;
  std::vector<std::string> overrides{
      "vehicle.file=" + std::filesystem::absolute(c.vehicle_file).string(), "model=" + c.model};
  if (c.controller == certified) {
    for (std::string& o : detail::car_schedule(file, stem(c.vehicle_file))) {
      overrides.push_back(std::move(o));
    }
  }
  if (c.imperfection) {
    for (const std::string& o : c.imperfection->overrides) overrides.push_back(o);
  }
  const runner::Scenario scenario = runner::load_scenario(file, overrides);
  const runner::RunResult run = detail::run_with_controller(scenario, c.controller);
  Outcome o;
  o.scenario = scenario.name;
  o.car = stem(c.vehicle_file);
  o.model = c.model;
  o.controller = c.controller;
  o.imperfection = c.imperfection ? c.imperfection->name : nominal;
  o.group = c.imperfection ? c.imperfection->group : "";
  o.stop = run.simulation.stop_reason;
  const Metrics& m = run.metrics;
  o.above = static_cast<long>(m.angle_violations) + m.held_rate_violations +
            m.held_acceleration_violations;
  o.max_e = settle_time_s > 0.0 ? 0.0 : m.max_abs_rear_error_m;
  if (settle_time_s > 0.0) {
    for (const TraceSample& r : run.simulation.trace) {
      if (r.time_s >= settle_time_s) o.max_e = std::max(o.max_e, std::abs(r.lateral_error_m));
    }
  }
  // A run that stopped on an error or a non-finite value counts as lost, whatever its figure.
  if (o.stop == "controller_error" || o.stop == "non_finite") {
    o.max_e = std::numeric_limits<double>::infinity();
  }
  return o;
}

void require(bool holds, const std::string& message) {
  if (!holds) throw std::invalid_argument("RobustnessOptions: " + message);
}

}  // namespace

std::vector<Imperfection> default_imperfections() {
  std::vector<Imperfection> list;
  const auto add = [&list](std::string name, const char* group, std::string key, double value) {
    list.push_back({std::move(name), group, {key + "=" + ResultsTable::number(value, 4)}});
  };
  const auto text = [](double value, int digits) { return ResultsTable::number(value, digits); };
  // Disturbances: a misaligned rack, a road sloping across, a crosswind (steady, and a step from
  // 3 s on). 400 N is 0.5 rho v^2 c_y A for a 20 m/s wind across a saloon with c_y A = 1.7 m^2
  // (an assumed side-force area); its centre of pressure 0.5 m ahead of the CG gives 200 N m.
  for (const double offset : {0.005, -0.005, 0.01, -0.01, 0.02, -0.02}) {
    add("rack offset " + text(offset, 3) + " rad", "disturbance", "simulation.steering_offset_rad",
        offset);
  }
  for (const double grade : {0.01, 0.02, 0.03, -0.02}) {
    add("crossfall " + text(100.0 * grade, 0) + " %", "disturbance", "simulation.crossfall", grade);
  }
  list.push_back(
      {"crosswind 400 N",
       "disturbance",
       {"simulation.side_force.force_n=400", "simulation.side_force.yaw_moment_nm=200"}});
  list.push_back({"gust 800 N at 3 s",
                  "disturbance",
                  {"simulation.side_force.force_n=800", "simulation.side_force.yaw_moment_nm=400",
                   "simulation.side_force.start_s=3"}});
  // Model errors: the plant differs from the vehicle file the controller is given.
  for (const double mass : {1.3, 0.9}) {
    add("mass x" + text(mass, 1), "model error", "simulation.plant_scales.mass", mass);
  }
  for (const double stiffness : {1.25, 0.75}) {
    add("cornering stiffness x" + text(stiffness, 2), "model error",
        "simulation.plant_scales.cornering_stiffness", stiffness);
  }
  add("friction x0.6", "model error", "simulation.plant_scales.friction", 0.6);
  for (const double shift : {0.1, -0.1}) {
    add("CG " + text(shift, 1) + " L forward", "model error", "simulation.plant_scales.cg_position",
        shift);
  }
  for (const double bandwidth : {0.5, 1.5}) {
    add("actuator bandwidth x" + text(bandwidth, 1), "model error",
        "simulation.plant_actuator_scales.bandwidth", bandwidth);
  }
  // Sensing: a late pose (not told to the controller), a slow pose, biased sensors.
  for (const double latency : {0.03, 0.06, 0.1}) {
    add("pose " + text(1000.0 * latency, 0) + " ms late", "sensing", "simulation.pose_latency_s",
        latency);
  }
  add("pose at 10 Hz", "sensing", "simulation.pose_rate_hz", 10.0);
  for (const double offset : {0.01, -0.01}) {
    add("angle sensor " + text(offset, 2) + " rad", "sensing",
        "simulation.steering_angle_sensor_offset_rad", offset);
  }
  add("gyro bias 0.005 rad/s", "sensing", "simulation.gyro_bias_radps", 0.005);
  return list;
}

void RobustnessOptions::validate() const {
  require(!scenarios.empty(), "scenarios is empty");
  for (const RobustnessScenario& scenario : scenarios) {
    require(!scenario.file.empty(), "a scenario has no file");
    require(scenario.settle_time_s >= 0.0 && scenario.settle_time_s <= 1e4,
            scenario.file + ": settle_time_s = " + ResultsTable::number(scenario.settle_time_s) +
                " must be in [0, 1e4] s");
  }
  require(!vehicle_files.empty(), "vehicle_files is empty");
  require(!models.empty(), "models is empty");
  for (const std::string& model : models) {
    require(model == "dynamic" || model == "double_track",
            "models contains '" + model + "'; expected dynamic or double_track");
  }
  require(!controllers.empty(), "controllers is empty");
  const std::vector<std::string> known = road_suite_controller_names();
  for (const std::string& name : controllers) {
    require(std::find(known.begin(), known.end(), name) != known.end(),
            "controllers contains '" + name +
                "', which is neither 'certified' nor a comparison controller");
  }
  require(!imperfections.empty(), "imperfections is empty");
  for (const Imperfection& imperfection : imperfections) {
    require(!imperfection.name.empty() && imperfection.name != nominal,
            "an imperfection needs a name other than 'nominal'");
    require(!imperfection.overrides.empty(),
            "imperfection '" + imperfection.name + "' has no overrides");
  }
  require(threads >= 1 && threads <= 256,
          "threads = " + std::to_string(threads) + " must be in [1, 256]");
}

RobustnessResult run_robustness_comparison(const RobustnessOptions& options) {
  options.validate();
  std::vector<Case> cases;
  for (const RobustnessScenario& scenario : options.scenarios) {
    for (const std::string& vehicle : options.vehicle_files) {
      for (const std::string& model : options.models) {
        for (const std::string& controller : options.controllers) {
          cases.push_back({&scenario, vehicle, model, controller, nullptr});
          for (const Imperfection& imperfection : options.imperfections) {
            cases.push_back({&scenario, vehicle, model, controller, &imperfection});
          }
        }
      }
    }
  }
  std::vector<Outcome> outcomes(cases.size());
  detail::run_cases_in_parallel(cases.size(), options.threads, "robustness comparison",
                                [&](std::size_t i) { outcomes[i] = run_case(cases[i]); });

  using Key = std::tuple<std::string, std::string, std::string, std::string>;
  std::map<std::tuple<std::string, std::string, std::string, std::string, std::string>, double>
      figure;  // scenario, car, model, imperfection, controller -> max |e|
  for (const Outcome& o : outcomes) {
    figure[{o.scenario, o.car, o.model, o.imperfection, o.controller}] = o.max_e;
  }
  RobustnessResult result;
  ResultsTable& runs = result.runs;
  runs.title = "Robustness: every controller under each imperfection (rear axle)";
  runs.header = {"scenario",
                 "car",
                 "plant",
                 "imperfection",
                 "group",
                 "controller",
                 "max_abs_e_m",
                 "nominal_max_abs_e_m",
                 "held_above_limits",
                 "stop"};
  for (const Outcome& o : outcomes) {
    runs.rows.push_back(
        {o.scenario, o.car, plant_name(o.model), o.imperfection, o.group, o.controller,
         ResultsTable::number(o.max_e),
         ResultsTable::number(figure[{o.scenario, o.car, o.model, nominal, o.controller}]),
         std::to_string(o.above), o.stop});
  }
  runs.notes = {
      "max_abs_e_m: the rear axle's max |e| over the run (from the scenario's settle time on); "
      "nominal_max_abs_e_m: the same controller without the imperfection; inf: the run "
      "stopped on an error. held_above_limits: held-command samples above the car's angle, rate "
      "or acceleration limit. The imperfection acts on the plant or the sensors only. certified: "
      "the scenario's own controller with the car's schedule; every other row is a baseline "
      "behind the second-order limiter (docs/baselines.md)."};

  ResultsTable& summary = result.summary;
  summary.title = "Robustness: the certified route against the best baseline";
  summary.header = {"scenario",        "car",         "plant",           "imperfection",
                    "certified_m",     "nominal_m",   "within_1.2x+2cm", "best_baseline",
                    "best_baseline_m", "at_most_best"};
  std::map<Key, std::pair<double, std::string>> best;
  for (const Outcome& o : outcomes) {
    if (o.controller == certified) continue;
    const Key key{o.scenario, o.car, o.model, o.imperfection};
    const auto found = best.find(key);
    if (found == best.end() || o.max_e < found->second.first) best[key] = {o.max_e, o.controller};
  }
  int within = 0, at_most = 0, total = 0;
  for (const Outcome& o : outcomes) {
    if (o.controller != certified || o.imperfection == nominal) continue;
    const double own = o.max_e;
    const double reference = figure[{o.scenario, o.car, o.model, nominal, certified}];
    const bool close = own <= target_factor * reference + target_margin_m;
    const auto found = best.find({o.scenario, o.car, o.model, o.imperfection});
    const bool has_best = found != best.end();
    const bool beats = has_best && own <= found->second.first;
    ++total;
    within += close ? 1 : 0;
    at_most += beats ? 1 : 0;
    summary.rows.push_back({o.scenario, o.car, plant_name(o.model), o.imperfection,
                            ResultsTable::number(own), ResultsTable::number(reference),
                            close ? "yes" : "no", has_best ? found->second.second : "",
                            has_best ? ResultsTable::number(found->second.first) : "",
                            has_best ? (beats ? "yes" : "no") : ""});
  }
  summary.notes = {
      "certified_m: the certified route's max |e| under the imperfection; nominal_m: without "
      "it. within_1.2x+2cm: certified_m <= 1.2 nominal_m + 0.02 m; at_most_best: certified_m <= "
      "the best baseline's max |e| under the same imperfection. Over the " +
      std::to_string(total) + " cases: " + std::to_string(within) + " within 1.2x + 2 cm, " +
      std::to_string(at_most) + " at most the best baseline."};
  return result;
}

}  // namespace smoothsteer
