#!/usr/bin/python3
"""Vehicle-dynamics compensation study (docs/vehicle_dynamics.md, docs/results.md).

Runs the shipped kinetic scenarios with the compensations on (as shipped), off, with the linear
observer or the true slip instead of the shipped Magic Formula observer, with the observer's cornering stiffness and mass off by +-20 %, and
with actuator inversion, and prints a Markdown table of the rear axle's max |e| (whole run; after
8 s for circle_sections), the held command's largest rate and acceleration, the samples above the
car's limits, the largest side slip and the slip estimate's largest error.

    /usr/bin/python3 studies/vehicle_dynamics_study.py [--cli build/ci/apps/smoothsteer]
"""
import argparse
import csv
import json
import math
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENARIOS = ["lane_change_10", "lane_change_15", "lane_change_19", "circle_sections"]
OFF = ["controller.slip_preview=false", "controller.preview_time_s=0", "controller.cornering_target=rear_axle",
       "controller.curvature_preview=centred_ramp",
       "simulation.side_slip.source=none"]
# The scenarios' actuator: 10 Hz third-order low-pass, T = 1 / pole = sqrt(2^(1/3) - 1) / (2 pi 10).
ACTUATOR_T = math.sqrt(2 ** (1 / 3) - 1) / (2 * math.pi * 10.0)
VARIANTS = [
    ("compensation off", OFF),
    ("shipped: observer (Magic Formula) + single-track inversion (scenario preview_time_s)", []),
    ("linear single-track observer instead", ["simulation.side_slip.tire_model=linear"]),
    ("true slip instead of the observer", ["simulation.side_slip.source=truth"]),
    ("observer stiffness x 0.8", ["simulation.side_slip.cornering_stiffness_scale=0.8"]),
    ("observer stiffness x 1.2", ["simulation.side_slip.cornering_stiffness_scale=1.2"]),
    ("observer mass x 0.8", ["simulation.side_slip.mass_scale=0.8"]),
    ("observer mass x 1.2", ["simulation.side_slip.mass_scale=1.2"]),
    ("shipped + actuator inversion (Smith delay 0.024 s)",
     [f"controller.actuator_time_constant_s={ACTUATOR_T:.6f}", "controller.actuator_delay_s=0.024"]),
    ("off + actuator inversion (Smith delay 0.024 s)",
     OFF + [f"controller.actuator_time_constant_s={ACTUATOR_T:.6f}",
            "controller.actuator_delay_s=0.024"]),
]


def run(cli, scenario, overrides):
    out = tempfile.mkdtemp(prefix="smoothsteer_study_")
    args = [cli, "run", os.path.join(ROOT, "scenarios", scenario + ".yaml"), "--out", out]
    for o in overrides:
        args += ["--set", o]
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        return None
    rows = list(csv.DictReader(open(os.path.join(out, "trace.csv"))))
    summary = json.load(open(os.path.join(out, "summary.json")))
    m = summary["metrics"]
    start = 8.0 if scenario == "circle_sections" else 0.0
    error = max(abs(float(r["e"])) for r in rows if float(r["t"]) >= start)
    spin = any(abs(float(r["heading_error"])) > 1.0 for r in rows)
    return {"e": error, "rate": m["held_rate_max_radps"], "acc": m["held_acceleration_max_radps2"],
            "held_over": m["held_rate_violations"] + m["held_acceleration_violations"],
            "actual_over": m["actual_rate_violations"] + m["actual_acceleration_violations"],
            "slip": m["max_abs_side_slip_rad"], "slip_error": m["max_abs_rear_slip_input_error_rad"], "spin": spin}


def print_seed_spread(cli, seeds):
    """The shipped files' max |e| over the sensor-noise seeds 1..seeds (the files' own seed is one
    draw of the pose and slip-sensor noise), and how many seeds meet the certified-tuning and
    the vehicle-dynamics targets."""
    targets = {"lane_change_10": (0.03, None), "lane_change_15": (0.05, 0.03),
               "lane_change_19": (0.5, 0.25), "circle_sections": (0.10, 0.05)}
    print("| scenario | min | median | max | "
          "seeds within the certified-tuning / vehicle-dynamics target |")
    print("|---|---|---|---|---|")
    for scenario in SCENARIOS:
        runs = [run(cli, scenario, [f"simulation.noise_seed={seed}"]) for seed in range(1, seeds + 1)]
        if None in runs:
            raise SystemExit(f"{scenario}: the CLI failed at noise seed {runs.index(None) + 1}")
        errors = sorted(r["e"] for r in runs)
        median = (errors[(seeds - 1) // 2] + errors[seeds // 2]) / 2
        met = [f"{sum(e <= target for e in errors)} of {seeds} ({target} m)" if target else "-"
               for target in targets[scenario]]
        print(f"| {scenario} | {errors[0]:.4f} m | {median:.4f} m | {errors[-1]:.4f} m | "
              f"{' / '.join(met)} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=os.path.join(ROOT, "build", "ci", "apps", "smoothsteer"))
    parser.add_argument("--seeds", type=int, default=0,
                        help="instead: the shipped files over noise seeds 1..N (min / median / max)")
    args = parser.parse_args()
    if args.seeds > 0:
        print_seed_spread(args.cli, args.seeds)
        return
    print("| variant | " + " | ".join(SCENARIOS) + " |")
    print("|---|" + "---|" * len(SCENARIOS))
    details = []
    for label, overrides in VARIANTS:
        cells = []
        for scenario in SCENARIOS:
            r = run(args.cli, scenario, overrides)
            if r is None:
                cells.append("failed")
                continue
            cells.append(f"{r['e']:.3f} m" + (" (spin)" if r["spin"] else ""))
            details.append((label, scenario, r))
        print(f"| {label} | " + " | ".join(cells) + " |")
    print()
    print("| variant | scenario | held rate max | held acc. max | samples above 0.4 rad/s or 8 rad/s^2 (held, actuator) | "
          "max side slip | max slip-estimate error |")
    print("|---|---|---|---|---|---|---|")
    for label, scenario, r in details:
        print(f"| {label} | {scenario} | {r['rate']:.3f} rad/s | {r['acc']:.2f} rad/s^2 | "
              f"{r['held_over']}, {r['actual_over']} | {r['slip']:.3f} rad | {r['slip_error']:.4f} rad |")


if __name__ == "__main__":
    main()
