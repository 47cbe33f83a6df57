// Tuning from actuator limits (include/smoothsteer/tuning/): VehicleLimits, TuningOptions,
// the gain schedule over speed, parameters_for_vehicle() and ScheduledController.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "smoothsteer/io/schedule_files.hpp"
#include "smoothsteer/tuning/gain_schedule.hpp"
#include "smoothsteer/tuning/path_demand.hpp"
#include "smoothsteer/tuning/scheduled_controller.hpp"
#include "smoothsteer/tuning/speed_compensation.hpp"

namespace smoothsteer::python {
namespace {

//! The schedule's columns as numpy arrays, keyed like the CSV of `smoothsteer tune`.
py::dict schedule_arrays(const GainSchedule& schedule) {
  const auto& entries = schedule.entries();
  py::dict columns;
  const auto column = [&](const char* name, const std::function<double(const ScheduleEntry&)>& f) {
    py::array_t<double> values(static_cast<py::ssize_t>(entries.size()));
    auto out = values.mutable_unchecked<1>();
    for (std::size_t i = 0; i < entries.size(); ++i)
      out(static_cast<py::ssize_t>(i)) = f(entries[i]);
    columns[name] = values;
  };
  column("speed_mps", [](const ScheduleEntry& e) { return e.speed_mps; });
  column("region", [](const ScheduleEntry& e) { return static_cast<double>(e.region); });
  column("fictive_wheelbase_m", [](const ScheduleEntry& e) { return e.fictive_wheelbase_m; });
  column("lead_wheelbase_m", [](const ScheduleEntry& e) { return e.lead_wheelbase_m; });
  column("lead_curvature_bound", [](const ScheduleEntry& e) { return e.lead_curvature_bound; });
  column("k_rob", [](const ScheduleEntry& e) { return e.k_rob; });
  column("feedforward_curvature_bound",
         [](const ScheduleEntry& e) { return e.feedforward_curvature_bound; });
  column("feedforward_curvature_rate",
         [](const ScheduleEntry& e) { return e.feedforward_curvature_rate; });
  column("max_steering_angle_rad", [](const ScheduleEntry& e) { return e.max_steering_angle_rad; });
  column("max_steering_rate_radps",
         [](const ScheduleEntry& e) { return e.max_steering_rate_radps; });
  column("max_steering_acceleration_radps2",
         [](const ScheduleEntry& e) { return e.max_steering_acceleration_radps2; });
  return columns;
}

//! The path's curvature and curvature rate raise the options' bounds, as in `tune --path`.
void add_path_demand(TuningOptions& options, const std::shared_ptr<Path>& path) {
  apply_path_demand(options, path);
}

GainSchedule tune(const VehicleLimits& vehicle, const std::vector<double>& speeds,
                  const std::shared_ptr<Path>& path, TuningOptions options) {
  add_path_demand(options, path);
  py::gil_scoped_release unlocked;  // the box route builds a static map: seconds
  if (options.certificate == Certificate::feedforward) {
    return compute_feedforward_schedule(vehicle, options, speeds);
  }
  StaticMapOptions map_options;
  map_options.max_steering_angle_rad =
      std::max(map_options.max_steering_angle_rad, std::min(1.49, vehicle.max_steering_angle_rad));
  return compute_gain_schedule(vehicle, options, speeds, StaticMap(map_options));
}

}  // namespace

void bind_tuning(py::module_& m) {
  using V = VehicleLimits;
  py::class_<V>(m, "VehicleLimits",
                "The car's wheelbase and steering limits (paper Sec. II-C, C1-C3), SI units; "
                "keyword arguments set any field.")
      .def(py::init(&from_keywords<V>))
      .def_readwrite("wheelbase_m", &V::wheelbase_m, "lambda_veh [m]")
      .def_readwrite("max_steering_angle_rad", &V::max_steering_angle_rad, "C1 [rad]")
      .def_readwrite("max_steering_rate_radps", &V::max_steering_rate_radps, "C2 [rad/s]")
      .def_readwrite("max_steering_acceleration_radps2", &V::max_steering_acceleration_radps2,
                     "C3 [rad/s^2]; inf = none")
      .def_readwrite("max_lateral_acceleration_mps2", &V::max_lateral_acceleration_mps2,
                     "friction limit mu g [m/s^2]; inf = none")
      .def("validate", &V::validate)
      .def_static("from_file", &io::load_vehicle_limits, py::arg("yaml_path"),
                  "Reads vehicles/*.yaml (ValueError naming the file and key).");

  py::enum_<Certificate>(m, "Certificate")
      .value("box", Certificate::box, "the paper's route: worst case over the invariant box")
      .value("feedforward", Certificate::feedforward, "curvature feedforward + switching part");

  using T = TuningOptions;
  py::class_<T>(m, "TuningOptions", "Options of the tuner (docs/tuning.md); keyword arguments.")
      .def(py::init(&from_keywords<T>))
      .def_readwrite("certificate", &T::certificate)
      .def_readwrite("order", &T::order, "n: 1 or 2")
      .def_readwrite("max_longitudinal_acceleration_mps2", &T::max_longitudinal_acceleration_mps2,
                     "largest |dv/dt| to cover [m/s^2]")
      .def_readwrite("min_lead_curvature_bound", &T::min_lead_curvature_bound, "[1/m]")
      .def_readwrite("matched_disturbance_curvature", &T::matched_disturbance_curvature, "[1/m]")
      .def_readwrite("path_curvature_bound", &T::path_curvature_bound, "[1/m]")
      .def_readwrite("path_curvature_rate_bound", &T::path_curvature_rate_bound, "[1/m^2]")
      .def_readwrite("feedforward_headroom", &T::feedforward_headroom,
                     "kbar_ff over the path's largest curvature, in [1, 3]")
      .def_property(
          "reference_path",
          [](const T& options) { return std::const_pointer_cast<Path>(options.reference_path); },
          [](T& options, std::shared_ptr<Path> path) { options.reference_path = std::move(path); },
          "the path whose lead-wheel curvature rate L_ff covers (None: unknown)")
      .def_readwrite("feedforward_rate_margin", &T::feedforward_rate_margin)
      .def_readwrite("feedforward_rate_share", &T::feedforward_rate_share)
      .def_readwrite("feedforward_ramp_length_m", &T::feedforward_ramp_length_m, "[m]")
      .def_readwrite("switching_floor_share", &T::switching_floor_share)
      .def_readwrite("k_rob_floor", &T::k_rob_floor)
      .def_readwrite("k_rob_ceiling", &T::k_rob_ceiling)
      .def_readwrite("base", &T::base, "template ControllerParameters")
      .def("validate", &T::validate);

  py::class_<GainSchedule>(m, "GainSchedule", "Parameters over speed for ScheduledController.")
      .def_property_readonly("vehicle", &GainSchedule::vehicle)
      .def_property_readonly("max_speed_mps", &GainSchedule::max_speed_mps, "[m/s]")
      .def("parameters_at", &GainSchedule::parameters_at, py::arg("speed_mps"),
           "ControllerParameters at |v| [m/s] (conservative interpolation)")
      .def("arrays", &schedule_arrays,
           "The schedule as a dict of numpy arrays (the columns of `smoothsteer tune`).")
      .def_static("from_csv", &io::read_schedule_csv, py::arg("csv_path"),
                  py::arg("base") = ControllerParameters{}, "Reads a `smoothsteer tune` CSV.");

  m.def("_tune", &tune, py::arg("vehicle"), py::arg("speeds"), py::arg("path"), py::arg("options"));
  m.def(
      "parameters_for_vehicle",
      [](const VehicleLimits& vehicle, double speed_mps, const std::shared_ptr<Path>& path,
         const py::kwargs& keywords) {
        TuningOptions options = from_keywords<TuningOptions>(keywords);
        add_path_demand(options, path);
        return parameters_for_vehicle(vehicle, speed_mps, options);
      },
      py::arg("vehicle"), py::arg("speed_mps"), py::arg("path") = nullptr,
      "Certified ControllerParameters for the car up to speed_mps [m/s]; `path` (or the "
      "TuningOptions keywords path_curvature_bound [1/m], path_curvature_rate_bound [1/m^2]) "
      "gives the curvature to follow. Raises InfeasibleLimits naming the binding limit.");

  py::class_<SpeedCompensation>(
      m, "SpeedCompensation",
      "The Smith delay and the catch-up over speed (docs/vehicle_dynamics.md section 8).")
      .def(py::init<>())
      .def_readwrite("actuator_group_delay_s", &SpeedCompensation::actuator_group_delay_s)
      .def_readwrite("slip_gradient_sum_s2pm", &SpeedCompensation::slip_gradient_sum_s2pm)
      .def_readwrite("design_curvature_per_m", &SpeedCompensation::design_curvature_per_m)
      .def_readwrite("friction_limit_mps2", &SpeedCompensation::friction_limit_mps2)
      .def("friction_usage", &SpeedCompensation::friction_usage, py::arg("speed_mps"))
      .def("delay_s", &SpeedCompensation::delay_s, py::arg("speed_mps"))
      .def("catch_up", &SpeedCompensation::catch_up, py::arg("speed_mps"))
      .def("validate", &SpeedCompensation::validate);

  py::class_<ScheduledController, SteeringController>(
      m, "ScheduledController", "The lead-wheel controller with parameters scheduled over speed.")
      .def(py::init([](const GainSchedule& schedule, std::shared_ptr<Path> path,
                       std::optional<SpeedCompensation> compensation) {
             return std::make_unique<ScheduledController>(schedule, std::move(path), compensation);
           }),
           py::arg("schedule"), py::arg("path"), py::arg("compensation") = py::none())
      .def_property_readonly("schedule", &ScheduledController::schedule)
      .def_property_readonly("compensation", &ScheduledController::compensation)
      .def("parameters_at", &ScheduledController::parameters_at, py::arg("speed_mps"));
}

}  // namespace smoothsteer::python
