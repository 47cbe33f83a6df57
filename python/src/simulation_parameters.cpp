// The closed loop's simulation settings (smoothsteer/sim/simulation.hpp), above all where the
// plant differs from what the controller is told (plant_imperfections.hpp): a scenario's
// `simulation` block as Scenario.simulation, and the structs to build or check one.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "smoothsteer/sim/simulation.hpp"

namespace smoothsteer::python {

void bind_simulation_parameters(py::module_& m) {
  using S = PlantScales;
  py::class_<S>(m, "PlantScales",
                "Factors on the plant's vehicle only (kinetic plants); keyword arguments.")
      .def(py::init(&from_keywords<S>))
      .def_readwrite("mass", &S::mass, "mass factor; the axle cornering stiffnesses stay")
      .def_readwrite("yaw_inertia", &S::yaw_inertia, "Iz factor")
      .def_readwrite("cornering_stiffness", &S::cornering_stiffness, "factor on B")
      .def_readwrite("friction", &S::friction, "factor on mu; the cornering stiffness stays")
      .def_readwrite("cg_position", &S::cg_position,
                     "CG shift toward the front axle [fraction of the wheelbase]");

  using A = PlantActuatorScales;
  py::class_<A>(m, "PlantActuatorScales", "Factors on the simulated actuator only; keywords.")
      .def(py::init(&from_keywords<A>))
      .def_readwrite("dead_time", &A::dead_time, "dead-time factor (rounded to the sub-step)")
      .def_readwrite("bandwidth", &A::bandwidth, "bandwidth factor");

  using F = SideForce;
  py::class_<F>(m, "SideForce", "A lateral force at the CG and a yaw moment from start_s on.")
      .def(py::init(&from_keywords<F>))
      .def_readwrite("force_n", &F::force_n, "[N], + to the car's left")
      .def_readwrite("yaw_moment_nm", &F::yaw_moment_nm, "[N m], + counter-clockwise")
      .def_readwrite("start_s", &F::start_s, "[s]");

  using W = PlannerWindows;
  py::class_<W>(m, "PlannerWindows",
                "Stack mode: the road arrives as a planner's windows by set_path() every "
                "period_s (docs/simulation.md); keyword arguments.")
      .def(py::init(&from_keywords<W>))
      .def_readwrite("period_s", &W::period_s, "[s], a multiple of the control period; 0: off")
      .def_readwrite("behind_m", &W::behind_m, "[m] behind the rear axle's closest point")
      .def_readwrite("ahead_m", &W::ahead_m, "[m] ahead of it")
      .def_readwrite("spacing_m", &W::spacing_m, "[m] between waypoints")
      .def_readwrite("jitter_std_m", &W::jitter_std_m, "[m] Gaussian, per coordinate")
      .def_readwrite("smoothing_tolerance_m", &W::smoothing_tolerance_m,
                     "[m]; None: the jitter estimated from the windows (WaypointConditioner)");

  py::enum_<SideSlipSource>(m, "SideSlipSource")
      .value("none", SideSlipSource::none, "beta_r = 0: the kinematic assumption")
      .value("truth", SideSlipSource::truth, "the plant's own slip, an ideal sensor")
      .value("observer", SideSlipSource::observer, "SideSlipObserver on the simulated sensors");

  using E = SideSlipEstimation;
  py::class_<E>(m, "SideSlipEstimation",
                "Where the steering system's beta_r comes from and what its observer believes "
                "(a scenario's simulation.side_slip); keyword arguments.")
      .def(py::init(&from_keywords<E>))
      .def_readwrite("source", &E::source, "SideSlipSource")
      .def_readwrite("cornering_stiffness_scale", &E::cornering_stiffness_scale,
                     "the observer's belief / the vehicle file")
      .def_readwrite("mass_scale", &E::mass_scale, "the same for mass and yaw inertia")
      .def_readwrite("tire_model", &E::tire_model, "ObserverTireModel")
      .def_readwrite("yaw_rate_noise_std_radps", &E::yaw_rate_noise_std_radps)
      .def_readwrite("lateral_acceleration_noise_std_mps2", &E::lateral_acceleration_noise_std_mps2)
      .def_readwrite("max_steering_offset_rad", &E::max_steering_offset_rad,
                     "the observer's steering-offset bound (0: off)")
      .def_readwrite("steering_offset_process_std_radps", &E::steering_offset_process_std_radps)
      .def_readwrite("compensate_steering_offset", &E::compensate_steering_offset,
                     "the held command makes up for the learned offset")
      .def_readwrite("estimate_course_error", &E::estimate_course_error,
                     "the system learns the slip's scale and a course bias from the pose");

  using P = SimulationParameters;
  py::class_<P>(m, "SimulationParameters",
                "A scenario's simulation block (docs/simulation.md): disturbances, model error "
                "and imperfect sensors given to the plant only; keyword arguments.")
      .def(py::init(&from_keywords<P>))
      .def_readwrite("control_period_s", &P::control_period_s)
      .def_readwrite("substep_s", &P::substep_s)
      .def_readwrite("duration_s", &P::duration_s)
      .def_readwrite("matched_disturbance", &P::matched_disturbance, "[1/m]")
      .def_readwrite("plant_curvature_disturbance", &P::plant_curvature_disturbance, "[1/m]")
      .def_readwrite("steering_offset_rad", &P::steering_offset_rad, "rack offset [rad]")
      .def_readwrite("plant_scales", &P::plant_scales, "PlantScales")
      .def_readwrite("plant_actuator_scales", &P::plant_actuator_scales, "PlantActuatorScales")
      .def_readwrite("crossfall", &P::crossfall, "grade tan(phi); + falls to the car's right")
      .def_readwrite("side_force", &P::side_force, "SideForce")
      .def_readwrite("pose_latency_s", &P::pose_latency_s, "[s]")
      .def_readwrite("pose_rate_hz", &P::pose_rate_hz, "[Hz]; None: every control step")
      .def_readwrite("pose_age_known", &P::pose_age_known,
                     "the system is told the pose's age (SteeringSystemInput.pose_age_s)")
      .def_readwrite("steering_angle_sensor_offset_rad", &P::steering_angle_sensor_offset_rad,
                     "[rad]")
      .def_readwrite("gyro_bias_radps", &P::gyro_bias_radps, "[rad/s]")
      .def_readwrite("position_noise_std_m", &P::position_noise_std_m)
      .def_readwrite("heading_noise_std_rad", &P::heading_noise_std_rad)
      .def_readwrite("noise_seed", &P::noise_seed)
      .def_readwrite("side_slip", &P::side_slip, "SideSlipEstimation")
      .def_readwrite("planner", &P::planner, "PlannerWindows (stack mode)")
      .def("validation_error", &P::validation_error,
           "'' when valid, else the message naming the field, value and rule.")
      .def("validate", &P::validate, "Raises ValueError naming the field, value and rule.");

  m.def("scaled_plant_vehicle", &scaled_plant_vehicle, py::arg("vehicle"), py::arg("scales"),
        "The plant's VehicleParameters under PlantScales (ValueError naming the scale when the "
        "result describes no car).");
}

}  // namespace smoothsteer::python
