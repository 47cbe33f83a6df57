"""The car's SteeringSystem built from the car alone, as a driving stack uses it from Python: no
path at set-up, windows of a planner's trajectory by set_path(), a flag for a path beyond the
domain and for a speed above the certified one."""
import math

import numpy as np
import pytest

import smoothsteer as ss
from conftest import ROOT

VEHICLE = ROOT / "vehicles" / "passenger_car.yaml"


def car():
    return ss.VehicleDescription(vehicle=ss.VehicleParameters.from_file(str(VEHICLE)))


def test_no_path_until_set_path_then_it_steers():
    system = ss.make_steering_system(car(), ss.SteeringSystemOptions(max_speed_mps=40.0))
    assert system.parameters.certified_max_speed_mps >= 30.0
    assert system.parameters.domain is not None
    with pytest.raises(ss.ControllerError, match="not_configured"):
        system.update((0.0, 0.5), 0.0, 10.0)
    system.set_path(ss.Path.straight_line((-10.0, 0.0), 0.0, 200.0))
    out = system.update((0.0, 0.5), 0.0, 10.0)
    assert out.steering_angle_rad < 0.0  # left of the line: steers right
    assert out.active_limits & ss.ActiveLimit.path_beyond_domain == 0


def test_stack_windows_on_a_curve_stay_on_the_path():
    """A planner's window (5 m behind, 100 m ahead, 1 m spacing) every 0.1 s on a 60 m circle
    at 12 m/s, on a kinematic car that follows the command exactly (so the law takes beta_r = 0:
    the Magic-Formula observer would read the kinematic car's motion as the kinetic model's and
    leave a 0.15 m offset, on a system built on the path as well)."""
    system = ss.make_steering_system(
        car(), ss.SteeringSystemOptions(max_speed_mps=30.0, slip_input=ss.SlipInput.kinematic))
    radius, speed, period = 60.0, 12.0, 0.02
    wheelbase = car().vehicle.wheelbase_m
    model = ss.KinematicSingleTrack(wheelbase)
    position, heading = (0.0, -radius - 0.3), 0.0
    worst = 0.0
    for k in range(1000):
        if k % 5 == 0:
            angle = math.atan2(position[1], position[0])
            s = np.arange(-5.0, 100.0, 1.0) / radius + angle
            window = np.column_stack([radius * np.cos(s), radius * np.sin(s)])
            system.set_path(ss.Path.from_waypoints(window))
        out = system.update(position, heading, speed, period_s=period)
        if k > 250:
            worst = max(worst, abs(math.hypot(*position) - radius))
        position, heading = model.step(position, heading, out.steering_angle_rad, speed, period)
    assert worst < 0.05, worst


def test_beyond_domain_and_certified_speed_are_flagged():
    domain = ss.DrivingDomain.for_vehicle(car().vehicle)
    domain.max_curvature_per_m = 0.02
    system = ss.make_steering_system(
        car(), ss.SteeringSystemOptions(max_speed_mps=10.0, domain=domain))
    system.set_path(ss.Path.circle((0.0, 10.0), 10.0))
    out = system.update((0.0, 0.0), 0.0, 3.0)
    assert out.active_limits & ss.ActiveLimit.path_beyond_domain
    assert "path_beyond_domain" in out.active_limit_names
    out = system.update((0.05, 0.0), 0.0, system.parameters.certified_max_speed_mps + 5.0)
    assert out.active_limits & ss.ActiveLimit.beyond_certified_speed


def test_bad_domain_names_the_field():
    domain = ss.DrivingDomain(max_lateral_jerk_mps3=-1.0)
    with pytest.raises(ValueError, match="max_lateral_jerk_mps3"):
        ss.make_steering_system(car(), ss.SteeringSystemOptions(domain=domain))
