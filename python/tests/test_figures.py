"""The figures command runs and writes every figure (CI checks that it runs, not its pixels);
scripts/plot_trace.py plots the demo's trace, whose columns are those of `smoothsteer run`."""
import csv
import subprocess
import sys

import smoothsteer as ss
from conftest import BUILD, ROOT, python_environment
from smoothsteer import figures


def test_figures_command_writes_every_figure(tmp_path):
    result = subprocess.run([sys.executable, "-m", "smoothsteer.figures", "--out", str(tmp_path)],
                            cwd=ROOT, env=python_environment(), capture_output=True, text=True,
                            timeout=900)
    assert result.returncode == 0, result.stdout + result.stderr
    for name in figures.FIGURES:
        png = tmp_path / f"{name}.png"
        assert png.exists(), name
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_tuned_pareto_plots_the_committed_table(tmp_path):
    result = subprocess.run([sys.executable, "-m", "smoothsteer.figures", "--out", str(tmp_path),
                             "--only", "tuned_pareto"], cwd=ROOT, env=python_environment(),
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stdout + result.stderr
    with open(ROOT / "docs" / "results" / "tuning_rule.csv", newline="") as handle:
        scenarios = {row["scenario"] for row in csv.DictReader(handle)}
    assert scenarios
    for scenario in scenarios:
        assert (tmp_path / f"pareto_{scenario}.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_unknown_figure_is_an_error(tmp_path):
    result = subprocess.run([sys.executable, "-m", "smoothsteer.figures", "--out", str(tmp_path),
                             "--only", "simu,nonsense"], cwd=ROOT, env=python_environment(),
                            capture_output=True, text=True)
    assert result.returncode == 2
    assert "unknown figure(s) nonsense" in result.stderr


def test_demo_trace_has_the_run_columns_and_plots(tmp_path):
    trace = tmp_path / "demo_trace.csv"
    subprocess.run([str(BUILD / "apps" / "smoothsteer_demo"), str(trace)], check=True,
                   capture_output=True)
    with open(trace, newline="") as handle:
        header = next(csv.reader(handle))
    assert header == ss.trace_column_names()
    assert (tmp_path / "demo_trace_path.csv").exists()
    png = tmp_path / "demo.png"
    result = subprocess.run(["/usr/bin/python3", str(ROOT / "scripts" / "plot_trace.py"),
                             str(trace), str(png)], capture_output=True, text=True,
                            env=python_environment())
    assert result.returncode == 0, result.stderr
    assert png.exists()


def test_run_plot_draws_the_path_and_the_bounds(tmp_path):
    """`run --plot` writes path.csv and the PNG; with the module importable the plot script
    takes a fixed lead-wheel controller's bounds from scenario_certificate()."""
    out = tmp_path / "run"
    result = subprocess.run([str(BUILD / "apps" / "smoothsteer"), "run",
                             "scenarios/reaching_p02pi.yaml", "--out", str(out), "--plot"],
                            cwd=ROOT, env=python_environment(), capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    assert (out / "trace.png").exists()
    with open(out / "path.csv", newline="") as handle:
        rows = list(csv.reader(handle))
    assert rows[0] == ["x", "y"] and len(rows) > 100
    bounds = ss.scenario_certificate(ss.load_scenario("scenarios/reaching_p02pi.yaml"))
    assert bounds["box_rate_per_meter"] > 0.0
    assert ss.scenario_certificate(ss.load_scenario("scenarios/lane_change_15.yaml")) is None
