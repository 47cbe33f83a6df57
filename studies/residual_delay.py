#!/usr/bin/python3
"""The Smith delay that the linear model asks for (docs/vehicle_dynamics.md, section 7).

The feedforward inverts the linear single-track model (section 3 of that document: preview
d = (K_f + K_r) v^2 / g, gain g, second-order term c); what it leaves, together with the
scenario's third-order actuator and the zero-order hold of its control period, is a lag between
the curvature the law asks for and the curvature the rear axle runs on. This script computes that
lag in two ways, from each shipped lane change's resolved parameters (its vehicle, actuator,
control period, speed and `slip_preview_second_order`; cornering stiffness B C mu F_z from the
Magic Formula coefficients, Rajamani ch. 2-3):

* the group delay at low frequency, -d arg P(j w) / d w at w -> 0, where
  P = (single-track response) x (its inversion) x (actuator) x (hold);
* the pure delay that best matches P applied to the curvature the rear axle meets in the run
  (least squares), and, with --run, the file's figure at that delay against its own
  `actuator_delay_s`.

    PYTHONPATH=build/ci/python /usr/bin/python3 studies/residual_delay.py [--run]
"""
import argparse
import math

import numpy as np

LANE_CHANGES = ["lane_change_10", "lane_change_15", "lane_change_19"]


class LinearSingleTrack:
    """A vehicle's linear single-track model and the feedforward's inversion of it, from the
    resolved `vehicle` parameters of a scenario (smoothsteer.load_scenario(...).parameters)."""

    def __init__(self, vehicle):
        self.m, self.iz = vehicle["mass_kg"], vehicle["yaw_inertia_kgm2"]
        self.lf, self.lr = vehicle["cg_to_front_axle_m"], vehicle["cg_to_rear_axle_m"]
        self.wheelbase = self.lf + self.lr

        def stiffness(tire, load_share):
            return (tire["stiffness_factor_b"] * tire["shape_factor_c"] * tire["friction_mu"] *
                    self.m * vehicle["gravity_mps2"] * load_share)

        self.cf = stiffness(vehicle["front_tire"], self.lr / self.wheelbase)
        self.cr = stiffness(vehicle["rear_tire"], self.lf / self.wheelbase)
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


class Loop:
    """Inversion, hold, actuator and car at one speed: the transfer P of the module docstring."""

    def __init__(self, model, parameters):
        """parameters: a scenario's resolved parameters (speed, actuator, simulation, controller)."""
        self.model = model
        self.speed = parameters["speed"]["initial_mps"]
        self.second_order = parameters["controller"]["slip_preview_second_order"]
        self.period = parameters["simulation"]["control_period_s"]
        # The third-order low-pass of src/vehicle/steering_actuator.cpp.
        self.pole = (2.0 * math.pi * parameters["actuator"]["bandwidth_hz"] /
                     math.sqrt(2.0 ** (1.0 / 3.0) - 1.0))

    def response(self, s):
        hold = (1.0 - np.exp(-s * self.period)) / (s * self.period)
        actuator = (self.pole / (s + self.pole)) ** 3
        return (self.model.curvature_response(s, self.speed) *
                self.model.inversion(s, self.speed, self.second_order) * actuator * hold)

    def group_delay(self, frequency_hz=0.0, step=1e-4):
        w = max(2.0 * math.pi * frequency_hz, 2.0 * step)
        phase = [np.angle(self.response(1j * x)) for x in (w - step, w + step)]
        return -(phase[1] - phase[0]) / (2.0 * step)

    def fitted_delay(self, curvature, dt, delays=np.arange(0.0, 0.1, 0.0005)):
        """Pure delay that best matches P applied to a sampled curvature signal (least squares)."""
        n = 4 * len(curvature)
        spectrum = np.fft.rfft(curvature, n)
        w = 2.0 * math.pi * np.fft.rfftfreq(n, dt)
        response = np.array([self.response(1j * x) if x > 0 else 1.0 for x in w])
        response /= abs(self.response(1e-6j))
        errors = [np.sum(abs(spectrum * response - spectrum * np.exp(-1j * w * tau))**2)
                  for tau in delays]
        return float(delays[int(np.argmin(errors))])


def main():
    import smoothsteer  # the built module (PYTHONPATH=build/ci/python)

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument("--run", action="store_true", help="also run the files at that delay")
    args = parser.parse_args()
    print("| scenario | low-frequency delay (actuator + half the period) | delay at 0.5 / 1 Hz | "
          "fitted on the run's curvature | max abs e there | at the file's own delay |")
    print("|---|---|---|---|---|---|")
    for scenario in LANE_CHANGES:
        file = f"scenarios/{scenario}.yaml"
        parameters = smoothsteer.load_scenario(file).parameters
        loop = Loop(LinearSingleTrack(parameters["vehicle"]), parameters)
        trace, summary = smoothsteer.run_scenario(file)
        delay = loop.fitted_delay(trace["path_kappa"], loop.period)
        low = (f"{loop.group_delay():.4f} s ({3.0 / loop.pole:.4f} + {loop.period / 2:.4f} s)")
        at_frequency = " / ".join(f"{loop.group_delay(f):.4f}" for f in (0.5, 1.0))
        there = "-"
        if args.run:
            _, at_delay = smoothsteer.run_scenario(file, [f"controller.actuator_delay_s={delay}"])
            there = f"{at_delay['metrics']['max_abs_rear_error_m']:.3f} m"
        own = parameters["controller"]["actuator_delay_s"]
        print(f"| {scenario} | {low} | {at_frequency} s | {delay:.4f} s | {there} | "
              f"{summary['metrics']['max_abs_rear_error_m']:.3f} m at {own} s |")


if __name__ == "__main__":
    main()
