// The comparison controllers (include/smoothsteer/baselines/comparison_controllers.hpp), each
// wrapped in the SaturatedController that clamps what it does not respect itself.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <limits>
#include <memory>
#include <string>

#include "bindings.hpp"
#include "smoothsteer/baselines/comparison_controllers.hpp"

namespace smoothsteer::python {

void bind_baselines(py::module_& m) {
  py::class_<SaturationStatistics>(m, "SaturationStatistics",
                                   "How often and by how much the limits clamped the command.")
      .def_readonly("updates", &SaturationStatistics::updates)
      .def_readonly("angle_limited", &SaturationStatistics::angle_limited)
      .def_readonly("rate_limited", &SaturationStatistics::rate_limited)
      .def_readonly("max_angle_excess_rad", &SaturationStatistics::max_angle_excess_rad, "[rad]")
      .def_readonly("acceleration_limited", &SaturationStatistics::acceleration_limited)
      .def_readonly("limited", &SaturationStatistics::limited, "updates with any clamp")
      .def_readonly("max_rate_excess_radps", &SaturationStatistics::max_rate_excess_radps,
                    "[rad/s]")
      .def_readonly("max_acceleration_excess_radps2",
                    &SaturationStatistics::max_acceleration_excess_radps2, "[rad/s^2]")
      .def_property_readonly("limited_fraction", &SaturationStatistics::limited_fraction);

  py::class_<SaturatedController, SteeringController>(
      m, "ComparisonController",
      "A controller of the comparison (docs/baselines.md) behind the common steering limits.")
      .def(py::init([](const std::string& name, std::shared_ptr<Path> path, double wheelbase_m,
                       double nominal_speed_mps, double max_steering_angle_rad,
                       double max_steering_rate_radps, double k_rob, double lead_wheelbase_m,
                       double max_steering_acceleration_radps2) {
             ComparisonSetup setup;
             setup.path = std::move(path);
             setup.wheelbase_m = wheelbase_m;
             setup.nominal_speed_mps = nominal_speed_mps;
             setup.limits.angle_rad = max_steering_angle_rad;
             setup.limits.rate_radps = max_steering_rate_radps;
             setup.limits.acceleration_radps2 = max_steering_acceleration_radps2;
             setup.k_rob = k_rob;
             setup.lead_wheelbase_m = lead_wheelbase_m;
             return make_comparison_controller(name, setup);
           }),
           py::arg("name"), py::arg("path"), py::arg("wheelbase_m") = 2.7,
           py::arg("nominal_speed_mps") = 10.0, py::arg("max_steering_angle_rad") = 0.5,
           py::arg("max_steering_rate_radps") = 0.6, py::arg("k_rob") = 0.3,
           py::arg("lead_wheelbase_m") = 1.0,
           py::arg("max_steering_acceleration_radps2") = std::numeric_limits<double>::infinity(),
           "name: one of comparison_controller_names(); wheelbase [m]; the speed [m/s] that turns "
           "the rate limit into a bound per metre; angle [rad] and rate [rad/s] limits; k_rob "
           "of the sliding-mode controllers; lambda_l [m] of proposed_c1; the acceleration limit "
           "[rad/s^2] of the second-order limiter (inf: none). ValueError for an unknown name "
           "(the message lists the known ones) or an invalid limit.")
      .def_property_readonly("saturation", &SaturatedController::saturation);

  m.def("comparison_controller_names", &comparison_controller_names,
        "Names accepted by ComparisonController, in table order.");
}

}  // namespace smoothsteer::python
