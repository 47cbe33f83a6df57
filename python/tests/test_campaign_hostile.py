"""Hostile campaign specs and results directories through the command line: each ends with
exit code 2 and one message naming the file or option, the key and the rule, never a
traceback, and a bomb or an oversized input is refused before the work it would cost."""
import os
import subprocess
import sys
import tracemalloc

import pytest
import yaml

from campaign_support import write_spec
from conftest import ROOT, python_environment
from smoothsteer import campaign
from smoothsteer.campaign.spec import CampaignSpecError

# A guard against a hang, far above the second a refused spec takes; not a timing assertion.
HANG_GUARD_S = 300


def replace_line(spec, key, text):
    """The spec with the line `key: ...` written as `key: text` (YAML that safe_dump cannot)."""
    lines = [f"{key}: {text}" if line.startswith(f"{key}:") else line
             for line in spec.read_text().splitlines()]
    spec.write_text("\n".join(lines) + "\n")


def append(spec, text):
    spec.write_text(spec.read_text() + text)


def billion_laughs(spec):
    levels = ["  a0: &a0 [x, x, x, x, x, x, x, x, x]"]
    levels += [f"  a{i}: &a{i} [{', '.join([f'*a{i - 1}'] * 9)}]" for i in range(1, 10)]
    append(spec, "description:\n" + "\n".join(levels) + "\n")


def nested(spec):
    append(spec, "description: " + "[" * 200000 + "]" * 200000 + "\n")


def past_the_old_cut(spec):
    # Read to its end: a key past the first MiB is checked (an unknown metric here).
    append(spec, "# " + "x" * (3 << 19) + "\nmetrics: [no_such_metric]\n")


def too_large(spec):
    append(spec, "# " + "x" * (16 << 20) + "\n")


def many_choices(spec):
    variables = {"controller.curvature_preview": {"distribution": "choice",
                                                  "values": ["planned_jumps"] * 200000}}
    spec.write_text(spec.read_text().split("variables:")[0] + yaml.safe_dump(
        {"variables": variables}, default_flow_style=None, width=1 << 30))


def tiny_step(spec):
    variables = {"speed.initial_mps": {"distribution": "uniform", "low": 5, "high": 20,
                                       "step": 1e-300}}
    spec.write_text(spec.read_text().split("variables:")[0] + yaml.safe_dump(
        {"variables": variables}))


SPECS = [
    ("octal cases", lambda s: replace_line(s, "cases", "010"), "key 'cases'", "decimal"),
    ("hex cases", lambda s: replace_line(s, "cases", "0xff"), "key 'cases'", "decimal"),
    ("underscore", lambda s: replace_line(s, "cases", "1_0"), "key 'cases'", "decimal"),
    ("sexagesimal seed", lambda s: replace_line(s, "seed", "1:30"), "key 'seed'", "decimal"),
    ("cases above the maximum", lambda s: replace_line(s, "cases", "100000000"), "key 'cases'",
     "must be in [1, 1000000]"),
    ("alias bomb", billion_laughs, "key 'description.", "more than 4000000 nodes"),
    ("alias cycle", lambda s: append(s, "description: &d [*d]\n"), "key 'description.0'",
     "contains it"),
    ("nesting", nested, "line ", "nested deeper than 64 levels"),
    ("past 1 MiB", past_the_old_cut, "key 'metrics.0'", "unknown metric"),
    ("above 16 MiB", too_large, "spec.yaml: ", "larger than 16777216 bytes"),
    ("200 000 choices", many_choices, "key 'variables.controller.curvature_preview.values'",
     "at most 1000"),
    ("step too small", tiny_step, "key 'variables.speed.initial_mps.step'", "too small"),
    ("no metric", lambda s: append(s, "metrics: []\n"), "key 'metrics'", "at least one"),
    ("a list as a metric", lambda s: append(s, "metrics: [[1]]\n"), "key 'metrics.0'",
     "non-empty string"),
    ("a list as a key", lambda s: append(s, "report: {[1]: 2}\n"), "key 'report'",
     "plain string"),
    ("malformed YAML", lambda s: append(s, "report: {a: [\n"), "not valid YAML", "line"),
    ("a number as the description", lambda s: append(s, "description: 5\n"),
     "key 'description'", "non-empty string"),
]


def run_cli(*arguments):
    result = subprocess.run([sys.executable, "-m", "smoothsteer.campaign", *map(str, arguments),
                             "--quiet"], cwd=ROOT, env=python_environment(), capture_output=True,
                            text=True, timeout=HANG_GUARD_S)
    return result.returncode, result.stdout + result.stderr


def assert_refused(code, output, *parts):
    assert code == 2, output
    assert "Traceback" not in output, output
    message = output.strip().splitlines()[-1]
    assert message.startswith("error: "), output
    for part in parts:
        assert part in message, message


@pytest.mark.parametrize("name,change,key,rule", SPECS, ids=[case[0] for case in SPECS])
def test_a_hostile_spec_is_refused_naming_its_key(tmp_path, name, change, key, rule):
    spec = write_spec(tmp_path)
    change(spec)
    code, output = run_cli(spec, "--out", tmp_path / "out", "--serial", "--no-report")
    assert_refused(code, output, f"{spec}: ", key, rule)
    assert not (tmp_path / "out").exists()


def test_a_spec_that_is_a_fifo_is_refused_without_blocking(tmp_path):
    fifo = tmp_path / "spec.yaml"
    os.mkfifo(fifo)
    code, output = run_cli(fifo, "--out", tmp_path / "out", "--serial")
    assert_refused(code, output, f"{fifo}: ", "not a regular file")


def test_cases_above_the_maximum_fail_before_allocating(tmp_path):
    spec = write_spec(tmp_path, cases=10**8)
    tracemalloc.start()
    try:
        with pytest.raises(CampaignSpecError, match=r"key 'cases' \(line \d+\)"):
            campaign.load_spec(spec)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 8 << 20, f"{peak} bytes allocated while refusing cases = 10^8"


def file_out(tmp_path):
    path = tmp_path / "plain_file"
    path.write_text("x\n")
    return path


def dangling_link(tmp_path):
    path = tmp_path / "link"
    path.symlink_to(tmp_path / "nowhere")
    return path


def results_a_directory(tmp_path):
    (tmp_path / "out" / "results.csv").mkdir(parents=True)
    return tmp_path / "out"


def corrupt_metadata(tmp_path):
    (tmp_path / "out").mkdir()
    (tmp_path / "out" / "campaign.json").write_text("{\"identity\": ")
    return tmp_path / "out"


def metadata_a_list(tmp_path):
    (tmp_path / "out").mkdir()
    (tmp_path / "out" / "campaign.json").write_text("[1, 2]\n")
    return tmp_path / "out"


# /sys refuses a new entry even to root, for whom a chmod'ed directory stays writable.
OUTS = [
    ("a file", file_out, "is a file, not a directory"),
    ("/dev/null", lambda _: "/dev/null", "is a device, not a directory"),
    ("a dangling link", dangling_link, "does not exist, not a directory"),
    ("read-only, missing", lambda _: "/sys/no_such_campaign", "cannot create"),
    ("read-only, existing", lambda _: "/sys/kernel", "cannot write campaign.json"),
    ("results.csv a directory", results_a_directory, "results.csv is a directory"),
    ("corrupt campaign.json", corrupt_metadata, "campaign.json cannot be read: not valid JSON"),
    ("campaign.json not an object", metadata_a_list, "campaign.json is not a campaign's"),
]


@pytest.mark.parametrize("name,make,problem", OUTS, ids=[case[0] for case in OUTS])
def test_every_results_directory_problem_is_named(tmp_path, name, make, problem):
    out = make(tmp_path)
    code, output = run_cli(write_spec(tmp_path), "--out", out, "--serial")
    assert_refused(code, output, f"--out {out}: ", problem)


@pytest.mark.parametrize("prepare", ["missing", "empty"])
def test_report_only_without_results_says_to_run_first(tmp_path, prepare):
    out = tmp_path / "out"
    if prepare == "empty":
        out.mkdir()
    code, output = run_cli(write_spec(tmp_path), "--out", out, "--report-only")
    assert_refused(code, output, f"--out {out}: ", "run the campaign first")


def test_a_bad_scheduler_address_is_named(tmp_path):
    code, output = run_cli(write_spec(tmp_path), "--out", tmp_path / "out", "--scheduler",
                           "nonsense://host:1")
    assert_refused(code, output, "--scheduler nonsense://host:1: ", "cannot connect")
