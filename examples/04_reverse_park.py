"""Example 4: reverse and park. A parallel-parking plan of three pieces (reverse S into the slot,
forward, reverse) meets at two cusps; CuspSequencer hands each piece to the controller and
brakes to a standstill at every cusp (docs/cusps.md).
"""
import math

import smoothsteer as ss

turn = math.acos(1.0 - 2.5 / (2.0 * 8.0))  # S of two 8 m arcs, 2.5 m sideways
back_in = ss.PathBuilder((0.0, 0.0), math.pi).line(3.0).arc(8.0, turn).arc(8.0, -turn).line(6.0).build()
slot = back_in.evaluate(back_in.length_m).position
forward = ss.PathBuilder(slot, 0.0).line(6.0).build()
back = ss.PathBuilder((slot[0] + 6.0, slot[1]), math.pi).line(8.0).build()
plan = ss.PathPlan.from_pieces([(back_in, ss.Gear.reverse), (forward, ss.Gear.forward),
                                (back, ss.Gear.reverse)])

controller = ss.LeadWheelController(ss.ControllerParameters(), back_in)
sequencer = ss.CuspSequencer(plan, controller)  # cruise 1.5 m/s, braking 0.5 m/s^2
car = ss.KinematicSingleTrack(2.7)
position, heading, t = (0.0, 0.0), 0.0, 0.0  # facing +x, about to reverse along -x
while t < 120.0 and not sequencer.finished:
    speed = sequencer.speed_command(position, 0.02)  # signed: < 0 reverses
    out = controller.update(position, heading, speed, 0.0, 0.02)
    position, heading = car.step(position, heading, out.steering_angle_rad, speed, 0.02)
    t += 0.02
goal = plan.final_position
position_error = math.hypot(position[0] - goal[0], position[1] - goal[1])
heading_error = abs(math.remainder(heading - plan.final_vehicle_heading_rad, 2 * math.pi))
print(f"parked after {t:.1f} s through {plan.cusp_count} cusps: position error "
      f"{position_error:.3f} m, heading error {heading_error:.4f} rad")
assert sequencer.finished and position_error < 0.05
