#!/usr/bin/python3
"""Plot a `smoothsteer run` trace (or the demo's): path, errors, steering angle, rate and
acceleration. Writes a PNG.

Usage: /usr/bin/python3 scripts/plot_trace.py DIR/trace.csv [OUT.png]

Beside the trace it reads, when present:
  summary.json     (written by `run`) for the title (scenario, controller, speed), the vehicle's
                   steering limits and the controller's schedule, whose certified rate and
                   acceleration at the current speed are drawn as bounds (for a fixed lead-wheel
                   controller the bounds come from its certificate, if the Python module
                   smoothsteer can be imported);
  path.csv, or <trace name>_path.csv   (written by `run --plot` and by the demo) for the
                   reference path itself; without it the path is drawn from the closest points;
  <trace name>_limits.json   (written by the demo, where there is no summary.json) for the
                   title and the car's steering angle, rate and acceleration limits.
Needs matplotlib and numpy (Debian python3-matplotlib, python3-numpy).
"""
import csv
import json
import os
import sys
import tempfile

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_columns(path):
    with open(path, newline="") as handle:
        rows = [row for row in csv.reader(handle) if row and not row[0].startswith("#")]
    if len(rows) < 2:
        sys.exit(f"{path}: no rows")
    header, values = rows[0], np.array(rows[1:], dtype=float)
    return {name: values[:, i] for i, name in enumerate(header)}


def read_summary(trace_path):
    file = os.path.join(os.path.dirname(os.path.abspath(trace_path)), "summary.json")
    if not os.path.exists(file):
        return None
    with open(file) as handle:
        return json.load(handle)


def read_limits(trace_path):
    """The demo's {title, max_steering_*} beside the trace, or None."""
    file = os.path.splitext(os.path.abspath(trace_path))[0] + "_limits.json"
    if not os.path.exists(file):
        return None
    with open(file) as handle:
        return json.load(handle)


def reference_path(trace_path, t):
    """(x, y, label) of the reference path: the path file beside the trace, else the closest
    points of the rear axle, p - e n with n the path's left normal."""
    directory = os.path.dirname(os.path.abspath(trace_path))
    stem = os.path.splitext(os.path.basename(trace_path))[0]
    for name in (stem + "_path.csv", "path.csv"):
        file = os.path.join(directory, name)
        if os.path.exists(file):
            path = read_columns(file)
            return path["x"], path["y"], "reference path"
    heading = t["psi"] - t["heading_error"]
    return (t["x"] + t["e"] * np.sin(heading), t["y"] - t["e"] * np.cos(heading),
            "reference path (closest points)")


def certified_bounds(summary, speed, acceleration):
    """Certified |rate| and |acceleration| of the command at each sample, or None: from the
    controller's schedule (the entry it uses: the first grid speed >= |v|), else, if the Python
    module smoothsteer can be imported, from the certificate of a fixed lead-wheel controller
    (per metre travelled, times |v| and v^2; the box bound when the rate is not certified)."""
    controller = summary["parameters"].get("controller", {}) if summary else {}
    schedule = controller.get("schedule")
    if schedule:
        scenario_directory = os.path.dirname(summary.get("scenario_file", ""))
        file = schedule if os.path.isabs(schedule) else os.path.join(scenario_directory, schedule)
        if not os.path.exists(file):
            return None
        table = read_columns(file)
        index = np.minimum(np.searchsorted(table["speed_mps"], np.abs(speed) - 1e-9),
                           len(table["speed_mps"]) - 1)
        return (table["max_steering_rate_radps"][index],
                table["max_steering_acceleration_radps2"][index])
    if not summary:
        return None
    try:
        import smoothsteer
        scenario = smoothsteer.load_scenario(summary["scenario_file"], summary["overrides"])
        bounds = smoothsteer.scenario_certificate(scenario)
    except Exception:  # no module, or the scenario moved: no bound line
        return None
    if bounds is None:
        return None
    rate = bounds["rate_per_meter"]
    if not np.isfinite(rate):
        rate = bounds["box_rate_per_meter"]
    return (rate * np.abs(speed),
            speed ** 2 * bounds["acceleration_per_meter2"] + np.abs(acceleration) * rate)


def held_derivatives(t, delta):
    """Rate and acceleration of the held command, differenced at the control period, from rows
    1 and 2 on (NaN before: no command precedes the first row), as the metrics held_rate_* and
    held_acceleration_* (docs/metrics.md), so that the curves peak at the reported maxima."""
    rate = np.full(len(t), np.nan)
    acceleration = np.full(len(t), np.nan)
    if len(t) > 1:
        period = np.diff(t)
        rate[1:] = np.diff(delta) / period
        acceleration[2:] = np.diff(rate[1:]) / period[1:]
    return rate, acceleration


def draw_limits(axis, bound_t, bound, limit, unit):
    if bound is not None and np.isfinite(bound).any():
        axis.plot(bound_t, bound, "g--", linewidth=1.0, label="certified bound")
        axis.plot(bound_t, -bound, "g--", linewidth=1.0)
    if limit is not None and np.isfinite(limit):
        axis.axhline(limit, color="r", linestyle=":", linewidth=1.0,
                     label=f"vehicle limit {limit:g} {unit}")
        axis.axhline(-limit, color="r", linestyle=":", linewidth=1.0)


def draw_angle_limit(axis, limit, values):
    """The angle limit as lines where it is within reach of the data, else in the legend only
    (a passenger car's 1.07 rad would flatten a lane change's 0.05 rad)."""
    if limit is None or not np.isfinite(limit):
        return
    if limit <= 3.0 * np.max(np.abs(values)):
        draw_limits(axis, None, None, limit, "rad")
    else:
        axis.plot([], [], "r:", linewidth=1.0, label=f"vehicle limit {limit:g} rad (off scale)")


def title(trace_path, summary, t, limits=None):
    speed = f"v = {t['v'][0]:.1f} m/s" if np.ptp(t["v"]) < 1e-9 else (
        f"v = {t['v'].min():.1f} .. {t['v'].max():.1f} m/s")
    if limits and "title" in limits:
        return limits["title"]
    if summary:
        return f"{summary['scenario']}: {summary['controller']}, {speed}"
    return f"{os.path.basename(trace_path)}: {speed}"


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    trace_path = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) == 3 else os.path.splitext(trace_path)[0] + ".png"
    t = read_columns(trace_path)
    summary = read_summary(trace_path)
    limits = None if summary else read_limits(trace_path)
    vehicle = summary["parameters"]["vehicle"] if summary else (limits or {})
    figure, axes = plt.subplots(5, 1, figsize=(9, 14),
                                gridspec_kw={"height_ratios": [1.5, 1, 1, 1, 1]})
    x, y, label = reference_path(trace_path, t)
    axes[0].plot(x, y, "k--", linewidth=1.0, label=label)
    axes[0].plot(t["x"], t["y"], linewidth=1.2, label="rear axle")
    span = np.ptp(np.concatenate([x, t["x"]])), np.ptp(np.concatenate([y, t["y"]]))
    if min(span) > 0.2 * max(span):  # a square-ish path: true proportions
        axes[0].set_aspect("equal", adjustable="datalim")
    # else (a lane change: 200 m by 4 m) stretch y, so that the manoeuvre shows
    axes[0].set_xlabel("x [m]")
    axes[0].set_ylabel("y [m]")
    axes[0].legend(loc="best")
    time = t["t"]
    for key, name in (("e", "e (rear axle)"), ("e_front", "e_front"), ("e_lead", "e_lead")):
        axes[1].plot(time, t[key], linewidth=1.0, label=name)
    axes[1].set_ylabel("lateral error [m]")
    axes[1].legend(loc="best", ncol=3)
    axes[2].plot(time, t["delta_cmd"], linewidth=1.0, label="delta_cmd")
    axes[2].plot(time, t["delta_actual"], linewidth=1.0, label="delta_actual")
    if limits:  # the demo: the angle against the car's limit too
        draw_angle_limit(axes[2], vehicle.get("max_steering_angle_rad"), t["delta_cmd"])
    axes[2].set_ylabel("steering angle [rad]")
    axes[2].legend(loc="best")
    held_rate, held_acceleration = held_derivatives(time, t["delta_cmd"])
    bounds = certified_bounds(summary, t["v"], t["a"])
    axes[3].plot(time, held_rate, linewidth=1.0, label="held command")
    axes[3].plot(time, t["delta_actual_rate"], linewidth=1.0, label="actuator output")
    draw_limits(axes[3], time, bounds[0] if bounds else None,
                vehicle.get("max_steering_rate_radps"), "rad/s")
    axes[3].set_ylabel("steering rate [rad/s]")
    axes[3].legend(loc="best", fontsize=8, ncol=2)
    axes[4].plot(time, held_acceleration, linewidth=1.0, label="held command")
    axes[4].plot(time, t["delta_actual_acc"], linewidth=1.0, label="actuator output")
    draw_limits(axes[4], time, bounds[1] if bounds else None,
                vehicle.get("max_steering_acceleration_radps2"), "rad/s^2")
    axes[4].set_ylabel("steering acceleration [rad/s^2]")
    axes[4].set_xlabel("t [s]")
    axes[4].legend(loc="best", fontsize=8, ncol=2)
    for axis in axes[1:]:
        axis.grid(alpha=0.3)
    figure.suptitle(title(trace_path, summary, t, limits))
    figure.tight_layout()
    # Atomic: write next to the target, then rename.
    handle, temporary = tempfile.mkstemp(suffix=".png", dir=os.path.dirname(os.path.abspath(out)))
    os.close(handle)
    figure.savefig(temporary, dpi=110, metadata={"Software": None})
    # mkstemp creates 0600; give the figure the permissions of any other output file.
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(temporary, 0o666 & ~umask)
    os.replace(temporary, out)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
