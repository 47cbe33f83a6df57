"""Example 7: compare controllers on the 15 m/s lane change: the scenario's certified lead-wheel
controller and every comparison controller (docs/baselines.md) on the same kinetic car and
actuator, run in parallel threads (run_scenario releases the GIL).
`smoothsteer compare lane-change` makes the full table (docs/results/).
"""
from concurrent.futures import ThreadPoolExecutor

import smoothsteer as ss


def run(name):
    overrides = {"controller": {"type": name, "nominal_speed_mps": 15}} if name else {}
    return ss.run_scenario("scenarios/lane_change_15.yaml", overrides)[1]


with ThreadPoolExecutor(max_workers=2) as pool:
    summaries = list(pool.map(run, [None] + ss.comparison_controller_names()))
print(f"{'controller':22} {'max |e| [m]':>12} {'max rate [rad/s]':>16} {'rate > 0.4 [%]':>14}")
for summary in summaries:
    m = summary["metrics"]
    print(f"{summary['controller']:22} {m['max_abs_rear_error_m']:12.3f} "
          f"{m['held_rate_max_radps']:16.3f} {100 * m['held_rate_violations'] / m['steps']:14.1f}")
