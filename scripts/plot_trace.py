#!/usr/bin/python3
"""Plot a `smoothsteer run` trace: path driven, errors, steering. Writes a PNG.

Usage: /usr/bin/python3 scripts/plot_trace.py DIR/trace.csv [OUT.png]
Needs matplotlib (Debian python3-matplotlib); uses only the csv module for reading.
"""
import csv
import math
import os
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    if not rows:
        sys.exit(f"{path}: no rows")
    return {key: [float(row[key]) for row in rows] for key in rows[0]}


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    trace_path = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) == 3 else os.path.splitext(trace_path)[0] + ".png"
    t = read(trace_path)
    fig, axes = plt.subplots(3, 1, figsize=(9, 11))
    # Closest path point of the rear axle: p - e n, with n the left normal of the path heading
    # psi - heading_error (heading_error is relative to the direction of travel; the normal is
    # the same up to sign, which e carries).
    path_heading = [psi - he for psi, he in zip(t["psi"], t["heading_error"])]
    reference_x = [x + e * math.sin(h) for x, e, h in zip(t["x"], t["e"], path_heading)]
    reference_y = [y - e * math.cos(h) for y, e, h in zip(t["y"], t["e"], path_heading)]
    axes[0].plot(reference_x, reference_y, "k--", linewidth=1.0, label="reference path (closest points)")
    axes[0].plot(t["x"], t["y"], label="rear axle")
    axes[0].set_aspect("equal", adjustable="datalim")
    axes[0].set_xlabel("x [m]")
    axes[0].set_ylabel("y [m]")
    axes[0].legend()
    for key, label in (("e_lead", "e_lead"), ("e_front", "front"), ("e", "rear")):
        axes[1].plot(t["t"], t[key], label=label)
    axes[1].set_ylabel("lateral error [m]")
    axes[1].legend()
    axes[2].plot(t["t"], t["delta_cmd"], label="delta_cmd")
    axes[2].plot(t["t"], t["delta_actual"], label="delta_actual")
    axes[2].set_xlabel("t [s]")
    axes[2].set_ylabel("steering [rad]")
    axes[2].legend()
    fig.tight_layout()
    # Atomic: write next to the target, then rename.
    handle, temporary = tempfile.mkstemp(suffix=".png", dir=os.path.dirname(os.path.abspath(out)))
    os.close(handle)
    fig.savefig(temporary, dpi=110)
    # mkstemp creates 0600; give the figure the permissions of any other output file.
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(temporary, 0o666 & ~umask)
    os.replace(temporary, out)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
