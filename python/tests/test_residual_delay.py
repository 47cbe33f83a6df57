"""scripts/residual_delay.py: the feedforward's inversion (docs/vehicle_dynamics.md section 3)
checked against the state-space single-track model written independently in the script, and the
delays it reports checked against their closed forms."""
import importlib.util
import math
import random

import numpy as np

from conftest import ROOT, base_seed, property_cases

_spec = importlib.util.spec_from_file_location("residual_delay",
                                               ROOT / "scripts" / "residual_delay.py")
delay = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(delay)


def model_with_point_masses():
    """The shipped car with Iz = m lf lr, where section 3's two-mass split is exact."""
    model = delay.LinearSingleTrack(ROOT / "vehicles" / "passenger_car.yaml")
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
    model = delay.LinearSingleTrack(ROOT / "vehicles" / "passenger_car.yaml")
    expected = 3.0 / delay.actuator_pole() + delay.CONTROL_PERIOD_S / 2.0
    for case in range(property_cases()):
        v = rng.uniform(3.0, 25.0)
        measured = delay.group_delay(model, v, rng.random() < 0.5)
        assert abs(measured - expected) < 5e-4, f"seed {base_seed() + 1} case {case}: v = {v}"


def test_the_fitted_delay_of_a_slow_signal_is_the_low_frequency_delay():
    model = delay.LinearSingleTrack(ROOT / "vehicles" / "passenger_car.yaml")
    dt = 0.02
    time = np.arange(0.0, 60.0, dt)
    slow = 0.01 * np.exp(-((time - 30.0) / 6.0) ** 2)
    fitted = delay.fitted_delay(model, 15.0, True, slow, dt)
    assert abs(fitted - delay.group_delay(model, 15.0, True)) < 1e-3
