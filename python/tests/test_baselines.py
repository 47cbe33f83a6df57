"""The comparison controllers' second-order limiter from Python: the acceleration limit is a
constructor argument (validated, named in the error), the held command keeps it, and the
saturation statistics count its clamps."""
import math

import pytest

import smoothsteer as ss


def drive(controller, steps=300, period=0.01):
    """Closed loop on the kinematic model from 1 m and 0.2 rad off a straight line."""
    car = ss.KinematicSingleTrack(2.7)
    position, heading = (0.0, 1.0), 0.2
    commands = []
    for _ in range(steps):
        out = controller.update(position, heading, 10.0, 0.0, period)
        commands.append(out.steering_angle_rad)
        position, heading = car.step(position, heading, out.steering_angle_rad, 10.0, period)
    return commands


def held_accelerations(commands, period):
    rates = [(b - a) / period for a, b in zip([0.0] + commands[:-1], commands)]
    return [(b - a) / period for a, b in zip([0.0] + rates[:-1], rates)]


def test_acceleration_limit_holds_the_held_command():
    path = ss.Path.straight_line((0.0, 0.0), 0.0, 500.0)
    free = ss.ComparisonController("hosm", path, max_steering_rate_radps=0.4)
    limited = ss.ComparisonController("hosm", path, max_steering_rate_radps=0.4,
                                      max_steering_acceleration_radps2=8.0)
    # Bang-bang on the rate: without the limit the held command jumps by 0.4 rad/s per period.
    assert max(map(abs, held_accelerations(drive(free), 0.01))) > 30.0
    assert max(map(abs, held_accelerations(drive(limited), 0.01))) <= 8.0 * (1 + 1e-9) + 1e-9
    s = limited.saturation
    assert s.acceleration_limited > 0
    assert s.max_acceleration_excess_radps2 > 0.0
    assert s.limited >= s.acceleration_limited
    assert 0.0 < s.limited_fraction <= 1.0
    assert free.saturation.acceleration_limited == 0


def test_invalid_acceleration_limit_names_the_field():
    path = ss.Path.straight_line((0.0, 0.0), 0.0, 100.0)
    with pytest.raises(ValueError, match="acceleration_radps2 = 0 must be > 0"):
        ss.ComparisonController("stanley", path, max_steering_acceleration_radps2=0.0)
    with pytest.raises(ValueError, match="acceleration_radps2 = nan"):
        ss.ComparisonController("stanley", path, max_steering_acceleration_radps2=math.nan)
