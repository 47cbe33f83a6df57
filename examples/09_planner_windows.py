"""Example 9: the car's steering system driven as a driving stack drives it. It is built once
from the car alone (no path at set-up); a planner sends a window of waypoints every 0.1 s (5 m
behind the car to 100 m ahead, 1 m apart, here with 2 cm of Gaussian jitter, as planners and
recordings deliver them), and set_waypoints() fits each window at the jitter it reads from the
windows, pooled over them, before it replaces the path. The car is the kinematic single-track
model behind a first-order steering lag; it has no tire slip, which the system, built for the
car's tires, partly steers for: with clean windows the S costs 0.08 m, with 2 cm of jitter 0.11.
"""
import math
import sys

import numpy as np

import smoothsteer as ss

car = ss.VehicleDescription(
    vehicle=ss.VehicleParameters.from_file("vehicles/passenger_car.yaml"),
    actuator=ss.ActuatorParameters(bandwidth_hz=10.0))
system = ss.make_steering_system(car, ss.SteeringSystemOptions(max_speed_mps=20.0))

# The road the planner knows (the system never sees it): an S of two 100 m arcs.
road = (ss.PathBuilder((0.0, 0.0), 0.0).line(50.0).clothoid(30.0, 0.01).arc(100.0, 0.6)
        .clothoid(40.0, -0.01).arc(100.0, -0.6).clothoid(30.0, 0.0).line(250.0).build())
rng = np.random.default_rng(1)

wheelbase = car.vehicle.wheelbase_m
stand_in = ss.KinematicSingleTrack(wheelbase)
position, heading, road_wheel_angle, worst = (0.0, 0.5), 0.0, 0.0, 0.0
speed, period = 15.0, 0.02
for k in range(1001):
    on_road = road.project(position)
    if k % 5 == 0:  # the planner's window, every 0.1 s
        s = np.arange(max(0.0, on_road.arc_length_m - 5.0),
                      min(road.length_m, on_road.arc_length_m + 100.0) + 1e-9, 1.0)
        system.set_waypoints(road.sample(s)[:, :2] + rng.normal(0.0, 0.02, (len(s), 2)))
    yaw_rate = speed * math.tan(road_wheel_angle) / wheelbase
    out = system.update(position, heading, speed, yaw_rate_radps=yaw_rate,
                        lateral_acceleration_mps2=speed * yaw_rate, period_s=period,
                        steering_angle_rad=road_wheel_angle)
    if k >= 150:
        worst = max(worst, abs(on_road.lateral_error_m))
    if k % 200 == 0:
        print(f"t {k * period:5.2f} s  e {on_road.lateral_error_m:+.3f} m (to the road)  "
              f"delta {out.steering_angle_rad:+.4f} rad  "
              f"jitter read {system.waypoint_conditioner.jitter_m:.4f} m")
    road_wheel_angle += (out.steering_angle_rad - road_wheel_angle) * period / 0.03
    position, heading = stand_in.step(position, heading, road_wheel_angle, speed, period)
jitter = system.waypoint_conditioner.jitter_m
print(f"max |e| to the road after 3 s: {worst:.3f} m; the planner's jitter read as {jitter:.4f} m")
sys.exit(0 if worst < 0.15 and abs(jitter / 0.02 - 1.0) < 0.25 else 1)
