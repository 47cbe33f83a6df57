// The reaching benchmark of Tab. roc_vx / Fig. benchmark_e (include/smoothsteer/evaluation/):
// the numerically optimal manoeuvre (Ipopt), HOSM, and the benchmark's own settings; the
// robustness and tight-corner comparisons and the kinetic tracking reference.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "smoothsteer/baselines/hosm_controller.hpp"
#include "smoothsteer/evaluation/kinetic_reference.hpp"
#include "smoothsteer/evaluation/optimal_reaching.hpp"
#include "smoothsteer/evaluation/reaching_benchmark.hpp"
#include "smoothsteer/evaluation/robustness_comparison.hpp"
#include "smoothsteer/evaluation/tight_corners.hpp"

namespace smoothsteer::python {
namespace {

py::array_t<double> array(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

//! A table's rows as dicts keyed by its header (every cell a string, as in its CSV).
py::list table_rows(const ResultsTable& table) {
  py::list rows;
  for (const std::vector<std::string>& row : table.rows) {
    py::dict entry;
    for (std::size_t k = 0; k < row.size() && k < table.header.size(); ++k) {
      entry[py::str(table.header[k])] = row[k];
    }
    rows.append(entry);
  }
  return rows;
}

//! A comparison's tables as Python returns them: {'runs', 'summary', 'summary_notes'}.
py::dict comparison_tables(const ResultsTable& runs, const ResultsTable& summary) {
  py::dict tables;
  tables["runs"] = table_rows(runs);
  tables["summary"] = table_rows(summary);
  tables["summary_notes"] = summary.notes;
  return tables;
}

py::dict compare_robustness(const std::vector<std::pair<std::string, double>>& scenarios,
                            const std::vector<std::string>& vehicles,
                            const std::vector<std::string>& models,
                            const std::vector<std::string>& controllers,
                            const std::optional<std::vector<Imperfection>>& imperfections,
                            int threads) {
  RobustnessOptions options;
  for (const auto& [file, settle] : scenarios) options.scenarios.push_back({file, settle});
  options.vehicle_files = vehicles;
  options.models = models;
  options.controllers = controllers;
  if (imperfections) options.imperfections = *imperfections;
  options.threads = threads;
  RobustnessResult result;
  {
    py::gil_scoped_release unlocked;  // minutes for the whole matrix
    result = run_robustness_comparison(options);
  }
  return comparison_tables(result.runs, result.summary);
}

py::dict compare_tight_corners(const std::string& scenario_directory,
                               const std::vector<std::string>& baselines, int threads) {
  TightCornerOptions options;
  options.corners = shipped_tight_corners(scenario_directory);
  options.baselines = baselines;
  options.threads = threads;
  TightCornerResult result;
  {
    py::gil_scoped_release unlocked;  // about 20 s on two threads
    result = run_tight_corner_study(options);
  }
  return comparison_tables(result.table(), result.summary());
}

py::dict kinetic_reference(std::shared_ptr<const Path> path, const VehicleParameters& vehicle,
                           double speed_mps, double start_arc_length_m, double duration_s,
                           double time_step_s) {
  KineticReferenceProblem problem;
  problem.path = std::move(path);
  problem.vehicle = vehicle;
  problem.speed_mps = speed_mps;
  problem.start_arc_length_m = start_arc_length_m;
  problem.duration_s = duration_s;
  problem.time_step_s = time_step_s;
  KineticReference reference;
  KineticReferenceCheck check;
  {
    py::gil_scoped_release unlocked;  // Ipopt: about a second for 1000 intervals
    reference = solve_kinetic_reference(problem);
    check = resimulate_kinetic_reference(problem, reference);
  }
  py::dict result;
  result["converged"] = reference.converged;
  result["solver_status"] = reference.solver_status;
  result["max_abs_lateral_error_m"] = reference.max_abs_lateral_error_m;
  result["resimulated_max_abs_lateral_error_m"] = check.max_abs_lateral_error_m;
  result["time_s"] = array(reference.time_s);
  result["lateral_error_m"] = array(reference.lateral_error_m);
  result["steering_rad"] = array(reference.steering_rad);
  result["steering_rate_radps"] = array(reference.steering_rate_radps);
  result["steering_acceleration_radps2"] = array(reference.steering_acceleration_radps2);
  return result;
}

py::dict solve(const py::kwargs& keywords) {
  py::object problem_object = py::cast(ReachingProblem{});
  set_attributes(problem_object, keywords);
  const ReachingProblem problem = problem_object.cast<ReachingProblem>();
  ReachingSolution solution;
  {
    py::gil_scoped_release unlocked;  // Ipopt: a fraction of a second to seconds
    solution = solve_optimal_reaching(problem);
  }
  py::dict result;
  result["converged"] = solution.converged;
  result["solver_status"] = solution.solver_status;
  result["distance_m"] = solution.distance_m;
  result["arc_length_m"] = array(solution.arc_length_m);
  result["lateral_error_m"] = array(solution.lateral_error_m);
  result["heading_rad"] = array(solution.heading_rad);
  result["steering_rad"] = array(solution.steering_rad);
  result["steering_rate_per_m"] = array(solution.steering_rate_per_m);
  return result;
}

}  // namespace

void bind_evaluation(py::module_& m) {
  using R = ReachingProblem;
  py::class_<R>(m, "ReachingProblem", "Optimal reaching under C1 and C2 (paper Sec. IV-B).")
      .def(py::init<>())
      .def_readwrite("wheelbase_m", &R::wheelbase_m, "lambda [m]")
      .def_readwrite("steering_angle_bound_rad", &R::steering_angle_bound_rad, "C1 [rad]")
      .def_readwrite("steering_rate_bound_per_m", &R::steering_rate_bound_per_m, "C2 [rad/m]")
      .def_readwrite("initial_lateral_error_m", &R::initial_lateral_error_m, "e(0) [m]")
      .def_readwrite("initial_heading_rad", &R::initial_heading_rad, "psi(0) [rad]")
      .def_readwrite("initial_steering_rad", &R::initial_steering_rad, "delta(0) [rad]")
      .def_readwrite("terminal_lateral_tolerance_m", &R::terminal_lateral_tolerance_m, "[m]")
      .def_readwrite("terminal_heading_tolerance_rad", &R::terminal_heading_tolerance_rad, "[rad]")
      .def_readwrite("terminal_steering_free", &R::terminal_steering_free)
      .def_readwrite("intervals", &R::intervals)
      .def_readwrite("max_iterations", &R::max_iterations)
      .def_readwrite("tolerance", &R::tolerance)
      .def_readwrite("exact_hessian", &R::exact_hessian);
  m.def("solve_optimal_reaching", &solve,
        "The shortest reaching manoeuvre (Ipopt) for ReachingProblem keyword fields: a dict with "
        "distance_m [m], converged, and node arrays arc_length_m [m], lateral_error_m [m], "
        "heading_rad [rad], steering_rad [rad], steering_rate_per_m [rad/m].");

  py::class_<Imperfection>(m, "Imperfection",
                           "A car's imperfection: scenario overrides acting on the plant only.")
      .def(py::init<std::string, std::string, std::vector<std::string>>(), py::arg("name"),
           py::arg("group"), py::arg("overrides"))
      .def_readwrite("name", &Imperfection::name)
      .def_readwrite("group", &Imperfection::group, "disturbance, model error or sensing")
      .def_readwrite("overrides", &Imperfection::overrides,
                     "--set entries, e.g. "
                     "'simulation.steering_offset_rad=0.01'");
  m.def("default_imperfections", &default_imperfections,
        "The imperfections of `smoothsteer compare robustness` (docs/results/robustness.md).");
  m.def("compare_robustness", &compare_robustness, py::arg("scenarios"),
        py::arg("vehicles") = std::vector<std::string>{"vehicles/passenger_car.yaml"},
        py::arg("models") = std::vector<std::string>{"dynamic"},
        py::arg("controllers") = std::vector<std::string>{"certified", "stanley"},
        py::arg("imperfections") = py::none(), py::arg("threads") = 1,
        "Every controller under each imperfection (smoothsteer compare robustness): scenarios "
        "as (file, settle_time_s) pairs. Returns {'runs': [...], 'summary': [...], "
        "'summary_notes': [...]}, rows as dicts of the CSV's columns. Raises ValueError naming "
        "the bad option.");

  m.def("compare_tight_corners", &compare_tight_corners,
        py::arg("scenario_directory") = "scenarios",
        py::arg("baselines") = std::vector<std::string>{}, py::arg("threads") = 1,
        "The tight corners against the best baseline and the two optimal-control references "
        "(smoothsteer compare corners, docs/corners.md); baselines empty: the tuning study's. "
        "Returns {'runs': [...], 'summary': [...], 'summary_notes': [...]}, rows as dicts of "
        "the CSV's columns. Raises ValueError naming the bad option.");
  m.def("solve_kinetic_reference", &kinetic_reference, py::arg("path"), py::arg("vehicle"),
        py::arg("speed_mps"), py::arg("start_arc_length_m") = 0.0, py::arg("duration_s") = 10.0,
        py::arg("time_step_s") = 0.02,
        "The least max |e| of the rear axle any steering reaches on the linear single track "
        "under the vehicle's steering limits (kinetic_reference.hpp): a dict with "
        "max_abs_lateral_error_m [m], its RK4 re-simulation, converged, solver_status and node "
        "arrays time_s, lateral_error_m, steering_rad, steering_rate_radps, and the held "
        "steering_acceleration_radps2 per interval. Raises ValueError naming the bad field.");

  using O = ReachingBenchmarkOptions;
  py::class_<O>(m, "ReachingBenchmarkOptions", "Settings of the reaching benchmark.")
      .def(py::init<>())
      .def_readonly("wheelbase_m", &O::wheelbase_m, "lambda [m]")
      .def_readonly("steering_angle_bound_rad", &O::steering_angle_bound_rad, "delta-bar [rad]")
      .def_readonly("initial_lateral_error_m", &O::initial_lateral_error_m, "e(0) [m]")
      .def_readonly("initial_headings_rad", &O::initial_headings_rad, "psi(0) [rad]")
      .def_readonly("lateral_tolerance_m", &O::lateral_tolerance_m, "[m]")
      .def_readonly("heading_tolerance_rad", &O::heading_tolerance_rad, "[rad]")
      .def_readonly("speed_mps", &O::speed_mps, "[m/s]")
      .def_readonly("period_s", &O::period_s, "[s]")
      .def_readonly("horizon_m", &O::horizon_m, "[m]");

  py::class_<HosmController, SteeringController>(
      m, "HosmController", "The constrained higher-order sliding-mode controller of Sec. IV-B.")
      .def(py::init([](std::shared_ptr<Path> path, double wheelbase_m,
                       double steering_angle_bound_rad, double steering_rate_bound_per_m,
                       double heading_bound_rad, double substep_m) {
             HosmParameters parameters;
             parameters.wheelbase_m = wheelbase_m;
             parameters.steering_angle_bound_rad = steering_angle_bound_rad;
             parameters.steering_rate_bound_per_m = steering_rate_bound_per_m;
             parameters.heading_bound_rad = heading_bound_rad;
             parameters.substep_m = substep_m;
             return std::make_unique<HosmController>(parameters, std::move(path));
           }),
           py::arg("path"), py::arg("wheelbase_m"), py::arg("steering_angle_bound_rad"),
           py::arg("steering_rate_bound_per_m"), py::arg("heading_bound_rad"),
           py::arg("substep_m") = 0.01,
           "lambda [m], delta-bar [rad], delta-bar' [rad/m], psi-bar [rad], sub-step [m].");
}

}  // namespace smoothsteer::python
