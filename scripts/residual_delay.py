#!/usr/bin/python3
"""The Smith delay that the linear model asks for (docs/vehicle_dynamics.md, section 7).

The feedforward inverts the linear single-track model (section 3 of that document: preview
d = (K_f + K_r) v^2 / g, gain g, second-order term c); what it leaves, together with the 10 Hz
third-order actuator and the zero-order hold of the 20 ms control period, is a lag between the
curvature the law asks for and the curvature the rear axle runs on. This script computes that lag
in two ways, from the vehicle file's linear model (cornering stiffness B C mu F_z from the Magic
Formula coefficients, Rajamani ch. 2-3):

* the group delay at low frequency, -d arg P(j w) / d w at w -> 0, where
  P = (single-track response) x (its inversion) x (actuator) x (hold);
* the pure delay that best matches P applied to the curvature each shipped lane change's rear axle
  meets (least squares over the run, read from the CLI's trace), and, with --run, the files'
  figures at that delay against their hand-set 0.048 s.

    /usr/bin/python3 scripts/residual_delay.py [--cli build/ci/apps/smoothsteer] [--run]
"""
import argparse
import csv
import json
import math
import os
import subprocess
import tempfile

import numpy as np
import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GRAVITY = 9.81
CONTROL_PERIOD_S = 0.02
ACTUATOR_BANDWIDTH_HZ = 10.0
# (scenario, speed [m/s], whether the file keeps the second-order term c)
LANE_CHANGES = [("lane_change_10", 10.0, True), ("lane_change_15", 15.0, True),
                ("lane_change_19", 19.0, False)]


class LinearSingleTrack:
    """The vehicle file's linear single-track model and the feedforward's inversion of it."""

    def __init__(self, vehicle_file):
        car = yaml.safe_load(open(vehicle_file))
        self.m, self.iz = car["mass_kg"], car["yaw_inertia_kgm2"]
        self.lf, self.lr = car["cg_to_front_axle_m"], car["cg_to_rear_axle_m"]
        self.wheelbase = self.lf + self.lr

        def stiffness(tire, load_share):
            return (tire["stiffness_factor_b"] * tire["shape_factor_c"] * tire["friction_mu"] *
                    self.m * GRAVITY * load_share)

        self.cf = stiffness(car["front_tire"], self.lr / self.wheelbase)
        self.cr = stiffness(car["rear_tire"], self.lf / self.wheelbase)
        # Slip gradients, docs/vehicle_dynamics.md section 3.
        self.kf = self.m * self.lr / (self.wheelbase * self.cf)
        self.kr = self.m * self.lf / (self.wheelbase * self.cr)

    def curvature_response(self, s, v):
        """Rear axle's course curvature per steering angle, (r + d beta_r / dt) / v."""
        m, iz, lf, lr, cf, cr = self.m, self.iz, self.lf, self.lr, self.cf, self.cr
        a = np.array([[-(cf + cr) / (m * v), -v - (cf * lf - cr * lr) / (m * v)],
                      [-(cf * lf - cr * lr) / (iz * v), -(cf * lf**2 + cr * lr**2) / (iz * v)]])
        b = np.array([cf / m, cf * lf / iz])
        lateral_velocity, yaw_rate = np.linalg.solve(s * np.eye(2) - a, b)
        return (yaw_rate + s * (lateral_velocity - lr * yaw_rate) / v) / v

    def inversion(self, s, v, second_order):
        """Steering per path curvature that the feedforward commands (section 3)."""
        gain = 1.0 + (self.kf - self.kr) * v**2 / self.wheelbase
        preview = (self.kf + self.kr) * v**2 / gain
        c = self.kf * self.kr * v**4 - ((self.kf + self.kr) * v**2)**2 / (2.0 * gain)
        return self.wheelbase * (gain * np.exp(s * preview / v) +
                                 (c * s**2 / v**2 if second_order else 0.0))


def actuator_pole():
    """The scenarios' third-order low-pass (src/vehicle/steering_actuator.cpp)."""
    return 2.0 * math.pi * ACTUATOR_BANDWIDTH_HZ / math.sqrt(2.0 ** (1.0 / 3.0) - 1.0)


def actuator(s):
    return (actuator_pole() / (s + actuator_pole())) ** 3


def hold(s):
    return (1.0 - np.exp(-s * CONTROL_PERIOD_S)) / (s * CONTROL_PERIOD_S)


def chain(model, s, v, second_order):
    """P: path curvature to the rear axle's curvature through inversion, hold, actuator, car."""
    return (model.curvature_response(s, v) * model.inversion(s, v, second_order) * actuator(s) *
            hold(s))


def group_delay(model, v, second_order, frequency_hz=0.0, step=1e-4):
    w = max(2.0 * math.pi * frequency_hz, 2.0 * step)
    phase = [np.angle(chain(model, 1j * x, v, second_order)) for x in (w - step, w + step)]
    return -(phase[1] - phase[0]) / (2.0 * step)


def fitted_delay(model, v, second_order, curvature, dt, delays=np.arange(0.0, 0.1, 0.0005)):
    """Pure delay that best matches P applied to a sampled curvature signal (least squares)."""
    n = 4 * len(curvature)
    spectrum = np.fft.rfft(curvature, n)
    w = 2.0 * math.pi * np.fft.rfftfreq(n, dt)
    response = np.array([chain(model, 1j * x, v, second_order) if x > 0 else 1.0 for x in w])
    response /= abs(chain(model, 1e-6j, v, second_order))
    errors = [np.sum(abs(spectrum * response - spectrum * np.exp(-1j * w * tau))**2)
              for tau in delays]
    return float(delays[int(np.argmin(errors))])


def run(cli, scenario, overrides=()):
    out = tempfile.mkdtemp(prefix="smoothsteer_delay_")
    args = [cli, "run", os.path.join(ROOT, "scenarios", scenario + ".yaml"), "--out", out]
    for override in overrides:
        args += ["--set", override]
    subprocess.run(args, check=True, capture_output=True)
    rows = list(csv.DictReader(open(os.path.join(out, "trace.csv"))))
    metrics = json.load(open(os.path.join(out, "summary.json")))["metrics"]
    return rows, metrics


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=os.path.join(ROOT, "build/ci/apps/smoothsteer"))
    parser.add_argument("--run", action="store_true", help="also run the files at that delay")
    args = parser.parse_args()
    model = LinearSingleTrack(os.path.join(ROOT, "vehicles/passenger_car.yaml"))
    print(f"low-frequency delay: {group_delay(model, 15.0, True):.4f} s (actuator "
          f"{3.0 / actuator_pole():.4f} s + half the control period {CONTROL_PERIOD_S / 2:.4f} s)")
    print("| scenario | delay at 0.5 / 1 Hz | fitted on the run's curvature | max abs e there | "
          "at the file's 0.048 s |")
    print("|---|---|---|---|---|")
    for scenario, v, second_order in LANE_CHANGES:
        rows, metrics = run(args.cli, scenario)
        time = np.array([float(r["t"]) for r in rows])
        curvature = np.array([float(r["path_kappa"]) for r in rows])
        delay = fitted_delay(model, v, second_order, curvature, time[1] - time[0])
        at_frequency = " / ".join(f"{group_delay(model, v, second_order, f):.4f}" for f in (0.5, 1.0))
        there = "-"
        if args.run:
            _, at_delay = run(args.cli, scenario, [f"controller.actuator_delay_s={delay}"])
            there = f"{at_delay['max_abs_rear_error_m']:.3f} m"
        print(f"| {scenario} | {at_frequency} s | {delay:.4f} s | {there} | "
              f"{metrics['max_abs_rear_error_m']:.3f} m |")


if __name__ == "__main__":
    main()
