"""Clothoid pieces of PathBuilder from Python (C++ tests: tests/path/test_clothoid.cpp)."""
import math

import numpy as np
import pytest

import smoothsteer as ss


def test_clothoid_bend_has_continuous_curvature_and_turns_as_designed():
    """Straight, clothoid A = 20 m into R = 40 m, arc, clothoid out, straight: a 90 degree bend
    whose curvature ramps linearly (no jump) and whose end heading is pi / 2."""
    radius, transition = 40.0, 20.0**2 / 40.0
    path = (ss.PathBuilder((0.0, 0.0), 0.0)
            .line(50.0)
            .clothoid(transition, 1.0 / radius)
            .arc(radius, 0.5 * math.pi - transition / radius)
            .clothoid(transition, 0.0)
            .line(50.0)
            .build())
    samples = path.sample(np.linspace(0.0, path.length_m, 4001))
    assert abs(samples[-1, 2] - 0.5 * math.pi) < 1e-9
    curvature = samples[:, 3]
    assert np.max(np.abs(np.diff(curvature))) < 1.1 * (1.0 / radius) / transition * (
        path.length_m / 4000)
    assert abs(np.max(curvature) - 1.0 / radius) < 1e-12


def test_clothoid_joints_are_kinks_and_splines_have_none():
    """Path.curvature_kinks lists the clothoid's slope steps (docs/feedforward.md section 2b);
    a line-clothoid-arc path has no curvature jump, a waypoint spline no kink."""
    path = ss.PathBuilder((0.0, 0.0), 0.0).line(20.0).clothoid(6.0, 1.0 / 12.0) \
        .arc(12.0, 1.0).build()
    assert path.curvature_jumps == [(pytest.approx(path.length_m), pytest.approx(1.0 / 12.0), 0.0)]
    kinks = path.curvature_kinks
    assert [k[0] for k in kinks] == [pytest.approx(20.0), pytest.approx(26.0)]
    assert kinks[0][2] - kinks[0][1] == pytest.approx(1.0 / 72.0)
    assert kinks[1][2] - kinks[1][1] == pytest.approx(-1.0 / 72.0)
    spline = ss.Path.from_waypoints([[0, 0], [20, 2], [40, -2], [60, 0]])
    assert spline.curvature_kinks == []
