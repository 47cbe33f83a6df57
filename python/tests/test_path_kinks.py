"""Path.max_abs_curvature_kink and Path.max_abs_spline_kink: what the feedforward rounds."""

import numpy as np

import smoothsteer as ss


def urban_turn():
    """60 m, a 2.5 m clothoid into R = 10 m, the clothoid back, 50 m (scenarios/roads)."""
    return (
        ss.PathBuilder((0.0, 0.0), 0.0)
        .line(60.0)
        .clothoid(2.5, -0.1)
        .arc(10.0, -1.3207963267948966)
        .clothoid(2.5, 0.0)
        .line(50.0)
        .build()
    )


def test_a_road_lists_its_kinks_and_has_no_spline_kink():
    road = urban_turn()
    assert abs(road.max_abs_curvature_kink - 0.1 / 2.5) < 1e-12
    assert road.max_abs_spline_kink == 0.0


def test_its_waypoints_give_the_same_step_through_the_splines_ringing():
    road = urban_turn()
    step = 0.1 / 2.5
    for phase in (0.0, 0.25, 0.5, 0.75):
        knots = np.arange(phase, road.length_m, 1.0)
        spline = ss.Path.from_waypoints(road.sample(knots)[:, :2])
        assert spline.curvature_kinks == []
        assert abs(spline.max_abs_spline_kink / step - 1.0) < 0.1, f"phase {phase}"
