// Scenario files and runs (include/smoothsteer/io/): the same objects as `smoothsteer run`, so
// that a trace from Python equals the CLI's trace.csv and the summary its summary.json.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "smoothsteer/io/trace_csv.hpp"
#include "smoothsteer/runner/run_output.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "smoothsteer/sim/metrics.hpp"

namespace smoothsteer::python {
namespace {

using TraceRow = std::array<double, io::trace_column_count>;

py::object from_json(const nlohmann::json& value) {
  const std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return py::module_::import("json").attr("loads")(text);
}

//! Simulates as runner::run_scenario(scenario, OutputDirectory&) does, keeping the rows in memory.
py::tuple run(const runner::Scenario& scenario) {
  std::vector<TraceRow> rows;
  runner::RunResult result;
  {
    py::gil_scoped_release unlocked;  // a run takes from milliseconds to seconds
    const std::unique_ptr<SteeringController> controller = runner::make_controller(scenario);
    MetricsAccumulator metrics(scenario.metrics);
    result.simulation =
        runner::simulate_scenario(scenario, *controller, [&](const TraceSample& sample) {
          rows.push_back(io::trace_row(sample));
          metrics.add(sample);
        });
    result.metrics = metrics.result();
    result.controller_name = controller->name();
  }
  py::dict trace;
  const auto& names = io::trace_column_names();
  for (std::size_t column = 0; column < names.size(); ++column) {
    py::array_t<double> values(static_cast<py::ssize_t>(rows.size()));
    auto out = values.mutable_unchecked<1>();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      out(static_cast<py::ssize_t>(i)) = rows[i][column];
    }
    trace[names[column]] = values;
  }
  return py::make_tuple(trace, from_json(runner::summary_json(scenario, result)));
}

//! The certified bounds of the scenario's controller if it is a (fixed) LeadWheelController:
//! rate [rad/m] and acceleration [rad/m^2] per metre travelled, and the box bound of the
//! invariant sets [rad/m]; None for any other controller (a schedule's bounds are in its CSV).
py::object certificate(const runner::Scenario& scenario) {
  const std::unique_ptr<LeadWheelController> lead_wheel =
      runner::make_lead_wheel_controller(scenario);
  if (!lead_wheel) return py::none();
  py::dict bounds;
  bounds["rate_per_meter"] = lead_wheel->certificate().rate_per_meter;
  bounds["acceleration_per_meter2"] = lead_wheel->certificate().acceleration_per_meter2;
  bounds["box_rate_per_meter"] = lead_wheel->bounds().steering_rate_per_meter;
  return bounds;
}

}  // namespace

void bind_scenario(py::module_& m) {
  py::class_<runner::Scenario, std::shared_ptr<runner::Scenario>>(
      m, "Scenario", "A loaded scenario file (docs/scenarios.md), every default filled in.")
      .def_readonly("name", &runner::Scenario::name)
      .def_readonly("description", &runner::Scenario::description)
      .def_readonly("file", &runner::Scenario::file)
      .def_readonly("model", &runner::Scenario::model, "'dynamic' or 'kinematic'")
      .def_readonly("vehicle_name", &runner::Scenario::vehicle_name)
      .def_readonly("overrides", &runner::Scenario::overrides)
      .def_property_readonly(
          "path", [](const runner::Scenario& s) { return std::const_pointer_cast<Path>(s.path); },
          "the reference Path")
      .def_property_readonly(
          "start",
          [](const runner::Scenario& s) {
            return py::make_tuple(s.start.position.x, s.start.position.y, s.start.heading_rad);
          },
          "rear-axle start pose (x [m], y [m], psi [rad])")
      .def_readonly("simulation", &runner::Scenario::simulation,
                    "the SimulationParameters the run uses (a copy to read or check)")
      .def_property_readonly(
          "plant_vehicle",
          [](const runner::Scenario& s) -> py::object {
            return s.plant_vehicle ? py::cast(*s.plant_vehicle) : py::none();
          },
          "simulation.plant_vehicle's VehicleParameters (the truth), None: the plant is the "
          "scenario's vehicle")
      .def_property_readonly(
          "parameters", [](const runner::Scenario& s) { return from_json(s.parameters); },
          "the resolved parameter set as a dict (summary.json's "
          "'parameters')");

  m.def("_load_scenario", &runner::load_scenario, py::arg("file"), py::arg("overrides"));
  m.def("_load_scenario_reusing_files", &runner::load_scenario_reusing_files, py::arg("file"),
        py::arg("overrides"));
  m.def("_run_scenario", &run, py::arg("scenario"));
  m.def("scenario_certificate", &certificate, py::arg("scenario"),
        "Certified bounds of a scenario's lead-wheel controller, per metre travelled: a dict "
        "with rate_per_meter [rad/m], acceleration_per_meter2 [rad/m^2] (inf where the "
        "parameters certify none) and box_rate_per_meter [rad/m]; None for other controllers.");
  m.def(
      "trace_column_names",
      [] {
        const auto& names = io::trace_column_names();
        return std::vector<std::string>(names.begin(), names.end());
      },
      "The columns of trace.csv, in order (docs/cli.md).");
}

}  // namespace smoothsteer::python
