#!/usr/bin/python3
"""The double-track model written again in Python from its documented equations
(include/smoothsteer/vehicle/double_track.hpp, docs/simulation.md), integrated by scipy's
Dormand-Prince 5(4) (solve_ivp RK45) at the C++ default's absolute tolerance 1e-6, against the
C++ closed loop (docs/benchmarks.md, "Double-track model"). One run:

1. `smoothsteer run SCENARIO --set model=double_track` (default lane_change_15, 10 s);
2. the same 10 s open loop in Python, fed the actuator angle the C++ run recorded (cubic
   interpolation of its 50 Hz samples; the actuator's output is C^2);
3. prints the wall time of both and the largest differences of yaw rate, lateral velocity and
   rear-axle position (the second implementation agreeing is a check of the first; the inputs
   differ by the interpolation).

    /usr/bin/python3 bench/python/double_track_scipy.py [--cli build/ci/apps/smoothsteer]
"""
import argparse
import csv
import json
import math
import os
import subprocess
import tempfile
import time

import numpy as np
from scipy.integrate import solve_ivp
from scipy.interpolate import CubicSpline

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def magic_formula(tire, alpha, load):
    b, c, e = tire["stiffness_factor_b"], tire["shape_factor_c"], tire["curvature_factor_e"]
    x = b * alpha
    return tire["friction_mu"] * load * math.sin(c * math.atan(x - e * (x - math.atan(x))))


class DoubleTrack:
    """Same equations as DoubleTrack (double_track.hpp), acceleration input, parallel steer."""

    def __init__(self, v):
        self.v, self.d = v, v["double_track"]
        self.m, self.h, self.g = v["mass_kg"], v["cg_height_m"], v.get("gravity_mps2", 9.81)
        self.lf, self.lr = v["cg_to_front_axle_m"], v["cg_to_rear_axle_m"]
        self.L = self.lf + self.lr
        tf, tr = self.d["front_track_m"], self.d["rear_track_m"]
        self.x = [self.lf, self.lf, -self.lr, -self.lr]
        self.y = [tf / 2, -tf / 2, tr / 2, -tr / 2]
        front = self.m * self.g * self.lr / self.L / 2
        rear = self.m * self.g * self.lf / self.L / 2
        self.static = [front, front, rear, rear]
        self.i_phi = self.d["roll_inertia_kgm2"] + self.m * self.h ** 2
        self.k_phi = self.d["front_roll_stiffness_nmprad"] + self.d["rear_roll_stiffness_nmprad"]
        self.d_phi = self.d["front_roll_damping_nmsprad"] + self.d["rear_roll_damping_nmsprad"]

    def forces(self, s, delta, ax):
        X, Y, psi, vx, vy, r, phi, dphi = s
        d, m, h = self.d, self.m, self.h
        angles = [delta, delta, 0.0, 0.0]
        pitch = 0.5 * m * ax * h / self.L
        fr = (d["front_roll_stiffness_nmprad"] * phi + d["front_roll_damping_nmsprad"] * dphi) / d["front_track_m"]
        rr = (d["rear_roll_stiffness_nmprad"] * phi + d["rear_roll_damping_nmsprad"] * dphi) / d["rear_track_m"]
        transfer = [-pitch - fr, -pitch + fr, pitch - rr, pitch + rr]
        fy0, cap = [], []
        for i in range(4):
            load = max(0.0, self.static[i] + transfer[i])
            scale = max(0.0, 1.0 + d["friction_load_sensitivity"] * (load - self.static[i]) / self.static[i])
            eff = load * scale
            cap.append(d["longitudinal_friction_mu"] * eff)
            forward = max(vx - r * self.y[i], self.v["kinematic_below_mps"])
            alpha = angles[i] - math.atan2(vy + r * self.x[i], forward)
            tire = self.v["front_tire"] if i < 2 else self.v["rear_tire"]
            fy0.append(magic_formula(tire, alpha, eff))

        def shares(force):
            f = d["drive_share_front"] if force >= 0 else d["brake_share_front"]
            return [f / 2, f / 2, (1 - f) / 2, (1 - f) / 2]

        def fx_of(share, force, i):
            return min(max(share * force, -cap[i]), cap[i])

        def fy_of(fx, i):
            used = fx / cap[i] if cap[i] > 0 else 1.0
            return fy0[i] * math.sqrt(max(0.0, 1.0 - used * used))

        target = m * (ax - vy * r) + 2 * m * h * math.cos(phi) * dphi * r
        force = target
        for _ in range(2):
            sh = shares(force)
            num = target + sum(fy_of(fx_of(sh[i], force, i), i) * math.sin(angles[i]) for i in range(4))
            den = sum(sh[i] * math.cos(angles[i]) for i in range(4))
            force = num / den
        sh = shares(force)
        fx = [fx_of(sh[i], force, i) for i in range(4)]
        fy = [fy_of(fx[i], i) for i in range(4)]
        return angles, fx, fy

    def derivative(self, s, delta, ax):
        X, Y, psi, vx, vy, r, phi, dphi = s
        m, h, g, iz = self.m, self.h, self.g, self.v["yaw_inertia_kgm2"]
        sp, cp, mh = math.sin(phi), math.cos(phi), m * h
        roll_moment = -self.k_phi * phi - self.d_phi * dphi + m * g * h * sp
        angles, fxw, fyw = self.forces(s, delta, ax)
        fx = fy = n = 0.0
        for i in range(4):
            c, sn = math.cos(angles[i]), math.sin(angles[i])
            bx, by = fxw[i] * c - fyw[i] * sn, fxw[i] * sn + fyw[i] * c
            fx, fy, n = fx + bx, fy + by, n + self.x[i] * by - self.y[i] * bx
        b_x = fx + m * vy * r - 2 * mh * cp * dphi * r
        b_yaw = n + mh * sp * vy * r
        cx = mh * sp
        det_x = m * iz - cx * cx
        b_y = fy - m * vx * r - mh * sp * (dphi * dphi + r * r)
        b_roll = mh * cp * vx * r + roll_moment
        cy = mh * cp
        det_y = m * self.i_phi - cy * cy
        return [vx * math.cos(psi) - vy * math.sin(psi), vx * math.sin(psi) + vy * math.cos(psi), r,
                (b_x * iz - cx * b_yaw) / det_x, (b_y * self.i_phi + cy * b_roll) / det_y,
                (m * b_yaw - cx * b_x) / det_x, dphi, (m * b_roll + cy * b_y) / det_y]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cli", default=os.path.join(ROOT, "build", "ci", "apps", "smoothsteer"))
    parser.add_argument("--scenario", default=os.path.join(ROOT, "scenarios", "lane_change_15.yaml"))
    parser.add_argument("--duration", type=float, default=10.0)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as out:
        command = [args.cli, "run", args.scenario, "--out", out, "--set", "model=double_track",
                   "--set", f"simulation.duration_s={args.duration}"]
        start = time.perf_counter()
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        cpp_wall = time.perf_counter() - start
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        with open(os.path.join(out, "trace.csv")) as f:
            rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    vehicle = summary["parameters"]["vehicle"]
    model = DoubleTrack(vehicle)
    t = np.array([r["t"] for r in rows])
    steering = CubicSpline(t, [r["delta_actual"] for r in rows])
    acceleration = rows[0]["a"]
    r0 = rows[0]
    state0 = [r0["x"] + model.lr * math.cos(r0["psi"]), r0["y"] + model.lr * math.sin(r0["psi"]),
              r0["psi"], r0["v"], r0["vy"], r0["yaw_rate"], 0.0, 0.0]
    start = time.perf_counter()
    solution = solve_ivp(lambda time_s, s: model.derivative(s, float(steering(time_s)), acceleration),
                         (0.0, t[-1]), state0, method="RK45", atol=1e-6, rtol=1e-13, t_eval=t)
    python_wall = time.perf_counter() - start
    X, Y, psi, vx, vy, r = solution.y[:6]
    rear_x, rear_y = X - model.lr * np.cos(psi), Y - model.lr * np.sin(psi)
    print(f"scenario {os.path.basename(args.scenario)}, {t[-1]:.1f} s, model double_track")
    print(f"C++ closed loop (smoothsteer run, dopri5 1e-6, controller and I/O included): "
          f"{cpp_wall:.3f} s wall, {summary['model_evaluations']} evaluations")
    print(f"Python open loop (scipy solve_ivp RK45, atol 1e-6): {python_wall:.3f} s wall, "
          f"{solution.nfev} evaluations ({python_wall / cpp_wall:.0f}x the C++ run's wall time; "
          f"{1e6 * python_wall / solution.nfev:.0f} us per evaluation)")
    print("largest differences Python - C++: yaw rate "
          f"{max(abs(r - [q['yaw_rate'] for q in rows])):.2e} rad/s, lateral velocity "
          f"{max(abs(vy - [q['vy'] for q in rows])):.2e} m/s, rear axle position "
          f"{max(np.hypot(rear_x - [q['x'] for q in rows], rear_y - [q['y'] for q in rows])):.2e} m")


if __name__ == "__main__":
    main()
