#!/usr/bin/python3
"""How well can the certified controller class take a curvature jump? (docs/feedforward.md,
section 6, "At a curvature jump the centred ramp, not the certificate, sets the error").

The certificate (include/smoothsteer/controller/steering_certificate.hpp) holds for any lead
curvature kappa_n = f + w with |f| <= kbar_ff, |df/ds| <= L_ff and |w| <= kbar_sw. This script
asks, for one jump of the path's curvature from k1 to k2 at s = 0 and one schedule row, what the
smallest worst rear-axle offset max |y| is that any such kappa_n can achieve, planned with full
knowledge of the path. It is a linear programme on the chain linearised about the straight:

    in sigma coordinates each stage is the lag d sigma_{i-1}/ds = (kappa_i - sigma_{i-1}) / lambda_i
    (paper-notes section 1), the rear axle's curvature is sigma_0, and y'' = sigma_0 - kappa_path.

It ignores the tyres, the actuator and the measurement noise, so it is a lower bound for the
kinematic model, not for the car. Three figures per jump:

* centred ramp: the lead curvature ramps at L_ff, centred a chain's reach before the jump (what
  the shipped preview asks for, less its chain inverse, which the rate limit cannot follow);
* feedforward alone (w = 0): the best planned f;
* certified class: the best planned f + w.

    PYTHONPATH=build/ci/python /usr/bin/python3 studies/feedforward_bound.py
        [--schedule scenarios/schedules/passenger_car_circle_sections.csv]
        [--jump SPEED:K1:K2 ...]

Without --jump it takes circle_sections' five jumps at the speeds where the scenario meets them.
The limits at a speed are the controller's own (GainSchedule.parameters_at of the smoothsteer
module, the schedule's conservative interpolation), so the module must be built.
"""
import argparse
import math
import os

import numpy as np
from scipy.linalg import expm
from scipy.optimize import linprog

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_SCHEDULE = os.path.join(ROOT, "scenarios", "schedules", "passenger_car_circle_sections.csv")
# circle_sections: 2.8 m/s, then +0.5 m/s^2 from t = 2 s up to 12.5 m/s. Its arcs meet at
# s = 15, 62.1, 187.8, 344.9 and 392.0 m.
CIRCLE_JUMPS = [(4.15, 0.0, 1 / 30), (8.0, 1 / 30, -1 / 40), (12.5, -1 / 40, 1 / 50),
                (12.5, 1 / 50, -1 / 30), (12.5, -1 / 30, 0.0)]


def schedule_limits(path, speed):
    """(lambda_1 .. lambda_n, kbar_ff, L_ff, kbar_sw) the scheduled controller runs at `speed`."""
    import smoothsteer  # the built module: the controller's own interpolation of the schedule

    p = smoothsteer.GainSchedule.from_csv(path).parameters_at(speed)
    feedforward_bound = p.feedforward_share * p.lead_curvature_bound
    return (list(p.wheelbases_m)[:p.order], feedforward_bound, p.feedforward_curvature_rate,
            p.lead_curvature_bound - feedforward_bound)


def chain_model(k1, k2, wheelbases, before, after, step):
    """The linearised chain for the jump k1 -> k2 at s = 0, discretised exactly for inputs held
    over each step: arc lengths s, and the rear offset y and heading theta at them as
    y = y_effect @ kappa_n + y_free, theta = theta_effect @ kappa_n + theta_free (stationary on k1
    at s = -before).

    State z = (sigma_{n-1} .. sigma_0, theta, y): sigma_{i-1}' = (kappa_i - sigma_{i-1}) / lambda_i,
    theta' = sigma_0 - kappa_path, y' = theta; inputs kappa_n and kappa_path."""
    index = np.arange(-round(before / step), round(after / step) + 1)
    s = index * step  # step k holds its inputs over [s_k, s_k + step)
    n = len(s)
    path = np.where(index >= 0, k2, k1)
    stages = len(wheelbases)
    dim = stages + 2
    a = np.zeros((dim, dim))
    b = np.zeros((dim, 2))
    for i in range(stages):  # row i: sigma of stage n - i, fed by row i - 1 (or kappa_n)
        lam = wheelbases[stages - 1 - i]
        a[i, i] = -1.0 / lam
        if i == 0:
            b[i, 0] = 1.0 / lam
        else:
            a[i, i - 1] = 1.0 / lam
    a[stages, stages - 1] = 1.0  # theta' = sigma_0 - kappa_path
    b[stages, 1] = -1.0
    a[stages + 1, stages] = 1.0  # y' = theta
    augmented = np.zeros((dim + 2, dim + 2))
    augmented[:dim, :dim] = a
    augmented[:dim, dim:] = b
    discrete = expm(augmented * step)
    ad, bd = discrete[:dim, :dim], discrete[:dim, dim:]
    # Impulse responses of (theta, y) to each input, and the free response from z0.
    z0 = np.zeros(dim)
    z0[:stages] = k1
    impulse = np.zeros((n, 2, 2))  # [m, output, input]
    free = np.zeros((n, 2))
    power = np.eye(dim)
    for m in range(n):
        free[m] = (power @ z0)[stages:]
        impulse[m] = (power @ bd)[stages:, :]
        power = ad @ power
    lag = np.subtract.outer(np.arange(n), np.arange(n)) - 1  # k - 1 - j
    mask = lag >= 0
    lag = np.where(mask, lag, 0)
    effect = [np.where(mask, impulse[lag, out, 0], 0.0) for out in (0, 1)]
    driven = [free[:, out] + np.where(mask, impulse[lag, out, 1], 0.0) @ path for out in (0, 1)]
    return s, effect[1], driven[1], effect[0], driven[0]


def centred_ramp_offset(k1, k2, wheelbases, ff_rate, before=25.0, after=30.0, step=0.1):
    """max |y| when the lead curvature ramps at L_ff, centred a chain's reach (sum lambda_i, the
    lags' mean delay) before the jump: the shipped preview's ramp without its inverse."""
    s, effect, free, _, _ = chain_model(k1, k2, wheelbases, before, after, step)
    width = abs(k2 - k1) / ff_rate
    middle = s + 0.5 * step  # the ramp's mean over each step
    lead = k1 + (k2 - k1) * np.clip((middle + sum(wheelbases)) / width + 0.5, 0.0, 1.0)
    return float(np.max(np.abs(effect @ lead + free)))


def lower_bound(k1, k2, wheelbases, ff_bound, ff_rate, sw_bound, before=25.0, after=30.0,
                step=0.1):
    """Smallest max |y| over planned f (+ w) for the jump k1 -> k2 at s = 0; returns (bound, x).

    wheelbases: lambda_1 .. lambda_n. The chain starts in stationary cornering on k1 at
    s = -before; over the last 15 m the lead curvature is held at k2 so that |y| <= bound also
    covers the settling of the lags, and the heading ends on the path's."""
    s, my, y0, heading_effect, heading_free = chain_model(k1, k2, wheelbases, before, after, step)
    n = len(s)
    use_w = sw_bound > 0.0
    nv = (2 * n if use_w else n) + 1
    def lift(block_f, block_w, t_col):
        cols = [block_f] + ([block_w] if use_w else []) + [t_col]
        return np.hstack(cols)
    ones = np.ones((n, 1))
    diff = np.zeros((n - 1, n))
    diff[np.arange(n - 1), np.arange(n - 1)] = -1.0
    diff[np.arange(n - 1), np.arange(1, n)] = 1.0
    zero_d = np.zeros((n - 1, n))
    zero_c = np.zeros((n - 1, 1))
    a_ub = np.vstack([lift(my, my, -ones), lift(-my, -my, -ones),
                      lift(diff, zero_d, zero_c), lift(-diff, zero_d, zero_c)])
    b_ub = np.concatenate([-y0, y0, np.full(n - 1, ff_rate * step), np.full(n - 1, ff_rate * step)])
    # Lead curvature k1 at the start, k2 (w = 0) over the last 15 m.
    a_eq, b_eq = [], []
    first = np.zeros(nv)
    first[0] = 1.0
    if use_w:
        first[n] = 1.0
    a_eq.append(first)
    b_eq.append(k1)
    for k in np.nonzero(s >= after - 15.0)[0]:
        row = np.zeros(nv)
        row[k] = 1.0
        a_eq.append(row)
        b_eq.append(k2)
        if use_w:
            row = np.zeros(nv)
            row[n + k] = 1.0
            a_eq.append(row)
            b_eq.append(0.0)
    # The heading settles on the path's: no drift after the window.
    row = np.zeros(nv)
    row[:n] = heading_effect[-1]
    if use_w:
        row[n:2 * n] = heading_effect[-1]
    a_eq.append(row)
    b_eq.append(-heading_free[-1])
    bounds = [(-ff_bound, ff_bound)] * n + ([(-sw_bound, sw_bound)] * n if use_w else []) + [(0, None)]
    cost = np.zeros(nv)
    cost[-1] = 1.0
    result = linprog(cost, A_ub=a_ub, b_ub=b_ub, A_eq=np.array(a_eq), b_eq=b_eq, bounds=bounds,
                     method="highs")
    if result.status != 0:
        return math.nan, None
    return result.x[-1], result.x


def jump_argument(text):
    """SPEED:K1:K2 with a finite speed > 0 and finite curvatures, else an argparse error."""
    try:
        speed, k1, k2 = (float(x) for x in text.split(":"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' must be SPEED:K1:K2 (three numbers)")
    if not (math.isfinite(speed) and speed > 0 and math.isfinite(k1) and math.isfinite(k2)):
        raise argparse.ArgumentTypeError(f"'{text}': speed must be finite and > 0, "
                                         "curvatures finite")
    return speed, k1, k2


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--schedule", default=DEFAULT_SCHEDULE)
    parser.add_argument("--jump", action="append", default=[], type=jump_argument,
                        help="SPEED:K1:K2 (m/s, 1/m, 1/m); repeatable")
    args = parser.parse_args()
    jumps = args.jump or CIRCLE_JUMPS
    print("| speed | jump | L_ff | kbar_ff | kbar_sw | lambda_i | centred ramp | "
          "feedforward alone | certified class |")
    print("|---|---|---|---|---|---|---|---|---|")
    for speed, k1, k2 in jumps:
        try:
            wheelbases, ff_bound, ff_rate, sw_bound = schedule_limits(args.schedule, speed)
        except ValueError as error:  # the schedule reader names the file, line and rule
            parser.error(str(error))
        alone, _ = lower_bound(k1, k2, wheelbases, ff_bound, ff_rate, 0.0)
        both, _ = lower_bound(k1, k2, wheelbases, ff_bound, ff_rate, sw_bound)
        print(f"| {speed:g} m/s | {k1:+.4f} -> {k2:+.4f} 1/m | {ff_rate:.4f} 1/m^2 | "
              f"{ff_bound:.4f} 1/m | {sw_bound:.4f} 1/m | "
              f"{', '.join(f'{lam:.2f}' for lam in wheelbases)} m | "
              f"{centred_ramp_offset(k1, k2, wheelbases, ff_rate):.3f} m | {alone:.3f} m | {both:.3f} m |")


if __name__ == "__main__":
    main()
