"""Example 6: replanning. The car follows a straight lane at 10 m/s; after 5 s the planner moves
the path 3.5 m to the left (a new lane) and set_path() swaps it in between two update() calls.
The command stays continuous: no jump in delta (docs/replanning.md).
"""
import smoothsteer as ss

lane = ss.Path.straight_line((0.0, 0.0), 0.0, 400.0)
next_lane = ss.Path.straight_line((0.0, 3.5), 0.0, 400.0)
controller = ss.LeadWheelController(ss.ControllerParameters(), lane)
car = ss.KinematicSingleTrack(2.7)
position, heading = (0.0, 0.0), 0.0
largest_step, previous = 0.0, 0.0
for k in range(1000):  # 20 s at 50 Hz
    if k == 250:  # t = 5 s
        controller.set_path(next_lane)
    out = controller.update(position, heading, 10.0, 0.0, 0.02)
    position, heading = car.step(position, heading, out.steering_angle_rad, 10.0, 0.02)
    largest_step = max(largest_step, abs(out.steering_angle_rad - previous))
    previous = out.steering_angle_rad
print(f"after the swap: y = {position[1]:.3f} m (new lane at 3.5 m), largest change of delta "
      f"per period {largest_step:.4f} rad")
assert abs(position[1] - 3.5) < 0.05
