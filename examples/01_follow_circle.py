"""Example 1: the C^1 controller (n = 2) drives a kinematic car onto a circle (the README loop).

Run from the repository root: PYTHONPATH=build/release/python /usr/bin/python3 examples/01_follow_circle.py
"""
import smoothsteer as ss

path = ss.Path.circle((0.0, 0.0), 30.0)
controller = ss.LeadWheelController(ss.ControllerParameters(), path)  # n = 2, SI units
car = ss.KinematicSingleTrack(2.7)
position, heading = (-50.0, 20.0), 1.0
for k in range(3000):  # 60 s at 50 Hz, 8 m/s
    out = controller.update(position, heading, 8.0, 0.0, 0.02)
    position, heading = car.step(position, heading, out.steering_angle_rad, 8.0, 0.02)
print(f"e = {out.diagnostics.lateral_error_m:.4f} m, delta = {out.steering_angle_rad:.4f} rad, "
      f"rate = {out.steering_rate_radps:.4f} rad/s")
