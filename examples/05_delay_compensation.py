"""Example 5: delay compensation. The 15 m/s lane change with 50 ms of dead time in front of the
steering actuator, once without and once with the controller's delay compensation
(controller.actuator_delay_s, a Smith predictor on the kinematic model).
"""
import numpy as np

import smoothsteer as ss

for delay in (0.0, 0.05):
    trace, summary = ss.run_scenario("scenarios/lane_change_15.yaml",
                                     {"actuator.dead_time_s": 0.05,
                                      "controller.actuator_delay_s": delay})
    print(f"dead time 50 ms, actuator_delay_s = {delay:<4} s: max |e| "
          f"{np.abs(trace['e']).max():.3f} m, stop: {summary['stop_reason']}")
