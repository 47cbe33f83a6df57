"""studies/residual_delay.py: the feedforward's inversion (docs/vehicle_dynamics.md section 3)
checked against the state-space single-track model written independently in the script, and the
delays it reports checked against their closed forms."""
import importlib.util
import math
import random

import numpy as np

import smoothsteer
from conftest import ROOT, base_seed, property_cases

_spec = importlib.util.spec_from_file_location("residual_delay",
                                               ROOT / "studies" / "residual_delay.py")
delay = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(delay)

PARAMETERS = smoothsteer.load_scenario(str(ROOT / "scenarios" / "lane_change_15.yaml")).parameters


def loop_at(speed, second_order):
    """lane_change_15's loop (its car, actuator and control period) at another speed."""
    parameters = dict(PARAMETERS, speed={"initial_mps": speed},
                      controller={"slip_preview_second_order": second_order})
    return delay.Loop(delay.LinearSingleTrack(PARAMETERS["vehicle"]), parameters)


def model_with_point_masses():
    """The shipped car with Iz = m lf lr, where section 3's two-mass split is exact."""
    model = delay.LinearSingleTrack(PARAMETERS["vehicle"])
    model.iz = model.m * model.lf * model.lr
    return model


def inversion_residual(model, v, w, second_order):
    s = 1j * w
    return abs(model.curvature_response(s, v) * model.inversion(s, v, second_order) - 1.0)


def test_the_inversion_is_exact_to_second_order_in_frequency():
    """With the second-order term the residual of (response x inversion) falls with w^3, without
    it with w^2: halving w divides it by about 8, resp. 4."""
    rng = random.Random(base_seed())
    model = model_with_point_masses()
    for case in range(property_cases()):
        v = rng.uniform(3.0, 25.0)
        w = rng.uniform(0.05, 0.2)
        context = f"seed {base_seed()} case {case}: v = {v} m/s, w = {w} rad/s"
        with_c = inversion_residual(model, v, w, True) / inversion_residual(model, v, w / 2, True)
        without = inversion_residual(model, v, w, False) / inversion_residual(model, v, w / 2, False)
        assert 7.0 < with_c < 9.0, context
        assert 3.5 < without < 4.5, context


def test_the_low_frequency_delay_is_the_actuator_plus_half_the_hold():
    rng = random.Random(base_seed() + 1)
    bandwidth = PARAMETERS["actuator"]["bandwidth_hz"]
    pole = 2.0 * math.pi * bandwidth / math.sqrt(2.0 ** (1.0 / 3.0) - 1.0)
    expected = 3.0 / pole + PARAMETERS["simulation"]["control_period_s"] / 2.0
    for case in range(property_cases()):
        v = rng.uniform(3.0, 25.0)
        measured = loop_at(v, rng.random() < 0.5).group_delay()
        assert abs(measured - expected) < 5e-4, f"seed {base_seed() + 1} case {case}: v = {v}"


def test_the_fitted_delay_of_a_slow_signal_is_the_low_frequency_delay():
    loop = loop_at(15.0, True)
    time = np.arange(0.0, 60.0, loop.period)
    slow = 0.01 * np.exp(-((time - 30.0) / 6.0) ** 2)
    assert abs(loop.fitted_delay(slow, loop.period) - loop.group_delay()) < 1e-3
