#!/usr/bin/env bash
# The installed-package test of the Python package (docs/python.md, "Install, build, import"):
# pip installs a copy of this checkout (the files git tracks or would track, so the tree gets no
# _skbuild/ or egg-info) into a fresh venv with the system site packages (numpy, matplotlib from
# Debian), then, from a directory outside the tree, imports smoothsteer from that venv and runs
# the README's Python example (python/tests/readme_example.py). scikit-build builds the
# libraries and the module only, in Release, on every core. Prints the time each step took.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir "$work/source" "$work/outside"
git ls-files -z --cached --others --exclude-standard | xargs -0 cp --parents -t "$work/source"
cp -r vehicles "$work/outside/"  # the example reads vehicles/passenger_car.yaml

SECONDS=0
/usr/bin/python3 -m venv --system-site-packages "$work/venv"
export CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)}"
"$work/venv/bin/python" -m pip install --no-build-isolation --no-deps --quiet "$work/source"
echo "python package: built and installed in ${SECONDS} s"

location="$(cd "$work/outside" && "$work/venv/bin/python" -c \
  'import smoothsteer; print(smoothsteer.__file__)')"
if [[ "$location" != "$work/venv/"* ]]; then
  echo "python package: imported $location, not the venv's package" >&2
  exit 1
fi
/usr/bin/python3 python/tests/readme_example.py --python "$work/venv/bin/python" --cwd "$work/outside"
echo "python package: 1 passed, 0 failed (imported from $location)"
