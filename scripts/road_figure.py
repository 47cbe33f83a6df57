#!/usr/bin/python3
"""One figure of the road suite (docs/scenarios.md): per road its path with the rear axle's
track, the rear-axle lateral error and the steering command over time, for the runs of
`smoothsteer run FILE --out DIR/NAME --plot` of each road (DIR/NAME/trace.csv, path.csv).

    for f in scenarios/roads/*.yaml scenarios/hairpin.yaml; do
      build/ci/apps/smoothsteer run $f --out /tmp/roads/$(basename $f .yaml) --plot; done
    /usr/bin/python3 scripts/road_figure.py /tmp/roads docs/figures/road_suite.png
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROADS = ["rural_80", "motorway_exit", "roundabout", "urban_turn", "mountain_hairpins", "hairpin"]


def columns(path):
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    return {key: [float(row[key]) for row in rows] for key in rows[0]}


def main():
    directory, output = sys.argv[1], sys.argv[2]
    figure, axes = plt.subplots(len(ROADS), 3, figsize=(11, 2.1 * len(ROADS)),
                                gridspec_kw={"width_ratios": [1.3, 1, 1]})
    for row, name in zip(axes, ROADS):
        trace = columns(os.path.join(directory, name, "trace.csv"))
        path = columns(os.path.join(directory, name, "path.csv"))
        row[0].plot(path["x"], path["y"], "k--", lw=1, label="path")
        row[0].plot(trace["x"], trace["y"], lw=1, label="rear axle")
        row[0].set_aspect("equal", adjustable="datalim")
        row[0].set_title(name, fontsize=9, loc="left")
        row[1].plot(trace["t"], trace["e"], lw=1)
        row[1].set_ylabel("e rear [m]", fontsize=8)
        row[2].plot(trace["t"], trace["delta_cmd"], lw=1)
        row[2].set_ylabel("delta_cmd [rad]", fontsize=8)
        for axis in row:
            axis.tick_params(labelsize=7)
            axis.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7)
    axes[-1][1].set_xlabel("t [s]", fontsize=8)
    axes[-1][2].set_xlabel("t [s]", fontsize=8)
    figure.tight_layout()
    figure.savefig(output, dpi=72)


if __name__ == "__main__":
    main()
