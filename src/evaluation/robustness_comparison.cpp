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

constexpr const char* certified = "certified";
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
  runner::RunResult run;
  if (c.controller == certified) {
    run = runner::run_scenario(scenario);
  } else {
    auto controller =
        make_comparison_controller(c.controller, detail::comparison_setup_for(scenario));
    run = runner::run_scenario(scenario, *controller);
  }
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
  for (const double offset : {0.005, -0.005, 0.01, -0.01, 0.02, -0.02}) {
    list.push_back({"rack offset " + ResultsTable::number(offset, 3) + " rad",
                    "disturbance",
                    {"simulation.steering_offset_rad=" + ResultsTable::number(offset, 3)}});
  }
  // A plant curvature of g sin(phi) / v^2 is crossfall phi at speed v: 0.001 1/m is about 2 %
  // at 15 m/s.
  for (const double curvature : {0.001, -0.001, 0.002}) {
    list.push_back(
        {"plant curvature " + ResultsTable::number(curvature, 3) + " 1/m",
         "disturbance",
         {"simulation.plant_curvature_disturbance=" + ResultsTable::number(curvature, 3)}});
  }
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
