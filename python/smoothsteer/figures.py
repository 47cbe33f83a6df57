"""The paper's figures, regenerated from this project's own simulations (docs/results.md).

    PYTHONPATH=build/release/python /usr/bin/python3 -m smoothsteer.figures --out docs/figures

Run from the repository root (the scenario files name their vehicle and schedule files
relatively). Deterministic: the simulations are (their noise is seeded), the optimiser starts
from fixed guesses, and the PNGs carry no date or version. Figures (paper labels):
  simu             path, errors e / e_front / e_lead, delta_cmd and the actuator's delta on
                   circle_sections
  el_comp          e_lead on circle_sections for the four parameter settings of Sec. IV-A
  parameter_radar  the four indicators of those settings
  param_v          the tuned lambda, lambda_l, lead radius 1/kbar_l and the certified maximum
                   rate and acceleration over speed (shipped car, both certificates)
  benchmark_e      reaching a straight path: optimal, proposed (n = 1) and HOSM, two starts,
                   rear and front wheel
  lanechange       the 15 m/s lane change: path, errors, steering, steering rate
  pareto           the lane-change comparison: tracking error against steering effort
  tuned_pareto     the tuned comparison's Pareto figures, pareto_<scenario>.png, from the
                   committed docs/results/tuning_rule.csv (no simulation; use --out docs/results)
"""
import argparse
import os
import sys

from ._plotting import plt
from .figures_simulation import (fig_el_comp, fig_lanechange, fig_parameter_radar, fig_simu,
                                 paper_setting_runs)
from .figures_comparison import fig_tuned_pareto
from .figures_tuning import fig_benchmark_e, fig_param_v, fig_pareto

FIGURES = ["simu", "el_comp", "parameter_radar", "param_v", "benchmark_e", "lanechange",
           "pareto"]
# Written only when named with --only (they belong to docs/results, not docs/figures).
EXTRA = ["tuned_pareto"]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="docs/figures", help="output directory")
    parser.add_argument("--only", default="", help="comma-separated subset of " +
                        ", ".join(FIGURES + EXTRA))
    arguments = parser.parse_args(argv)
    wanted = [name for name in arguments.only.split(",") if name] or FIGURES
    unknown = sorted(set(wanted) - set(FIGURES + EXTRA))
    if unknown:
        parser.error(f"unknown figure(s) {', '.join(unknown)}; known: "
                     f"{', '.join(FIGURES + EXTRA)}")
    os.makedirs(arguments.out, exist_ok=True)
    plt.rcParams.update({"font.size": 9, "svg.hashsalt": "smoothsteer"})
    runs = paper_setting_runs() if {"el_comp", "parameter_radar"} & set(wanted) else None
    makers = {"simu": fig_simu, "el_comp": lambda out: fig_el_comp(out, runs),
              "parameter_radar": lambda out: fig_parameter_radar(out, runs),
              "param_v": fig_param_v, "benchmark_e": fig_benchmark_e,
              "lanechange": fig_lanechange, "pareto": fig_pareto,
              "tuned_pareto": fig_tuned_pareto}
    for name in FIGURES + EXTRA:
        if name in wanted:
            makers[name](arguments.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
