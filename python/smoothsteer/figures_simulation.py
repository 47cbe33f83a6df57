"""Figures of the paper's simulations (Sec. IV-A and IV-C): simu, el_comp, parameter_radar,
lanechange. Each runs the project's scenario files (smoothsteer.run_scenario)."""
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import smoothsteer as ss
from ._plotting import controller_label, plt, reference_path, save

# The paper's Sec. IV-A controller: n = 2, kbar_l = 0.2 1/m, lambda_l = 0.5 m, k_rob = 0.3, the
# lead wheel on the path, no feedforward; with a 3 rad/s actuator (docs/results.md, "Previous
# figures"), because the car's 0.4 rad/s cannot follow these parameters.
PAPER_CONTROLLER = {"type": "lead_wheel", "order": 2, "lead_wheelbase_m": 0.5,
                    "lead_curvature_bound": 0.2, "k_rob": 0.3, "feedforward_share": 0,
                    "boundary_layer": 0, "cornering_target": "lead_wheel"}
PAPER_SETTINGS = [  # Fig. parameter_radar's four settings
    ("base", {}),
    ("kbar_l -50 %", {"lead_curvature_bound": 0.1}),
    ("lambda_l +300 %", {"lead_wheelbase_m": 2.0}),
    ("k_rob -33 %", {"k_rob": 0.2}),
]


def fig_simu(out):
    """Fig. simu: circle_sections with the certified, scheduled controller of the scenario."""
    file = "scenarios/circle_sections.yaml"
    scenario = ss.load_scenario(file)
    trace, summary = ss.run_scenario(scenario)
    figure, axes = plt.subplots(3, 1, figsize=(8, 9.5), gridspec_kw={"height_ratios": [1.4, 1, 1]})
    x, y = reference_path(scenario)
    axes[0].plot(x, y, "k--", linewidth=1.0, label="reference path")
    axes[0].plot(trace["x"], trace["y"], linewidth=1.2, label="rear axle (driven)")
    axes[0].set_aspect("equal", adjustable="datalim")
    axes[0].set_xlabel("x [m]")
    axes[0].set_ylabel("y [m]")
    axes[0].legend(loc="upper left")
    t = trace["t"]
    for key, label in (("e", "e (rear axle)"), ("e_front", "e_front"), ("e_lead", "e_lead")):
        axes[1].plot(t, trace[key], linewidth=1.0, label=label)
    axes[1].set_ylabel("lateral error [m]")
    axes[1].legend(loc="upper left", ncol=3)
    axes[2].plot(t, trace["delta_cmd"], linewidth=1.0, label="delta (command)")
    axes[2].plot(t, trace["delta_actual"], linewidth=1.0, label="delta_veh (actuator output)")
    axes[2].set_xlabel("t [s]")
    axes[2].set_ylabel("steering angle [rad]")
    axes[2].legend(loc="upper right")
    for axis in axes[1:]:
        axis.grid(alpha=0.3)
    figure.suptitle(f"Fig. simu: {summary['scenario']}, {controller_label(summary)}, "
                    f"v = {trace['v'].min():.1f} -> {trace['v'].max():.1f} m/s")
    figure.tight_layout()
    return save(figure, out, "simu")


def paper_setting_runs():
    """circle_sections with the paper's controller and its three variations, in parallel."""
    def run(setting):
        name, change = setting
        controller = dict(PAPER_CONTROLLER, **change)
        # The paper's controller is the kinematic one: it gets no side-slip input (its bang-bang
        # law diverges when it steers the course; docs/vehicle_dynamics.md, section 2).
        trace, summary = ss.run_scenario("scenarios/circle_sections.yaml",
                                         {"actuator.max_rate_radps": 3, "controller": controller,
                                          "simulation.side_slip.source": "none"})
        return name, controller, trace, summary

    with ThreadPoolExecutor(max_workers=2) as pool:  # run_scenario releases the GIL
        return list(pool.map(run, PAPER_SETTINGS))


def fig_el_comp(out, runs):
    figure, (reach, settled) = plt.subplots(1, 2, figsize=(10, 4.2),
                                            gridspec_kw={"width_ratios": [1, 2.2]})
    for name, _, trace, summary in runs:
        reached = summary["metrics"]["reaching_time_s"]
        label = f"{name} (reached at {reached:.1f} s)"
        reach.plot(trace["t"], trace["e_lead"], linewidth=1.0, label=label)
        settled.plot(trace["t"], trace["e_lead"], linewidth=0.7, label=label)
    reach.set_xlim(0.0, 4.0)
    reach.set_title("reaching (start 1 m off)")
    settled.set_xlim(4.0, trace["t"][-1])
    settled.set_ylim(-0.15, 0.15)
    settled.set_title("after reaching (pose noise 1 cm / 0.002 rad)")
    settled.legend(loc="upper left", ncol=2, fontsize=8)
    for axis in (reach, settled):
        axis.set_xlabel("t [s]")
        axis.grid(alpha=0.3)
    reach.set_ylabel("e_lead [m]")
    figure.suptitle("Fig. el_comp: e_lead on circle_sections for the four parameter settings "
                    "(paper's controller, 3 rad/s actuator)", fontsize=10)
    figure.tight_layout()
    return save(figure, out, "el_comp")


def fig_parameter_radar(out, runs):
    indicators = [("reaching_time_s", "reaching time", "s"),
                  ("max_abs_lead_error_after_reaching_m", "max |e_lead| after reaching", "m"),
                  ("command_rate_std_radps", "std of the steering rate", "rad/s"),
                  ("command_acceleration_std_radps2", "std of the steering acceleration",
                   "rad/s^2")]
    values = np.array([[summary["metrics"][key] for key, _, _ in indicators]
                       for _, _, _, summary in runs])
    scaled = values / values.max(axis=0)  # 1 = the largest of the four settings
    angles = np.linspace(0.0, 2.0 * np.pi, len(indicators), endpoint=False) + np.pi / 4.0
    figure = plt.figure(figsize=(7.5, 7.0))
    axis = figure.add_subplot(projection="polar")
    for (name, _, _, _), row in zip(runs, scaled):
        closed = np.append(row, row[0])
        axis.plot(np.append(angles, angles[0]), closed, linewidth=1.3, marker="o", label=name)
    axis.set_xticks(angles)
    axis.set_xticklabels([label.replace(" the ", "\nthe ", 1).replace(" after", "\nafter")
                          for _, label, _ in indicators])
    axis.set_ylim(0.0, 1.05)
    axis.set_yticks([0.25, 0.5, 0.75, 1.0])
    axis.set_rlabel_position(0.0)
    axis.tick_params(axis="x", pad=12)
    axis.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=4, fontsize=8)
    largest = "; ".join(f"{label} {value:.3g} {unit}" for (_, label, unit), value in
                        zip(indicators, values.max(axis=0)))
    figure.suptitle("Fig. parameter_radar: circle_sections (paper's controller, 3 rad/s "
                    "actuator),\neach indicator divided by its largest value over the four "
                    "settings (smaller is better)", fontsize=10)
    figure.text(0.5, 0.02, "largest values: " + largest, ha="center", fontsize=8, wrap=True)
    figure.tight_layout(rect=(0.0, 0.05, 1.0, 1.0))
    return save(figure, out, "parameter_radar")


def fig_lanechange(out):
    file = "scenarios/lane_change_15.yaml"
    scenario = ss.load_scenario(file)
    trace, summary = ss.run_scenario(scenario)
    vehicle = summary["parameters"]["vehicle"]
    figure, axes = plt.subplots(4, 1, figsize=(8, 10), sharex=True)
    x, y = reference_path(scenario)
    axes[0].plot(x, y, "k--", linewidth=1.0, label="reference path")
    axes[0].plot(trace["x"], trace["y"], linewidth=1.2, label="rear axle (driven)")
    axes[0].set_ylabel("y [m]")
    axes[0].legend(loc="upper right")
    for key, label in (("e", "e (rear axle)"), ("e_front", "e_front"), ("e_lead", "e_lead")):
        axes[1].plot(trace["x"], trace[key], linewidth=1.0, label=label)
    axes[1].set_ylabel("lateral error [m]")
    axes[1].legend(loc="lower left", ncol=3)
    axes[2].plot(trace["x"], trace["delta_cmd"], linewidth=1.0, label="delta (command)")
    axes[2].plot(trace["x"], trace["delta_actual"], linewidth=1.0, label="delta_veh (actuator)")
    axes[2].set_ylabel("steering angle [rad]")
    axes[2].legend(loc="upper right")
    held = np.diff(trace["delta_cmd"], prepend=trace["delta_cmd"][0]) / np.diff(
        trace["t"], prepend=trace["t"][0] - (trace["t"][1] - trace["t"][0]))
    axes[3].plot(trace["x"], held, linewidth=1.0, label="held command (difference)")
    axes[3].plot(trace["x"], trace["delta_actual_rate"], linewidth=1.0, label="actuator output")
    limit = vehicle["max_steering_rate_radps"]
    for sign in (1, -1):
        axes[3].axhline(sign * limit, color="k", linestyle=":", linewidth=0.9,
                        label=f"car's limit +-{limit} rad/s" if sign > 0 else None)
    axes[3].set_ylabel("steering rate [rad/s]")
    axes[3].set_xlabel("x [m]")
    axes[3].legend(loc="upper right", fontsize=8)
    for axis in axes:
        axis.grid(alpha=0.3)
    m = summary["metrics"]
    figure.suptitle(f"Fig. lanechange: {summary['scenario']}, {controller_label(summary)}, "
                    f"v = {trace['v'][0]:.0f} m/s; max |e| {m['max_abs_rear_error_m']:.3f} m, "
                    f"max side slip {m['max_abs_side_slip_rad']:.3f} rad", fontsize=10)
    figure.tight_layout()
    return save(figure, out, "lanechange")
