"""Clothoid pieces of PathBuilder from Python (C++ tests: tests/path/test_clothoid.cpp)."""
import math

import numpy as np

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
