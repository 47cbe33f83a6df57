#!/usr/bin/env bash
# Builds smoothsteer (Release) and runs the demo: a closed loop from 40 m away, facing away from
# the path, onto a curved path. Writes build/release/demo_trace.csv.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j"$(nproc)" --target smoothsteer_demo
./build/release/apps/smoothsteer_demo build/release/demo_trace.csv
