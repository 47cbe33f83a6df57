"""Figures of the tuning and the comparisons: param_v (Sec. III), benchmark_e (Sec. IV-B) and
the lane-change comparison's Pareto figure."""
import math
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import matplotlib.ticker

import smoothsteer as ss
from ._plotting import plt, save


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
                   "(baselines held to the car's 0.4 rad/s and 8 rad/s^2 by SaturatedController)",
                   fontsize=10)
    figure.tight_layout()
    return save(figure, out, "pareto")
