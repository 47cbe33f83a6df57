"""The tuned comparison's Pareto figures (smoothsteer.figures, `tuned_pareto`): max |e| against
the actuator's RMS steering rate, one PNG per held-out scenario, from the table of
`smoothsteer compare tuning` (docs/results/tuning_rule.csv, docs/baselines.md). No simulation."""
import csv
import os

from ._plotting import plt, save

LIMITS = "car: 0.4 rad/s, 8 rad/s^2, 10 Hz actuator"


def read_table(path):
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    if not rows:
        raise SystemExit(f"{path}: no rows")
    return rows


def plot_scenario(scenario, rows, out):
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
    axes.set_title(f"{scenario}: held-out, tuned by one rule ({LIMITS})", fontsize=9)
    note = "filled: no held-command sample above the car's limits; hollow: some"
    if dropped:
        note += "\ndiverged (not shown): " + ", ".join(dropped)
    figure.text(0.01, 0.01, note, fontsize=7, va="bottom")
    axes.grid(True, which="both", linewidth=0.3)
    figure.tight_layout(rect=(0, 0.07, 1, 1))
    return save(figure, out, f"pareto_{scenario}")


def fig_tuned_pareto(out, table=None):
    """pareto_<scenario>.png for every scenario of the table, into `out`. The table is
    out/tuning_rule.csv when `compare tuning` wrote one there, else the committed one."""
    if table is None:
        written = os.path.join(out, "tuning_rule.csv")
        table = written if os.path.exists(written) else "docs/results/tuning_rule.csv"
    rows = read_table(table)
    return [plot_scenario(s, [r for r in rows if r["scenario"] == s], out)
            for s in dict.fromkeys(r["scenario"] for r in rows)]
