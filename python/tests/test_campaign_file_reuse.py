"""A campaign's cases load the base scenario's files parsed once per process
(load_scenario(reuse_files=True)); its rows and its error messages are those of loading the
files for every case."""
import pytest

import smoothsteer as ss
from campaign_support import BASE, rows, write_spec
from smoothsteer import campaign
from smoothsteer.campaign import cases


def campaign_rows(spec, out, reuse, monkeypatch):
    monkeypatch.setattr(cases, "REUSE_BASE_FILES", reuse)
    campaign.run_campaign(spec, out, serial=True, progress=False)
    return rows(out)


def test_a_campaign_gives_the_same_rows_with_and_without_reuse(tmp_path, monkeypatch):
    # Each value loads alone, but an odd dead time on the 2 ms sub-step is refused: the failed
    # cases' messages must match too.
    spec = write_spec(tmp_path, cases=16, variables={
        "speed.initial_mps": {"distribution": "uniform", "low": 5, "high": 20},
        "start.y_m": {"distribution": "uniform", "low": -0.2, "high": 0.2},
        "simulation.substep_s": {"distribution": "choice", "values": [0.001, 0.002]},
        "actuator.dead_time_s": {"distribution": "choice", "values": [0.0, 0.001, 0.02]},
        "simulation.noise_seed": {"distribution": "integer", "low": 1, "high": 1000}})
    reused = campaign_rows(spec, tmp_path / "reused", True, monkeypatch)
    read = campaign_rows(spec, tmp_path / "read", False, monkeypatch)
    assert len(reused) == 16
    assert set(reused["status"]) == {"ok", "failed"}
    assert (reused["error"].str.contains("dead_time_s") == (reused["status"] == "failed")).all()
    assert reused.equals(read)


@pytest.mark.parametrize("overrides", [
    {"speed.initial_mps": 500},
    {"speed.no_such_key": 1},
    ["speed.initial_mps"],
    {"controller.k_rob": -1},
    {"vehicle.file": "missing.yaml"},
])
def test_a_bad_override_gives_the_same_message(overrides):
    messages = []
    for reuse in (False, True, True):  # from the file; parsed; from the parsed copy
        with pytest.raises(ss.ConfigError) as error:
            ss.load_scenario(BASE, overrides, reuse_files=reuse)
        messages.append(str(error.value))
    assert messages[0] and messages[1:] == messages[:1] * 2
