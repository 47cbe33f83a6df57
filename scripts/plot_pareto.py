#!/usr/bin/python3
"""Pareto figures of the tuned comparison: max |e| against the actuator's RMS steering rate, one
PNG per held-out scenario, from the table of `smoothsteer compare tuning` (docs/baselines.md).

Usage: /usr/bin/python3 scripts/plot_pareto.py [DIR]
Reads DIR/tuning_rule.csv (default docs/results) and writes DIR/pareto_<scenario>.png.
Needs matplotlib (Debian python3-matplotlib). The PNGs carry no date or version metadata, so a
rerun on the same table gives the same files.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LIMITS = "car: 0.4 rad/s, 8 rad/s^2, 10 Hz actuator"


def read(path):
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    if not rows:
        sys.exit(f"{path}: no rows")
    return rows


def plot(scenario, rows, out_path):
    figure, axes = plt.subplots(figsize=(6.4, 4.6))
    shown = [r for r in rows if r["diverged"] == "no"]
    front = sorted((r for r in shown if r["pareto"] == "yes"),
                   key=lambda r: float(r["actual_rate_rms_radps"]))
    if front:
        axes.step([float(r["actual_rate_rms_radps"]) for r in front],
                  [float(r["max_abs_e_m"]) for r in front],
                  where="post", color="0.6", linewidth=1.0, label="Pareto front")
    for r in shown:
        x, y = float(r["actual_rate_rms_radps"]), float(r["max_abs_e_m"])
        within = r["held_above_limits"] == "0"
        certified = r["controller"] == "certified"
        axes.plot(x, y, marker="*" if certified else "o",
                  markersize=13 if certified else 7,
                  markerfacecolor=("tab:red" if certified else "tab:blue") if within else "none",
                  markeredgecolor="tab:red" if certified else "tab:blue", linestyle="none")
        axes.annotate(r["controller"], (x, y), textcoords="offset points", xytext=(5, 4),
                      fontsize=8)
    dropped = [r["controller"] for r in rows if r["diverged"] != "no"]
    axes.set_yscale("log")
    axes.set_xlabel("RMS actuator steering rate [rad/s]")
    axes.set_ylabel("max |e| rear axle [m] (log)")
    title = f"{scenario}: held-out, tuned by one rule ({LIMITS})"
    axes.set_title(title, fontsize=9)
    note = "filled: no held-command sample above the car's limits; hollow: some"
    if dropped:
        note += "\ndiverged (not shown): " + ", ".join(dropped)
    figure.text(0.01, 0.01, note, fontsize=7, va="bottom")
    axes.grid(True, which="both", linewidth=0.3)
    figure.tight_layout(rect=(0, 0.07, 1, 1))
    figure.savefig(out_path, dpi=110, metadata={"Software": None})
    plt.close(figure)


def main():
    if len(sys.argv) > 2:
        sys.exit(__doc__)
    directory = sys.argv[1] if len(sys.argv) == 2 else "docs/results"
    rows = read(os.path.join(directory, "tuning_rule.csv"))
    scenarios = list(dict.fromkeys(r["scenario"] for r in rows))
    for scenario in scenarios:
        out_path = os.path.join(directory, f"pareto_{scenario}.png")
        plot(scenario, [r for r in rows if r["scenario"] == scenario], out_path)
        print(f"written: {out_path}")


if __name__ == "__main__":
    main()
