#pragma once
// The pieces of the Python module _smoothsteer (python/smoothsteer/__init__.py re-exports them).
// One function per part of the library; module.cpp calls them in order, so that a class is
// registered before the functions that take it.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/math/vec2.hpp"
#include "smoothsteer/status.hpp"

namespace smoothsteer::python {

namespace py = pybind11;

//! A real-time call returned an error status; Python sees smoothsteer.ControllerError, its
//! message "<call> returned <status>[: <what was wrong>]", as the CLI's names the input.
class ControllerError : public std::runtime_error {
 public:
  explicit ControllerError(Status status, const std::string& detail = "",
                           const std::string& call = "update()")
      : std::runtime_error(call + " returned " + to_string(status) +
                           (detail.empty() ? "" : ": " + detail)) {}
};

//! The first input of a control step outside ControllerInputRange, named with its value and
//! bound ("speed_mps = 10000 is outside ControllerInputRange: magnitude <= 1000 m/s"); empty if
//! every one is inside.
std::string input_range_detail(const ControllerInput& input);

//! ConfigError, InfeasibleLimits and ControllerError as Python exceptions.
void bind_errors(py::module_& m);
//! Path, PathPoint, PathProjection, PathBuilder.
void bind_path(py::module_& m);
//! ControllerParameters, ControllerOutput, SteeringController, LeadWheelController.
void bind_controller(py::module_& m);
//! The comparison controllers (baselines/comparison_controllers.hpp).
void bind_baselines(py::module_& m);
//! VehicleLimits, tune(), parameters_for_vehicle(), ScheduledController.
void bind_tuning(py::module_& m);
//! KinematicSingleTrack, Gear, PathPlan, CuspSequencer.
void bind_cusps(py::module_& m);
//! simulate_kinematic(): the kinematic closed loop.
void bind_kinematic_loop(py::module_& m);
//! solve_optimal_reaching(), HosmController, ReachingBenchmarkOptions.
void bind_evaluation(py::module_& m);
//! SimulationParameters, PlantScales, PlantActuatorScales, SideForce, scaled_plant_vehicle().
void bind_simulation_parameters(py::module_& m);
//! load_scenario(), run_scenario(), Scenario.
void bind_scenario(py::module_& m);
//! VehicleParameters, ActuatorParameters, SteeringSystem, make_steering_system().
void bind_system(py::module_& m);

//! A point from any sequence of two numbers (tuple, list, numpy array); TypeError otherwise.
Vec2 to_vec2(const py::handle& point, const char* argument);
//! Waypoints from an N x 2 array of x, y [m]; ValueError naming `where` otherwise.
std::vector<Vec2> waypoints_from(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
    const char* where = "Path.from_waypoints");
//! Sets the attributes of `target` (a bound object) from keyword arguments, `enabled` last; an
//! unknown name raises TypeError naming it and the class.
void set_attributes(py::object& target, const py::kwargs& keywords);
//! A default T with the attributes `keywords` names set (set_attributes): the keyword
//! constructor of the bound parameter structs.
template <typename T>
T from_keywords(const py::kwargs& keywords) {
  py::object value = py::cast(T{});
  set_attributes(value, keywords);
  return value.cast<T>();
}

}  // namespace smoothsteer::python
