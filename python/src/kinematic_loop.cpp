// The kinematic closed loop (include/smoothsteer/sim/kinematic_closed_loop.hpp): a controller
// and the kinematic car at constant speed, the whole loop in C++ and without the GIL.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <functional>
#include <vector>

#include "bindings.hpp"
#include "smoothsteer/sim/kinematic_closed_loop.hpp"

namespace smoothsteer::python {
namespace {

py::dict loop(SteeringController& controller, const py::tuple& start, double speed_mps,
              double period_s, double duration_s, double wheelbase_m) {
  if (py::len(start) != 3) {
    throw py::value_error("simulate_kinematic: start must be (x [m], y [m], heading [rad])");
  }
  const Pose2 pose{{start[0].cast<double>(), start[1].cast<double>()}, start[2].cast<double>()};
  KinematicLoopOptions options;
  options.wheelbase_m = wheelbase_m;
  options.speed_mps = speed_mps;
  options.period_s = period_s;
  options.duration_s = duration_s;
  KinematicLoopResult result;
  {
    py::gil_scoped_release unlocked;
    (void)controller.reset(0.0);  // 0 is always accepted
    result = run_kinematic_closed_loop(controller, pose, options);
  }
  if (result.status != Status::ok) throw ControllerError(result.status);
  py::dict trace;
  const auto column = [&](const char* name,
                          const std::function<double(const KinematicTraceSample&)>& value) {
    py::array_t<double> values(static_cast<py::ssize_t>(result.trace.size()));
    auto out = values.mutable_unchecked<1>();
    for (std::size_t i = 0; i < result.trace.size(); ++i) {
      out(static_cast<py::ssize_t>(i)) = value(result.trace[i]);
    }
    trace[name] = values;
  };
  using S = const KinematicTraceSample&;
  column("t", [](S s) { return s.time_s; });
  column("s", [](S s) { return s.distance_m; });
  column("x", [](S s) { return s.pose.position.x; });
  column("y", [](S s) { return s.pose.position.y; });
  column("psi", [](S s) { return s.pose.heading_rad; });
  column("delta_cmd", [](S s) { return s.output.steering_angle_rad; });
  column("delta_cmd_rate", [](S s) { return s.output.steering_rate_radps; });
  column("delta_cmd_acc", [](S s) { return s.output.steering_acceleration_radps2; });
  column("e", [](S s) { return s.output.diagnostics.lateral_error_m; });
  column("heading_error", [](S s) { return s.output.diagnostics.heading_error_rad; });
  column("e_front", [](S s) { return s.output.diagnostics.front_lateral_error_m; });
  column("e_lead", [](S s) { return s.output.diagnostics.lead_lateral_error_m; });
  return trace;
}

}  // namespace

void bind_kinematic_loop(py::module_& m) {
  m.def("simulate_kinematic", &loop, py::arg("controller"), py::arg("start"), py::arg("speed_mps"),
        py::arg("period_s") = 0.02, py::arg("duration_s") = 60.0, py::arg("wheelbase_m") = 2.7,
        "The controller (reset first) drives the kinematic car from start (x [m], y [m], "
        "heading [rad]) at a constant speed [m/s], period [s], for duration [s]. Returns a dict "
        "of numpy arrays: t [s], s [m], x, y [m], psi [rad], delta_cmd [rad], delta_cmd_rate "
        "[rad/s], delta_cmd_acc [rad/s^2], e, e_front, e_lead [m], heading_error [rad]. The "
        "loop runs in C++ without the GIL.");
}

}  // namespace smoothsteer::python
