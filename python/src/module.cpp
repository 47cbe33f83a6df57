// The extension module _smoothsteer: Python bindings of smoothsteer (docs/python.md).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "bindings.hpp"
#include "smoothsteer/evaluation/controller_registration.hpp"
#include "smoothsteer/runner/run_output.hpp"

namespace smoothsteer::python {

Vec2 to_vec2(const py::handle& point, const char* argument) {
  if (!py::hasattr(point, "__len__") || !py::hasattr(point, "__getitem__")) {
    throw py::type_error(std::string(argument) + ": expected two numbers (x, y) in metres");
  }
  if (py::len(point) != 2) {
    throw py::type_error(std::string(argument) + ": expected two numbers (x, y) in metres, got " +
                         std::to_string(py::len(point)));
  }
  return {point[py::int_(0)].cast<double>(), point[py::int_(1)].cast<double>()};
}

void set_attributes(py::object& target, const py::kwargs& keywords) {
  for (const auto& [key, value] : keywords) {
    const std::string name = py::str(key);
    if (name.starts_with("_") || !py::hasattr(py::type::of(target), key)) {
      throw py::type_error(std::string(py::str(py::type::of(target).attr("__name__"))) +
                           ": unknown keyword '" + name + "'");
    }
  }
  // `enabled` last: a compensation's value switches its group, and an `enabled` given with it
  // says what the caller wants whatever the keywords' order.
  for (const auto& [key, value] : keywords) {
    if (std::string(py::str(key)) != "enabled") py::setattr(target, key, value);
  }
  if (keywords.contains("enabled")) py::setattr(target, "enabled", keywords["enabled"]);
}

}  // namespace smoothsteer::python

PYBIND11_MODULE(_smoothsteer, m) {
  using namespace smoothsteer::python;
  m.doc() = "smoothsteer: n-smooth, differentially bounded path-tracking control (SI units)";
  m.attr("__version__") = smoothsteer::runner::tool_version();
  // pybind11 looks numpy's C API up once, in a function-local static, on the first array it
  // makes. Made from two threads at once, that look-up deadlocks (one thread holds the GIL and
  // waits for the static, the other holds the static and waits for the GIL in numpy's import).
  // So the first array is made here, at import, in one thread.
  pybind11::array_t<double> first_array(1);
  (void)first_array;
  // Scenario files may name every comparison controller, as in the CLI.
  smoothsteer::register_comparison_controllers();
  bind_errors(m);
  bind_path(m);
  bind_controller(m);
  bind_cusps(m);
  bind_kinematic_loop(m);
  bind_baselines(m);
  bind_tuning(m);
  bind_system(m);
  bind_evaluation(m);
  bind_simulation_parameters(m);
  bind_scenario(m);
}
