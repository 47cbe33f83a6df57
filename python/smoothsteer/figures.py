"""The paper's figures, regenerated from this project's own simulations (docs/results.md).

    PYTHONPATH=build/release/python /usr/bin/python3 -m smoothsteer.figures --out docs/figures

Run from the repository root (the scenario files name their vehicle and schedule files
relatively). Deterministic: the simulations are (their noise is seeded), the optimiser starts
from fixed guesses, and the PNGs carry no date or version. Figures (paper labels):
  simu             path, errors e / e_front / e_lead, delta_cmd and the actuator's delta on
                   circle_sections
  el_comp          e_lead on circle_sections for the four parameter settings of Sec. IV-A
  parameter_radar  the four indicators of those settings
  param_v          the tuned lambda, lambda_l, lead radius 1/kbar_l and the certified maximum
                   rate and acceleration over speed (shipped car, both certificates)
  benchmark_e      reaching a straight path: optimal, proposed (n = 1) and HOSM, two starts,
                   rear and front wheel
  lanechange       the 15 m/s lane change: path, errors, steering, steering rate
  pareto           the lane-change comparison: tracking error against steering effort
"""
import argparse
import math
import os
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

import smoothsteer as ss  # noqa: E402

DPI = 110
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


def save(figure, out, name):
    path = os.path.join(out, name + ".png")
    figure.savefig(path, dpi=DPI, metadata={"Software": None})
    plt.close(figure)
    print(f"wrote {path} ({os.path.getsize(path) // 1024} KiB)")
    return path


def reference_path(scenario, samples=4000):
    path = scenario.path
    points = path.sample(np.linspace(0.0, path.length_m, samples))
    return points[:, 0], points[:, 1]


def controller_label(summary):
    return summary["controller"].replace("scheduled_lead_wheel", "lead wheel, scheduled")


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
        trace, summary = ss.run_scenario("scenarios/circle_sections.yaml",
                                         {"actuator.max_rate_radps": 3, "controller": controller})
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


def fig_param_v(out):
    """Fig. param_v for the shipped car (0.4 rad/s, 8 rad/s^2): the feedforward route on the
    lane-change path, and the paper's box route on a straight path with 5 rad/s^2 (the settings
    of docs/param_v.csv, docs/tuning.md)."""
    car = ss.VehicleLimits.from_file("vehicles/passenger_car.yaml")
    lane_change = ss.load_scenario("scenarios/lane_change_15.yaml").path
    speeds = np.arange(0.5, 20.01, 0.5)
    feedforward = ss.tune(car, speeds, path=lane_change)
    box_car = ss.VehicleLimits.from_file("vehicles/passenger_car.yaml")
    box_car.max_steering_acceleration_radps2 = 5.0
    box = ss.tune(box_car, speeds, certificate="box")
    figure, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True,
                                gridspec_kw={"height_ratios": [1.6, 1, 1]})
    for schedule, style, route in ((box, "--", "box (paper), straight path"),
                                   (feedforward, "-", "feedforward, lane-change path")):
        v = schedule["speed_mps"]
        axes[0].plot(v, schedule["fictive_wheelbase_m"], style, color="C0",
                     label=f"lambda, {route}")
        axes[0].plot(v, schedule["lead_wheelbase_m"], style, color="C1",
                     label=f"lambda_l, {route}")
        axes[0].plot(v, 1.0 / schedule["lead_curvature_bound"], style, color="C2",
                     label=f"lead radius 1/kbar_l, {route}")
        axes[1].plot(v, schedule["max_steering_rate_radps"], style, color="C3", label=route)
        axes[2].plot(v, schedule["max_steering_acceleration_radps2"], style, color="C4",
                     label=route)
    axes[0].set_yscale("log")
    axes[0].set_ylim(0.03, 5e3)  # room for the legend above the curves
    axes[0].set_ylabel("length [m]")
    axes[0].legend(fontsize=8, ncol=2, loc="upper left")
    axes[1].axhline(car.max_steering_rate_radps, color="k", linewidth=0.8, linestyle=":",
                    label=f"car's limit {car.max_steering_rate_radps:g} rad/s")
    axes[1].set_ylim(0.0, 0.5)
    axes[1].set_ylabel("certified max rate [rad/s]")
    axes[2].axhline(car.max_steering_acceleration_radps2, color="k", linewidth=0.8,
                    linestyle=":", label=f"car's limit {car.max_steering_acceleration_radps2:g} "
                                         "rad/s^2")
    axes[2].axhline(5.0, color="k", linewidth=0.8, linestyle="-.",
                    label="limit given to the box route, 5 rad/s^2")
    axes[2].set_ylim(0.0, 9.0)
    axes[2].set_ylabel("certified max acceleration [rad/s^2]")
    axes[2].set_xlabel("speed v [m/s]")
    for axis in axes:
        axis.grid(alpha=0.3)
    for axis in axes[1:]:
        axis.legend(fontsize=8, loc="lower right")
    figure.suptitle("Fig. param_v: tuned parameters and certified maxima over speed,\n"
                    "passenger car (lambda_veh 2.578 m, 0.4 rad/s)", fontsize=10)
    figure.tight_layout()
    return save(figure, out, "param_v")


def reaching_distance(trace, tolerance_e=0.01, tolerance_psi=0.01):
    """Travel after which |e| <= tol_e and |psi| <= tol_psi for good (reaching_benchmark.hpp)."""
    outside = (np.abs(trace["e"]) > tolerance_e) | (np.abs(trace["heading_error"]) > tolerance_psi)
    if not outside.any():
        return 0.0
    last = np.nonzero(outside)[0][-1]
    return math.nan if last + 1 >= len(outside) else float(trace["s"][last + 1])


def fig_benchmark_e(out):
    """Fig. benchmark_e: the reaching benchmark of Tab. roc_vx (reaching_benchmark.hpp's set-up:
    lambda = 0.5 m, delta-bar = 0.5 rad, e(0) = -0.35 m, n = 1 with k_rob = 0, HOSM's psi-bar
    tuned for psi(0) = 0), from psi(0) = 0 and 0.2 pi."""
    settings = ss.ReachingBenchmarkOptions()
    lam, bound = settings.wheelbase_m, settings.steering_angle_bound_rad
    e0 = settings.initial_lateral_error_m
    line = ss.Path.straight_line((-100.0, 0.0), 0.0, 400.0)
    proposed = ss.LeadWheelController(
        ss.ControllerParameters.paper_c0(lam, math.sin(bound) / lam, 0.0), line)
    rate = proposed.bounds.steering_rate_per_meter

    def loop(controller, heading):
        return ss.simulate_kinematic(controller, (0.0, e0, heading), settings.speed_mps,
                                     settings.period_s, settings.horizon_m / settings.speed_mps,
                                     lam)

    best = (math.inf, 0.6)
    for candidate in np.arange(0.05, 1.5, 0.05):
        try:
            hosm = ss.HosmController(line, lam, bound, rate, float(candidate), 0.002)
        except ValueError:  # alpha <= 0: psi-bar too large for this rate bound
            break
        distance = reaching_distance(loop(hosm, 0.0))
        if distance < best[0]:
            best = (distance, float(candidate))
    hosm = ss.HosmController(line, lam, bound, rate, best[1], 0.002)
    headings = [0.0, 0.2 * math.pi]
    figure, axes = plt.subplots(2, 2, figsize=(9.5, 6.5), sharex=True, sharey="row")
    for column, heading in enumerate(headings):
        optimum = ss.solve_optimal_reaching(
            wheelbase_m=lam, steering_angle_bound_rad=bound, steering_rate_bound_per_m=rate,
            initial_lateral_error_m=e0, initial_heading_rad=heading, intervals=150)
        s = optimum["arc_length_m"]
        e, psi = optimum["lateral_error_m"], optimum["heading_rad"]
        curves = [(f"optimal ({optimum['distance_m']:.2f} m)", s, e, e + lam * np.sin(psi))]
        for name, controller in (("proposed, n = 1", proposed), ("HOSM", hosm)):
            trace = loop(controller, heading)
            reach = reaching_distance(trace)
            front = trace["e"] + lam * np.sin(trace["heading_error"])
            curves.append((f"{name} ({reach:.2f} m)", trace["s"], trace["e"], front))
        for label, s, rear, front in curves:
            axes[0][column].plot(s, rear, linewidth=1.2, label=label)
            axes[1][column].plot(s, front, linewidth=1.2, label=label)
        axes[0][column].set_title(f"psi(0) = {heading / math.pi:.1f} pi")
        axes[1][column].set_xlabel("travelled distance s [m]")
        axes[0][column].legend(fontsize=8, title="(reaching distance)", title_fontsize=8)
    axes[0][0].set_ylabel("rear wheel e [m]")
    axes[1][0].set_ylabel("front wheel e + lambda sin(psi) [m]")
    for axis in axes.flat:
        axis.set_xlim(0.0, 6.0)
        axis.grid(alpha=0.3)
    figure.suptitle(f"Fig. benchmark_e: reaching a straight path, e(0) = {e0} m, lambda = {lam} m,"
                    f"\n|delta| <= {bound} rad, |d delta/ds| <= {rate:.3f} rad/m; proposed n = 1, "
                    f"k_rob = 0; HOSM psi-bar = {best[1]:.2f} rad", fontsize=10)
    figure.tight_layout()
    return save(figure, out, "benchmark_e")


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


def fig_pareto(out):
    """Every controller of the comparison on the 15 m/s lane change (the scenario's car and
    actuator): tracking error against steering effort, with the Pareto front."""
    names = [None] + ss.comparison_controller_names()

    def run(name):
        overrides = {"controller": {"type": name, "nominal_speed_mps": 15}} if name else {}
        return ss.run_scenario("scenarios/lane_change_15.yaml", overrides)[1]

    with ThreadPoolExecutor(max_workers=2) as pool:
        summaries = list(pool.map(run, names))
    points = {}  # (effort, error) -> labels: coincident controllers share one point
    for summary in summaries:
        m = summary["metrics"]
        label = ("proposed, certified (scenario)" if summary["controller"] ==
                 "scheduled_lead_wheel" else summary["controller"])
        key = (m["held_rate_rms_radps"], m["max_abs_rear_error_m"], m["held_rate_violations"] > 0)
        for other in points:  # within 1 %: one point, one label
            if abs(math.log(other[0] / key[0])) < 0.01 and abs(math.log(other[1] / key[1])) < 0.01:
                key = other
        points.setdefault(key, []).append(label)
    figure, axis = plt.subplots(figsize=(8, 5.5))
    for (effort, error, violates), labels in points.items():
        axis.scatter(effort, error, marker="x" if violates else "o", s=40,
                     color="C3" if violates else "C0")
        axis.annotate(", ".join(labels), (effort, error), textcoords="offset points",
                      xytext=(5, 3), fontsize=8)
    front, best = [], math.inf
    for effort, error, _ in sorted(points):
        if error < best:
            front.append((effort, error))
            best = error
    axis.step([p[0] for p in front], [p[1] for p in front], where="post", color="k",
              linewidth=0.8, linestyle="--", label="Pareto front (lower left is better)")
    axis.scatter([], [], marker="o", color="C0", label="held rate within 0.4 rad/s")
    if any(violates for _, _, violates in points):
        axis.scatter([], [], marker="x", color="C3", label="held rate above 0.4 rad/s")
    axis.set_xscale("log")
    axis.set_yscale("log")
    for ticks in (axis.xaxis, axis.yaxis):  # plain numbers at 1, 2 and 5 times a power of 10
        ticks.set_major_locator(matplotlib.ticker.LogLocator(subs=(1.0, 2.0, 5.0)))
        ticks.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
        ticks.set_minor_formatter(matplotlib.ticker.NullFormatter())
    axis.set_xlabel("steering effort: RMS of the held command's rate [rad/s]")
    axis.set_ylabel("max |e| of the rear axle [m]")
    axis.grid(alpha=0.3, which="both")
    axis.legend(loc="lower right", fontsize=8)
    axis.set_title("Comparison: 15 m/s lane change, kinetic model, 10 Hz actuator at 0.4 rad/s\n"
                   "(baselines clamped to the car's 0.4 rad/s by SaturatedController)",
                   fontsize=10)
    figure.tight_layout()
    return save(figure, out, "pareto")


FIGURES = ["simu", "el_comp", "parameter_radar", "param_v", "benchmark_e", "lanechange",
           "pareto"]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="docs/figures", help="output directory")
    parser.add_argument("--only", default="", help="comma-separated subset of " +
                        ", ".join(FIGURES))
    arguments = parser.parse_args(argv)
    wanted = [name for name in arguments.only.split(",") if name] or FIGURES
    unknown = sorted(set(wanted) - set(FIGURES))
    if unknown:
        parser.error(f"unknown figure(s) {', '.join(unknown)}; known: {', '.join(FIGURES)}")
    os.makedirs(arguments.out, exist_ok=True)
    plt.rcParams.update({"font.size": 9, "svg.hashsalt": "smoothsteer"})
    runs = paper_setting_runs() if {"el_comp", "parameter_radar"} & set(wanted) else None
    makers = {"simu": fig_simu, "el_comp": lambda out: fig_el_comp(out, runs),
              "parameter_radar": lambda out: fig_parameter_radar(out, runs),
              "param_v": fig_param_v, "benchmark_e": fig_benchmark_e,
              "lanechange": fig_lanechange, "pareto": fig_pareto}
    for name in FIGURES:
        if name in wanted:
            makers[name](arguments.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
