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


def state(p):
    """Every flat field and every group's switch: what a setter can change."""
    values = {row["name"]: getattr(p, row["name"]) for row in ss.ControllerParameters.fields()
              if not row["name"].startswith("governor.")}
    values.update({group: getattr(p, group).enabled for group in GROUP_CLASSES
                   if group not in UNGATED})
    return values


def test_a_member_set_through_its_group_does_what_its_flat_field_does():
    switching = [row for row in ss.ControllerParameters.fields() if row["switches_group"]]
    assert len(switching) >= 5
    for row in switching:
        group, attribute = row["member"].split(".", 1)
        # One value inside the range and the off value (0 where the group has two switching
        # fields, the slip gradients: either one nonzero keeps it on).
        inside = row["min"] + 0.5 * (min(row["max"], row["min"] + 1.0) - row["min"])
        off = row["off"] if row["off"] is not None else 0.0
        for start in (inside, off):
            for value in (inside, off):
                flat = ss.ControllerParameters(**{row["name"]: start})
                grouped = ss.ControllerParameters(**{row["name"]: start})
                setattr(flat, row["name"], value)
                setattr(getattr(grouped, group), attribute, value)
                assert state(grouped) == state(flat), (row["name"], start, value)
    # The group's own keyword constructor: an explicit `enabled` wins whatever its position.
    assert ss.DelayCompensation(actuator_delay_s=0.048).enabled
    assert not ss.DelayCompensation(enabled=False, actuator_delay_s=0.048).enabled
    assert not ss.DelayCompensation(actuator_delay_s=0.048, enabled=False).enabled


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


# Each group of ControllerParameters and its class; the optional groups' `enabled` switch is the
# one member not in the table (the flat fields switch it), except the governor's.
GROUP_CLASSES = {"chain": "ChainParameters", "law": "SwitchingLawParameters",
                 "feedforward": "FeedforwardParameters", "delay_compensation": "DelayCompensation",
                 "single_track": "SingleTrackInversion",
                 "disturbance_estimation": "DisturbanceEstimation",
                 "friction_guard": "FrictionGuard", "actuator_inversion": "ActuatorInversion",
                 "governor": "SteeringGovernor"}
UNGATED = {"chain", "law", "feedforward", "governor"}


def data_attributes(cls):
    """The instance attributes (the static constants, max_order and the like, are not fields)."""
    return {name for name, value in vars(cls).items()
            if type(value) is property and not name.startswith("_")}


def test_each_group_class_has_exactly_the_tables_members():
    table = {}
    for row in ss.ControllerParameters.fields():
        group, member = row["member"].split(".", 1)
        table.setdefault(group, set()).add(member)
    assert set(table) == set(GROUP_CLASSES)
    for group, class_name in GROUP_CLASSES.items():
        expected = table[group] | (set() if group in UNGATED else {"enabled"})
        assert data_attributes(getattr(ss, class_name)) == expected, class_name
    flat = data_attributes(ss.ControllerParameters) - set(GROUP_CLASSES)
    rows = {row["name"] for row in ss.ControllerParameters.fields()
            if not row["name"].startswith("governor.")}
    assert flat == rows


def test_a_group_attribute_and_its_flat_name_reach_the_same_member():
    rows = [row for row in ss.ControllerParameters.fields() if row["name"] != "wheelbases_m"]
    for row in rows:
        group, member = row["member"].split(".", 1)
        p = ss.ControllerParameters()
        value = getattr(getattr(p, group), member)
        if isinstance(value, bool):
            changed = not value
        elif isinstance(value, int) and not hasattr(value, "name"):
            changed = value + 1
        elif isinstance(value, float):
            changed = 0.5 if value != 0.5 else 0.25
        else:
            continue  # an enumeration: its values are checked by the scenario tests
        holder = getattr(p, group)
        setattr(holder, member, changed)
        setattr(p, group, holder)
        assert getattr(getattr(p, group), member) == changed, row["name"]
        if not row["name"].startswith("governor."):
            assert getattr(p, row["name"]) == changed, row["name"]
