// ControllerParameters, ControllerOutput and the lead-wheel controller
// (include/smoothsteer/controller/).

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "smoothsteer/controller/lead_wheel_controller.hpp"

namespace smoothsteer::python {
namespace {

//! lambda_1..lambda_n [m]: the first `order` entries (at least one) are shown; setting k values
//! replaces the first k and keeps the rest.
std::vector<double> wheelbases(const ControllerParameters& p) {
  const int shown = std::clamp(p.order, 1, ControllerParameters::max_order);
  return {p.wheelbases_m.begin(), p.wheelbases_m.begin() + shown};
}

void set_wheelbases(ControllerParameters& p, const std::vector<double>& values) {
  if (values.empty() || values.size() > p.wheelbases_m.size()) {
    throw py::value_error("ControllerParameters.wheelbases_m: give 1 to " +
                          std::to_string(ControllerParameters::max_order) + " lengths [m], got " +
                          std::to_string(values.size()));
  }
  std::copy(values.begin(), values.end(), p.wheelbases_m.begin());
}

//! One update() call; a non-ok status raises ControllerError.
ControllerOutput update(SteeringController& controller, const py::object& position,
                        double heading_rad, double speed_mps, double acceleration_mps2,
                        double period_s) {
  const ControllerInput input{to_vec2(position, "rear_axle_position"), heading_rad, speed_mps,
                              acceleration_mps2, period_s};
  ControllerOutput output;
  const Status status = controller.update(input, output);
  if (status != Status::ok) throw ControllerError(status);
  return output;
}

}  // namespace

void bind_controller(py::module_& m) {
  py::enum_<Status>(m, "Status", "Result of a real-time call.")
      .value("ok", Status::ok)
      .value("invalid_input", Status::invalid_input)
      .value("not_configured", Status::not_configured)
      .value("numerical_error", Status::numerical_error)
      .value("unsupported", Status::unsupported);
  py::enum_<SlidingSurface>(m, "SlidingSurface")
      .value("global_", SlidingSurface::global, "globally convergent (default)")
      .value("paper", SlidingSurface::paper, "eq. (sigma) as printed");
  py::enum_<CurvaturePreview>(m, "CurvaturePreview")
      .value("centred_ramp", CurvaturePreview::centred_ramp,
             "a jump becomes a ramp at L_ff centred on it (default)")
      .value("planned_jumps", CurvaturePreview::planned_jumps,
             "each curvature jump gets a planned counter-steer and overshoot "
             "(docs/feedforward.md, section 2b)");
  py::enum_<CorneringTarget>(m, "CorneringTarget")
      .value("rear_axle", CorneringTarget::rear_axle, "the rear axle on the path (default)")
      .value("rear_axle_exact", CorneringTarget::rear_axle_exact,
             "the rear axle on the path also while the curvature changes (the chain's inverse)")
      .value("lead_wheel", CorneringTarget::lead_wheel, "the lead wheel on the path (paper)");

  using G = SteeringGovernor;
  py::class_<G>(m, "SteeringGovernor",
                "The car's rate and acceleration limits held on the command inside the control "
                "step (docs/governor.md); keyword arguments set any field.")
      .def(py::init([](const py::kwargs& keywords) {
        py::object governor = py::cast(G{});
        set_attributes(governor, keywords);
        return governor.cast<G>();
      }))
      .def_readwrite("enabled", &G::enabled)
      .def_readwrite("max_steering_rate_radps", &G::max_steering_rate_radps, "R [rad/s]")
      .def_readwrite("max_steering_acceleration_radps2", &G::max_steering_acceleration_radps2,
                     "A [rad/s^2]")
      .def_readwrite("max_longitudinal_acceleration_mps2", &G::max_longitudinal_acceleration_mps2,
                     "|dv/dt| budgeted beyond the measured one [m/s^2]")
      .def_readwrite("law_length_m", &G::law_length_m, "l [m]; 0 = derived")
      .def_readwrite("margin", &G::margin, "share of R and A kept in reserve")
      .def_readwrite("max_steering_angle_rad", &G::max_steering_angle_rad,
                     "angle limit the authority is derived from [rad]")
      .def_readwrite("max_lateral_acceleration_mps2", &G::max_lateral_acceleration_mps2,
                     "friction limit mu g the authority is derived from [m/s^2]")
      .def_readwrite("certified_switching_bound", &G::certified_switching_bound,
                     "the near-path law's authority [1/m]; 0 = kbar_sw");

  using P = ControllerParameters;
  py::class_<P>(m, "ControllerParameters",
                "Parameters of the lead-wheel controller, SI units; keyword arguments set any "
                "field: ControllerParameters(order=2, lead_curvature_bound=0.1).")
      .def(py::init([](const py::kwargs& keywords) {
        py::object parameters = py::cast(P{});
        set_attributes(parameters, keywords);
        return parameters.cast<P>();
      }))
      .def_readwrite("order", &P::order, "n: fictive wheels; delta is C^(n-1)")
      .def_readwrite("vehicle_wheelbase_m", &P::vehicle_wheelbase_m, "lambda_veh [m]")
      .def_property("wheelbases_m", &wheelbases, &set_wheelbases,
                    "lambda_1..lambda_n [m]; lambda_1 = lambda, lambda_2 = lambda_l for n = 2")
      .def_readwrite("lead_curvature_bound", &P::lead_curvature_bound, "kbar_n [1/m]")
      .def_readwrite("k_rob", &P::k_rob, "robustness margin in [0, 1)")
      .def_readwrite("approach_angle_rad", &P::approach_angle_rad, "psi_max [rad]")
      .def_readwrite("feedforward_share", &P::feedforward_share, "kbar_ff / kbar_n in [0, 1)")
      .def_readwrite("feedforward_curvature_rate", &P::feedforward_curvature_rate,
                     "L_ff [1/m^2]; inf = unlimited")
      .def_readwrite("feedforward_catch_up", &P::feedforward_catch_up,
                     "share of kbar_sw that makes up the feedforward's rate-limit lag, in [0, 1]")
      .def_readwrite("boundary_layer", &P::boundary_layer, "epsilon >= 0 [rad]")
      .def_readwrite("actuator_delay_s", &P::actuator_delay_s,
                     "Smith predictor's delay [s], in [0, max_actuator_delay_s]; 0 = off")
      .def_readwrite("preview_time_s", &P::preview_time_s,
                     "extra feedforward preview [s] times |v|, in [0, max_actuator_delay_s]")
      .def_readwrite("disturbance_estimation_length_m", &P::disturbance_estimation_length_m,
                     "low-pass length of the plant-curvature estimate [m]; 0 = off, else "
                     "[1, 1000]")
      .def_readwrite("rear_slip_gradient_s2pm", &P::rear_slip_gradient_s2pm,
                     "K_r of the single-track inversion [s^2/m], in [0, 0.1]")
      .def_readwrite("front_slip_gradient_s2pm", &P::front_slip_gradient_s2pm,
                     "K_f of the single-track inversion [s^2/m], in [0, 0.1]")
      .def_readwrite("slip_preview_second_order", &P::slip_preview_second_order,
                     "with the inversion's K_f K_r v^4 kappa'' term")
      .def_readwrite("max_lateral_acceleration_mps2", &P::max_lateral_acceleration_mps2,
                     "friction guard a_max [m/s^2]; inf = off")
      .def_readwrite("actuator_time_constant_s", &P::actuator_time_constant_s,
                     "T of the actuator inversion (1 + T s)^m [s], in [0, 0.5]; 0 = off")
      .def_readwrite("actuator_lag_count", &P::actuator_lag_count,
                     "m of the actuator inversion, in [1, 3]")
      .def_readwrite("surface", &P::surface)
      .def_readwrite("cornering_target", &P::cornering_target)
      .def_readwrite("curvature_preview", &P::curvature_preview)
      .def_readwrite("max_substep_fraction", &P::max_substep_fraction,
                     "largest RK4 step of the chain over the shortest wheelbase")
      .def_readwrite("max_substeps", &P::max_substeps, "sub-steps per period at most")
      .def_readwrite("governor", &P::governor, "SteeringGovernor (docs/governor.md)")
      .def("validate", &P::validate, "Raises ValueError naming the field, value and rule.")
      .def_readonly_static("max_order", &P::max_order)
      .def_readonly_static("max_actuator_delay_s", &P::max_actuator_delay_s)
      .def_readonly_static("max_slip_gradient_s2pm", &P::max_slip_gradient_s2pm)
      .def_static("paper_c1", &P::paper_c1, py::arg("vehicle_wheelbase_m"),
                  py::arg("lead_wheelbase_m"), py::arg("lead_curvature_bound"), py::arg("k_rob"),
                  "The paper's C^1 controller (n = 2), lambda from eq. (cornering_constr).")
      .def_static("paper_c0", &P::paper_c0, py::arg("vehicle_wheelbase_m"),
                  py::arg("front_curvature_bound"), py::arg("k_rob"),
                  "The C^0 controller (n = 1), eq. (ext1).")
      .def("__repr__", [](const P& p) {
        return "ControllerParameters(order=" + std::to_string(p.order) +
               ", vehicle_wheelbase_m=" + std::to_string(p.vehicle_wheelbase_m) +
               ", lead_curvature_bound=" + std::to_string(p.lead_curvature_bound) +
               ", k_rob=" + std::to_string(p.k_rob) + ")";
      });

  using D = TrackingDiagnostics;
  py::class_<D>(m, "TrackingDiagnostics", "The tracking state relative to the path.")
      .def_readonly("lateral_error_m", &D::lateral_error_m, "e of the rear axle [m], left +")
      .def_readonly("heading_error_rad", &D::heading_error_rad, "[rad]")
      .def_readonly("front_lateral_error_m", &D::front_lateral_error_m, "e_front [m]")
      .def_readonly("lead_lateral_error_m", &D::lead_lateral_error_m, "e_lead [m]")
      .def_readonly("lead_heading_error_rad", &D::lead_heading_error_rad, "[rad]")
      .def_readonly("sliding_variable", &D::sliding_variable, "sigma [m] or [rad]")
      .def_readonly("lead_curvature", &D::lead_curvature, "kappa_n [1/m]")
      .def_readonly("feedforward_curvature", &D::feedforward_curvature, "kappa_ff [1/m]")
      .def_readonly("path_arc_length_m", &D::path_arc_length_m, "s of the closest point [m]")
      .def_readonly("path_curvature", &D::path_curvature, "[1/m]")
      .def_readonly("fictive_steering_angle_rad", &D::fictive_steering_angle_rad, "delta_1 [rad]");

  using O = ControllerOutput;
  py::class_<O>(m, "ControllerOutput", "The steering command and its diagnostics.")
      .def_readonly("steering_angle_rad", &O::steering_angle_rad, "delta_veh [rad]")
      .def_readonly("steering_rate_radps", &O::steering_rate_radps, "d delta_veh/dt [rad/s]")
      .def_readonly("steering_acceleration_radps2", &O::steering_acceleration_radps2,
                    "d2 delta_veh/dt2 [rad/s^2]")
      .def_readonly("derivatives_available", &O::derivatives_available)
      .def_readonly("diagnostics", &O::diagnostics);

  py::class_<SteeringController>(m, "SteeringController",
                                 "Interface of every controller: update() once per period.")
      .def("update", &update, py::arg("rear_axle_position"), py::arg("heading_rad"),
           py::arg("speed_mps"), py::arg("acceleration_mps2") = 0.0, py::arg("period_s") = 0.02,
           "One control period: rear axle (x, y) [m], heading [rad], signed speed [m/s], dv/dt "
           "[m/s^2], period [s]. Returns a ControllerOutput; raises ControllerError on an error "
           "status (e.g. a NaN input).")
      .def("reset", &SteeringController::reset, py::arg("measured_steering_angle_rad") = 0.0)
      .def_property_readonly("name", &SteeringController::name)
      .def(
          "set_path",
          [](SteeringController& controller, std::shared_ptr<Path> path) {
            const Status status = controller.set_path(std::move(path));
            if (status != Status::ok) throw ControllerError(status);
          },
          py::arg("path"), "Replanning: replaces the path between two update() calls.");

  py::class_<ChainBounds>(m, "ChainBounds", "Bounds of the invariant sets.")
      .def_readonly("steering_angle_rad", &ChainBounds::steering_angle_rad, "[rad]")
      .def_readonly("steering_rate_per_meter", &ChainBounds::steering_rate_per_meter,
                    "box bound of |d delta/ds| [rad/m]");
  py::class_<SteeringCertificate>(m, "SteeringCertificate",
                                  "Certified bounds of delta_veh under the feedforward split.")
      .def_readonly("steering_angle_rad", &SteeringCertificate::steering_angle_rad, "[rad]")
      .def_readonly("rate_per_meter", &SteeringCertificate::rate_per_meter, "[rad/m]")
      .def_readonly("acceleration_per_meter2", &SteeringCertificate::acceleration_per_meter2,
                    "[rad/m^2]")
      .def("rate_radps", &SteeringCertificate::rate_radps, py::arg("speed_mps"),
           "|d delta/dt| bound at a speed [rad/s]")
      .def("acceleration_radps2", &SteeringCertificate::acceleration_radps2, py::arg("speed_mps"),
           py::arg("acceleration_mps2") = 0.0, "|d2 delta/dt2| bound [rad/s^2]");

  py::class_<LeadWheelController, SteeringController>(
      m, "LeadWheelController",
      "The n-smooth lead-wheel controller (paper Sec. II). Its update() releases nothing and "
      "allocates nothing in C++; one call costs about a microsecond.")
      .def(py::init([](const ControllerParameters& parameters, std::shared_ptr<Path> path) {
             return std::make_unique<LeadWheelController>(parameters, std::move(path));
           }),
           py::arg("parameters"), py::arg("path"),
           "Validates the parameters (ValueError naming the field).")
      .def_property_readonly("parameters", &LeadWheelController::parameters)
      .def_property_readonly("bounds", &LeadWheelController::bounds)
      .def_property_readonly("certificate", &LeadWheelController::certificate)
      .def_property_readonly("direction", &LeadWheelController::direction,
                             "+1 forwards, -1 in reverse")
      .def(
          "retune",
          [](LeadWheelController& controller, const ControllerParameters& parameters) {
            const Status status = controller.retune(parameters);
            if (status != Status::ok) throw ControllerError(status);
          },
          py::arg("parameters"), "Real-time parameter change (same order n).");
}

}  // namespace smoothsteer::python
