"""The car's SteeringSystem from Python: a closed loop driven in Python equals the same loop in
C++ (tests/system_reference.cpp) bit for bit on seeded inputs; every field of the C++ parameter
structs is a keyword in Python (read from the headers, so a field added in C++ and not bound
fails here); construction errors name the field."""
import math
import re
import subprocess

import numpy as np
import pytest

import smoothsteer as ss
from conftest import BUILD, ROOT, base_seed, property_cases

REFERENCE = BUILD / "python" / "python_system_reference"
VEHICLE = ROOT / "vehicles" / "passenger_car.yaml"
WAYPOINTS = [(0, 0), (30, 0), (60, 8), (90, 8), (120, 0), (150, 0)]


def seeded_inputs(rng, steps):
    """Per period: speed [m/s], dv/dt [m/s^2], gyro and accelerometer noise, measured flag."""
    rows = []
    for k in range(steps):
        speed = 8.0 + 3.0 * math.sin(0.013 * k) + float(rng.uniform(-0.05, 0.05))
        rows.append((speed, float(rng.uniform(-1.0, 1.0)), float(rng.normal(0.0, 0.002)),
                     float(rng.normal(0.0, 0.05)), int(rng.random() < 0.7)))
    return rows


def python_loop(rows):
    """The loop of system_reference.cpp, driven from Python with the bound objects."""
    car = ss.VehicleDescription(vehicle=ss.VehicleParameters.from_file(str(VEHICLE)))
    path = ss.Path.from_waypoints(np.array(WAYPOINTS, dtype=float))
    system = ss.make_steering_system(car, path, ss.SteeringSystemOptions(max_speed_mps=12.0))
    wheelbase = car.vehicle.wheelbase_m
    model = ss.KinematicSingleTrack(wheelbase)
    position, heading, actual = (-5.0, 1.0), 0.05, 0.0
    lines = []
    for speed, acceleration, yaw_noise, lateral_noise, measured in rows:
        yaw_rate = speed * math.tan(actual) / wheelbase
        try:
            out = system.update(position, heading, speed, acceleration,
                                yaw_rate_radps=yaw_rate + yaw_noise,
                                lateral_acceleration_mps2=speed * yaw_rate + lateral_noise,
                                period_s=0.02, steering_angle_rad=actual if measured else None)
        except ss.ControllerError as error:
            lines.append(str(error).split()[-1])
            break
        lines.append(" ".join(["ok"] + [repr(float(v)) for v in (
            out.steering_angle_rad, out.steering_rate_radps, out.steering_acceleration_radps2,
            out.side_slip.rear_axle_side_slip_rad, out.tracking.lateral_error_m,
            out.tracking.lead_curvature, out.side_slip.yaw_rate_radps)] + [str(out.active_limits)]))
        actual = actual + 0.3 * (out.steering_angle_rad - actual)
        position, heading = model.step(position, heading, actual, speed, 0.02)
    return lines


def cpp_loop(rows):
    text = "".join(f"{s!r} {a!r} {y!r} {l!r} {m}\n" for s, a, y, l, m in rows)
    result = subprocess.run([str(REFERENCE), str(VEHICLE)], input=text, capture_output=True,
                            text=True, check=True)
    lines = []
    for line in result.stdout.splitlines():
        fields = line.split()
        if fields[0] != "ok":
            lines.append(fields[0])
            break
        lines.append(" ".join(["ok"] + [repr(float(v)) for v in fields[1:-1]] + [fields[-1]]))
    return lines


def test_closed_loop_equals_cpp_bit_for_bit():
    for case in range(max(1, property_cases(4) // 10)):
        seed = base_seed() + 7919 * case
        rows = seeded_inputs(np.random.default_rng(seed), 600)
        expected = cpp_loop(rows)
        actual = python_loop(rows)
        assert len(expected) == len(rows)
        for k, (a, e) in enumerate(zip(actual, expected)):
            assert a == e, f"seed {seed}, period {k}: inputs {rows[k]}\n python {a}\n C++    {e}"
        # The loop tracks: the S-curve's lateral error ends small, and the observer ran.
        assert abs(float(actual[-1].split()[5])) < 0.3, f"seed {seed}"
        assert any(float(line.split()[4]) != 0.0 for line in actual), f"seed {seed}"


def struct_fields(header, struct):
    """The data members of `struct` in a C++ header: its top-level declarations that are not
    static, not functions and not comments."""
    text = (ROOT / "include" / "smoothsteer" / header).read_text()
    start = re.search(r"^struct " + struct + r" \{$", text, re.M)
    assert start, f"struct {struct} not found in {header}"
    body = text[start.end():text.index("\n};", start.end())]
    fields = []
    for line in body.splitlines():
        if not line.startswith("  ") or line.startswith("   ") or line.startswith("  //"):
            continue
        code = line.split("//")[0].strip()
        if not code.endswith(";") or code.startswith(("static", "using", "enum", "friend")):
            continue
        declaration = re.split(r"\{|=", code)[0]
        if "(" in declaration:
            continue  # a function
        fields.append(declaration.split()[-1].rstrip(";"))
    assert fields, f"no fields read from {struct}"
    return fields


BOUND_STRUCTS = [
    ("controller/controller_parameters.hpp", "ControllerParameters", "ControllerParameters", []),
    ("controller/controller_parameters.hpp", "SteeringGovernor", "SteeringGovernor", []),
    ("controller/controller_parameters.hpp", "ChainParameters", "ChainParameters", []),
    ("controller/controller_parameters.hpp", "SwitchingLawParameters", "SwitchingLawParameters",
     []),
    ("controller/controller_parameters.hpp", "FeedforwardParameters", "FeedforwardParameters",
     []),
    ("controller/controller_parameters.hpp", "DelayCompensation", "DelayCompensation", []),
    ("controller/controller_parameters.hpp", "SingleTrackInversion", "SingleTrackInversion", []),
    ("controller/controller_parameters.hpp", "DisturbanceEstimation", "DisturbanceEstimation",
     []),
    ("controller/controller_parameters.hpp", "FrictionGuard", "FrictionGuard", []),
    ("controller/controller_parameters.hpp", "ActuatorInversion", "ActuatorInversion", []),
    ("tuning/gain_schedule.hpp", "TuningOptions", "TuningOptions", []),
    ("tuning/vehicle_steering_system.hpp", "SteeringSystemOptions", "SteeringSystemOptions", []),
    ("tuning/vehicle_steering_system.hpp", "VehicleDescription", "VehicleDescription", []),
    ("system/steering_system.hpp", "SteeringSystemParameters", "SteeringSystemParameters", []),
    ("system/driving_domain.hpp", "DrivingDomain", "DrivingDomain", []),
    ("system/course_error_estimator.hpp", "CourseErrorParameters", "CourseErrorParameters", []),
    ("vehicle/side_slip_observer.hpp", "SideSlipObserverParameters",
     "SideSlipObserverParameters", []),
    ("vehicle/sensor_fault_gate.hpp", "SideSlipFaultGate", "SideSlipFaultGate", []),
    # The double-track group is read from vehicle files only (docs/python.md).
    ("vehicle/vehicle_parameters.hpp", "VehicleParameters", "VehicleParameters", ["double_track"]),
    ("vehicle/vehicle_parameters.hpp", "TireParameters", "TireParameters", []),
    ("vehicle/steering_actuator.hpp", "ActuatorParameters", "ActuatorParameters", []),
]


@pytest.mark.parametrize("header, struct, python_name, unbound", BOUND_STRUCTS)
def test_every_cpp_field_is_a_keyword(header, struct, python_name, unbound):
    cls = getattr(ss, python_name)
    for field in struct_fields(header, struct):
        if field in unbound:
            continue
        default = getattr(cls(), field, None)
        assert hasattr(cls(), field), f"{python_name}.{field} (C++ {header}) is not bound"
        try:
            cls(**{field: default})
        except TypeError as error:
            pytest.fail(f"{python_name}({field}=...) raises TypeError: {error}")


def test_the_header_reader_sees_every_kind_of_declaration():
    # Arrays with initializer lists, nested structs, enums, bools and ints: the groups of
    # ControllerParameters and the fields of its chain group as of this test (a field added
    # since is simply more).
    known = ["chain", "law", "feedforward", "delay_compensation", "single_track",
             "disturbance_estimation", "friction_guard", "actuator_inversion", "governor"]
    fields = struct_fields("controller/controller_parameters.hpp", "ControllerParameters")
    assert set(known) <= set(fields), sorted(set(known) - set(fields))
    chain = struct_fields("controller/controller_parameters.hpp", "ChainParameters")
    assert {"order", "vehicle_wheelbase_m", "wheelbases_m", "lead_curvature_bound",
            "max_substep_fraction", "max_substeps"} <= set(chain), chain
    assert not {"max_order", "validate", "paper_c1", "feedforward_curvature_bound"} & set(fields)


def test_docs_list_every_controller_field():
    text = (ROOT / "docs" / "python.md").read_text()
    for field in struct_fields("controller/controller_parameters.hpp", "ControllerParameters"):
        assert f"`{field}`" in text, f"docs/python.md does not list ControllerParameters.{field}"


def test_new_keywords_reach_cpp():
    p = ss.ControllerParameters(preview_time_s=0.05, rear_slip_gradient_s2pm=0.004,
                                front_slip_gradient_s2pm=0.003, slip_preview_second_order=False,
                                actuator_time_constant_s=0.01, actuator_lag_count=2,
                                max_lateral_acceleration_mps2=8.0,
                                disturbance_estimation_length_m=20.0)
    p.validate()
    with pytest.raises(ValueError, match="actuator_lag_count = 7"):
        ss.ControllerParameters(actuator_lag_count=7).validate()
    assert ss.TuningOptions(feedforward_headroom=1.5).feedforward_headroom == 1.5
    with pytest.raises(TypeError, match="unknown keyword 'preview_time'"):
        ss.ControllerParameters(preview_time=0.1)


def test_construction_errors_name_the_field():
    car = ss.VehicleDescription(vehicle=ss.VehicleParameters.from_file(str(VEHICLE)))
    path = ss.Path.circle((0.0, 0.0), 40.0)
    with pytest.raises(ValueError, match=r"SteeringSystemOptions: max_speed_mps = -1 "):
        ss.make_steering_system(car, path, ss.SteeringSystemOptions(max_speed_mps=-1.0))
    wrong = ss.ControllerParameters(vehicle_wheelbase_m=2.7)
    with pytest.raises(ValueError, match="vehicle_wheelbase_m = 2.7 must be the vehicle's"):
        ss.SteeringSystem(car.vehicle, wrong, path)
    bad = ss.VehicleDescription(vehicle=car.vehicle,
                                actuator=ss.ActuatorParameters(bandwidth_hz=-1.0))
    with pytest.raises(ValueError, match="actuator.bandwidth_hz = -1"):
        ss.make_steering_system(bad, path)


def test_any_controller_can_be_composed():
    vehicle = ss.VehicleParameters()
    path = ss.Path.circle((0.0, 0.0), 40.0)
    controller = ss.LeadWheelController(
        ss.ControllerParameters(vehicle_wheelbase_m=vehicle.wheelbase_m), path)
    system = ss.SteeringSystem(controller,
                               ss.SteeringSystemParameters(slip_input=ss.SlipInput.sensor))
    del controller  # the system keeps it alive
    out = system.update((41.0, 0.0), math.pi / 2, 8.0, rear_axle_side_slip_rad=0.01)
    assert out.side_slip.rear_axle_side_slip_rad == 0.01
    assert out.active_limit_names == ss.describe_active_limits(out.active_limits)


def test_course_error_is_on_by_default_and_reported():
    """The system learns the slip's scale and a course bias from the pose by default; off with
    course_error=None; what it learned is in SideSlipDiagnostics; bad parameters name the field."""
    car = ss.VehicleDescription(vehicle=ss.VehicleParameters.from_file(str(VEHICLE)))
    path = ss.Path.from_waypoints(np.array(WAYPOINTS, dtype=float))
    system = ss.make_steering_system(car, path, ss.SteeringSystemOptions(max_speed_mps=12.0))
    assert system.parameters.course_error is not None
    # Driving straight along the path, the pose steps beside the course the slip says: c grows.
    heading = math.atan2(0.0, 1.0)
    out = None
    for k in range(200):
        out = system.update((-5.0 + 10.0 * 0.02 * k, 0.002 * 10.0 * 0.02 * k), heading, 10.0,
                            yaw_rate_radps=0.0, lateral_acceleration_mps2=0.0)
    assert out.side_slip.course_bias_rad > 5e-4
    assert abs(out.side_slip.slip_error) <= ss.CourseErrorParameters().max_slip_error
    system.forget_course_error()
    with pytest.raises(ValueError, match="course_error.max_slip_error"):
        ss.SteeringSystemParameters(course_error=ss.CourseErrorParameters(max_slip_error=0.9)
                                    ).validate()
    assert ss.SteeringSystemParameters(course_error=None).course_error is None
