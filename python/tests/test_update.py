"""update() in Python equals update() in C++ (tests/update_reference.cpp) bit for bit, on seeded
random inputs: poses around the path, speeds of both signs, accelerations and periods. The case
count is SMOOTHSTEER_PROPERTY_CASES; a failure prints the seed and the inputs."""
import subprocess

import numpy as np
import pytest

import smoothsteer as ss
from conftest import BUILD, base_seed, property_cases

REFERENCE = BUILD / "python" / "python_update_reference"
WAYPOINTS = np.array([[0, 0], [20, 5], [40, -5], [60, 10], [80, 0]], dtype=float)


def random_case(rng):
    shape = "circle" if rng.random() < 0.5 else "waypoints"
    order = int(rng.integers(1, 4))
    settings = (shape, order, rng.uniform(0.05, 0.4), rng.uniform(0.0, 0.8),
                rng.uniform(0.0, 0.9), float(rng.choice([0.0, 0.05])))
    steps = int(rng.integers(5, 40))
    inputs = []
    for _ in range(steps):
        inputs.append((rng.uniform(-50, 90), rng.uniform(-40, 40), rng.uniform(-4, 4),
                       rng.uniform(-6, 20), rng.uniform(-2, 2), rng.choice([0.01, 0.02, 0.05])))
    return settings, inputs


def python_outputs(settings, inputs):
    shape, order, kbar, k_rob, share, delay = settings
    path = ss.Path.circle((0.0, 0.0), 30.0) if shape == "circle" else ss.Path.from_waypoints(WAYPOINTS)
    parameters = ss.ControllerParameters(order=order, lead_curvature_bound=kbar, k_rob=k_rob,
                                         feedforward_share=share, actuator_delay_s=delay)
    try:
        controller = ss.LeadWheelController(parameters, path)
    except ValueError as error:  # the same message as C++'s validation_error()
        return [f"invalid {error}"]
    lines = []
    for x, y, heading, speed, acceleration, period in inputs:
        try:
            out = controller.update((x, y), heading, speed, acceleration, period)
            status = "ok"
        except ss.ControllerError as error:
            lines.append(str(error).split()[-1])
            continue
        d = out.diagnostics
        lines.append(" ".join([status] + [repr(float(v)) for v in (
            out.steering_angle_rad, out.steering_rate_radps, out.steering_acceleration_radps2,
            d.lateral_error_m, d.front_lateral_error_m, d.lead_lateral_error_m,
            d.sliding_variable)]))
    return lines


def cpp_outputs(settings, inputs):
    shape, order, kbar, k_rob, share, delay = settings
    text = "".join(" ".join(repr(float(v)) for v in row) + "\n" for row in inputs)
    result = subprocess.run([str(REFERENCE), shape, str(order), repr(kbar), repr(k_rob),
                             repr(share), repr(delay)],
                            input=text, capture_output=True, text=True, check=True)
    lines = []
    for line in result.stdout.splitlines():
        fields = line.split()
        if fields[0] == "invalid":
            return [line]
        lines.append(fields[0] if fields[0] != "ok" else " ".join(
            ["ok"] + [repr(float(v)) for v in fields[1:]]))
    return lines


def test_update_equals_cpp_on_random_inputs():
    seed = base_seed()
    rng = np.random.default_rng(seed)
    valid = 0
    for case in range(property_cases()):
        settings, inputs = random_case(rng)
        expected = cpp_outputs(settings, inputs)
        actual = python_outputs(settings, inputs)
        assert actual == expected, (
            f"seed {seed}, case {case}: settings {settings}, inputs {inputs}")
        valid += not expected[0].startswith("invalid")
    # Most random parameter sets must be valid, or the comparison tests little.
    assert valid >= property_cases() // 2, f"seed {seed}: only {valid} valid cases"


def test_reference_program_exists():
    if not REFERENCE.exists():
        pytest.fail(f"{REFERENCE} not built (build target python_update_reference)")
