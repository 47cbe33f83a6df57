#!/usr/bin/python3
"""The shipped kinetic scenarios on the single-track plant (model: dynamic, as shipped) and on the
double-track plant (model: double_track), with the shipped controller untouched
(docs/simulation.md, "The shipped scenarios on the double-track plant"). Prints a Markdown table:
rear-axle max |e| (whole run; after 8 s for circle_sections, as docs/results.md), RMS |e|, the
largest rear-axle side slip, the largest error of the slip estimate the controller received,
the held command's largest rate and acceleration and the samples above the car's limits; each
also with the true slip instead of the observer (simulation.side_slip.source=truth).

    /usr/bin/python3 scripts/double_track_comparison.py [--cli build/ci/apps/smoothsteer]
"""
import argparse
import csv
import json
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENARIOS = ["lane_change_10", "lane_change_15", "lane_change_19", "circle_sections"]
PLANTS = [("single-track", "dynamic"), ("double-track", "double_track")]
SLIP = [("observer (shipped)", []), ("true slip", ["simulation.side_slip.source=truth"])]


def run(cli, scenario, model, extra, directory):
    out = os.path.join(directory, f"{scenario}_{model}_{len(extra)}")
    command = [cli, "run", os.path.join(ROOT, "scenarios", scenario + ".yaml"), "--out", out,
               "--set", f"model={model}"]
    for item in extra:
        command += ["--set", item]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        metrics = json.load(f)["metrics"]
    after = 8.0 if scenario == "circle_sections" else 0.0
    with open(os.path.join(out, "trace.csv")) as f:
        rows = [r for r in csv.DictReader(f)]
    error = max(abs(float(r["e"])) for r in rows if float(r["t"]) >= after)
    slip = max(abs(float(r["beta_rear"])) for r in rows)
    return dict(error=error, rms=metrics["rms_rear_error_m"], slip=slip,
                slip_error=metrics["max_abs_rear_slip_input_error_rad"],
                rate=metrics["held_rate_max_radps"], acc=metrics["held_acceleration_max_radps2"],
                held=metrics["held_rate_violations"] + metrics["held_acceleration_violations"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cli", default=os.path.join(ROOT, "build", "ci", "apps", "smoothsteer"))
    args = parser.parse_args()
    print("| scenario | slip input | plant | max abs e [m] | RMS e [m] | max abs beta_r [mrad] | "
          "slip input error [mrad] | held rate [rad/s] | held acc. [rad/s^2] | held above limits |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as directory:
        for scenario in SCENARIOS:
            for slip_name, extra in SLIP:
                for plant_name, model in PLANTS:
                    m = run(args.cli, scenario, model, extra, directory)
                    print(f"| {scenario} | {slip_name} | {plant_name} | {m['error']:.3f} | "
                          f"{m['rms']:.3f} | {1e3 * m['slip']:.1f} | {1e3 * m['slip_error']:.1f} | "
                          f"{m['rate']:.3f} | {m['acc']:.2f} | {m['held']} |")


if __name__ == "__main__":
    main()
