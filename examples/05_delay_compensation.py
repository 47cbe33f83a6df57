"""Example 5: delay compensation. The 15 m/s lane change with 50 ms of dead time in front of the
steering actuator, once without the controller's delay compensation (no Smith predictor) and
once with it: the file's derived_compensation takes the actuator block's dead time into the
Smith predictor's delay, with the low-pass's group delay and the tires' lag over speed.
"""
import numpy as np

import smoothsteer as ss

for label, overrides in (("without", {"controller.derived_compensation": False}), ("with", {})):
    trace, summary = ss.run_scenario("scenarios/lane_change_15.yaml",
                                     {"actuator.dead_time_s": 0.05, **overrides})
    print(f"dead time 50 ms, {label:<7} delay compensation: max |e| "
          f"{np.abs(trace['e']).max():.3f} m, stop: {summary['stop_reason']}")
