"""Path.from_waypoints with smoothing_tolerance_m: a smoothing spline through noisy waypoints."""

import numpy as np
import pytest

import smoothsteer as ss


def jittered_arc(radius, sigma, seed):
    rng = np.random.default_rng(seed)
    s = np.arange(0.0, 80.0, 1.0)
    xy = np.column_stack([radius * np.sin(s / radius), radius * (1.0 - np.cos(s / radius))])
    return xy + rng.normal(0.0, sigma, xy.shape)


def middle_curvature_error(path, radius):
    s = np.linspace(0.2 * path.length_m, 0.8 * path.length_m, 100)
    return np.sqrt(np.mean((path.sample(s)[:, 3] - 1.0 / radius) ** 2))


def test_smoothing_keeps_the_arcs_curvature():
    for seed in range(5):
        xy = jittered_arc(100.0, 0.01, seed)
        interpolating = ss.Path.from_waypoints(xy)
        smoothed = ss.Path.from_waypoints(xy, smoothing_tolerance_m=0.01 * np.sqrt(2.0))
        assert middle_curvature_error(smoothed, 100.0) < 0.1 * middle_curvature_error(
            interpolating, 100.0
        ), f"seed {seed}"


def test_zero_tolerance_interpolates():
    xy = jittered_arc(50.0, 0.005, 3)
    a = ss.Path.from_waypoints(xy).sample(np.linspace(0.0, 70.0, 50))
    b = ss.Path.from_waypoints(xy, smoothing_tolerance_m=0.0).sample(np.linspace(0.0, 70.0, 50))
    np.testing.assert_array_equal(a, b)


def test_bad_tolerance_names_the_field():
    with pytest.raises(ValueError, match="smoothing.tolerance_m"):
        ss.Path.from_waypoints(jittered_arc(50.0, 0.005, 1), smoothing_tolerance_m=-1.0)
