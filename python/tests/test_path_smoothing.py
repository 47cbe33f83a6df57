"""Path.from_waypoints with smoothing_tolerance_m or the jitter estimated from the waypoints: a
smoothing spline through noisy waypoints; WaypointConditioner for a stack's windows."""

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
        interpolating = ss.Path.from_waypoints(xy, estimate_jitter=False)
        smoothed = ss.Path.from_waypoints(xy, smoothing_tolerance_m=0.01 * np.sqrt(2.0))
        assert middle_curvature_error(smoothed, 100.0) < 0.1 * middle_curvature_error(
            interpolating, 100.0
        ), f"seed {seed}"


def test_zero_tolerance_without_the_estimate_interpolates():
    xy = jittered_arc(50.0, 0.005, 3)
    s = np.linspace(0.0, 70.0, 50)
    a = ss.Path.from_waypoints(xy, estimate_jitter=False).sample(s)
    b = ss.Path.from_waypoints(xy, smoothing_tolerance_m=0.0, estimate_jitter=False).sample(s)
    np.testing.assert_array_equal(a, b)
    assert np.abs(a[:, 3] - 1.0 / 50.0).max() > 0.01  # the jitter's curvature, interpolated


def test_by_default_the_jitter_is_estimated_from_the_waypoints():
    for seed in range(5):
        for sigma in (0.002, 0.01, 0.04):
            xy = jittered_arc(100.0, sigma, seed)
            assert 0.5 * sigma < ss.estimate_waypoint_jitter(xy) < 1.6 * sigma, (seed, sigma)
            by_default = ss.Path.from_waypoints(xy)
            told = ss.Path.from_waypoints(xy, smoothing_tolerance_m=sigma * np.sqrt(2.0))
            interpolating = ss.Path.from_waypoints(xy, estimate_jitter=False)
            error = middle_curvature_error(by_default, 100.0)
            assert error < 0.1 * middle_curvature_error(interpolating, 100.0), (seed, sigma)
            assert error < 2.0 * middle_curvature_error(told, 100.0) + 1e-4, (seed, sigma)
    clean = jittered_arc(100.0, 0.0, 0)
    assert ss.estimate_waypoint_jitter(clean) == 0.0
    s = np.linspace(0.0, 70.0, 50)
    np.testing.assert_array_equal(
        ss.Path.from_waypoints(clean).sample(s),
        ss.Path.from_waypoints(clean, estimate_jitter=False).sample(s))


def test_tight_corners_are_restored_by_default():
    # A 20 m radius with 3 cm of jitter: Reinsch's fit (restore_corners=False) cuts the arc by
    # a few jitters; twiced, the fit stays closer to it. A 100 m radius is not twiced.
    for seed in range(5):
        xy = jittered_arc(20.0, 0.03, seed)
        s = np.linspace(10.0, 50.0, 200)
        distance = {}
        for restore in (True, False):
            fitted = ss.Path.from_waypoints(xy, smoothing_tolerance_m=0.03 * np.sqrt(2.0),
                                            estimate_jitter=False, restore_corners=restore)
            points = fitted.sample(s)[:, :2]
            distance[restore] = np.abs(np.hypot(points[:, 0], points[:, 1] - 20.0) - 20.0).max()
        assert distance[True] < 0.9 * distance[False], (seed, distance)
        gentle = jittered_arc(100.0, 0.03, seed)
        np.testing.assert_array_equal(
            ss.Path.from_waypoints(gentle, restore_corners=True).sample(s),
            ss.Path.from_waypoints(gentle, restore_corners=False).sample(s))


def test_the_conditioner_pools_the_windows_jitter():
    conditioner = ss.WaypointConditioner(ss.WaypointConditionerParameters(memory_windows=10))
    assert conditioner.windows == 0 and conditioner.jitter_m == 0.0
    for seed in range(20):
        path = conditioner.fit(jittered_arc(100.0, 0.01, seed))
        assert isinstance(path, ss.Path)
    assert conditioner.windows == 20
    assert 0.008 < conditioner.jitter_m < 0.012
    assert conditioner.tolerance_m == pytest.approx(np.sqrt(2.0) * conditioner.jitter_m)
    conditioner.reset()
    assert conditioner.windows == 0
    with pytest.raises(ValueError, match="memory_windows = 0 must be finite and in"):
        ss.WaypointConditioner(ss.WaypointConditionerParameters(memory_windows=0))


def test_the_conditioner_fits_each_window_with_the_ones_before():
    # Windows of a 100 m radius advancing 2 m each: 5 m into a window, where a stack's car is,
    # the fit with the earlier windows' waypoints behind it lies closer to the arc.
    rng = np.random.default_rng(5)
    radius = 100.0
    with_history = ss.WaypointConditioner()
    alone = ss.WaypointConditioner(ss.WaypointConditionerParameters(history_m=0.0))
    squares = {True: 0.0, False: 0.0}
    for k in range(40):
        s = np.arange(2.0 * k, 2.0 * k + 80.0, 1.0)
        xy = np.column_stack([radius * np.sin(s / radius), radius * (1.0 - np.cos(s / radius))])
        xy += rng.normal(0.0, 0.03, xy.shape)
        for history, conditioner in ((True, with_history), (False, alone)):
            x, y = conditioner.fit(xy).sample(np.array([5.0]))[0, :2]
            if k >= 15:
                squares[history] += (np.hypot(x, y - radius) - radius) ** 2
    assert squares[True] < 0.8 * squares[False], squares
    with pytest.raises(ValueError, match="history_m = -1 must be finite and in"):
        ss.WaypointConditionerParameters(history_m=-1.0).validate()


def test_bad_tolerance_names_the_field():
    with pytest.raises(ValueError, match="smoothing.tolerance_m"):
        ss.Path.from_waypoints(jittered_arc(50.0, 0.005, 1), smoothing_tolerance_m=-1.0)
