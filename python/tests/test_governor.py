"""The steering governor from Python (docs/governor.md): its fields are reachable by keyword, its
validation names the field, and on seeded random engagement errors the held command keeps the
governor's rate and acceleration limits. The case count is SMOOTHSTEER_PROPERTY_CASES."""
import numpy as np
import pytest

import smoothsteer as ss
from conftest import base_seed, property_cases


def governed_parameters(rate, acceleration):
    governor = ss.SteeringGovernor(enabled=True, max_steering_rate_radps=rate,
                                   max_steering_acceleration_radps2=acceleration,
                                   law_length_m=6.0)
    return ss.ControllerParameters(order=2, lead_curvature_bound=0.1, feedforward_share=0.3,
                                   boundary_layer=0.03, governor=governor)


def test_governor_fields_round_trip():
    parameters = governed_parameters(0.4, 8.0)
    assert parameters.governor.enabled
    assert parameters.governor.max_steering_rate_radps == 0.4
    assert parameters.governor.max_steering_acceleration_radps2 == 8.0
    # Setting the far law's length fixes it; 0 goes back to the derived one.
    assert parameters.governor.fixed_law_length
    assert parameters.governor.law_length_m == 6.0
    parameters.validate()
    parameters.governor.law_length_m = 0.0
    assert not parameters.governor.fixed_law_length
    parameters.validate()


def test_a_length_while_derived_is_refused_naming_both_fields():
    parameters = governed_parameters(0.4, 8.0)
    parameters.governor.fixed_law_length = False
    assert parameters.governor.law_length_m == 6.0
    with pytest.raises(ValueError, match="governor.law_length_m = 6 has no effect while "
                                         "governor.fixed_law_length is false"):
        parameters.validate()


def test_governor_validation_names_the_field():
    parameters = governed_parameters(0.4, 8.0)
    governor = parameters.governor
    governor.max_steering_acceleration_radps2 = float("inf")
    parameters.governor = governor
    with pytest.raises(ValueError, match="governor.max_steering_acceleration_radps2"):
        parameters.validate()


def test_held_command_keeps_the_limits_from_engagement_errors():
    path = ss.Path.from_waypoints([[0, 0], [40, 3], [80, -3], [120, 0], [160, 0]])
    for case in range(property_cases(10)):
        seed = base_seed() + case
        rng = np.random.default_rng(seed)
        rate, acceleration = rng.uniform(0.3, 1.0), rng.uniform(6.0, 20.0)
        speed = rng.uniform(3.0, 12.0)
        controller = ss.LeadWheelController(governed_parameters(rate, acceleration), path)
        car = ss.KinematicSingleTrack(2.7)
        position, heading = (0.0, rng.uniform(-1.0, 1.0)), rng.uniform(-0.3, 0.3)
        dt, held = 0.02, []
        for _ in range(400):
            out = controller.update(position, heading, speed, 0.0, dt)
            held.append(out.steering_angle_rad)
            position, heading = car.step(position, heading, out.steering_angle_rad, speed, dt)
        held = np.array(held)
        rates = np.abs(np.diff(held)) / dt
        accelerations = np.abs(np.diff(held, 2)) / dt**2
        message = f"seed {seed}: R={rate} A={acceleration} v={speed}"
        assert rates.max() <= rate * (1 + 1e-9), message
        assert accelerations.max() <= acceleration * (1 + 1e-9), message


def test_governor_equations_from_python():
    """Eq. (governed_law_length) grows as sqrt(2 v lambda_veh |psi| / R) above its floor and is
    0.7 sqrt(v lambda_veh / R) at the reversal heading; eq. (governed_feedforward_rate) steers at
    R; the widened parameters keep the certified switching authority."""
    parameters = governed_parameters(0.4, 8.0)
    parameters.governor.law_length_m = 0.0  # derived again
    wheelbase = parameters.chain.vehicle_wheelbase_m
    speed = 15.0
    floor = max(sum(parameters.chain.wheelbases_m[:2]), 1.0 + 0.25 * speed)
    for heading in (0.0, 0.05, 0.1, 0.3):
        expected = max(floor, np.sqrt(2.0 * speed * wheelbase * heading / 0.4))
        assert ss.governed_law_length(parameters, speed, heading) == pytest.approx(expected)
        assert ss.governed_law_length(parameters, speed, -heading) == \
            ss.governed_law_length(parameters, speed, heading)
    reversal = ss.governed_law_length(parameters, speed, ss.governed_reversal_heading_rad)
    assert reversal == pytest.approx(max(floor, 0.7 * np.sqrt(speed * wheelbase / 0.4)))
    rate = ss.governed_feedforward_rate(parameters, speed)
    assert wheelbase * speed * rate == pytest.approx(0.4)
    assert np.isinf(ss.governed_feedforward_rate(parameters, 0.0))
    widened = ss.governed_parameters(parameters, speed)
    assert widened.chain.lead_curvature_bound >= parameters.chain.lead_curvature_bound
    # The near law keeps the certified kbar_sw (docs/governor.md, section 4).
    assert np.isinf(parameters.governor.near_law_switching_bound)
    assert widened.governor.near_law_switching_bound == pytest.approx(
        (1.0 - parameters.feedforward.share) * parameters.chain.lead_curvature_bound)
    assert ss.governed_reversal_curvature(parameters, speed) > 0.0
