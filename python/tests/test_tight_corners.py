"""The tight corners and the kinetic tracking reference from Python: the CLI's tables, and a
reference that keeps the car's limits, reproduces itself re-simulated and turns positive where
the steering rate binds."""
import numpy as np
import pytest
import smoothsteer as ss

HAIRPIN = "scenarios/hairpin.yaml"


def hairpin_reference(speed, duration_s=None):
    """From the straight's last 20 m through the corner and 20 m beyond it."""
    scenario = ss.load_scenario(HAIRPIN)
    vehicle = ss.VehicleParameters.from_file("vehicles/passenger_car.yaml")
    if duration_s is None:
        duration_s = (scenario.path.length_m - 70.0) / speed
    return ss.solve_kinetic_reference(scenario.path, vehicle, speed, start_arc_length_m=30.0,
                                      duration_s=duration_s), vehicle


def test_the_reference_keeps_the_limits_and_turns_positive_where_the_rate_binds():
    slow, vehicle = hairpin_reference(8.0)
    fast, _ = hairpin_reference(15.5)
    for reference in (slow, fast):
        assert reference["converged"], reference["solver_status"]
        assert np.all(np.abs(reference["steering_rate_radps"])
                      <= vehicle.max_steering_rate_radps + 1e-7)
        assert np.all(np.abs(reference["lateral_error_m"])
                      <= reference["max_abs_lateral_error_m"] + 1e-7)
        assert reference["resimulated_max_abs_lateral_error_m"] == pytest.approx(
            reference["max_abs_lateral_error_m"], abs=5e-3)
    assert slow["max_abs_lateral_error_m"] < 0.01 < fast["max_abs_lateral_error_m"]


def test_a_bad_problem_raises_a_value_error_naming_the_field():
    with pytest.raises(ValueError, match="speed_mps = 0"):
        hairpin_reference(0.0, duration_s=10.0)


def test_the_comparison_returns_the_cli_tables():
    tables = ss.compare_tight_corners(baselines=["stanley"], threads=2)
    summary = tables["summary"]
    assert [row["scenario"] for row in summary] == [
        "hairpin", "hairpin", "hairpin", "urban_turn", "mountain_hairpins", "parking_lot"]
    for row in summary:
        assert row["best_baseline"] == "stanley" and row["held_above_limits"] == "0"
    assert summary[-1]["kinetic_reference_m"] == "nan"  # the parking lot changes gear
    controllers = {row["controller"] for row in tables["runs"]}
    assert controllers == {"scenario (scheduled_lead_wheel)", "stanley", "lower_bound",
                           "kinetic_reference"}
