#!/usr/bin/python3
"""One figure per road of the road suite (docs/results/road_suite.md): for each of the three cars
on the held-out double-track plant, the path (grey) with the rear axle's track, the rear-axle lateral
error and the steering command over the distance travelled, for the certified route and four
baselines. Reads the traces of `smoothsteer compare road-suite --traces DIR`:

    build/ci/apps/smoothsteer compare road-suite --threads 2 --traces /tmp/road_traces \\
        --out docs/results
    /usr/bin/python3 scripts/road_suite_figures.py /tmp/road_traces docs/figures/roads

writes docs/figures/roads/<road>.png (no date or version metadata).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

CARS = ["ford_escort", "bmw_320i", "vw_vanagon"]
CONTROLLERS = [("certified", "k", 1.6), ("pure_pursuit", "tab:blue", 0.9),
               ("stanley", "tab:orange", 0.9), ("lqr", "tab:green", 0.9),
               ("mpc_constrained", "tab:red", 0.9)]
PLANT = "double_track"


def columns(path):
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    return {key: [float(row[key]) for row in rows] for key in rows[0]}


def road_figure(directory, road, output):
    figure, axes = plt.subplots(len(CARS), 3, figsize=(12, 2.6 * len(CARS)),
                                gridspec_kw={"width_ratios": [1.2, 1, 1]})
    path = columns(os.path.join(directory, road, "path.csv"))
    for row, car in zip(axes, CARS):
        row[0].plot(path["x"], path["y"], color="0.6", lw=3.0, alpha=0.5, label="path")
        for controller, colour, width in CONTROLLERS:
            file = os.path.join(directory, road, "%s_%s_%s.csv" % (car, PLANT, controller))
            if not os.path.exists(file):
                continue
            trace = columns(file)
            row[0].plot(trace["x"], trace["y"], color=colour, lw=width, label=controller)
            row[1].plot(trace["s"], trace["e"], color=colour, lw=width)
            row[2].plot(trace["s"], trace["delta_cmd"], color=colour, lw=width)
        row[0].set_aspect("equal", adjustable="datalim")
        row[0].set_title("%s, %s (double-track plant)" % (road, car), fontsize=9, loc="left")
        row[1].set_ylabel("e rear axle [m]", fontsize=8)
        row[1].set_ylim(-1.5, 1.5)
        row[2].set_ylabel("delta_cmd [rad]", fontsize=8)
        for axis in row:
            axis.tick_params(labelsize=7)
            axis.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7, loc="best")
    axes[-1][1].set_xlabel("distance travelled [m]", fontsize=8)
    axes[-1][2].set_xlabel("distance travelled [m]", fontsize=8)
    figure.tight_layout()
    figure.savefig(output, dpi=72, metadata={"Software": None})
    plt.close(figure)


def main():
    directory, output = sys.argv[1], sys.argv[2]
    os.makedirs(output, exist_ok=True)
    for road in sorted(d for d in os.listdir(directory)
                       if os.path.isdir(os.path.join(directory, d))):
        road_figure(directory, road, os.path.join(output, road + ".png"))
        print("wrote", os.path.join(output, road + ".png"))


if __name__ == "__main__":
    main()
