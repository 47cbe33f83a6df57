"""The speed compensation from Python: the same values as the C++ rule (speed_compensation.hpp),
and the validation message that names the field."""
import math

import smoothsteer as ss


def lane_change_path():
    return ss.PathBuilder((0.0, 0.0), 0.0).line(20.0).arc(30.0, 1.0).line(20.0).build()


def test_the_rule_from_the_car_and_the_path():
    car = ss.VehicleParameters()
    compensation = ss.speed_compensation(car, 0.0243, lane_change_path())
    assert math.isclose(compensation.design_curvature_per_m, 1.0 / 30.0, rel_tol=1e-6)
    assert compensation.delay_s(0.0) == 0.0243
    v = 15.0
    usage = min(1.0, v * v / 30.0 / compensation.friction_limit_mps2)
    assert math.isclose(compensation.friction_usage(v), usage, rel_tol=1e-12)
    expected = 0.0243 + 0.25 * compensation.slip_gradient_sum_s2pm * v * usage
    assert math.isclose(compensation.delay_s(v), expected, rel_tol=1e-12)
    assert compensation.catch_up(v) == (0.5 if usage >= 0.7 else 0.0)


def test_invalid_compensation_names_the_field():
    compensation = ss.SpeedCompensation()
    compensation.friction_limit_mps2 = 0.0
    try:
        compensation.validate()
    except ValueError as error:
        assert "friction_limit_mps2 = 0" in str(error)
    else:
        raise AssertionError("accepted mu g = 0")
