"""Example 3: tune for your car and drive the schedule. The car's steering limits (vehicle YAML)
and the path's curvature give certified parameters over speed (docs/tuning.md); the scheduled
controller then drives a 40 m circle while the car speeds up from 5 to 15 m/s.
"""
import numpy as np

import smoothsteer as ss

car = ss.VehicleLimits.from_file("vehicles/passenger_car.yaml")
path = ss.Path.circle((0.0, 0.0), 40.0)
schedule = ss.tune(car, np.arange(1.0, 15.5, 1.0), path=path,
                   max_longitudinal_acceleration_mps2=0.5)  # a dict of numpy arrays
controller = ss.ScheduledController(schedule.gain_schedule, path)

model = ss.KinematicSingleTrack(car.wheelbase_m)
position, heading = (40.0, -1.0), np.pi / 2  # 1 m outside the circle, along it
rates, accelerations, late_errors = [], [], []
for k in range(2500):  # 50 s at 50 Hz
    speed = min(15.0, 5.0 + 0.5 * k * 0.02)  # 0.5 m/s^2 ramp
    out = controller.update(position, heading, speed, 0.5 if speed < 15.0 else 0.0, 0.02)
    position, heading = model.step(position, heading, out.steering_angle_rad, speed, 0.02)
    rates.append(abs(out.steering_rate_radps))
    accelerations.append(abs(out.steering_acceleration_radps2))
    if k > 1500:
        late_errors.append(abs(out.diagnostics.lateral_error_m))
kbar = schedule["lead_curvature_bound"]
print(f"schedule: {len(kbar)} speeds up to {schedule['speed_mps'][-1]:.0f} m/s, "
      f"kbar_l {kbar.min():.4f} .. {kbar.max():.4f} 1/m")
print(f"max |rate| {max(rates):.3f} rad/s (car {car.max_steering_rate_radps:.1f}), "
      f"max |acc| {max(accelerations):.2f} rad/s^2 (car {car.max_steering_acceleration_radps2:.1f}), "
      f"|e| at 15 m/s <= {max(late_errors):.3f} m")
assert max(rates) <= car.max_steering_rate_radps
