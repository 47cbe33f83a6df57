"""Example 2: follow a C2 spline through the waypoints of a CSV file ("x,y" per line, metres)
with the kinematic car at 8 m/s. Usage: python3 examples/02_follow_waypoints.py [WAYPOINTS.csv]
"""
import sys

import numpy as np

import smoothsteer as ss

file = sys.argv[1] if len(sys.argv) > 1 else "scenarios/waypoints/s_curve.csv"
waypoints = np.loadtxt(file, delimiter=",", comments="#", skiprows=2)  # header "x,y"
path = ss.Path.from_waypoints(waypoints)
controller = ss.LeadWheelController(ss.ControllerParameters(), path)
car = ss.KinematicSingleTrack(2.7)
position, heading = (0.0, -2.0), 0.3  # 2 m right of the first waypoint
errors, k = [], 0
while True:
    out = controller.update(position, heading, 8.0, 0.0, 0.02)
    position, heading = car.step(position, heading, out.steering_angle_rad, 8.0, 0.02)
    if k * 0.02 > 5.0:
        errors.append(abs(out.diagnostics.lateral_error_m))
    k += 1
    if out.diagnostics.path_arc_length_m >= path.length_m:
        break
print(f"{len(waypoints)} waypoints, path {path.length_m:.1f} m: "
      f"max |e| after 5 s = {max(errors):.3f} m")
