// Exceptions: the library's messages reach Python unchanged. std::invalid_argument becomes
// ValueError and std::runtime_error RuntimeError (pybind11's defaults); the errors a caller may
// want to catch on their own get their own classes.

#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "smoothsteer/io/config_section.hpp"
#include "smoothsteer/tuning/gain_schedule.hpp"

namespace smoothsteer::python {

void bind_errors(py::module_& m) {
  // A bad scenario, vehicle or waypoint file: the message names the file, the key and the rule.
  py::register_exception<io::ConfigError>(m, "ConfigError", PyExc_ValueError);
  // The limits cannot be certified at some speed: the message names that speed and the limit.
  py::register_exception<InfeasibleLimits>(m, "InfeasibleLimits", PyExc_ValueError);
  // A real-time call returned an error status (smoothsteer::Status), e.g. for a NaN pose.
  py::register_exception<ControllerError>(m, "ControllerError", PyExc_RuntimeError);
}

}  // namespace smoothsteer::python
