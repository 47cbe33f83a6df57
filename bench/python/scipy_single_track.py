#!/usr/bin/python3
"""The user's alternative, measured in one run: the same dynamic single-track model as
src/vehicle/vehicle_model.cpp (Pacejka lateral forces, kinematic blend at low speed), written in
Python and integrated with scipy.integrate.odeint at the tolerance of the C++ adaptive
integrator, restarted at every control period like it. The steering input is the actuator output
of a C++ run: between control instants the cubic Hermite interpolant of its delta_actual and
delta_actual_rate columns (C^1, like the actuator's output); the longitudinal acceleration is its
`a` column; both start from the first row of that trace. The C++ run uses the default plant
integrator (dopri5, docs/simulation.md) at the same tolerance.

Usage (repository root, after a Release build):
  /usr/bin/python3 bench/python/scipy_single_track.py [SCENARIO.yaml] [--tolerance 1e-6]
Prints model evaluations and time per control step of both, and how far apart the final poses
are (the Python run sees the steering only through its values and rates at the control instants).
Needs python3-numpy and python3-scipy (Debian).
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.integrate import odeint


def lateral_force(tire, slip, load):
    b_alpha = tire["stiffness_factor_b"] * slip
    inner = b_alpha - tire["curvature_factor_e"] * (b_alpha - math.atan(b_alpha))
    return tire["friction_mu"] * load * math.sin(tire["shape_factor_c"] * math.atan(inner))


def make_model(p):
    lf, lr, m, iz, g = (p["cg_to_front_axle_m"], p["cg_to_rear_axle_m"], p["mass_kg"],
                        p["yaw_inertia_kgm2"], p["gravity_mps2"])
    wheelbase = lf + lr
    front_load, rear_load = m * g * lr / wheelbase, m * g * lf / wheelbase
    below, above, relax = p["kinematic_below_mps"], p["kinetic_above_mps"], p["kinematic_relaxation_s"]
    counter = [0]

    def derivative(y, t, delta_of, ax):
        counter[0] += 1
        x, yy, psi, vx, vy, r = y
        delta = delta_of(t)
        c, s = math.cos(psi), math.sin(psi)
        w = min(max((vx - below) / (above - below), 0.0), 1.0)
        dvy = dr = 0.0
        if w > 0.0:
            vxs = max(vx, below)
            alpha_f = delta - math.atan2(vy + lf * r, vxs)
            alpha_r = -math.atan2(vy - lr * r, vxs)
            fyf = lateral_force(p["front_tire"], alpha_f, front_load)
            fyr = lateral_force(p["rear_tire"], alpha_r, rear_load)
            cd = math.cos(delta)
            dvy += w * ((fyr + fyf * cd) / m - vx * r)
            dr += w * (lf * fyf * cd - lr * fyr) / iz
        if w < 1.0:
            kr = vx * math.tan(delta) / wheelbase
            dvy += (1.0 - w) * (lr * kr - vy) / relax
            dr += (1.0 - w) * (kr - r) / relax
        return [vx * c - vy * s, vx * s + vy * c, r, ax, dvy, dr]

    return derivative, counter


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("scenario", nargs="?", default="scenarios/lane_change_15.yaml")
    parser.add_argument("--tolerance", type=float, default=1e-6)
    parser.add_argument("--cli", default="build/release/apps/smoothsteer")
    args = parser.parse_args()
    if not os.path.exists(args.cli):
        args.cli = "build/ci/apps/smoothsteer"
    with tempfile.TemporaryDirectory() as scratch:
        out = os.path.join(scratch, "run")
        started = time.perf_counter()
        subprocess.run([args.cli, "run", args.scenario, "--out", out, "--set",
                        f"simulation.integrator_tolerance={args.tolerance}"],
                       check=True, stdout=subprocess.DEVNULL)
        cli_seconds = time.perf_counter() - started
        summary = json.load(open(os.path.join(out, "summary.json")))
        with open(os.path.join(out, "trace.csv"), newline="") as handle:
            rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(handle)]
    vehicle = summary["parameters"]["vehicle"]
    if summary["model"] != "dynamic":
        sys.exit("the comparison needs a scenario with the dynamic model")
    derivative, counter = make_model(vehicle)
    lr = vehicle["cg_to_rear_axle_m"]
    first = rows[0]
    y = np.array([first["x"] + lr * math.cos(first["psi"]), first["y"] + lr * math.sin(first["psi"]),
                  first["psi"], first["v"], first["vy"], first["yaw_rate"]])
    started = time.perf_counter()
    for k in range(len(rows) - 1):
        t0, t1 = rows[k]["t"], rows[k + 1]["t"]
        d0, d1 = rows[k]["delta_actual"], rows[k + 1]["delta_actual"]
        r0, r1 = rows[k]["delta_actual_rate"], rows[k + 1]["delta_actual_rate"]

        def delta_of(t, t0=t0, t1=t1, d0=d0, d1=d1, r0=r0, r1=r1):
            h = t1 - t0
            u = (t - t0) / h
            return ((2 * u**3 - 3 * u**2 + 1) * d0 + (u**3 - 2 * u**2 + u) * h * r0
                    + (-2 * u**3 + 3 * u**2) * d1 + (u**3 - u**2) * h * r1)

        y = odeint(derivative, y, [t0, t1], args=(delta_of, rows[k]["a"]),
                   atol=args.tolerance, rtol=0.0)[-1]  # absolute, like the C++ integrators
    python_seconds = time.perf_counter() - started
    steps = len(rows) - 1
    last = rows[-1]
    rear = (y[0] - lr * math.cos(y[2]), y[1] - lr * math.sin(y[2]))
    gap = math.hypot(rear[0] - last["x"], rear[1] - last["y"])
    print(f"scenario {summary['scenario']}: {steps} control steps, tolerance {args.tolerance:g}")
    print(f"  C++ {summary['parameters']['simulation']['integrator']} "
          f"(whole run incl. controller, file output): "
          f"{summary['model_evaluations'] / summary['metrics']['steps']:.1f} model evaluations/step, "
          f"{1e6 * cli_seconds / steps:.1f} us/step (process wall time)")
    print(f"  Python + scipy odeint (plant only): {counter[0] / steps:.1f} model evaluations/step, "
          f"{1e6 * python_seconds / steps:.1f} us/step")
    print(f"  final rear-axle position apart by {gap * 1000:.2f} mm, heading by "
          f"{abs(y[2] - last['psi']):.2e} rad")


if __name__ == "__main__":
    main()
