"""The README's Python example (its first python block), run by a given interpreter from a given
directory. Shared by the in-tree test (test_examples.py) and the installed-package check
(scripts/test_python_package.sh, which runs this file with the venv's python)."""
import argparse
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
#: The example's closed loop ends this close to the path [m].
REACHED_M = 0.1


def readme_python_block(root=ROOT):
    text = (pathlib.Path(root) / "README.md").read_text()
    return text.split("```python\n", 1)[1].split("```", 1)[0]


def run_readme_python_block(python, cwd, env=None, root=ROOT):
    """Runs the block with `python` in `cwd` (which holds vehicles/); returns the lateral error it
    prints, after checking that it ran and reached the path."""
    result = subprocess.run([str(python), "-c", readme_python_block(root)], cwd=cwd, env=env,
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    error = float(result.stdout.split()[0])
    assert abs(error) < REACHED_M, result.stdout
    return error


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--python", required=True, help="the interpreter that imports smoothsteer")
    parser.add_argument("--cwd", required=True, help="directory to run in; holds vehicles/")
    arguments = parser.parse_args()
    error = run_readme_python_block(arguments.python, arguments.cwd)
    print(f"README Python example: lateral error {error:.2e} m (< {REACHED_M} m)")


if __name__ == "__main__":
    sys.exit(main())
