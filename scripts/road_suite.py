#!/usr/bin/python3
"""Writes the road suite, scenarios/roads/*.yaml, and scenarios/hairpin.yaml (docs/scenarios.md).

Each road is laid out from straights, clothoids and arcs the way the road-design guidelines do:
  * minimum radius from the design speed, R_min = V^2 / (127 (e + f)) (V in km/h, e the
    superelevation, f the side friction factor; AASHTO, "A Policy on Geometric Design of
    Highways and Streets", 7th ed. 2018, section 3.3: the simplified curve formula, f from its
    table of side friction factors for open highways);
  * clothoid parameter A with R / 3 <= A <= R (German guidelines RAL 2012 for rural roads and
    RAA 2008 for motorways: the clothoid length L = A^2 / R);
  * the speed profile from the path's curvature (speed.profile: curvature): the design speed on
    the straights, v <= sqrt(a_lat / |kappa|) with a_lat = g (e + f) of the design, accelerating
    at <= 1 m/s^2 and braking at <= 2 m/s^2 (well below the 3.4 m/s^2 that AASHTO's stopping
    sight distance assumes, section 3.2);
  * the parking lot: the bay and aisle of 90 deg parking of the German EAR 2005 (FGSV), two cusps
    (`gear:` on the pieces), a signed profile at 1.5 m/s that rests 1 s at each cusp.
The numbers of each design are in the comments of its file. Run from the repository root:

    /usr/bin/python3 scripts/road_suite.py
"""
import math
import os

G = 9.81
ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def aashto_min_radius(speed_kmh, e, f):
    """AASHTO 2018 section 3.3: R_min = V^2 / (127 (e + f)) [m]."""
    return speed_kmh**2 / (127.0 * (e + f))


class Layout:
    """Tracks heading, curvature and position while pieces are appended (as PathBuilder does;
    the position by the midpoint rule on 1 mm steps, for placing a manoeuvre)."""

    STEP = 1e-3

    def __init__(self):
        self.pieces = []
        self.curvature = 0.0
        self.heading = 0.0
        self.x = 0.0
        self.y = 0.0
        self.notes = []
        self.pending_gear = None

    def _advance(self, length, start_curvature, end_curvature):
        steps = max(1, int(round(length / self.STEP)))
        h = length / steps
        rate = (end_curvature - start_curvature) / length
        for i in range(steps):
            s = (i + 0.5) * h  # heading theta(s) = theta0 + k0 s + rate s^2 / 2
            theta = self.heading + start_curvature * s + 0.5 * rate * s * s
            self.x += h * math.cos(theta)
            self.y += h * math.sin(theta)
        self.heading += 0.5 * (start_curvature + end_curvature) * length

    def _append(self, text):
        if self.pending_gear:
            text = text[:-1] + ", gear: %s}" % self.pending_gear
            self.pending_gear = None
        self.pieces.append(text)

    def gear(self, name):
        """A change of direction (a cusp): the next piece is driven in gear `name`, from here,
        in the opposite direction of travel (heading + pi), from curvature 0."""
        self.pending_gear = name
        self.heading += math.pi
        self.curvature = 0.0
        return self

    def line(self, length):
        self._advance(length, 0.0, 0.0)
        self._append("{line_m: %r}" % float(length))
        self.curvature = 0.0
        return self

    def clothoid(self, parameter, end_curvature):
        """Clothoid of parameter A from the current curvature to end_curvature: L = A^2 |dk|."""
        length = parameter**2 * abs(end_curvature - self.curvature)
        self._advance(length, self.curvature, end_curvature)
        self._append("{clothoid_parameter_m: %r, end_curvature_per_m: %r}"
                     % (float(parameter), float(end_curvature)))
        self.curvature = end_curvature
        return self

    def arc(self, signed_radius, angle):
        assert angle * signed_radius > 0.0, "arc angle %r has the wrong sign or is 0" % angle
        self._advance(abs(angle * signed_radius), 1.0 / signed_radius, 1.0 / signed_radius)
        self._append("{arc_radius_m: %r, arc_angle_rad: %r}" % (abs(signed_radius), angle))
        self.curvature = 1.0 / signed_radius
        return self

    def bend(self, signed_radius, deflection, parameter_in, parameter_out):
        """Clothoid in, arc, clothoid out, turning by `deflection` [rad] in all; each clothoid
        from or to a straight turns L / (2 R)."""
        radius = abs(signed_radius)
        for a in (parameter_in, parameter_out):
            assert radius / 3.0 - 1e-9 <= a <= radius + 1e-9, "A = %r outside [R/3, R]" % a
        turn = math.copysign(1.0, signed_radius)
        spirals = (parameter_in**2 + parameter_out**2) / (2.0 * radius**2)
        arc = abs(deflection) - spirals
        assert arc > 0.0, "deflection too small for the clothoids"
        self.clothoid(parameter_in, turn / radius)
        self.arc(signed_radius, turn * arc)
        self.clothoid(parameter_out, 0.0)
        return self


CONTROLLER = """\
# The passenger car's one controller block, as in lane_change_*.yaml and circle_sections.yaml
# (the certified route; its schedule covers 0.5-20 m/s and was tuned on the lane change's path).
controller:
  type: scheduled_lead_wheel
  schedule: {schedule}
  # The steering governor (docs/governor.md), as in every shipped lead-wheel scenario.
  governor: {{enabled: true}}
  cornering_target: rear_axle_exact
  curvature_preview: planned_jumps
  slip_preview: true
  # The Smith predictor's delay and the catch-up over speed, from the actuator, the tires and the
  # path (docs/vehicle_dynamics.md, "Compensation over speed").
  derived_compensation: true
  boundary_layer: 0.03
"""

SIMULATION = """\
simulation:
  control_period_s: 0.02
  substep_s: 0.001
  duration_s: {duration}
  side_slip: {{source: observer, tire_model: magic_formula, yaw_rate_noise_std_radps: 0.002,
              lateral_acceleration_noise_std_mps2: 0.05}}
metrics: {{reaching_threshold_m: 0.1}}
"""


def write(path, name, description, design, layout, speed, duration, relative, simulation=None,
          controller=None):
    text = ["name: %s" % name, 'description: "%s"' % description]
    text += ["# " + line for line in design]
    text.append("# Generated by scripts/road_suite.py (edit the script, not this file).")
    text.append("model: dynamic")
    text.append("vehicle: {file: %s../vehicles/passenger_car.yaml}" % relative)
    text.append("# Third-order low-pass steering without dead time, the car's own rate limit.")
    text.append("actuator: {bandwidth_hz: 10.0, dead_time_s: 0.0}")
    text.append("speed: " + speed)
    text.append("start: {x_m: 0.0, y_m: 0.0, heading_rad: 0.0}")
    text.append("path:")
    text.append("  type: segments")
    text.append("  start: [0.0, 0.0]")
    text.append("  heading_rad: 0.0")
    text.append("  pieces:")
    text += ["    - " + piece for piece in layout.pieces]
    body = "\n".join(text) + "\n"
    body += (controller or CONTROLLER).format(
        schedule=relative + "schedules/passenger_car_lane_change.csv")
    body += (simulation or SIMULATION).format(duration=float(duration))
    with open(os.path.join(ROOT, path), "w") as out:
        out.write(body)
    print("%-40s final heading %+.6f rad" % (path, layout.heading))


def curvature_speed(max_mps, lateral):
    return ("{profile: curvature, max_mps: %r, max_lateral_acceleration_mps2: %r, "
            "max_acceleration_mps2: 1.0, max_deceleration_mps2: 2.0}"
            % (round(max_mps, 3), round(lateral, 3)))


def rural_80():
    # 80 km/h, e_max = 8 %, f = 0.14: R_min = 229 m. Curves of 300 m and 250 m (a reverse curve
    # with a 60 m straight between), A = R / 2.
    r_min = aashto_min_radius(80.0, 0.08, 0.14)
    lay = Layout().line(120.0)
    lay.bend(300.0, math.radians(35.0), 150.0, 150.0).line(60.0)
    lay.bend(-250.0, math.radians(45.0), 125.0, 125.0).line(120.0)
    lay.bend(400.0, math.radians(20.0), 200.0, 200.0).line(100.0)
    design = [
        "Rural two-lane road, design speed 80 km/h (22.2 m/s). AASHTO Green Book (2018, 3.3):",
        "R_min = V^2 / (127 (e + f)) = %.0f m with e_max = 0.08, f = 0.14 (its f table)." % r_min,
        "Curves R = 300 m left 35 deg, R = 250 m right 45 deg, R = 400 m left 20 deg, each",
        "entered and left through clothoids A = R / 2 (RAL 2012: R/3 <= A <= R, L = A^2 / R).",
        "Speed: the design speed, v <= sqrt(g (e + f) / |kappa|) (2.16 m/s^2: not binding).",
    ]
    write("scenarios/roads/rural_80.yaml", "rural_80",
          "Rural road at 80 km/h: three clothoid-arc-clothoid bends (AASHTO R_min 229 m)",
          design, lay, curvature_speed(80 / 3.6, G * 0.22), 60.0, "../")


def mountain_hairpins():
    # Mountain road, design speed 40 km/h: e = 0.08, f = 0.23 -> R_min = 41 m; the a_lat of
    # that design, g (e + f) = 3.04 m/s^2, then sets the hairpin speed sqrt(3.04 * 12) = 6 m/s.
    r_min = aashto_min_radius(40.0, 0.08, 0.23)
    lay = Layout().line(60.0)
    lay.bend(50.0, math.radians(30.0), 25.0, 25.0).line(60.0)
    lay.bend(12.0, math.pi, 8.0, 8.0).line(60.0)  # hairpin left: the legs 24 m apart
    lay.bend(-12.0, math.pi, 8.0, 8.0).line(60.0)  # hairpin right
    lay.bend(-45.0, math.radians(30.0), 22.5, 22.5).line(50.0)
    design = [
        "Mountain road, design speed 40 km/h (11.1 m/s): AASHTO (3.3) with e = 0.08, f = 0.23",
        "gives R_min = %.0f m; curves R = 50 m left and 45 m right (A = R / 2), two hairpins of" % r_min,
        "R = 12 m (180 deg left, then right: three parallel legs of 60 m, 24 m apart), clothoids",
        "A = 8 m (R/3 <= A <= R; L = 5.3 m). Speed limited by",
        "g (e + f) = 3.04 m/s^2: 6.0 m/s (22 km/h) in the hairpins.",
    ]
    write("scenarios/roads/mountain_hairpins.yaml", "mountain_hairpins",
          "Mountain road at 40 km/h with two 12 m hairpins (clothoids A = 8 m)",
          design, lay, curvature_speed(40 / 3.6, G * 0.31), 120.0, "../")


def motorway_exit():
    # Exit from a 100 km/h carriageway: a parallel deceleration lane, a diverging curve R = 300 m,
    # an egg-shaped clothoid into the loop R = 50 m (270 deg), clothoid out. Loop design speed
    # 40 km/h (AASHTO 3.3: e = 0.08, f = 0.23 -> R_min 41 m).
    r_min = aashto_min_radius(40.0, 0.08, 0.23)
    lay = Layout().line(80.0)
    lay.clothoid(150.0, -1.0 / 300.0)
    lay.arc(-300.0, -math.radians(8.0))
    lay.clothoid(45.0, -1.0 / 50.0)  # between the two arcs of the same sense: L = A^2 |dk|
    loop = math.radians(270.0) - (abs(lay.heading) + math.radians(0.0))
    spiral_out = 30.0**2 / (2.0 * 50.0**2)
    lay.arc(-50.0, -(loop - spiral_out))
    lay.clothoid(30.0, 0.0).line(60.0)
    design = [
        "Motorway exit ramp with its loop (cloverleaf): a 80 m parallel deceleration lane at",
        "100 km/h, a clothoid A = 150 m into R = 300 m right (8 deg), an egg-shaped clothoid",
        "A = 45 m from R = 300 m to R = 50 m, the loop R = 50 m (270 deg from the start in all),",
        "clothoid A = 30 m out (R/3 <= A <= R) and 60 m straight. Loop design speed 40 km/h:",
        "AASHTO (3.3) with e = 0.08, f = 0.23: R_min = %.0f m; a_lat = g (e + f) = 3.04 m/s^2," % r_min,
        "so 12.3 m/s in the loop, braked down from 27.8 m/s at 2 m/s^2.",
    ]
    write("scenarios/roads/motorway_exit.yaml", "motorway_exit",
          "Motorway exit at 100 km/h into a 270 deg loop ramp of R = 50 m",
          design, lay, curvature_speed(100 / 3.6, G * 0.31), 90.0, "../")


def roundabout():
    # Single-lane roundabout, straight through. FHWA/NCHRP Report 672 (2010), section 6.7: the
    # fastest path's radii; entry R1 = 25 m, circulating R2 = 18 m around the island, exit
    # R3 = 25 m, reverse curves joined by clothoids through zero curvature (A = 10 m).
    entry, circulate = 25.0, 18.0
    lay = Layout().line(70.0)
    lay.clothoid(12.5, -1.0 / entry)
    turn_in = math.radians(40.0)
    lay.arc(-entry, -turn_in)
    lay.clothoid(10.0, 1.0 / circulate)
    # The layout is symmetric: the middle arc makes the total heading change zero.
    spiral_entry = 12.5**2 / (2.0 * entry**2)
    reverse = 0.5 * (1.0 / circulate - 1.0 / entry) * 10.0**2 * (1.0 / circulate + 1.0 / entry)
    middle = 2.0 * (spiral_entry + turn_in) - 2.0 * reverse
    lay.arc(circulate, middle)
    lay.clothoid(10.0, -1.0 / entry)
    lay.arc(-entry, -turn_in)
    lay.clothoid(12.5, 0.0).line(70.0)
    speed_circ = math.sqrt(G * 0.26 * circulate)
    design = [
        "Single-lane roundabout, through movement (NCHRP Report 672, 'Roundabouts: An",
        "Informational Guide', 2nd ed. 2010, chapter 6: the fastest vehicle path): entry",
        "curve R = 25 m right, circulating R = 18 m left around the central island (%.0f deg), exit"
        % math.degrees(middle),
        "R = 25 m right; clothoids A = 12.5 m from and to the approach straights and A = 10 m",
        "through zero curvature between the reverse curves. Approach 50 km/h; speed from",
        "AASHTO (3.3) with e = -0.02 (outward cross slope) and f = 0.28 (30 km/h):",
        "a_lat = 0.26 g = 2.55 m/s^2, %.1f m/s (%.0f km/h) on the circle." % (speed_circ,
                                                                          speed_circ * 3.6),
    ]
    write("scenarios/roads/roundabout.yaml", "roundabout",
          "Roundabout passage: entry R 25 m, around the island R 18 m, exit R 25 m",
          design, lay, curvature_speed(50 / 3.6, G * 0.26), 60.0, "../")


def urban_turn():
    # Right turn at an urban intersection: centre-line radius 10 m, short clothoids A = 5 m.
    radius = 10.0
    lay = Layout().line(60.0)
    lay.bend(-radius, math.pi / 2, 5.0, 5.0).line(50.0)
    speed = math.sqrt(G * 0.32 * radius)
    design = [
        "Right turn at an urban intersection from a 50 km/h street: centre-line radius 10 m",
        "(AASHTO 2018 section 2.1: the passenger-car design vehicle's minimum turning radius is",
        "7.3 m), clothoids A = 5 m (R/3 <= A <= R; 2.5 m long). Turning speed from the 3.3 formula with",
        "e = 0 and f = 0.32 (near AASHTO's low-speed urban value at 20 km/h, 3.3): a_lat = 3.1 m/s^2,",
        "%.1f m/s (%.0f km/h)." % (speed, speed * 3.6),
    ]
    write("scenarios/roads/urban_turn.yaml", "urban_turn",
          "Urban intersection right turn, R = 10 m at 20 km/h after braking from 50 km/h",
          design, lay, curvature_speed(50 / 3.6, G * 0.32), 60.0, "../")


PARKING_CONTROLLER = """\
# The certified route with a schedule for parking speeds (0.5-2 m/s), from this path's peak
# curvature 0.2 1/m and curvature rate 1/A^2 = 0.0625 1/m^2 (the lane change's schedule bounds
# the lead curvature to 0.14 1/m at 1.5 m/s, below the path's 0.2):
#   smoothsteer tune --vehicle vehicles/passenger_car.yaml --speeds 0.5:2:0.25
#     --path-curvature 0.2 --path-curvature-rate 0.0625 --feedforward-headroom 1.2
#     --max-longitudinal-acceleration 0.5 --out scenarios/schedules/passenger_car_parking.csv
# Everything else as lane_change_15.yaml.
controller:
  type: scheduled_lead_wheel
  schedule: ../schedules/passenger_car_parking.csv
  governor: {{enabled: true}}
  cornering_target: rear_axle_exact
  curvature_preview: planned_jumps
  slip_preview: true
  # The Smith predictor's delay and the catch-up over speed, from the actuator, the tires and the
  # path (docs/vehicle_dynamics.md, "Compensation over speed").
  derived_compensation: true
  boundary_layer: 0.03
"""

PARKING_SIMULATION = """\
simulation:
  control_period_s: 0.02
  substep_s: 0.001
  duration_s: {duration}
  # At parking speed the rear axle does not slip: the single-track models are kinematic below
  # 1 m/s and in reverse (docs/simulation.md), so the controller gets no slip estimate.
  side_slip: {{source: none}}
metrics: {{reaching_threshold_m: 0.1}}
"""


def parking_lot():
    # Reverse into a 90 deg bay and drive out the other way: EAR 2005 (FGSV, "Empfehlungen fuer
    # Anlagen des ruhenden Verkehrs") for 90 deg parking: bays 2.50 m wide and 5.00 m
    # deep, aisle 6.00 m. The rear axle runs 0.5 m beyond the aisle's centre line, 3.5 m from the
    # bay line (y = 0; the bay's centre line at x = 20 m); each turn is a clothoid A = 4 m into
    # R = 5 m and out (R/3 <= A <= R; L = 3.2 m), 90 deg in all. A = 4 m keeps the steering rate
    # the clothoid asks at 1.5 m/s, v L / A^2 = 0.24 rad/s, below the cars' 0.4 rad/s (A = 3 m
    # would ask 0.43). The car stops at each cusp, changes gear in 1 s, and the rear axle ends
    # 4 m deep in the bay before it drives out.
    radius, parameter = 5.0, 4.0
    spiral = parameter**2 / (2.0 * radius**2)
    turn = Layout().clothoid(parameter, 1.0 / radius).arc(radius, math.pi / 2 - 2 * spiral)
    turn.clothoid(parameter, 0.0)
    d = turn.x  # the turn's displacement along and across its entry direction (symmetric)
    bay_x, depth, offset = 20.0, 4.0, 3.5
    back_straight = 1.0
    lay = Layout().line(bay_x + back_straight + d)  # forward along the aisle, past the bay
    lay.gear("reverse").line(back_straight)
    lay.clothoid(parameter, 1.0 / radius).arc(radius, math.pi / 2 - 2 * spiral)
    lay.clothoid(parameter, 0.0).line(offset + depth - d)  # into the bay
    assert abs(lay.x - bay_x) < 1e-6 and abs(lay.y + offset + depth) < 1e-6, (lay.x, lay.y)
    lay.gear("forward").line(offset + depth - d)  # out of the bay, turning right
    lay.clothoid(parameter, -1.0 / radius).arc(-radius, -(math.pi / 2 - 2 * spiral))
    lay.clothoid(parameter, 0.0).line(15.0)
    assert abs(lay.y) < 1e-6, lay.y
    design = [
        "Parking-lot manoeuvre with two cusps: along a 6.00 m aisle past a 90 deg bay of 2.50 m x",
        "5.00 m (EAR 2005, FGSV: 90 deg parking), the rear axle 3.5 m from the bay line;",
        "stop, reverse into the bay (clothoid A = 4 m, R = 5 m, clothoid: 90 deg; the rear axle",
        "4 m deep), stop, drive out forwards turning right (the same turn mirrored) and 15 m on",
        "along the aisle. Each gear run starts and ends on a straight. A = 4 m: the clothoid asks",
        "v L / A^2 = 0.24 rad/s of steering rate at 1.5 m/s (the cars allow 0.4). Speed: 1.5 m/s",
        "(5.4 km/h), 0.5 m/s^2 up and down, 1 s at rest at each cusp (speed.cusp_rest_s);",
        "a_lat <= 1 m/s^2 does not bind at R = 5 m.",
    ]
    write("scenarios/roads/parking_lot.yaml", "parking_lot",
          "Parking lot: reverse into a 90 deg bay (EAR 2005), drive out; two cusps at 1.5 m/s",
          design, lay,
          "{profile: curvature, max_mps: 1.5, max_lateral_acceleration_mps2: 1.0, "
          "max_acceleration_mps2: 0.5, max_deceleration_mps2: 0.5, cusp_rest_s: 1.0}",
          90.0, "../", PARKING_SIMULATION, PARKING_CONTROLLER)


def hairpin():
    # The hairpin test of the certified controller: straight, a 6 m clothoid into R = 12 m,
    # the half turn, a 6 m clothoid out, straight, at the speed where R = 12 m asks 6 m/s^2.
    radius, transition = 12.0, 6.0
    parameter = math.sqrt(transition * radius)
    lay = Layout().line(50.0)
    lay.bend(radius, math.pi, parameter, parameter).line(60.0)
    speed = math.sqrt(6.0 * radius)
    design = [
        "Hairpin: 50 m straight, a clothoid of 6 m (A = sqrt(6 * 12) = 8.49 m) into R = 12 m,",
        "the rest of a 180 deg left turn, a 6 m clothoid out, 60 m straight; constant speed",
        "sqrt(6 m/s^2 * 12 m) = %.3f m/s (6 m/s^2 of lateral acceleration on the arc)." % speed,
        "Everything else as lane_change_15.yaml.",
    ]
    write("scenarios/hairpin.yaml", "hairpin",
          "Hairpin: straight, 6 m clothoid, R = 12 m half turn at 8.49 m/s (6 m/s^2)", design,
          lay, "{initial_mps: %r}" % round(speed, 4), 30.0, "")


if __name__ == "__main__":
    os.makedirs(os.path.join(ROOT, "scenarios", "roads"), exist_ok=True)
    rural_80()
    mountain_hairpins()
    motorway_exit()
    roundabout()
    urban_turn()
    parking_lot()
    hairpin()
