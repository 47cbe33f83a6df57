"""Campaign specs are checked before any case runs, every error naming the spec's key; a case's
sample depends only on (seed, case index)."""
import re
import subprocess
import sys

import pytest

from campaign_support import VARIABLES, write_spec
from conftest import ROOT, python_environment
from smoothsteer import campaign
from smoothsteer.campaign.spec import CampaignSpecError


def changed_variable(key, distribution):
    return dict(VARIABLES, **{key: distribution})


MALFORMED = [
    ({"casess": 10}, "key 'casess' (line N): unknown key"),
    ({"cases": 0}, "key 'cases' (line N): value 0 out of range"),
    ({"seed": "seven"}, "key 'seed' (line N): must be an integer"),
    ({"variables": changed_variable("speed.initial_mps", {"distribution": "uniform", "low": 20,
                                                           "high": 5})},
     "key 'variables.speed.initial_mps.high'"),
    ({"variables": changed_variable("speed.initial_mps", {"distribution": "uniform", "low": -1,
                                                           "high": 5})},
     "key 'variables.speed.initial_mps.low' (line N): the scenario rejects it "
     "(speed.initial_mps = -1.0): "),
    ({"variables": changed_variable("start.y_mm", {"distribution": "uniform", "low": 0,
                                                    "high": 1})},
     "key 'variables.start.y_mm.low'"),
    ({"variables": changed_variable("actuator.dead_time_s", {"distribution": "uniform",
                                                              "low": 0, "high": 0.0105})},
     "key 'variables.actuator.dead_time_s.high'"),
    ({"variables": changed_variable("speed.initial_mps", {"distribution": "normal", "mean": 10,
                                                           "std": 2})},
     "key 'variables.speed.initial_mps.std'"),
    ({"variables": changed_variable("speed.initial_mps", {"distribution": "gauss"})},
     "key 'variables.speed.initial_mps.distribution'"),
    ({"variables": changed_variable("speed.initial_mps", {"distribution": "uniform", "low": 5,
                                                           "hi": 20})},
     "key 'variables.speed.initial_mps.hi'"),
    ({"variables": changed_variable("controller.curvature_preview",
                                    {"distribution": "choice", "values": ["planned", "x"]})},
     "key 'variables.controller.curvature_preview.values.0'"),
    ({"criteria": {"max_abs_e": {"max": 0.3}}}, "key 'criteria.max_abs_e'"),
    ({"criteria": {"max_abs_rear_error_m": {"below": 0.3}}},
     "key 'criteria.max_abs_rear_error_m.below'"),
    ({"metrics": ["rms_rear_error_m", "rms_e"]}, "key 'metrics.1'"),
    ({"overrides": {"speed.initial_mps": 10}}, "key 'variables.speed.initial_mps' (line N): is "
                                                "also fixed"),
    ({"overrides": {"simulation.duration_s": -3}}, "key 'overrides' (line N): the scenario"),
    ({"base": "missing.yaml"}, "key 'base' (line N): no scenario file"),
]


@pytest.mark.parametrize("changes,message", MALFORMED)
def test_a_malformed_spec_fails_before_any_case_runs_naming_the_key(tmp_path, changes, message):
    spec = write_spec(tmp_path, **changes)
    out = tmp_path / "out"
    with pytest.raises(CampaignSpecError) as error:
        campaign.run_campaign(spec, out, serial=True, progress=False)
    assert str(error.value).startswith(f"{spec}: ")
    expected = re.escape(message).replace(re.escape("(line N)"), r"\(line \d+\)")
    assert re.search(expected, str(error.value)), str(error.value)
    assert not out.exists()


def test_a_repeated_key_is_rejected_with_its_line(tmp_path):
    spec = write_spec(tmp_path)
    spec.write_text(spec.read_text() + "seed: 6\n")
    with pytest.raises(CampaignSpecError, match=r"key 'seed' \(line \d+\): repeated key"):
        campaign.load_spec(spec)


def test_the_command_line_prints_the_error_and_exits_2(tmp_path):
    spec = write_spec(tmp_path, cases=-1)
    result = subprocess.run([sys.executable, "-m", "smoothsteer.campaign", str(spec), "--out",
                             str(tmp_path / "out"), "--serial"], cwd=ROOT,
                            env=python_environment(), capture_output=True, text=True)
    assert result.returncode == 2
    assert "key 'cases'" in result.stderr and not (tmp_path / "out").exists()


def test_a_case_depends_only_on_the_seed_and_its_index(tmp_path):
    spec = campaign.load_spec(write_spec(tmp_path, cases=50))
    forward = [spec.case_overrides(case) for case in range(50)]
    backward = [spec.case_overrides(case) for case in reversed(range(50))][::-1]
    assert forward == backward
    longer = campaign.load_spec(write_spec(tmp_path, cases=80))
    assert [longer.case_overrides(case) for case in range(50)] == forward
    other_seed = campaign.load_spec(write_spec(tmp_path, cases=50, seed=6))
    assert other_seed.case_overrides(0) != forward[0]
    # Removing one variable leaves the others' samples as they were.
    fewer = dict(VARIABLES)
    del fewer["start.heading_rad"]
    reduced = campaign.load_spec(write_spec(tmp_path, cases=50, variables=fewer))
    assert reduced.case_overrides(7)["speed.initial_mps"] == forward[7]["speed.initial_mps"]


def test_samples_lie_in_their_ranges_and_on_their_steps(tmp_path):
    spec = campaign.load_spec(write_spec(tmp_path, cases=400))
    samples = [spec.case_overrides(case) for case in range(400)]
    speeds = [s["speed.initial_mps"] for s in samples]
    assert 5 <= min(speeds) < 6 and 19 < max(speeds) <= 20
    assert all(-0.3 <= s["start.y_m"] <= 0.3 for s in samples)
    dead_times = {s["actuator.dead_time_s"] for s in samples}
    assert dead_times <= {round(0.001 * k, 3) for k in range(51)} and len(dead_times) > 30
    scales = [s["simulation.side_slip.cornering_stiffness_scale"] for s in samples]
    assert 0.8 <= min(scales) and max(scales) <= 1.25
    assert {s["controller.curvature_preview"] for s in samples} == {"planned_jumps",
                                                                    "centred_ramp"}
    assert all(isinstance(s["simulation.noise_seed"], int) for s in samples)
