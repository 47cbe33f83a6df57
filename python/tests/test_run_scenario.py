"""run_scenario() in Python gives the CLI's trace.csv (to its printed precision: 9 significant
digits) and its summary.json."""
import csv
import json
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import smoothsteer as ss
from conftest import CLI

CASES = [
    ("scenarios/lane_change_10.yaml", {"simulation.duration_s": 12}),
    ("scenarios/reaching_p02pi.yaml", {}),
    ("scenarios/circle_sections.yaml",
     {"simulation.duration_s": 10, "controller": {"type": "lead_wheel", "order": 2,
                                                  "lead_wheelbase_m": 0.5}}),
]


def cli_run(scenario, overrides, out):
    command = [str(CLI), "run", scenario, "--out", str(out)]
    for key, value in overrides.items():
        command += ["--set", f"{key}={ss._override_text(value)}"]
    subprocess.run(command, check=True, capture_output=True, text=True)
    with open(out / "trace.csv", newline="") as handle:
        rows = list(csv.reader(handle))
    with open(out / "summary.json") as handle:
        return rows[0], rows[1:], json.load(handle)


@pytest.mark.parametrize("scenario,overrides", CASES)
def test_trace_and_summary_equal_the_cli(tmp_path, scenario, overrides):
    header, rows, cli_summary = cli_run(scenario, overrides, tmp_path / "run")
    trace, summary = ss.run_scenario(scenario, overrides)
    assert list(trace) == header == ss.trace_column_names()
    assert all(len(trace[name]) == len(rows) for name in header)
    for column, name in enumerate(header):
        for row, text in enumerate(r[column] for r in rows):
            value = trace[name][row]
            # The CLI prints 9 significant digits (std::to_chars); round ours the same way.
            assert float(f"{value:.9g}") == float(text), (scenario, name, row, value, text)
    assert summary == cli_summary


def test_overrides_as_list_equal_overrides_as_dict():
    as_dict = ss.run_scenario("scenarios/reaching_0.yaml", {"simulation.duration_s": 2.5})
    as_list = ss.run_scenario("scenarios/reaching_0.yaml", ["simulation.duration_s=2.5"])
    assert as_dict[1] == as_list[1]
    assert np.array_equal(as_dict[0]["e"], as_list[0]["e"])
    assert as_dict[0]["t"][-1] == pytest.approx(2.5)


def test_load_scenario_resolves_the_file():
    scenario = ss.load_scenario("scenarios/lane_change_15.yaml", {"speed.initial_mps": 12.0})
    assert scenario.name == "lane_change_15"
    assert scenario.parameters["speed"]["initial_mps"] == 12.0
    assert scenario.path.length_m > 150.0
    trace, summary = ss.run_scenario(ss.load_scenario("scenarios/reaching_0.yaml"))
    assert summary["scenario"] == "reaching_0"


def test_the_simulation_runs_without_the_gil():
    """A Python thread keeps counting while run_scenario() simulates; with the GIL held for the
    whole run it would stand still."""
    counts, stop = [0], threading.Event()

    def count():
        while not stop.is_set():
            counts[0] += 1

    # A long switch interval: a thread that holds the GIL keeps it for a second unless it
    # releases it, so only a released GIL lets the counter run during the call.
    interval = sys.getswitchinterval()
    sys.setswitchinterval(1.0)
    thread = threading.Thread(target=count)
    thread.start()
    time.sleep(0.05)
    before = counts[0]
    started = time.perf_counter()
    # circle_sections, 60 s with RK4 at a 0.1 ms plant step (the default adaptive integrator
    # would take a few hundredths): several tenths of a second in C++
    ss.run_scenario("scenarios/circle_sections.yaml",
                    {"simulation.substep_s": 0.0001, "simulation.integrator": "fixed_rk4"})
    elapsed = time.perf_counter() - started
    during = counts[0] - before
    stop.set()
    thread.join()
    sys.setswitchinterval(interval)
    # The counting thread runs only if the GIL is released: then it counts at least thousands of
    # times during a run of this length; held, not once. The count is what is checked; the time
    # is only reported.
    assert during > 10000, f"counted {during} times in {elapsed:.3f} s"


def test_runs_in_threads_equal_runs_in_sequence():
    """Threads run scenarios at once (numpy's API is looked up at import, not by the first
    thread that makes an array) and get what a sequential run gets."""
    from concurrent.futures import ThreadPoolExecutor

    names = ["lqr", "stanley", "pure_pursuit", "hosm"]

    def run(name):
        return ss.run_scenario("scenarios/lane_change_10.yaml",
                               {"controller": {"type": name}, "simulation.duration_s": 6})[1]

    with ThreadPoolExecutor(max_workers=4) as pool:
        parallel = list(pool.map(run, names))
    assert parallel == [run(name) for name in names]
