"""The robustness comparison and the pose's age from Python: the same tables as `smoothsteer
compare robustness`, and a late pose carried forward when its age is given."""
import math

import pytest
import smoothsteer as ss

RACK = ss.Imperfection("rack +0.01", "disturbance", ["simulation.steering_offset_rad=0.01"])


def test_the_comparison_returns_the_cli_tables():
    tables = ss.compare_robustness([("scenarios/lane_change_10.yaml", 0.0)],
                                   controllers=["certified", "stanley"], imperfections=[RACK])
    runs, summary = tables["runs"], tables["summary"]
    assert len(runs) == 4  # 2 controllers x (nominal + 1)
    for row in runs:
        assert row["held_above_limits"] == "0"
        if row["imperfection"] != "nominal":
            assert float(row["max_abs_e_m"]) > float(row["nominal_max_abs_e_m"]) + 0.005
    assert len(summary) == 1 and summary[0]["best_baseline"] == "stanley"
    assert "1 cases" in tables["summary_notes"][0]


def test_the_default_imperfections_are_overrides_the_scenarios_accept():
    for imperfection in ss.default_imperfections():
        assert imperfection.group in ("disturbance", "model error", "sensing")
        scenario = ss.load_scenario("scenarios/lane_change_10.yaml", {
            key: value for key, value in (o.split("=", 1) for o in imperfection.overrides)})
        assert scenario is not None


@pytest.mark.parametrize("options, field", [
    ({"controllers": ["stanly"]}, "controllers contains 'stanly'"),
    ({"models": ["bicycle"]}, "models contains 'bicycle'"),
    ({"threads": 0}, "threads = 0"),
])
def test_bad_options_raise_value_errors_naming_the_field(options, field):
    with pytest.raises(ValueError, match=field):
        ss.compare_robustness([("scenarios/lane_change_10.yaml", 0.0)], **options)


def test_a_late_pose_with_its_age_steers_as_the_on_time_one():
    """Kinematic plant, 60 ms of latency: told the age, the commands are the on-time ones."""
    path = ss.Path.circle((0.0, 0.0), 30.0)
    plant, period, lag = ss.KinematicSingleTrack(2.7), 0.02, 3

    def commands(latency, tell):
        controller = ss.LeadWheelController(ss.ControllerParameters(), path)
        poses, out = [((0.0, -31.0), 0.0)], []
        for k in range(300):
            seen = poses[max(0, k - latency)]
            age = min(k, latency) * period if tell else 0.0
            delta = controller.update(seen[0], seen[1], 8.0, period_s=period,
                                      pose_age_s=age).steering_angle_rad
            out.append(delta)
            poses.append(plant.step(poses[-1][0], poses[-1][1], delta, 8.0, period))
        return out

    on_time, told, untold = commands(0, True), commands(lag, True), commands(lag, False)
    assert max(abs(a - b) for a, b in zip(told, on_time)) < 1e-9
    assert max(abs(a - b) for a, b in zip(untold, on_time)) > 1e-3


@pytest.mark.parametrize("age", [-0.01, 0.51, math.nan])
def test_an_age_out_of_range_is_refused(age):
    controller = ss.LeadWheelController(ss.ControllerParameters(),
                                        ss.Path.from_waypoints([[0, 0], [30, 0], [60, 0]]))
    with pytest.raises(ss.ControllerError):
        controller.update((0.0, 0.5), 0.0, 5.0, pose_age_s=age)
