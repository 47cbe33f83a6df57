#!/usr/bin/env bash
# Builds smoothsteer (Release) and runs the demo: the passenger car's SteeringSystem, built from
# vehicles/passenger_car.yaml and its actuator, on the kinetic model over a lane change and a
# curve, started off the path. It prints the car's steering limits beside the held command's
# maxima, writes build/release/demo_trace.csv and draws build/release/demo_trace.png (path and
# trajectory, lateral error, steering angle, rate and acceleration against the car's limits).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j"$(nproc)" --target smoothsteer_demo
./build/release/apps/smoothsteer_demo build/release/demo_trace.csv
/usr/bin/python3 scripts/plot_trace.py build/release/demo_trace.csv build/release/demo_trace.png
