"""The C++ field table (parameter_fields.hpp) is what Python's flat keywords are made of: every
row is a keyword and an attribute, and a compensation's flat field switches its group."""
import math

import pytest

import smoothsteer as ss


def test_every_row_of_the_field_table_is_a_keyword():
    rows = ss.ControllerParameters.fields()
    assert len(rows) >= 30
    defaults = ss.ControllerParameters()
    for row in rows:
        name = row["name"]
        if name.startswith("governor."):
            assert hasattr(defaults.governor, name.split(".", 1)[1]), name
            continue
        value = getattr(defaults, name)
        p = ss.ControllerParameters(**{name: value})
        assert p.validate() is None, name


def test_a_flat_field_switches_its_group():
    p = ss.ControllerParameters(actuator_delay_s=0.048)
    assert p.delay_compensation.enabled and p.delay_compensation.actuator_delay_s == 0.048
    p.actuator_delay_s = 0.0
    assert not p.delay_compensation.enabled
    guard = ss.ControllerParameters(max_lateral_acceleration_mps2=8.0)
    assert guard.friction_guard.enabled
    guard.max_lateral_acceleration_mps2 = math.inf
    assert not guard.friction_guard.enabled


def test_groups_are_attributes_and_keywords():
    p = ss.ControllerParameters()
    p.chain.order = 1
    assert p.order == 1
    p.single_track = ss.SingleTrackInversion(enabled=True, rear_slip_gradient_s2pm=0.004,
                                             preview_time_s=0.05)
    assert p.preview_time_s == 0.05
    p.validate()


def test_an_inert_field_is_rejected_naming_its_switch():
    with pytest.raises(ValueError, match="actuator_lag_count = 2 has no effect while "
                                         "actuator_inversion.enabled is false"):
        ss.ControllerParameters(actuator_lag_count=2).validate()
