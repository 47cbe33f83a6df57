"""The campaign report: pass rates, percentiles, worst cases with commands that replay them,
failures by kind, and its PNGs."""
import json
import shlex

import pytest

import smoothsteer as ss
from campaign_support import rows, write_spec
from smoothsteer import campaign
from smoothsteer.campaign.report import replay_command


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    directory = tmp_path_factory.mktemp("report")
    spec = write_spec(directory, cases=20)
    out = directory / "out"
    campaign.run_campaign(spec, out, serial=True, progress=False)
    return campaign.load_spec(spec), out, campaign.write_report(spec, out)


def test_the_report_has_its_sections_and_figures(report):
    spec, out, path = report
    text = open(path).read()
    for heading in ("# Campaign `test_campaign`", "## Sampled variables", "## Pass criteria",
                    "## Metrics over the cases that ran", "## Worst cases",
                    "## Failures by kind", "## Figures"):
        assert heading in text, heading
    table = rows(out)
    passed = int(table["passed"].sum())
    assert f"passed: **{passed} of 20 ({100.0 * passed / 20:.2f} %)**" in text
    for name in ("histograms", "scatter", "worst_trace"):
        png = out / f"{name}.png"
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        assert f"![{name}]({name}.png)" in text


def test_the_worst_case_command_replays_its_row(report):
    spec, out, path = report
    table = rows(out)
    worst = table.sort_values("max_abs_rear_error_m", ascending=False).iloc[0]
    command = replay_command(spec, worst)
    assert command in open(path).read()
    words = shlex.split(command)
    assert words[:3] == ["smoothsteer", "run", words[2]] and words[-2:] == [
        "--out", f"case_{worst['case']}"]
    sets = [words[i + 1] for i, word in enumerate(words) if word == "--set"]
    # The --set texts are what the CLI parses; the loader behind run_scenario is the same.
    _, summary = ss.run_scenario(spec.base, sets)
    assert summary["metrics"]["max_abs_rear_error_m"] == worst["max_abs_rear_error_m"]
    assert json.loads(worst["overrides"]) == spec.case_overrides(int(worst["case"]))


def test_failures_are_reported_by_kind_with_their_replay(tmp_path):
    # Each end of each range passes the scenario's rules, and so do both ends together, but a
    # case with min_lookahead_m > max_lookahead_m breaks the rule between the two keys.
    spec = write_spec(tmp_path, cases=16, overrides={
        "simulation.duration_s": 3, "controller": {"type": "pure_pursuit"}}, variables={
        "controller.min_lookahead_m": {"distribution": "uniform", "low": 3, "high": 30},
        "controller.max_lookahead_m": {"distribution": "uniform", "low": 20, "high": 30}})
    out = tmp_path / "out"
    run = campaign.run_campaign(spec, out, serial=True, progress=False)
    table = rows(out)
    failed = table[table["status"] == "failed"]
    assert run.failed == len(failed) > 0
    assert set(failed["error_kind"]) == {"ConfigError"} and set(failed["attempts"]) == {2}
    text = open(campaign.write_report(spec, out, replay_trace=False)).read()
    assert f"| `ConfigError` | {len(failed)} | {failed.iloc[0]['case']} |" in text
    assert replay_command(campaign.load_spec(spec), failed.iloc[0]) in text
