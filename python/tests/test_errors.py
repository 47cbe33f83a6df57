"""Errors reach Python as exceptions with the library's own messages (the CLI prints the same)."""
import math
import subprocess

import numpy as np
import pytest

import smoothsteer as ss
from conftest import CLI


def cli_error(*arguments):
    result = subprocess.run([str(CLI), *arguments], capture_output=True, text=True)
    assert result.returncode == 1
    prefix = f"smoothsteer {arguments[0]}: "
    assert result.stderr.startswith(prefix), result.stderr
    return result.stderr[len(prefix):].rstrip("\n")


@pytest.mark.parametrize("override", [
    "controller.nope=1",
    "speed.initial_mps=-3",
    "simulation.control_period_s=abc",
    "actuator={bandwidth_hz: 10, colour: red}",
])
def test_scenario_errors_carry_the_cli_message(tmp_path, override):
    message = cli_error("run", "scenarios/lane_change_10.yaml", "--out", str(tmp_path / "o"),
                        "--set", override)
    with pytest.raises(ss.ConfigError) as error:
        ss.run_scenario("scenarios/lane_change_10.yaml", [override])
    assert str(error.value) == message
    assert "scenarios/lane_change_10.yaml" in message
    assert isinstance(error.value, ValueError)


def test_waypoint_file_error_names_file_and_line(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("x,y\n0,0\n1,one\n")
    override = f"path={{type: waypoints_csv, file: {bad}}}"
    message = cli_error("run", "scenarios/waypoints_s_curve.yaml", "--out",
                        str(tmp_path / "o"), "--set", override)
    with pytest.raises(ss.ConfigError) as error:
        ss.load_scenario("scenarios/waypoints_s_curve.yaml", [override])
    assert str(error.value) == message
    assert str(bad) in message


def test_missing_file():
    with pytest.raises(ss.ConfigError, match="does_not_exist.yaml"):
        ss.load_scenario("scenarios/does_not_exist.yaml")


def test_parameter_errors_name_field_value_and_rule():
    path = ss.Path.circle((0, 0), 30.0)
    parameters = ss.ControllerParameters(k_rob=1.5)
    with pytest.raises(ValueError) as error:
        ss.LeadWheelController(parameters, path)
    assert str(error.value) == (
        "ControllerParameters: k_rob = 1.5 must be in [0, 1) (eq. sigma divides by 1 - k_rob)")
    with pytest.raises(ValueError) as again:
        parameters.validate()
    assert str(again.value) == str(error.value)
    with pytest.raises(TypeError, match="ControllerParameters: unknown keyword 'kbar'"):
        ss.ControllerParameters(kbar=0.1)
    with pytest.raises(ValueError, match="wheelbases_m"):
        ss.ControllerParameters(wheelbases_m=[1.0] * 9)
    with pytest.raises(ValueError) as catch_up:
        ss.ControllerParameters(feedforward_catch_up=1.5).validate()
    assert str(catch_up.value) == "ControllerParameters: feedforward_catch_up = 1.5 must be in [0, 1]"
    with pytest.raises(ValueError, match="curvature_preview .* rear_axle_exact"):
        ss.ControllerParameters(curvature_preview=ss.CurvaturePreview.planned_jumps).validate()


def test_path_errors():
    with pytest.raises(ValueError, match="waypoints"):
        ss.Path.from_waypoints(np.array([[0.0, 0.0]]))
    with pytest.raises(ValueError, match="N x 2"):
        ss.Path.from_waypoints(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="radius"):
        ss.Path.circle((0, 0), -1.0)


def test_infeasible_limits_name_the_limit(tmp_path):
    car = ss.VehicleLimits(wheelbase_m=2.7, max_steering_angle_rad=0.5,
                           max_steering_rate_radps=0.01, max_steering_acceleration_radps2=0.1)
    with pytest.raises(ss.InfeasibleLimits) as error:
        ss.tune(car, [5.0, 30.0], path_curvature_bound=0.1, path_curvature_rate_bound=0.01)
    assert "steering" in str(error.value) or "k_rob" in str(error.value)


def test_controller_error_status():
    controller = ss.LeadWheelController(ss.ControllerParameters(), ss.Path.circle((0, 0), 30.0))
    with pytest.raises(ss.ControllerError, match="invalid_input"):
        controller.update((math.nan, 0.0), 0.0, 5.0)
    with pytest.raises(ss.ControllerError, match="invalid_input"):
        controller.update((0.0, 0.0), 0.0, 5.0, 0.0, -0.02)
    with pytest.raises(TypeError, match="rear_axle_position"):
        controller.update((1.0, 2.0, 3.0), 0.0, 5.0)


@pytest.mark.parametrize("text,got", [("", "an empty file"), ("# nothing\n", "an empty file"),
                                      ("[1, 2]\n", "a list or a scalar")])
def test_a_vehicle_file_without_a_mapping_is_refused(tmp_path, text, got):
    """As the scenario loader refuses it: an empty file is no car, not the default one."""
    vehicle = tmp_path / "car.yaml"
    vehicle.write_text(text)
    with pytest.raises(ss.ConfigError) as error:
        ss.VehicleParameters.from_file(str(vehicle))
    assert str(error.value).startswith(f"{vehicle}: expected a mapping of vehicle keys")
    assert got in str(error.value)


@pytest.mark.parametrize("arguments,named", [
    (((math.nan, 0.0), 0.0, 5.0), "rear_axle_position.x = nan"),
    (((0.0, 2e9), 0.0, 5.0), "rear_axle_position.y = 2000000000.0"),
    (((0.0, 0.0), math.inf, 5.0), "heading_rad = inf"),
    (((0.0, 0.0), 0.0, 1e4), "speed_mps = 10000.0"),
    (((0.0, 0.0), 0.0, 5.0, -1e5), "acceleration_mps2 = -100000.0"),
    (((0.0, 0.0), 0.0, 5.0, 0.0, -0.02), "period_s = -0.02"),
])
def test_a_controller_error_names_the_bad_input(arguments, named):
    """As the CLI's message does ("its input speed_mps = ... is outside ControllerInputRange")."""
    controller = ss.LeadWheelController(ss.ControllerParameters(), ss.Path.circle((0, 0), 30.0))
    with pytest.raises(ss.ControllerError) as error:
        controller.update(*arguments)
    message = str(error.value)
    assert message.startswith("update() returned invalid_input: "), message
    assert named in message and "ControllerInputRange" in message, message


def test_set_path_none_says_the_path_is_none():
    controller = ss.LeadWheelController(ss.ControllerParameters(), ss.Path.circle((0, 0), 30.0))
    with pytest.raises(ss.ControllerError, match=r"^set_path\(\) returned invalid_input: the "
                                                 r"path is None"):
        controller.set_path(None)
    controller.update((30.0, 0.0), math.pi / 2, 5.0)  # the old path stays


def test_the_steering_system_names_the_bad_input_and_a_missing_path():
    vehicle = ss.VehicleParameters()
    controller = ss.LeadWheelController(
        ss.ControllerParameters(vehicle_wheelbase_m=vehicle.wheelbase_m),
        ss.Path.circle((0.0, 0.0), 40.0))
    system = ss.SteeringSystem(controller, ss.SteeringSystemParameters())
    with pytest.raises(ss.ControllerError, match=r"invalid_input: speed_mps = 10000\.0 is"):
        system.update((41.0, 0.0), math.pi / 2, 1e4)
    with pytest.raises(ss.ControllerError, match=r"the path is None"):
        system.set_path(None)


@pytest.mark.parametrize("group,field,value,named,rule", [
    ("law", "boundary_layer", math.nan, "controller.law.boundary_layer = nan", "finite"),
    ("law", "k_rob", 0.2, "controller.law.k_rob = 0.2", "gain schedule"),
    ("feedforward", "share", 0.7, "controller.feedforward.share = 0.7", "gain schedule"),
])
def test_the_schedule_template_refuses_what_it_cannot_honour(group, field, value, named, rule):
    """k_rob and the feedforward share were silently replaced by the schedule's, and a NaN
    boundary layer came back from the tuner as InfeasibleLimits."""
    car = ss.VehicleDescription(
        vehicle=ss.VehicleParameters.from_file("vehicles/passenger_car.yaml"))
    options = ss.SteeringSystemOptions()
    setattr(getattr(options.controller, group), field, value)
    with pytest.raises(ValueError) as error:
        ss.make_steering_system(car, ss.Path.circle((0.0, 0.0), 40.0), options)
    assert not isinstance(error.value, ss.InfeasibleLimits), str(error.value)
    assert str(error.value).startswith(f"SteeringSystemOptions: {named} "), str(error.value)
    assert rule in str(error.value)
