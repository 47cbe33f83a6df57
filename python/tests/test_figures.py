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
