"""Example 8: a car's steering system, from its vehicle file to a running loop. The system is
built once from what is known about the car (vehicles/passenger_car.yaml and its steering
actuator) and the path: the certified schedule, the Smith predictor, the single-track inversion
and the side-slip observer. Every period the loop hands it what the car's buses and localization
give (rear-axle pose, speed, dv/dt, yaw rate, lateral acceleration, the measured steering angle)
and sends the command to the actuator. The car here is a stand-in: the kinematic single-track
model behind a first-order steering lag, with a gyro and an accelerometer that read its motion.
"""
import math
import sys

import numpy as np

import smoothsteer as ss

car = ss.VehicleDescription(
    vehicle=ss.VehicleParameters.from_file("vehicles/passenger_car.yaml"),
    actuator=ss.ActuatorParameters(bandwidth_hz=10.0, dead_time_s=0.0))
path = ss.Path.from_waypoints(
    np.array([[0, 0], [30, 0], [60, 3.5], [90, 3.5], [120, 0], [160, 0]], dtype=float))
system = ss.make_steering_system(car, path, ss.SteeringSystemOptions(max_speed_mps=15.0))

wheelbase = car.vehicle.wheelbase_m
stand_in = ss.KinematicSingleTrack(wheelbase)
position, heading, road_wheel_angle = (-10.0, 0.8), 0.0, 0.0
speed, period = 12.0, 0.02
for k in range(751):
    yaw_rate = speed * math.tan(road_wheel_angle) / wheelbase  # the gyro
    out = system.update(position, heading, speed, yaw_rate_radps=yaw_rate,
                        lateral_acceleration_mps2=speed * yaw_rate, period_s=period,
                        steering_angle_rad=road_wheel_angle)
    if k % 100 == 0:
        print(f"t {k * period:5.2f} s  e {out.tracking.lateral_error_m:+.3f} m  "
              f"delta {out.steering_angle_rad:+.4f} rad  "
              f"beta_r {out.side_slip.rear_axle_side_slip_rad:+.5f} rad  "
              f"limits {out.active_limit_names}")
    # The actuator follows the command with a 30 ms lag; the car moves on.
    road_wheel_angle += (out.steering_angle_rad - road_wheel_angle) * period / 0.03
    position, heading = stand_in.step(position, heading, road_wheel_angle, speed, period)
sys.exit(0 if abs(out.tracking.lateral_error_m) < 0.1 else 1)
