// ControllerParameters, ControllerOutput and the lead-wheel controller
// (include/smoothsteer/controller/).

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "bindings.hpp"
#include "smoothsteer/controller/feedforward.hpp"
#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/controller/parameter_fields.hpp"
#include "smoothsteer/controller/steering_governor.hpp"

namespace smoothsteer::python {
namespace {

std::vector<double> chain_wheelbases(const ChainParameters& chain) {
  const int shown = std::clamp(chain.order, 1, ControllerParameters::max_order);
  return {chain.wheelbases_m.begin(), chain.wheelbases_m.begin() + shown};
}

void set_chain_wheelbases(ChainParameters& chain, const std::vector<double>& values) {
  if (values.empty() || values.size() > chain.wheelbases_m.size()) {
    throw py::value_error("ControllerParameters.wheelbases_m: give 1 to " +
                          std::to_string(ControllerParameters::max_order) + " lengths [m], got " +
                          std::to_string(values.size()));
  }
  std::copy(values.begin(), values.end(), chain.wheelbases_m.begin());
}

//! lambda_1..lambda_n [m]: the first `order` entries (at least one) are shown; setting k values
//! replaces the first k and keeps the rest.
std::vector<double> wheelbases(const ControllerParameters& p) {
  return chain_wheelbases(p.chain);
}

void set_wheelbases(ControllerParameters& p, const std::vector<double>& values) {
  set_chain_wheelbases(p.chain, values);
}

//! A field of the table as Python sees it: float, int, bool or the enumeration.
py::object field_to_python(const ParameterField& field, const ControllerParameters& p) {
  const double value = field.get(p);
  switch (field.kind) {
    case FieldKind::integer:
      return py::int_(static_cast<int>(value));
    case FieldKind::boolean:
      return py::bool_(value != 0.0);
    case FieldKind::choice:
      if (field.name == "surface") return py::cast(p.law.surface);
      if (field.name == "cornering_target") return py::cast(p.feedforward.cornering_target);
      return py::cast(p.feedforward.curvature_preview);
    default:
      return py::float_(value);
  }
}

void field_from_python(const ParameterField& field, ControllerParameters& p,
                       const py::object& value) {
  switch (field.kind) {
    case FieldKind::integer:
      field.set(p, value.cast<int>());
      return;
    case FieldKind::boolean:
      field.set(p, value.cast<bool>() ? 1.0 : 0.0);
      return;
    case FieldKind::choice:
      if (field.name == "surface") {
        p.law.surface = value.cast<SlidingSurface>();
      } else if (field.name == "cornering_target") {
        p.feedforward.cornering_target = value.cast<CorneringTarget>();
      } else {
        p.feedforward.curvature_preview = value.cast<CurvaturePreview>();
      }
      return;
    default:
      field.set(p, value.cast<double>());
  }
}

//! Binds every row of the field table whose member lies in `group` (prefix "law." for
//! ControllerParameters::law) as a property of the group's class, named and documented as the
//! table says: the table is the one list of a group's members. A member set through its group
//! does what its flat attribute does: one that switches its group (actuator_delay_s) switches
//! it, any other leaves `enabled` as it is.
template <typename Group>
void bind_group_fields(py::class_<Group>& group_class, Group ControllerParameters::*group,
                       std::string_view prefix) {
  for (const ParameterField& field : controller_parameter_fields()) {
    if (!field.member.starts_with(prefix) || field.kind == FieldKind::wheelbases) continue;
    const ParameterField* f = &field;
    const std::string attribute(field.member.substr(prefix.size()));
    const bool is_switch = attribute == "enabled";
    group_class.def_property(
        attribute.c_str(),
        [f, group](const Group& g) {
          ControllerParameters p;
          p.*group = g;
          return field_to_python(*f, p);
        },
        [f, group, is_switch](Group& g, const py::object& value) {
          ControllerParameters p;
          p.*group = g;
          field_from_python(*f, p, value);
          if constexpr (requires { g.enabled; }) {
            if (!is_switch && !f->switches_group) (p.*group).enabled = g.enabled;
          }
          g = p.*group;
        },
        field.doc.data());
  }
}

py::list field_rows() {
  py::list rows;
  for (const ParameterField& field : controller_parameter_fields()) {
    py::dict row;
    row["name"] = std::string(field.name);
    row["member"] = std::string(field.member);
    row["unit"] = std::string(field.unit);
    row["rule"] = field_rule_text(field);
    row["doc"] = std::string(field.doc);
    row["default"] = field_default_text(field);
    row["scenario_key"] = field.scenario == ScenarioKey::direct;
    row["switches_group"] = field.switches_group;
    row["min"] = field.range.min;
    row["max"] = field.range.max;
    row["off"] = std::isnan(field.range.off) ? py::object(py::none()) : py::float_(field.range.off);
    rows.append(row);
  }
  return rows;
}

//! One update() call; a non-ok status raises ControllerError naming the bad input.
ControllerOutput update(SteeringController& controller, const py::object& position,
                        double heading_rad, double speed_mps, double acceleration_mps2,
                        double period_s, double rear_axle_side_slip_rad, double pose_age_s,
                        double slip_gradient_scale) {
  ControllerInput input{to_vec2(position, "rear_axle_position"), heading_rad, speed_mps,
                        acceleration_mps2, period_s};
  input.rear_axle_side_slip_rad = rear_axle_side_slip_rad;
  input.pose_age_s = pose_age_s;
  input.slip_gradient_scale = slip_gradient_scale;
  ControllerOutput output;
  const Status status = controller.update(input, output);
  if (status != Status::ok) {
    throw ControllerError(status, input_range_detail(input));
  }
  return output;
}

//! set_path(None) is a caller's mistake the status cannot name.
[[noreturn]] void refuse_missing_path(Status status) {
  throw ControllerError(status, "the path is None; give a smoothsteer.Path", "set_path()");
}

}  // namespace

std::string input_range_detail(const ControllerInput& input) {
  const std::optional<InputRangeViolation> bad = first_input_range_violation(input);
  if (!bad) return "";
  const auto text = [](double value) { return py::str(py::float_(value)).cast<std::string>(); };
  const std::string range = bad->low == -bad->high
                                ? "finite, magnitude <= " + text(bad->high)
                                : std::string(bad->low_open ? "in (" : "in [") + text(bad->low) +
                                      ", " + text(bad->high) + "]";
  return std::string(bad->field) + " = " + text(bad->value) + " is outside ControllerInputRange (" +
         range + " " + bad->unit + ")";
}

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
  py::class_<G> governor_class(
      m, "SteeringGovernor",
      "The car's rate and acceleration limits held on the command inside the control "
      "step (docs/governor.md); keyword arguments set any field.");
  governor_class.def(py::init([](const py::kwargs& keywords) {
    py::object governor = py::cast(G{});
    set_attributes(governor, keywords);
    return governor.cast<G>();
  }));
  bind_group_fields(governor_class, &ControllerParameters::governor, "governor.");

  // The rate-limited curvature preview (feedforward.hpp, docs/feedforward.md section 2).
  m.def(
      "preview_curvature",
      [](const Path& path, double arc_length_m, double step_m, double rate_per_meter,
         double bound) {
        // The C++ function takes its callers' finite values; from Python each is checked.
        auto require = [](bool ok, const char* name, double value, const char* rule) {
          if (!ok) {
            throw py::value_error(std::string("preview_curvature: ") + name + " = " +
                                  std::to_string(value) + " " + rule);
          }
        };
        require(std::isfinite(arc_length_m) && std::abs(arc_length_m) <= 1e9, "arc_length_m",
                arc_length_m, "must be finite, within +-1e9 m");
        require(std::isfinite(step_m) && step_m > 0.0 && step_m <= 100.0, "step_m", step_m,
                "must be in (0, 100] m");
        require(rate_per_meter >= 0.0, "rate_per_meter", rate_per_meter,
                "must be >= 0 1/m^2 (0 or inf: no rate limit)");
        require(std::isfinite(bound) && bound > 0.0, "bound", bound, "must be finite and > 0 1/m");
        const PreviewedCurvature c =
            preview_curvature(path, arc_length_m, step_m, rate_per_meter, bound);
        return std::make_tuple(c.before, c.at, c.after);
      },
      py::arg("path"), py::arg("arc_length_m"), py::arg("step_m"), py::arg("rate_per_meter"),
      py::arg("bound"),
      "The path's sampled curvature as the rate-limited feedforward sees it at s - step, s and "
      "s + step [1/m]: the midpoint of its upper and lower envelopes of slope 2 L_ff, clamped to "
      "+-bound; without a rate (0 or inf) the three samples.");

  // The governor's equations (steering_governor.hpp), for studies of its authority.
  m.def("governed_law_length", &governed_law_length, py::arg("parameters"), py::arg("speed_mps"),
        py::arg("heading_error_rad"),
        "Eq. (governed_law_length): the far law's length l(v, psi) [m] (docs/governor.md).");
  m.def("governed_feedforward_rate", &governed_feedforward_rate, py::arg("parameters"),
        py::arg("speed_mps"),
        "Eq. (governed_feedforward_rate): R / (lambda_veh |v|) [1/m^2], the rate at which the "
        "governed feedforward may move; +inf at standstill.");
  m.def("governed_reversal_curvature", &governed_reversal_curvature, py::arg("parameters"),
        py::arg("speed_mps"), "Eq. (governed_reversal): the far law's largest authority [1/m].");
  m.def("governed_parameters", &governed_parameters, py::arg("certified"), py::arg("speed_mps"),
        "Eq. (governed_authority): the parameters the governor widens a schedule entry to.");
  m.attr("governed_reversal_heading_rad") = governed_reversal_heading_rad;

  // The groups, each a class of its own, their members bound from the field table.
  py::class_<ChainParameters> chain_class(m, "ChainParameters",
                                          "The fictive trailer chain (ChainParameters).");
  chain_class.def(py::init(&from_keywords<ChainParameters>));
  chain_class.def_property("wheelbases_m", &chain_wheelbases, &set_chain_wheelbases,
                           find_parameter_field("wheelbases_m")->doc.data());
  bind_group_fields(chain_class, &ControllerParameters::chain, "chain.");
  py::class_<SwitchingLawParameters> law_class(m, "SwitchingLawParameters", "The switching law.");
  law_class.def(py::init(&from_keywords<SwitchingLawParameters>));
  bind_group_fields(law_class, &ControllerParameters::law, "law.");
  py::class_<FeedforwardParameters> feedforward_class(m, "FeedforwardParameters",
                                                      "The curvature feedforward.");
  feedforward_class.def(py::init(&from_keywords<FeedforwardParameters>));
  bind_group_fields(feedforward_class, &ControllerParameters::feedforward, "feedforward.");
  py::class_<DelayCompensation> delay_compensation_class(m, "DelayCompensation",
                                                         "The Smith predictor (optional).");
  delay_compensation_class.def(py::init(&from_keywords<DelayCompensation>));
  delay_compensation_class.def_readwrite("enabled", &DelayCompensation::enabled);
  bind_group_fields(delay_compensation_class, &ControllerParameters::delay_compensation,
                    "delay_compensation.");
  py::class_<SingleTrackInversion> single_track_class(
      m, "SingleTrackInversion", "The single-track inversion of the feedforward (optional).");
  single_track_class.def(py::init(&from_keywords<SingleTrackInversion>));
  single_track_class.def_readwrite("enabled", &SingleTrackInversion::enabled);
  bind_group_fields(single_track_class, &ControllerParameters::single_track, "single_track.");
  py::class_<DisturbanceEstimation> disturbance_estimation_class(
      m, "DisturbanceEstimation", "The plant-curvature estimate (optional).");
  disturbance_estimation_class.def(py::init(&from_keywords<DisturbanceEstimation>));
  disturbance_estimation_class.def_readwrite("enabled", &DisturbanceEstimation::enabled);
  bind_group_fields(disturbance_estimation_class, &ControllerParameters::disturbance_estimation,
                    "disturbance_estimation.");
  py::class_<FrictionGuard> friction_guard_class(m, "FrictionGuard",
                                                 "The friction guard (optional).");
  friction_guard_class.def(py::init(&from_keywords<FrictionGuard>));
  friction_guard_class.def_readwrite("enabled", &FrictionGuard::enabled);
  bind_group_fields(friction_guard_class, &ControllerParameters::friction_guard, "friction_guard.");
  py::class_<ActuatorInversion> actuator_inversion_class(
      m, "ActuatorInversion", "The steering-actuator inversion (optional).");
  actuator_inversion_class.def(py::init(&from_keywords<ActuatorInversion>));
  actuator_inversion_class.def_readwrite("enabled", &ActuatorInversion::enabled);
  bind_group_fields(actuator_inversion_class, &ControllerParameters::actuator_inversion,
                    "actuator_inversion.");

  using P = ControllerParameters;
  py::class_<P> parameters_class(
      m, "ControllerParameters",
      "Parameters of the lead-wheel controller, SI units, in groups (p.chain, p.law, "
      "p.feedforward, the optional compensations, p.governor). Keyword arguments set any field "
      "by its flat name from the field table: ControllerParameters(order=2, "
      "lead_curvature_bound=0.1, actuator_delay_s=0.048); a compensation's flat field switches "
      "its group on (0, resp. inf for max_lateral_acceleration_mps2, off), and so does the "
      "same member set through its group (p.delay_compensation.actuator_delay_s = 0.048).");
  parameters_class
      .def(py::init([](const py::kwargs& keywords) {
        py::object object = py::cast(P{});
        set_attributes(object, keywords);
        return object.cast<P>();
      }))
      .def_readwrite("chain", &P::chain)
      .def_readwrite("law", &P::law)
      .def_readwrite("feedforward", &P::feedforward)
      .def_readwrite("delay_compensation", &P::delay_compensation)
      .def_readwrite("single_track", &P::single_track)
      .def_readwrite("disturbance_estimation", &P::disturbance_estimation)
      .def_readwrite("friction_guard", &P::friction_guard)
      .def_readwrite("actuator_inversion", &P::actuator_inversion)
      .def_readwrite("governor", &P::governor, "SteeringGovernor (docs/governor.md)");
  // The flat names of the field table, as attributes and keywords (the governor's fields are
  // reached as p.governor.<field>).
  for (const ParameterField& field : controller_parameter_fields()) {
    if (field.group == ParameterGroup::governor) continue;
    if (field.kind == FieldKind::wheelbases) {
      parameters_class.def_property("wheelbases_m", &wheelbases, &set_wheelbases, field.doc.data());
      continue;
    }
    const ParameterField* f = &field;
    parameters_class.def_property(
        field.name.data(), [f](const P& p) { return field_to_python(*f, p); },
        [f](P& p, const py::object& value) { field_from_python(*f, p, value); }, field.doc.data());
  }
  parameters_class
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
      .def_static("fields", &field_rows,
                  "The field table: one dict per field (name, member, unit, rule, doc, default, "
                  "scenario_key, switches_group, min, max, off).")
      .def("__repr__", [](const P& p) {
        return "ControllerParameters(order=" + std::to_string(p.chain.order) +
               ", vehicle_wheelbase_m=" + std::to_string(p.chain.vehicle_wheelbase_m) +
               ", lead_curvature_bound=" + std::to_string(p.chain.lead_curvature_bound) +
               ", k_rob=" + std::to_string(p.law.k_rob) + ")";
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
      .def_readonly("fictive_steering_angle_rad", &D::fictive_steering_angle_rad, "delta_1 [rad]")
      .def_readonly("disturbance_curvature", &D::disturbance_curvature,
                    "the plant disturbance's estimate kappa_d [1/m] (0 without the estimation)");

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
           py::arg("rear_axle_side_slip_rad") = 0.0, py::arg("pose_age_s") = 0.0,
           py::arg("slip_gradient_scale") = 1.0,
           "One control period: rear axle (x, y) [m], heading [rad], signed speed [m/s], dv/dt "
           "[m/s^2], period [s], the rear axle's side slip beta_r [rad], how old the pose is "
           "[s] (0 <= pose_age_s <= 0.5) and the factor on the single-track inversion's slip "
           "gradients (0.5 ... 2). Returns a ControllerOutput; raises ControllerError on "
           "an error status (e.g. a NaN input).")
      .def(
          "reset",
          [](SteeringController& controller, double angle) {
            const Status status = controller.reset(angle);
            if (status != Status::ok) throw ControllerError(status);
          },
          py::arg("measured_steering_angle_rad") = 0.0,
          "Restarts at the measured steering angle [rad]; raises ControllerError for NaN, inf, "
          "|angle| >= pi/2 or beyond the car's angle limit (never wrapped).")
      .def_property_readonly("name", &SteeringController::name)
      .def(
          "set_path",
          [](SteeringController& controller, std::shared_ptr<Path> path) {
            const bool missing = !path;
            const Status status = controller.set_path(std::move(path));
            if (status != Status::ok && missing) refuse_missing_path(status);
            if (status != Status::ok) throw ControllerError(status, "", "set_path()");
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
