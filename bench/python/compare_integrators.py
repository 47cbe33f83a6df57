#!/usr/bin/python3
"""Metric differences between plant integrators on every shipped scenario (docs/benchmarks.md,
"Plant integration"). Runs `smoothsteer run` once per scenario and integrator setting and compares
every metric of summary.json with two converged references: fixed_rk4 at a 0.1 ms sub-step and
rkf78 at a tolerance of 1e-10 (and with fixed_rk4 at 1 ms, the method of earlier releases).

Usage (repository root, after a build):
  /usr/bin/python3 bench/python/compare_integrators.py [--cli build/ci/apps/smoothsteer]
      [--candidate rkf78:1e-8 --candidate dopri5:1e-7 ...] [--set key=value ...] [SCENARIO.yaml ...]
(--set applies to every run, e.g. --set model=double_track for the double-track plant.)
Prints, per scenario: model evaluations per control step, and for each candidate the largest
difference of a length metric [m], of an angle metric [rad], of a rate or acceleration metric
[rad/s, rad/s^2], of a time metric [s], and the counts that differ; then one markdown table.
Only the standard library.
"""
import argparse
import glob
import json
import os
import subprocess
import sys
import tempfile

REFERENCES = {"fixed_rk4 0.1 ms": ["simulation.integrator=fixed_rk4", "simulation.substep_s=0.0001"],
              "rkf78 1e-10": ["simulation.integrator=rkf78", "simulation.integrator_tolerance=1e-10"]}
BEFORE = ("fixed_rk4 1 ms", ["simulation.integrator=fixed_rk4"])


COMMON = []


def run(cli, scenario, overrides, scratch):
    out = os.path.join(scratch, "run")
    command = [cli, "run", scenario, "--out", out]
    for item in COMMON + overrides:
        command += ["--set", item]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as handle:
        return json.load(handle)


def kind(key, value):
    if isinstance(value, bool) or isinstance(value, int):
        return "count"
    if key.endswith("_m"):
        return "length"
    if key.endswith("_rad"):
        return "angle"
    if key.endswith("_radps") or key.endswith("_radps2"):
        return "rate"
    if key.endswith("_s"):
        return "time"
    return "other"


def differences(a, b):
    """Largest |a - b| per kind of metric, with the metric it occurs in, and differing counts."""
    worst = {}
    counts = []
    for key, value in a["metrics"].items():
        other = b["metrics"][key]
        k = kind(key, value)
        if k == "count":
            if value != other:
                counts.append(f"{key} {other} -> {value}")
            continue
        gap = abs(value - other)
        if gap >= worst.get(k, (0.0, ""))[0]:
            worst[k] = (gap, key)
    return worst, counts


def evaluations_per_step(summary):
    return summary["model_evaluations"] / summary["metrics"]["steps"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("scenarios", nargs="*")
    parser.add_argument("--cli", default="build/ci/apps/smoothsteer")
    parser.add_argument("--candidate", action="append",
                        help="integrator:tolerance, e.g. rkf78:1e-8 (default: the scenario's own)")
    parser.add_argument("--set", action="append", default=[], dest="common",
                        help="an override for every run, e.g. model=double_track")
    args = parser.parse_args()
    COMMON.extend(args.common)
    scenarios = args.scenarios or sorted(glob.glob("scenarios/*.yaml"))
    candidates = [(c, ["simulation.integrator=" + c.split(":")[0],
                       "simulation.integrator_tolerance=" + c.split(":")[1]])
                  for c in (args.candidate or [])] or [("default", [])]
    table = []
    with tempfile.TemporaryDirectory() as scratch:
        for scenario in scenarios:
            name = os.path.splitext(os.path.basename(scenario))[0]
            references = {r: run(args.cli, scenario, o, scratch) for r, o in REFERENCES.items()}
            runs = [(BEFORE[0], run(args.cli, scenario, BEFORE[1], scratch))]
            runs += [(c, run(args.cli, scenario, o, scratch)) for c, o in candidates]
            print(f"## {name} ({references['rkf78 1e-10']['metrics']['steps']} steps)")
            for label, summary in runs:
                print(f"  {label}: {evaluations_per_step(summary):.2f} evaluations/step")
                cells = [name, label, f"{evaluations_per_step(summary):.2f}"]
                for reference, reference_summary in references.items():
                    worst, counts = differences(summary, reference_summary)
                    text = ", ".join(f"{k} {gap:.2g} ({key})" for k, (gap, key) in sorted(worst.items()))
                    print(f"    vs {reference}: {text}; counts: {'; '.join(counts) or 'equal'}")
                    cells += [f"{worst['length'][0]:.1e} m", f"{worst['angle'][0]:.1e} rad",
                              f"{worst['rate'][0]:.1e}", "; ".join(counts) or "-"]
                table.append(cells)
            worst, counts = differences(references["fixed_rk4 0.1 ms"], references["rkf78 1e-10"])
            text = ", ".join(f"{k} {gap:.2g} ({key})" for k, (gap, key) in sorted(worst.items()))
            print(f"  references apart: {text}; counts: {'; '.join(counts) or 'equal'}")
            sys.stdout.flush()
    print("\n| scenario | integrator | evals/step | vs fixed_rk4 0.1 ms: length | angle | rate | counts "
          "| vs rkf78 1e-10: length | angle | rate | counts |")
    print("|" + "---|" * 11)
    for cells in table:
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
