"""Shared pieces of the figures (smoothsteer.figures): saving and the reference path."""
import os

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

DPI = 110


def save(figure, out, name):
    path = os.path.join(out, name + ".png")
    figure.savefig(path, dpi=DPI, metadata={"Software": None})
    plt.close(figure)
    print(f"wrote {path} ({os.path.getsize(path) // 1024} KiB)")
    return path


def reference_path(scenario, samples=4000):
    path = scenario.path
    points = path.sample(np.linspace(0.0, path.length_m, samples))
    return points[:, 0], points[:, 1]


def controller_label(summary):
    return summary["controller"].replace("scheduled_lead_wheel", "lead wheel, scheduled")
