"""Every Python example runs (from the repository root) and exits with status 0."""
import pathlib
import subprocess
import sys

import pytest

from conftest import ROOT, python_environment
from readme_example import readme_python_block, run_readme_python_block

EXAMPLES = sorted((ROOT / "examples").glob("[0-9][0-9]_*.py"))


def test_examples_come_in_pairs():
    assert len(EXAMPLES) >= 7
    for example in EXAMPLES:
        assert example.with_suffix(".cpp").exists(), f"{example.name} has no C++ twin"


@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.name)
def test_example_runs(example):
    result = subprocess.run([sys.executable, str(example)], cwd=ROOT, env=python_environment(),
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stdout + result.stderr
    assert result.stdout.strip(), f"{pathlib.Path(example).name} printed nothing"


def test_readme_python_loop_runs():
    """The README's closed loop in a dozen lines of Python runs and reaches the path."""
    assert len(readme_python_block().strip().splitlines()) <= 13
    run_readme_python_block(sys.executable, ROOT, env=python_environment())
