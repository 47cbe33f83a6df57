"""The report of a campaign (docs/campaigns.md): DIR/report.md with the pass rate per
criterion, percentiles of every metric, the worst cases per metric and every failure by kind,
each with the `smoothsteer run` command that replays it, and the PNGs of figures.py."""
import json
import os
import shlex

import numpy as np

from .. import _override_text
from . import figures as campaign_figures
from .results import read_rows
from .spec import display_path

PERCENTILES = (50, 90, 99, 99.9)
# Metrics whose smallest value is the worst when no criterion says otherwise.
LARGER_IS_BETTER = ("reached",)


def replay_command(spec, row):
    """The CLI command that runs the case again: the base with the case's overrides."""
    overrides = json.loads(row["overrides"])
    words = ["smoothsteer", "run", display_path(spec.base)]
    for key, value in overrides.items():
        words += ["--set", f"{key}={_override_text(value)}"]
    words += ["--out", f"case_{int(row['case'])}"]
    return " ".join(shlex.quote(word) for word in words)


def _format(value):
    if isinstance(value, (float, np.floating)):
        return f"{value:.4g}" if np.isfinite(value) else str(value)
    return str(value)


def _sampled(spec, row):
    return ", ".join(f"{v.key} = {_format(row[v.key])}" for v in spec.variables)


def _worst_direction(spec, metric):
    """True: smallest first (the metric's only criteria are minima, or it is 'reached')."""
    bounds = [c for c in spec.criteria if c.metric == metric]
    if not bounds:
        return metric in LARGER_IS_BETTER
    return all(c.max is None for c in bounds)


def _header(spec, frame, ran):
    passed = int(frame["passed"].sum())
    lines = [f"# Campaign `{spec.name}`", ""]
    if spec.description:
        lines += [spec.description, ""]
    lines += [f"- base scenario: `{display_path(spec.base)}`; seed {spec.seed}; "
              f"{len(frame)} of {spec.cases} cases in the results"
              + ("" if len(frame) == spec.cases else
                 f" (**{spec.cases - len(frame)} not run yet**)"),
              f"- passed: **{passed} of {len(frame)} "
              f"({100.0 * passed / max(len(frame), 1):.2f} %)**; ran: {len(ran)}; "
              f"failed to run: {len(frame) - len(ran)}",
              f"- simulation time per case (worker): mean {ran['elapsed_s'].mean() * 1e3:.1f} ms,"
              f" max {ran['elapsed_s'].max() * 1e3:.1f} ms" if len(ran) else "- no case ran"]
    if spec.overrides:
        fixed = ", ".join(f"`{k}={_override_text(v)}`" for k, v in spec.overrides.items())
        lines.append(f"- fixed overrides: {fixed}")
    lines += ["", "## Sampled variables", "", "| key | distribution | sampled min | median | max |",
              "|---|---|---|---|---|"]
    for variable in spec.variables:
        values = frame[variable.key]
        if variable.kind == "choice":
            counts = values.astype(str).value_counts().sort_index()
            spread = ", ".join(f"{k}: {n}" for k, n in counts.items())
            lines.append(f"| `{variable.key}` | {variable.describe()} | {spread} | | |")
        else:
            numbers = values.astype(float)
            lines.append(f"| `{variable.key}` | {variable.describe()} | {numbers.min():.4g} | "
                         f"{numbers.median():.4g} | {numbers.max():.4g} |")
    return lines


def _criteria(spec, frame, ran):
    lines = ["", "## Pass criteria", "", "| criterion | passed | of the cases that ran |",
             "|---|---|---|"]
    for criterion in spec.criteria:
        holds = ran[criterion.metric].astype(float).map(criterion.holds)
        lines.append(f"| {criterion.describe()} | {int(holds.sum())} of {len(ran)} | "
                     f"{100.0 * holds.mean():.2f} % |" if len(ran) else
                     f"| {criterion.describe()} | - | - |")
    lines.append(f"| all of them, and the run completed | {int(frame['passed'].sum())} of "
                 f"{len(frame)} | of all cases |")
    return lines


def _percentiles(spec, ran):
    names = " | ".join(f"p{p:g}" for p in PERCENTILES)
    lines = ["", "## Metrics over the cases that ran", "",
             f"| metric | min | {names} | max | mean |", "|---" * (len(PERCENTILES) + 4) + "|"]
    for metric in spec.metrics:
        values = ran[metric].astype(float).to_numpy()
        values = values[np.isfinite(values)]
        if not values.size:
            continue
        cells = [np.min(values)] + list(np.percentile(values, PERCENTILES)) + \
            [np.max(values), np.mean(values)]
        lines.append(f"| `{metric}` | " + " | ".join(_format(c) for c in cells) + " |")
    return lines


def _worst(spec, ran):
    lines = ["", "## Worst cases", ""]
    metrics = list(dict.fromkeys([spec.primary_metric] + [c.metric for c in spec.criteria]))
    for metric in metrics:
        ascending = _worst_direction(spec, metric)
        order = ran.sort_values([metric, "case"], ascending=[ascending, True])
        lines += [f"### `{metric}` ({'smallest' if ascending else 'largest'} first)", ""]
        values = ran[metric].astype(float)
        if values.nunique(dropna=False) == 1:
            lines += [f"Every case that ran: {_format(values.iloc[0])}.", ""]
            continue
        for rank, (_, row) in enumerate(order.head(spec.worst_cases).iterrows(), start=1):
            lines += [f"{rank}. case {int(row['case'])}: {metric} = {_format(row[metric])} "
                      f"({_sampled(spec, row)})", "", "   ```", f"   {replay_command(spec, row)}",
                      "   ```"]
        lines.append("")
    others = [m for m in spec.metrics if m not in metrics]
    if others:
        lines += ["### The worst case of every other metric", ""]
    for metric in others:
        values = ran[metric].astype(float)
        if values.nunique() <= 1:
            lines.append(f"- `{metric}`: {_format(values.iloc[0])} in every case that ran")
            continue
        row = ran.loc[values.idxmin() if _worst_direction(spec, metric) else values.idxmax()]
        lines += [f"- `{metric}` = {_format(row[metric])}, case {int(row['case'])}: "
                  f"`{replay_command(spec, row)}`"]
    return lines + [""]


def _failures(spec, frame, ran):
    lines = ["## Failures by kind", ""]
    failed = frame[frame["status"] == "failed"]
    if failed.empty:
        lines.append("No case failed to run.")
    else:
        lines += ["| kind | cases | first case | error |", "|---|---|---|---|"]
        for kind, group in failed.groupby("error_kind", sort=True):
            first = group.iloc[0]
            lines.append(f"| `{kind}` | {len(group)} | {int(first['case'])} | "
                         f"{str(first['error']).replace('|', '/')} |")
        lines += ["", "Replay the first case of each kind:", ""]
        for kind, group in failed.groupby("error_kind", sort=True):
            lines += [f"- `{kind}`:", "", "  ```", f"  {replay_command(spec, group.iloc[0])}",
                      "  ```"]
    lines += ["", "Cases that ran but broke a criterion:", ""]
    if not spec.criteria:
        lines.append("(the spec gives no criteria)")
    for criterion in spec.criteria:
        broken = ran[~ran[criterion.metric].astype(float).map(criterion.holds)]
        first = f", first: case {int(broken.iloc[0]['case'])}" if len(broken) else ""
        lines.append(f"- {criterion.describe()}: {len(broken)}{first}")
    return lines


def write_report(spec, out, replay_trace=True):
    """Writes DIR/report.md and histograms.png, scatter.png, worst_trace.png next to it."""
    frame = read_rows(out, spec)
    ran = frame[frame["sim_status"].notna()]
    lines = _header(spec, frame, ran) + _criteria(spec, frame, ran) + _percentiles(spec, ran)
    lines += _worst(spec, ran) + _failures(spec, frame, ran)
    figures = []
    if len(ran):
        figures.append(campaign_figures.histograms(spec, frame, out))
        figures.append(campaign_figures.scatter(spec, frame, out))
        if replay_trace:
            worst = ran.sort_values([spec.primary_metric, "case"],
                                    ascending=[_worst_direction(spec, spec.primary_metric),
                                               True]).iloc[0]
            figures.append(campaign_figures.worst_trace(spec, worst, out))
    lines += ["", "## Figures", ""]
    lines += [f"![{os.path.splitext(os.path.basename(p))[0]}]({os.path.basename(p)})"
              for p in figures]
    path = os.path.join(out, "report.md")
    with open(path, "w", encoding="utf-8") as handle:
        handle.write("\n".join(lines) + "\n")
    return path
