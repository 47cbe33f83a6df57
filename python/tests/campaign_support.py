"""Shared pieces of the campaign tests: small specs over the lane change, and batch runners
that the Dask workers import by name (this directory is on their sys.path)."""
import io
import os
import time

import pandas as pd
import yaml

from conftest import ROOT
from smoothsteer.campaign.cases import run_batch

BASE = ROOT / "scenarios" / "lane_change_15.yaml"

VARIABLES = {
    "speed.initial_mps": {"distribution": "uniform", "low": 5, "high": 20},
    "start.y_m": {"distribution": "normal", "mean": 0, "std": 0.1, "low": -0.3, "high": 0.3},
    "start.heading_rad": {"distribution": "uniform", "low": -0.05, "high": 0.05},
    "actuator.dead_time_s": {"distribution": "uniform", "low": 0, "high": 0.05, "step": 0.001},
    "simulation.side_slip.cornering_stiffness_scale":
        {"distribution": "log_uniform", "low": 0.8, "high": 1.25},
    "controller.curvature_preview":
        {"distribution": "choice", "values": ["planned_jumps", "centred_ramp"]},
    "simulation.noise_seed": {"distribution": "integer", "low": 1, "high": 1000},
}


def write_spec(directory, cases=24, seed=5, **changes):
    """A spec of short lane changes (3 s: about 10 ms a case) in `directory`."""
    spec = {"name": "test_campaign", "base": str(BASE), "cases": cases, "seed": seed,
            "overrides": {"simulation.duration_s": 3}, "variables": VARIABLES,
            "criteria": {"max_abs_rear_error_m": {"max": 0.3}, "held_above_limits": {"max": 0}}}
    spec.update(changes)
    path = directory / "spec.yaml"
    path.write_text(yaml.safe_dump(spec, sort_keys=False))
    return path


def rows(out):
    """The complete rows of results.csv (a line cut by a kill is not one) sorted by case,
    without the one column that is a measured time."""
    text = (out / "results.csv").read_text()
    text = text[:text.rfind("\n") + 1]
    frame = pd.read_csv(io.StringIO(text), keep_default_na=False, float_precision="round_trip")
    return frame.sort_values("case").drop(columns="elapsed_s").reset_index(drop=True)


def data_lines(out):
    path = out / "results.csv"
    if not path.exists():
        return 0
    with open(path) as handle:
        return max(handle.read().count("\n") - 1, 0)


def slow_batch(spec, cases):
    """run_batch, 50 ms per case slower, so that a worker can be killed in the middle."""
    time.sleep(0.05 * len(cases))
    return run_batch(spec, cases)


def fatal_batch(spec, cases):
    """run_batch, except that case 3 ends its worker process, every time."""
    if 3 in cases:
        os._exit(17)
    return run_batch(spec, cases)
