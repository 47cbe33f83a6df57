// The car's steering system (include/smoothsteer/system/, tuning/vehicle_steering_system.hpp):
// the vehicle description, the side-slip observer's parameters, SteeringSystem and
// make_steering_system().

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "smoothsteer/io/vehicle_file.hpp"
#include "smoothsteer/system/steering_system.hpp"
#include "smoothsteer/tuning/vehicle_steering_system.hpp"

namespace smoothsteer::python {
namespace {

//! One control period; a non-ok status raises ControllerError.
SteeringSystemOutput update(SteeringSystem& system, const py::object& position, double heading_rad,
                            double speed_mps, double acceleration_mps2, double yaw_rate_radps,
                            double lateral_acceleration_mps2, double period_s,
                            std::optional<double> steering_angle_rad,
                            std::optional<double> rear_axle_side_slip_rad, double pose_age_s) {
  SteeringSystemInput input;
  input.rear_axle_position = to_vec2(position, "rear_axle_position");
  input.heading_rad = heading_rad;
  input.speed_mps = speed_mps;
  input.acceleration_mps2 = acceleration_mps2;
  input.yaw_rate_radps = yaw_rate_radps;
  input.lateral_acceleration_mps2 = lateral_acceleration_mps2;
  input.period_s = period_s;
  input.steering_angle_rad = steering_angle_rad;
  input.rear_axle_side_slip_rad = rear_axle_side_slip_rad;
  input.pose_age_s = pose_age_s;
  SteeringSystemOutput output;
  const Status status = system.update(input, output);
  if (status != Status::ok) {
    ControllerInput seen{input.rear_axle_position, heading_rad, speed_mps, acceleration_mps2,
                         period_s};
    seen.rear_axle_side_slip_rad = input.rear_axle_side_slip_rad.value_or(0.0);
    seen.pose_age_s = pose_age_s;
    throw ControllerError(status, input_range_detail(seen));
  }
  return output;
}

void bind_vehicle(py::module_& m) {
  py::enum_<ObserverTireModel>(m, "ObserverTireModel")
      .value("linear", ObserverTireModel::linear, "the linear single-track model")
      .value("magic_formula", ObserverTireModel::magic_formula,
             "each axle's Magic Formula (extended Kalman filter)");

  using Tire = TireParameters;
  py::class_<Tire>(m, "TireParameters", "Lateral Magic Formula of one axle; keyword arguments.")
      .def(py::init(&from_keywords<Tire>))
      .def_readwrite("stiffness_factor_b", &Tire::stiffness_factor_b, "B [1/rad]")
      .def_readwrite("shape_factor_c", &Tire::shape_factor_c, "C")
      .def_readwrite("friction_mu", &Tire::friction_mu, "D / Fz")
      .def_readwrite("curvature_factor_e", &Tire::curvature_factor_e, "E");

  using V = VehicleParameters;
  py::class_<V>(m, "VehicleParameters",
                "The vehicle file's parameters (single-track models), SI units; keyword "
                "arguments set any field. The double-track group is read from files only.")
      .def(py::init(&from_keywords<V>))
      .def_readwrite("mass_kg", &V::mass_kg)
      .def_readwrite("yaw_inertia_kgm2", &V::yaw_inertia_kgm2)
      .def_readwrite("cg_to_front_axle_m", &V::cg_to_front_axle_m, "lf [m]")
      .def_readwrite("cg_to_rear_axle_m", &V::cg_to_rear_axle_m, "lr [m]")
      .def_readwrite("cg_height_m", &V::cg_height_m)
      .def_readwrite("gravity_mps2", &V::gravity_mps2)
      .def_readwrite("front_tire", &V::front_tire)
      .def_readwrite("rear_tire", &V::rear_tire)
      .def_readwrite("max_steering_angle_rad", &V::max_steering_angle_rad)
      .def_readwrite("max_steering_rate_radps", &V::max_steering_rate_radps)
      .def_readwrite("max_steering_acceleration_radps2", &V::max_steering_acceleration_radps2,
                     "inf = none given")
      .def_readwrite("kinematic_below_mps", &V::kinematic_below_mps)
      .def_readwrite("kinetic_above_mps", &V::kinetic_above_mps)
      .def_readwrite("kinematic_relaxation_s", &V::kinematic_relaxation_s)
      .def_property_readonly("wheelbase_m", &V::wheelbase_m, "lf + lr [m]")
      .def_property_readonly("friction_limit_mps2", &V::friction_limit_mps2, "min(mu) g")
      .def_property_readonly("rear_slip_gradient", &V::rear_slip_gradient, "K_r [s^2/m]")
      .def_property_readonly("front_slip_gradient", &V::front_slip_gradient, "K_f [s^2/m]")
      .def("validate", &V::validate)
      .def_static("from_file", &io::load_vehicle_file, py::arg("yaml_path"),
                  "Reads vehicles/*.yaml (ConfigError naming the file and key).");

  using A = ActuatorParameters;
  py::class_<A>(m, "ActuatorParameters",
                "The steering actuator: dead time, then a third-order low-pass; keywords.")
      .def(py::init(&from_keywords<A>))
      .def_readwrite("ideal", &A::ideal)
      .def_readwrite("bandwidth_hz", &A::bandwidth_hz, "f_b [Hz]")
      .def_readwrite("dead_time_s", &A::dead_time_s, "T_d [s]")
      .def_readwrite("max_angle_rad", &A::max_angle_rad)
      .def_readwrite("max_rate_radps", &A::max_rate_radps)
      .def_property_readonly("pole_radps", &A::pole_radps, "w_p [rad/s]");

  using G = SideSlipFaultGate;
  py::class_<G>(m, "SideSlipFaultGate",
                "What rejects a bad gyro or accelerometer sample; keyword arguments.")
      .def(py::init(&from_keywords<G>))
      .def_readwrite("innovation_gate", &G::innovation_gate, "chi-square of nu^2 / S")
      .def_readwrite("friction_margin", &G::friction_margin, "a_max = (1 + margin) mu g")
      .def_readwrite("noise_margin", &G::noise_margin, "noise stds added to every bound")
      .def_readwrite("max_side_slip_rad", &G::max_side_slip_rad, "saturated beyond [rad]")
      .def_readwrite("saturated_restart_s", &G::saturated_restart_s)
      .def_readwrite("uncorrected_untrusted_s", &G::uncorrected_untrusted_s)
      .def_readwrite("uncorrected_restart_s", &G::uncorrected_restart_s);

  using CE = CourseErrorParameters;
  py::class_<CE>(m, "CourseErrorParameters",
                 "The course error estimator: the slip's scale and a course bias learned from "
                 "the pose (docs/steering_system.md, 'Course error'); keyword arguments.")
      .def(py::init(&from_keywords<CE>))
      .def_readwrite("position_noise_std_m", &CE::position_noise_std_m)
      .def_readwrite("heading_noise_std_rad", &CE::heading_noise_std_rad)
      .def_readwrite("initial_slip_error_std", &CE::initial_slip_error_std)
      .def_readwrite("slip_error_process_std", &CE::slip_error_process_std, "[1/sqrt(s)]")
      .def_readwrite("initial_course_bias_std_rad", &CE::initial_course_bias_std_rad)
      .def_readwrite("course_bias_process_std_radps", &CE::course_bias_process_std_radps)
      .def_readwrite("max_slip_error", &CE::max_slip_error)
      .def_readwrite("max_course_bias_rad", &CE::max_course_bias_rad)
      .def_readwrite("min_speed_mps", &CE::min_speed_mps)
      .def_readwrite("max_lateral_acceleration_mps2", &CE::max_lateral_acceleration_mps2)
      .def_readwrite("max_innovation_sigmas", &CE::max_innovation_sigmas)
      .def("validate", &CE::validate);

  using O = SideSlipObserverParameters;
  py::class_<O>(m, "SideSlipObserverParameters",
                "The side-slip observer's model and sensor noise; keyword arguments.")
      .def(py::init(&from_keywords<O>))
      .def_readwrite("mass_kg", &O::mass_kg)
      .def_readwrite("yaw_inertia_kgm2", &O::yaw_inertia_kgm2)
      .def_readwrite("cg_to_front_axle_m", &O::cg_to_front_axle_m)
      .def_readwrite("cg_to_rear_axle_m", &O::cg_to_rear_axle_m)
      .def_readwrite("front_cornering_stiffness_npr", &O::front_cornering_stiffness_npr)
      .def_readwrite("rear_cornering_stiffness_npr", &O::rear_cornering_stiffness_npr)
      .def_readwrite("yaw_rate_noise_std_radps", &O::yaw_rate_noise_std_radps)
      .def_readwrite("lateral_acceleration_noise_std_mps2", &O::lateral_acceleration_noise_std_mps2)
      .def_readwrite("lateral_process_std_mps2", &O::lateral_process_std_mps2)
      .def_readwrite("yaw_process_std_radps2", &O::yaw_process_std_radps2)
      .def_readwrite("tire_model", &O::tire_model)
      .def_readwrite("front_tire", &O::front_tire)
      .def_readwrite("rear_tire", &O::rear_tire)
      .def_readwrite("gravity_mps2", &O::gravity_mps2)
      .def_readwrite("min_speed_mps", &O::min_speed_mps)
      .def_readwrite("max_steering_offset_rad", &O::max_steering_offset_rad,
                     "bound of the steering-offset state (0: off)")
      .def_readwrite("steering_offset_process_std_radps", &O::steering_offset_process_std_radps)
      .def_readwrite("offset_learning_min_speed_mps", &O::offset_learning_min_speed_mps)
      .def_readwrite("offset_learning_max_lateral_acceleration_mps2",
                     &O::offset_learning_max_lateral_acceleration_mps2)
      .def_readwrite("fault_gate", &O::fault_gate, "SideSlipFaultGate")
      .def_static("from_vehicle", &O::from_vehicle, py::arg("vehicle"),
                  py::arg("cornering_stiffness_scale") = 1.0, py::arg("mass_scale") = 1.0,
                  py::arg("tire_model") = ObserverTireModel::linear)
      .def("validate", &O::validate);
}

void bind_outputs(py::module_& m) {
  using H = SideSlipObserverHealth;
  py::class_<H>(m, "SideSlipObserverHealth", "What the observer's gates dropped and rejected.")
      .def_readonly("yaw_rate_dropped", &H::yaw_rate_dropped, "non-finite gyro samples")
      .def_readonly("yaw_rate_rejected", &H::yaw_rate_rejected, "implausible or gated")
      .def_readonly("lateral_acceleration_dropped", &H::lateral_acceleration_dropped)
      .def_readonly("lateral_acceleration_rejected", &H::lateral_acceleration_rejected)
      .def_readonly("restarts", &H::restarts, "re-initialisations from the kinematic model")
      .def_readonly("last_period", &H::last_period, "SensorFault bits of the last update")
      .def_readonly("trusted", &H::trusted)
      .def_readonly("saturated_s", &H::saturated_s)
      .def_readonly("uncorrected_s", &H::uncorrected_s);
  py::module_ faults = m.def_submodule("SensorFault", "The bits of last_period.");
  const std::pair<const char*, SensorFault> fault_bits[] = {
      {"none", fault_none},
      {"yaw_rate_dropped", fault_yaw_rate_dropped},
      {"yaw_rate_implausible", fault_yaw_rate_implausible},
      {"yaw_rate_innovation", fault_yaw_rate_innovation},
      {"lateral_acceleration_dropped", fault_lateral_acceleration_dropped},
      {"lateral_acceleration_implausible", fault_lateral_acceleration_implausible},
      {"lateral_acceleration_innovation", fault_lateral_acceleration_innovation},
      {"estimate_saturated", fault_estimate_saturated},
      {"uncorrected", fault_uncorrected},
      {"restarted", fault_restarted},
  };
  for (const auto& [name, bit] : fault_bits) faults.attr(name) = static_cast<int>(bit);

  using D = SideSlipDiagnostics;
  py::class_<D>(m, "SideSlipDiagnostics", "The rear axle's side slip as the system sees it.")
      .def_readonly("rear_axle_side_slip_rad", &D::rear_axle_side_slip_rad, "beta_r to the law")
      .def_readonly("side_slip_rad", &D::side_slip_rad, "observer's beta at the CG")
      .def_readonly("lateral_velocity_mps", &D::lateral_velocity_mps, "observer's vy")
      .def_readonly("yaw_rate_radps", &D::yaw_rate_radps, "observer's filtered r")
      .def_readonly("steering_offset_rad", &D::steering_offset_rad,
                    "observer's steering offset: road wheels minus measured angle")
      .def_readonly("slip_error", &D::slip_error,
                    "course error estimator: the slip's relative error a (beta_r and the slip "
                    "gradients times 1 + a)")
      .def_readonly("course_bias_rad", &D::course_bias_rad, "course error estimator: c [rad]")
      .def_readonly("observer_status", &D::observer_status)
      .def_readonly("estimate_trusted", &D::estimate_trusted,
                    "False: saturated or uncorrected; the law got beta_r = 0")
      .def_readonly("sensors", &D::sensors, "SideSlipObserverHealth");

  using O = SteeringSystemOutput;
  py::class_<O>(m, "SteeringSystemOutput", "The command, its derivatives and diagnostics.")
      .def_readonly("steering_angle_rad", &O::steering_angle_rad)
      .def_readonly("steering_rate_radps", &O::steering_rate_radps)
      .def_readonly("steering_acceleration_radps2", &O::steering_acceleration_radps2)
      .def_readonly("derivatives_available", &O::derivatives_available)
      .def_readonly("pose_age_s", &O::pose_age_s, "the pose's age used: given or estimated")
      .def_readonly("applied_steering_offset_rad", &O::applied_steering_offset_rad,
                    "the steering offset the held command makes up for (wheels = command + it)")
      .def_readonly("steering_angle_sensor_bias_rad", &O::steering_angle_sensor_bias_rad,
                    "the measured angle's bias against the actuator's predicted angle")
      .def_readonly("tracking", &O::tracking, "TrackingDiagnostics")
      .def_readonly("side_slip", &O::side_slip, "SideSlipDiagnostics")
      .def_readonly("active_limits", &O::active_limits, "ActiveLimit bits")
      .def_property_readonly(
          "active_limit_names",
          [](const O& out) { return describe_active_limits(out.active_limits); },
          "e.g. 'switching_bound|friction_guard', or 'none'");
  py::module_ limits = m.def_submodule("ActiveLimit", "The bits of active_limits.");
  limits.attr("none") = static_cast<int>(limit_none);
  limits.attr("lead_curvature") = static_cast<int>(limit_lead_curvature);
  limits.attr("feedforward_bound") = static_cast<int>(limit_feedforward_bound);
  limits.attr("friction_guard") = static_cast<int>(limit_friction_guard);
  limits.attr("switching_bound") = static_cast<int>(limit_switching_bound);
  limits.attr("steering_angle") = static_cast<int>(limit_steering_angle);
  limits.attr("path_beyond_domain") = static_cast<int>(limit_path_beyond_domain);
  limits.attr("beyond_certified_speed") = static_cast<int>(limit_beyond_certified_speed);
}

}  // namespace

void bind_system(py::module_& m) {
  bind_vehicle(m);
  bind_outputs(m);
  py::enum_<SlipInput>(m, "SlipInput")
      .value("kinematic", SlipInput::kinematic, "beta_r = 0")
      .value("sensor", SlipInput::sensor, "rear_axle_side_slip_rad of update()")
      .value("observer", SlipInput::observer, "SideSlipObserver (default)");

  using D = DrivingDomain;
  py::class_<D>(m, "DrivingDomain",
                "The paths a system built for the car alone is certified for, shrinking with "
                "speed (docs/steering_system.md); keyword arguments.")
      .def(py::init(&from_keywords<D>))
      .def_readwrite("max_curvature_per_m", &D::max_curvature_per_m)
      .def_readwrite("max_lateral_acceleration_mps2", &D::max_lateral_acceleration_mps2,
                     "|kappa| <= this / v^2")
      .def_readwrite("max_curvature_rate_per_m2", &D::max_curvature_rate_per_m2)
      .def_readwrite("max_lateral_jerk_mps3", &D::max_lateral_jerk_mps3,
                     "|d kappa / ds| <= this / v^3")
      .def_static("for_vehicle", &D::for_vehicle, py::arg("vehicle"),
                  "The road domain (the road_* bounds) capped by what the car can do.")
      .def_readonly_static("road_lateral_acceleration_mps2", &D::road_lateral_acceleration_mps2)
      .def_readonly_static("road_lateral_jerk_mps3", &D::road_lateral_jerk_mps3)
      .def_readonly_static("road_curvature_per_m", &D::road_curvature_per_m)
      .def_readonly_static("road_curvature_rate_per_m2", &D::road_curvature_rate_per_m2)
      .def("curvature_at", &D::curvature_at, py::arg("speed_mps"))
      .def("curvature_rate_at", &D::curvature_rate_at, py::arg("speed_mps"))
      .def("validate", &D::validate);

  using P = SteeringSystemParameters;
  py::class_<P>(m, "SteeringSystemParameters", "Slip input and observer; keyword arguments.")
      .def(py::init(&from_keywords<P>))
      .def_readwrite("slip_input", &P::slip_input)
      .def_readwrite("observer", &P::observer, "SideSlipObserverParameters")
      .def_readwrite("domain", &P::domain,
                     "DrivingDomain the controller is certified for (None: no such check)")
      .def_readwrite("certified_max_speed_mps", &P::certified_max_speed_mps,
                     "above it: ActiveLimit.beyond_certified_speed")
      .def_readwrite("estimate_pose_age", &P::estimate_pose_age,
                     "estimate the pose's age where update() is not given pose_age_s")
      .def_readwrite("actuator", &P::actuator,
                     "ActuatorParameters the command is held through (None: no offset "
                     "compensation)")
      .def_readwrite("course_error", &P::course_error,
                     "CourseErrorParameters of the course error estimator (None: off)")
      .def_readwrite("compensate_steering_offset", &P::compensate_steering_offset,
                     "the held command makes up for the observer's steering offset")
      .def_static("from_vehicle", &P::from_vehicle, py::arg("vehicle"),
                  py::arg("tire_model") = ObserverTireModel::linear)
      .def("validate", &P::validate);

  using C = VehicleDescription;
  py::class_<C>(m, "VehicleDescription", "The vehicle file and the actuator model; keywords.")
      .def(py::init(&from_keywords<C>))
      .def_readwrite("vehicle", &C::vehicle, "VehicleParameters")
      .def_readwrite("actuator", &C::actuator, "ActuatorParameters")
      .def("validate", &C::validate);

  using S = SteeringSystemOptions;
  py::class_<S>(m, "SteeringSystemOptions",
                "How make_steering_system() builds the car's system (docs/steering_system.md); "
                "keyword arguments.")
      .def(py::init(&from_keywords<S>))
      .def_readwrite("max_speed_mps", &S::max_speed_mps, "the schedule covers |v| up to this")
      .def_readwrite("speed_step_mps", &S::speed_step_mps)
      .def_readwrite("feedforward_headroom", &S::feedforward_headroom, "in [1, 3]")
      .def_readwrite("max_longitudinal_acceleration_mps2", &S::max_longitudinal_acceleration_mps2)
      .def_readwrite("controller", &S::controller, "template ControllerParameters")
      .def_readwrite("slip_preview", &S::slip_preview, "single-track inversion (K_f, K_r)")
      .def_readwrite("friction_guard", &S::friction_guard, "at the tires' mu g")
      .def_readwrite("actuator_delay_s", &S::actuator_delay_s,
                     "Smith delay [s]; None = dead time + 3 / w_p")
      .def_readwrite("slip_input", &S::slip_input)
      .def_readwrite("observer_tire_model", &S::observer_tire_model)
      .def_readwrite("domain", &S::domain,
                     "DrivingDomain of the car-alone build; None = DrivingDomain.for_vehicle")
      .def("validate", &S::validate);

  py::class_<SteeringSystem>(
      m, "SteeringSystem",
      "One real-time object per car: controller, side-slip observer and slip input "
      "(docs/steering_system.md). In C++ update() is noexcept and allocation free.")
      .def(py::init([](const VehicleParameters& vehicle, const ControllerParameters& parameters,
                       std::shared_ptr<Path> path, SlipInput slip_input) {
             return std::make_unique<SteeringSystem>(vehicle, parameters, std::move(path),
                                                     slip_input);
           }),
           py::arg("vehicle"), py::arg("parameters"), py::arg("path"),
           py::arg("slip_input") = SlipInput::observer,
           "The lead-wheel controller on the path with the vehicle's observer.")
      .def(py::init([](SteeringController& controller, const SteeringSystemParameters& p) {
             return std::make_unique<SteeringSystem>(controller, p);
           }),
           py::arg("controller"), py::arg("parameters"), py::keep_alive<1, 2>(),
           "Any controller (kept alive by the system) with these slip input and observer.")
      .def("update", &update, py::arg("rear_axle_position"), py::arg("heading_rad"),
           py::arg("speed_mps"), py::arg("acceleration_mps2") = 0.0,
           py::arg("yaw_rate_radps") = 0.0, py::arg("lateral_acceleration_mps2") = 0.0,
           py::arg("period_s") = 0.02, py::arg("steering_angle_rad") = py::none(),
           py::arg("rear_axle_side_slip_rad") = py::none(), py::arg("pose_age_s") = 0.0,
           "One control period with what the car measures: rear axle (x, y) [m], heading "
           "[rad], signed speed [m/s], dv/dt [m/s^2], yaw rate [rad/s], lateral acceleration "
           "at the CG [m/s^2], period [s], the measured road-wheel angle [rad] (None: the last "
           "command), a slip sensor's beta_r [rad] and how old the pose is [s] (localization "
           "latency, 0 <= pose_age_s <= 0.5; the controller carries the pose forward over it). "
           "Returns a SteeringSystemOutput; raises ControllerError on an error status.")
      .def("forget_steering_offset", &SteeringSystem::forget_steering_offset,
           "The observer's steering offset back to 0 (reset() keeps it)")
      .def("forget_course_error", &SteeringSystem::forget_course_error,
           "The course error estimator's slip error and course bias back to 0 (reset() keeps "
           "them)")
      .def(
          "reset",
          [](SteeringSystem& system, double angle) {
            const Status status = system.reset(angle);
            if (status != Status::ok) throw ControllerError(status);
          },
          py::arg("measured_steering_angle_rad") = 0.0,
          "Restarts at the measured steering angle [rad]; raises ControllerError for NaN, inf, "
          "|angle| >= pi/2 or beyond the car's angle limit (never wrapped).")
      .def(
          "set_path",
          [](SteeringSystem& system, std::shared_ptr<Path> path) {
            const bool missing = !path;
            const Status status = system.set_path(std::move(path));
            if (status != Status::ok) {
              throw ControllerError(
                  status, missing ? "the path is None; give a smoothsteer.Path" : "", "set_path()");
            }
          },
          py::arg("path"), "Replanning: replaces the path between two update() calls.")
      .def(
          "set_waypoints",
          [](SteeringSystem& system,
             const py::array_t<double, py::array::c_style | py::array::forcecast>& xy) {
            const Status status =
                system.set_waypoints(waypoints_from(xy, "SteeringSystem.set_waypoints"));
            if (status != Status::ok) throw ControllerError(status, "", "set_waypoints()");
          },
          py::arg("waypoints"),
          "A planner's window (N x 2 array x, y [m]): fitted at the jitter pooled over the "
          "windows so far (waypoint_conditioner; clean ones interpolated), then set_path(). "
          "Raises ValueError for waypoints Path.from_waypoints refuses.")
      .def_property_readonly("waypoint_conditioner", &SteeringSystem::waypoint_conditioner,
                             py::return_value_policy::reference_internal,
                             "the WaypointConditioner of set_waypoints(): jitter_m, windows")
      .def("forget_waypoint_jitter", &SteeringSystem::forget_waypoint_jitter,
           "forgets the pooled jitter (another planner)")
      .def_property_readonly("parameters", &SteeringSystem::parameters);

  m.def(
      "make_steering_system",
      [](const VehicleDescription& car, std::shared_ptr<Path> path,
         const SteeringSystemOptions& options) {
        return std::make_unique<SteeringSystem>(
            make_steering_system(car, std::move(path), options));
      },
      py::arg("car"), py::arg("path"), py::arg("options") = SteeringSystemOptions{},
      "The car's steering system on the path: the certified schedule from the car's limits, "
      "the vehicle's slip gradients and observer, the actuator's delay. Raises ValueError "
      "naming the field, InfeasibleLimits when the car cannot be certified.");
  m.def(
      "make_steering_system",
      [](const VehicleDescription& car, const SteeringSystemOptions& options) {
        return std::make_unique<SteeringSystem>(make_steering_system(car, options));
      },
      py::arg("car"), py::arg("options") = SteeringSystemOptions{},
      "The car's steering system from the car alone, certified over options.domain (else "
      "DrivingDomain.for_vehicle); paths arrive by set_path(), update() raises ControllerError "
      "(not_configured) before the first. Above parameters.certified_max_speed_mps the "
      "schedule's last entry holds (ActiveLimit.beyond_certified_speed); a path beyond the "
      "domain sets ActiveLimit.path_beyond_domain.");
  m.def("steering_system_controller", &steering_system_controller, py::arg("car"),
        py::arg("options") = SteeringSystemOptions{},
        "The ControllerParameters make_steering_system() gives its schedule as the template.");
  m.def("actuator_group_delay_s", &actuator_group_delay_s, py::arg("actuator"),
        "Dead time + 3 / w_p [s] (the default Smith delay).");
  m.def(
      "speed_compensation",
      [](const VehicleParameters& vehicle, double actuator_group_delay_s, const Path& path) {
        return speed_compensation(vehicle, actuator_group_delay_s, path_demand(path));
      },
      py::arg("vehicle"), py::arg("actuator_group_delay_s"), py::arg("path"),
      "The SpeedCompensation of the car on the path (its largest curvature, the tires' mu g).");
  m.def("describe_active_limits", &describe_active_limits, py::arg("limits"));
}

}  // namespace smoothsteer::python
