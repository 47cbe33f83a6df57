"""The figures of a campaign report (docs/campaigns.md): histograms of the criteria's metrics,
the primary metric against every sampled variable, and the trace of the worst case, replayed."""
import json
import textwrap

import numpy as np

import smoothsteer as ss
from .._plotting import controller_label, plt, reference_path, save

PASSED, NOT_PASSED = "tab:blue", "tab:red"


def _save(figure, out, name):
    """smoothsteer.figures' save, then a 64-colour palette: a scatter of 10^4 dots is a
    third of its RGBA size so (440 against 130 KiB) and looks the same."""
    from PIL import Image

    path = save(figure, out, name)
    with Image.open(path) as image:
        palette = image.convert("RGB").quantize(colors=64, method=Image.Quantize.MEDIANCUT)
    palette.save(path, optimize=True)
    return path


def _threshold_lines(axis, spec, metric, vertical):
    for criterion in spec.criteria:
        if criterion.metric != metric:
            continue
        for value, label in ((criterion.max, "max"), (criterion.min, "min")):
            if value is not None:
                line = axis.axvline if vertical else axis.axhline
                line(value, color="k", linestyle="--", linewidth=1.0,
                     label=f"criterion: {label} {value:g}")


def histograms(spec, frame, out):
    """One histogram per criterion metric (the primary metric first)."""
    metrics = list(dict.fromkeys([spec.primary_metric] + [c.metric for c in spec.criteria]))[:4]
    ran = frame[frame["sim_status"].notna()]
    figure, axes = plt.subplots(1, len(metrics), figsize=(4.2 * len(metrics), 3.6), squeeze=False)
    for axis, metric in zip(axes[0], metrics):
        values = ran[metric].astype(float).to_numpy()
        values = values[np.isfinite(values)]
        distinct, counts = np.unique(values, return_counts=True)
        if distinct.size <= 20 and np.all(distinct == np.round(distinct)):  # counts, flags
            axis.bar(distinct, counts, width=0.8, color=PASSED, alpha=0.85)
            axis.set_xticks(distinct)
            axis.set_xlim(distinct.min() - 1.0, distinct.max() + 1.0)
        else:
            axis.hist(values, bins=60, color=PASSED, alpha=0.85)
        _threshold_lines(axis, spec, metric, vertical=True)
        axis.set_yscale("log")
        axis.set_ylim(bottom=0.8)
        axis.set_xlabel(metric)
        axis.set_ylabel("cases")
        axis.grid(alpha=0.3)
        if axis.get_legend_handles_labels()[0]:
            axis.legend(fontsize=8)
    figure.suptitle(f"{spec.name}: {len(ran)} cases that ran", fontsize=10)
    figure.tight_layout()
    return _save(figure, out, "histograms")


def _axis_values(series):
    """Numbers for a numeric variable; category indices with their labels for a choice."""
    numbers = np.array([_number(v) for v in series], dtype=float)
    if np.all(np.isfinite(numbers)):
        return numbers, None
    labels = sorted({str(v) for v in series})
    index = {label: i for i, label in enumerate(labels)}
    jitter = np.random.default_rng(0).uniform(-0.2, 0.2, len(series))
    return np.array([index[str(v)] for v in series], dtype=float) + jitter, labels


def _number(value):
    try:
        return float(value)
    except (TypeError, ValueError):
        return float("nan")


def scatter(spec, frame, out):
    """The primary metric against each sampled variable, passed and not passed in two colours."""
    ran = frame[frame["sim_status"].notna()]
    count = len(spec.variables)
    columns = min(count, 3)
    rows = (count + columns - 1) // columns
    figure, axes = plt.subplots(rows, columns, figsize=(4.3 * columns, 3.4 * rows),
                                squeeze=False)
    y = ran[spec.primary_metric].astype(float).to_numpy()
    passed = ran["passed"].to_numpy() == 1
    for axis, variable in zip(axes.flat, spec.variables):
        x, labels = _axis_values(ran[variable.key].tolist())
        # Opaque dots: a PNG of 10^4 blended dots is several times larger.
        size = 2 if len(ran) > 2000 else 10
        axis.scatter(x[passed], y[passed], s=size, color=PASSED, linewidths=0, label="passed")
        axis.scatter(x[~passed], y[~passed], s=size, color=NOT_PASSED, linewidths=0,
                     label="not passed")
        if labels:
            axis.set_xticks(range(len(labels)))
            axis.set_xticklabels(labels, fontsize=8)
        _threshold_lines(axis, spec, spec.primary_metric, vertical=False)
        axis.set_xlabel(variable.key, fontsize=8)
        axis.set_ylabel(spec.primary_metric, fontsize=8)
        axis.grid(alpha=0.3)
    for axis in list(axes.flat)[count:]:
        axis.set_visible(False)
    axes.flat[0].legend(fontsize=7, loc="upper left")
    figure.suptitle(f"{spec.name}: {spec.primary_metric} against the sampled variables",
                    fontsize=10)
    figure.tight_layout()
    return _save(figure, out, "scatter")


def worst_trace(spec, row, out):
    """The worst case by the primary metric, replayed: path and track, errors, steering."""
    overrides = json.loads(row["overrides"])
    scenario = ss.load_scenario(spec.base, overrides)
    trace, summary = ss.run_scenario(scenario)
    figure, axes = plt.subplots(3, 1, figsize=(8, 8.5), gridspec_kw={"height_ratios": [1.2, 1, 1]})
    x, y = reference_path(scenario)
    axes[0].plot(x, y, "k--", linewidth=1.0, label="reference path")
    axes[0].plot(trace["x"], trace["y"], linewidth=1.2, label="rear axle")
    axes[0].set_xlim(trace["x"].min() - 5.0, trace["x"].max() + 5.0)
    axes[0].set_xlabel("x [m]")
    axes[0].set_ylabel("y [m]")
    axes[0].legend(loc="upper left", fontsize=8)
    for key, label in (("e", "e (rear axle)"), ("e_front", "e_front"), ("e_lead", "e_lead")):
        axes[1].plot(trace["t"], trace[key], linewidth=1.0, label=label)
    axes[1].set_ylabel("lateral error [m]")
    axes[1].legend(loc="upper right", ncol=3, fontsize=8)
    axes[2].plot(trace["t"], trace["delta_cmd"], linewidth=1.0, label="delta (command)")
    axes[2].plot(trace["t"], trace["delta_actual"], linewidth=1.0, label="delta (actuator)")
    axes[2].set_xlabel("t [s]")
    axes[2].set_ylabel("steering angle [rad]")
    axes[2].legend(loc="upper right", fontsize=8)
    for axis in axes[1:]:
        axis.grid(alpha=0.3)
    value = summary["metrics"].get(spec.primary_metric, row[spec.primary_metric])
    sampled = ", ".join(f"{v.key.rsplit('.', 1)[-1]} {_short(overrides[v.key])}"
                        for v in spec.variables)
    figure.suptitle(f"{spec.name}, worst case {int(row['case'])} "
                    f"({spec.primary_metric} {float(value):.3g}), "
                    f"{controller_label(summary)}\n" + textwrap.fill(sampled, 100), fontsize=9)
    figure.tight_layout()
    return _save(figure, out, "worst_trace")


def _short(value):
    return f"{value:.4g}" if isinstance(value, float) else str(value)
