"""studies/feedforward_bound.py: the linear programme's model and its optimum are checked against
an independent integration of the chain, and its ordering against feasible candidates."""
import importlib.util
import math
import random

import numpy as np

from conftest import ROOT, base_seed, property_cases

_spec = importlib.util.spec_from_file_location("feedforward_bound",
                                               ROOT / "studies" / "feedforward_bound.py")
bound = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(bound)

STEP = 0.1


def integrate_offset(k1, k2, wheelbases, lead, s, substeps=4):
    """max |y| of the chain driven by `lead` (held over each step), by classical RK4 sub-steps of
    d sigma / ds = (input - sigma) / lambda, theta' = sigma_0 - kappa_path, y' = theta:
    independent of the matrix exponential of chain_model."""
    def derivative(state, lead_value, path):
        out = np.empty_like(state)
        signal = lead_value
        for i, lam in enumerate(wheelbases):
            out[i] = (signal - state[i]) / lam
            signal = state[i]
        out[-2] = signal - path
        out[-1] = state[-2]
        return out

    state = np.array([k1] * len(wheelbases) + [0.0, 0.0])
    worst = 0.0
    h = STEP / substeps
    for k in range(len(s)):
        worst = max(worst, abs(state[-1]))
        path = k2 if s[k] >= -0.5 * STEP else k1
        for _ in range(substeps):
            d1 = derivative(state, lead[k], path)
            d2 = derivative(state + 0.5 * h * d1, lead[k], path)
            d3 = derivative(state + 0.5 * h * d2, lead[k], path)
            d4 = derivative(state + h * d3, lead[k], path)
            state = state + h / 6.0 * (d1 + 2 * d2 + 2 * d3 + d4)
    return max(worst, abs(state[-1]))


def random_case(rng):
    k1 = rng.uniform(-0.05, 0.05)
    k2 = rng.uniform(-0.05, 0.05)
    while abs(k2 - k1) < 0.01:
        k2 = rng.uniform(-0.05, 0.05)
    wheelbases = [rng.uniform(1.0, 3.0), rng.uniform(0.1, 0.8)]
    ff_bound = max(abs(k1), abs(k2)) * rng.uniform(1.0, 1.5)
    ff_rate = rng.uniform(0.004, 0.02)
    sw_bound = rng.uniform(0.002, 0.02)
    return k1, k2, wheelbases, ff_bound, ff_rate, sw_bound


def test_centred_ramp_without_lags_leaves_dkappa_s2_over_24():
    # A ramp of width S centred on the jump: heading back to zero, offset dkappa S^2 / 24.
    for k1, k2, rate in [(0.0, 0.03, 0.01), (0.02, -0.03, 0.005)]:
        width = abs(k2 - k1) / rate
        got = bound.centred_ramp_offset(k1, k2, [1e-3], rate, before=width + 5, after=width + 20)
        expected = abs(k2 - k1) * width ** 2 / 24
        assert abs(got - expected) < 0.03 * expected, (k1, k2, rate, got, expected)


def test_bound_is_attained_by_its_plan_and_ordered():
    cases = max(3, property_cases() // 50)
    for case in range(cases):
        seed = base_seed() + case
        rng = random.Random(seed)
        k1, k2, wheelbases, ff_bound, ff_rate, sw_bound = random_case(rng)
        context = f"seed {seed}: k1={k1} k2={k2} lambdas={wheelbases} kbar_ff={ff_bound} " \
                  f"L_ff={ff_rate} kbar_sw={sw_bound}"
        alone, x_alone = bound.lower_bound(k1, k2, wheelbases, ff_bound, ff_rate, 0.0, step=STEP)
        both, x_both = bound.lower_bound(k1, k2, wheelbases, ff_bound, ff_rate, sw_bound, step=STEP)
        assert x_alone is not None and x_both is not None, context
        # More freedom never hurts; the centred ramp is one plan of the class (when it fits).
        assert both <= alone + 1e-9, context
        if max(abs(k1), abs(k2)) <= ff_bound:
            assert alone <= bound.centred_ramp_offset(k1, k2, wheelbases, ff_rate) + 1e-9, context
        # The optimal plan respects the class and reproduces its bound on an independent model.
        n = (len(x_both) - 1) // 2
        f, w = x_both[:n], x_both[n:2 * n]
        assert np.all(np.abs(f) <= ff_bound + 1e-9) and np.all(np.abs(w) <= sw_bound + 1e-9), context
        assert np.all(np.abs(np.diff(f)) <= ff_rate * STEP * (1 + 1e-6) + 1e-12), context
        s = np.arange(-250, 301) * STEP
        replay = integrate_offset(k1, k2, wheelbases, f + w, s)
        assert math.isclose(replay, both, rel_tol=0.01, abs_tol=1e-5), f"{context}: {replay} vs {both}"
