"""Writes the built-in scenarios of ijs2023 (docs/papers/ijs2023.md) into
crates/tidepath-io/scenarios/: ijs-static-1 .. ijs-static-4, ijs-current, ijs-strong-0.8,
ijs-strong-1.2 and ijs-fleet. Edit this script, not the files, and run it again:

    python3 scripts/make_ijs2023_scenarios.py

All eight share one world, the paper's area (157.1-157.6 E, 19.6-19.9 N, down to 6500 m) as
a geographic scenario. What is ours, not the paper's (its A10):

- The seabed. The paper reads a DEM it does not supply; here a synthetic field of five
  seamounts (Gaussian peaks, `kind = "peaks"`) on a 6200 m deep plain, chosen by hand so that
  every straight start-goal line of Table 1 / Figs. 10-12 runs into a seamount's flank, the
  summits reach 600-2000 m below the surface (the relief of a seamount province: the paper's
  figures show peaks rising some 5 km from the floor), and every start and goal has at least
  3 km of water under it.
- The box reaches 19.59 N, not 19.6 N: the paper's first start lies at 19.5980 N, just
  outside its own box.
- Threats. The paper draws radar cylinders (every depth), floating spheres and cubes without
  giving their sizes or places: two cylinders, two spheres and two boxes here, placed by hand
  across the four routes, each clear of every start and goal by more than 1.5 km.
- eq. 14's window. UB = UR = 5 cells of the paper's 100 x 100 x 100 grid: 5 x 333 m = 1665 m
  sideways (y) and 5 x 65 m = 325 m vertically; the same window prices the last move to the
  goal (the cost model's target penalty F_p3).
- d_safe = 65 m, one cell of the grid's depth.
- The jet (ijs-current, ijs-strong-*, ijs-fleet): mapped onto the whole box, jet time = clock
  / 2000 s; every point where it flows moves at the stated ratio of the AUV's speed (A7, A8).

Positions are written as longitude/latitude (starts, goals, obstacle centres and corners);
peaks are in metres in the scenario's local frame, whose origin is the box centre.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "crates", "tidepath-io", "scenarios")

LON = (157.10, 157.60)
LAT = (19.59, 19.90)
FLOOR = -6500.0
BASE = -6200.0
SPEED = 1.542  # 3 knots (paper)
UB, UR = 1665.0, 325.0  # eq. 14, metres (5 cells each)
D_SAFE = 65.0
WAYPOINTS = 38  # D = 40 points with the start and the goal (paper)

# Table 1 and Figs. 10-12: (start, goal) as (lon, lat, z).
PAIRS = [
    ((157.1083, 19.5980, -5349.05), (157.5881, 19.8841, -110.29)),
    ((157.1184, 19.8901, -5073.33), (157.5830, 19.6191, -551.45)),
    ((157.1336, 19.6552, -1102.90), (157.5780, 19.8359, -3308.69)),
    ((157.1790, 19.8509, -827.17), (157.5578, 19.6251, -4411.59)),
]

# Seamounts in local metres (x east, y north of the box centre): height above the plain.
PEAKS = [
    dict(x=-11000.0, y=-5000.0, height=5800.0, sigma_x=4000.0, sigma_y=3500.0),
    dict(x=0.0, y=2000.0, height=6150.0, sigma_x=5000.0, sigma_y=4000.0),
    dict(x=12000.0, y=-9000.0, height=4800.0, sigma_x=3500.0, sigma_y=3500.0),
    dict(x=-8000.0, y=10000.0, height=4500.0, sigma_x=3000.0, sigma_y=3000.0),
    dict(x=16000.0, y=8000.0, height=4200.0, sigma_x=3000.0, sigma_y=3000.0),
]

# Threats: radar cylinders (every depth), floating spheres, boxes ("cubes").
CYLINDERS = [((157.31, 19.635), 2500.0), ((157.44, 19.80), 2000.0)]
SPHERES = [((157.25, 19.80, -3500.0), 2500.0), ((157.41, 19.71, -1500.0), 2000.0)]
BOXES = [
    ((157.26, 19.70, -2500.0), (157.30, 19.73, -300.0)),
    ((157.52, 19.68, -4000.0), (157.55, 19.71, -1000.0)),
]


def fmt(v):
    return f"{v:.4f}" if abs(v) < 1000 else f"{v:.2f}"


def world(current_ratio):
    lines = [
        "[world]",
        "dimensions = 3",
        'frame = "geographic"',
        "# [longitude, latitude, z]: west, south, 6500 m deep .. east, north, sea surface.",
        f"bounds = {{ min = [{LON[0]:.2f}, {LAT[0]:.2f}, {FLOOR:.1f}], max = [{LON[1]:.2f}, {LAT[1]:.2f}, 0.0] }}",
        "",
        "# A synthetic seamount field (the paper's DEM is not available): peaks in metres in the",
        "# local frame (origin at the box centre), heights above a 6200 m deep plain.",
        "[world.terrain]",
        'kind = "peaks"',
        f"base = {BASE:.1f}",
        "peaks = [",
    ]
    for p in PEAKS:
        lines.append(
            f"  {{ x = {p['x']:.1f}, y = {p['y']:.1f}, height = {p['height']:.1f}, "
            f"sigma_x = {p['sigma_x']:.1f}, sigma_y = {p['sigma_y']:.1f} }},"
        )
    lines.append("]")
    for (c, r) in CYLINDERS:
        lines += ["", "[[world.obstacles]]   # radar range: every depth", 'kind = "cylinder"',
                  f"center = [{c[0]:.4f}, {c[1]:.4f}]", f"radius = {r:.1f}"]
    for (c, r) in SPHERES:
        lines += ["", "[[world.obstacles]]   # floating sphere", 'kind = "sphere"',
                  f"center = [{c[0]:.4f}, {c[1]:.4f}, {c[2]:.1f}]", f"radius = {r:.1f}"]
    for (lo, hi) in BOXES:
        lines += ["", "[[world.obstacles]]   # cube", 'kind = "box"',
                  f"min = [{lo[0]:.4f}, {lo[1]:.4f}, {lo[2]:.1f}]", f"max = [{hi[0]:.4f}, {hi[1]:.4f}, {hi[2]:.1f}]"]
    if current_ratio is not None:
        lines += [
            "",
            "# The meandering jet of eqs. 27-28 over the whole box, jet time = clock / 2000 s; every",
            f"# point where it flows moves at {current_ratio} x the AUV's speed (A7, A8).",
            "[world.current]",
            'kind = "jet"',
            f"speed_ratio = {current_ratio}",
        ]
    return "\n".join(lines)


def vehicle(speed_range=False):
    lines = [
        "[vehicle]",
        f"speed = {SPEED}                       # 3 knots",
    ]
    if speed_range:
        lines += ["speed_min = 0.257                   # 0.5 knots", "speed_max = 2.058                   # 4 knots"]
    lines += [
        "max_turn_deg = 180.0                # no turn limit but eq. 14's window (the paper's)",
        "max_pitch_deg = 90.0",
        "depth_min = 5.0",
        "depth_max = 6500.0",
        f"safety_distance = {D_SAFE:.1f}              # d_safe: one cell of the paper's grid depth",
    ]
    return "\n".join(lines)


def encoding():
    return "\n".join([
        f"# D = 40 points: {WAYPOINTS} on planes x = const between the start and the goal (the paper's",
        "# planes parallel to YOZ), at most UB sideways and UR vertically from one to the next (eq. 14).",
        "[encoding]",
        'kind = "sliced"',
        'axis = "x"',
        f"waypoints = {WAYPOINTS}",
        f"lateral_step = {UB:.1f}",
        f"vertical_step = {UR:.1f}",
    ])


def cost(c1, c2):
    return "\n".join([
        "[model]",
        'travel_time = "vector-sum"         # eq. 17: the AUV\'s velocity plus the current, as vectors',
        "",
        "# Fit = F_p1 (c1 F_t + c2 F_p2 + c3 F_p3) (eq. 15); the window prices the last move (F_p3).",
        "[cost]",
        'model = "ijs2023"',
        f"weights = {{ w_time = {c1}, w_current = {c2}, lateral_step = {UB:.1f}, vertical_step = {UR:.1f}, target_axis = \"x\" }}",
    ])


def planner():
    return "\n".join([
        "# IJS with the paper's 45 jellyfish and 500 iterations (22 500 evaluations).",
        "[planner]",
        'id = "ijs"',
        "population = 45",
        "iterations = 500",
    ])


def mission(pair):
    (s, g) = pair
    return "\n".join([
        "[mission]",
        f"start = [{s[0]:.4f}, {s[1]:.4f}, {s[2]:.2f}]",
        f"goal = [{g[0]:.4f}, {g[1]:.4f}, {g[2]:.2f}]",
    ])


HEADER = """# tidepath built-in scenario "{name}": {what} of ijs2023 (docs/papers/ijs2023.md).
# Written by scripts/make_ijs2023_scenarios.py: edit the script, not this file.
# Copy it with `tidepath scenario {name} > my.toml`.
#
# The paper's area (157.1-157.6 E, 19.6-19.9 N, down to 6500 m) over a synthetic seamount field
# (the paper's DEM is not available), with radar cylinders, floating spheres and cubes placed by
# hand (the paper gives none of their values). What is ours and what is the paper's: the script's
# docstring and docs/papers/ijs2023.md (A7, A8, A10).
"""


def scenario(name, what, description, body):
    return HEADER.format(name=name, what=what) + f'\nname = "{name}"\ndescription = "{description}"\n\n' + body + "\n"


def write(name, text):
    with open(os.path.join(OUT, f"{name}.toml"), "w") as f:
        f.write(text)


def main():
    for k, pair in enumerate(PAIRS, start=1):
        roman = ["I", "II", "III", "IV"][k - 1]
        fig = {1: "Table 1, Fig. 9", 2: "Fig. 10", 3: "Fig. 11", 4: "Fig. 12"}[k]
        body = "\n\n".join([world(None), vehicle(), mission(pair), cost(1.0, 0.0), encoding(), planner()])
        write(f"ijs-static-{k}", scenario(
            f"ijs-static-{k}", f"static experiment {roman} ({fig})",
            f"3-D: ijs2023's static experiment {roman} over a seamount field, 40 points on planes across x, time-optimal, no current",
            body))
    for (name, ratio, what) in [
        ("ijs-current", 0.5, "the current experiment (Table 2, Fig. 13)"),
        ("ijs-strong-0.8", 0.8, "the strong-current experiment at 0.8 x the AUV's speed (Table 3)"),
        ("ijs-strong-1.2", 1.2, "the strong-current experiment at 1.2 x the AUV's speed (Table 3)"),
    ]:
        body = "\n\n".join([world(ratio), vehicle(), mission(PAIRS[0]), cost(0.7, 0.3), encoding(), planner()])
        write(name, scenario(
            name, what,
            f"3-D: ijs2023's experiment I in a meandering jet at {ratio} x the AUV's speed, time plus current-angle penalty",
            body))
    # The fleet (section IV-C, Fig. 17): three AUVs, speeds in [0.5, 4] knots, a current at
    # 0.2 x the AUV's speed, one goal. Goals 250 m apart around the paper's common goal so the vehicles
    # can arrive together without meeting (separation 100 m, chosen: A15).
    (g_lon, g_lat, g_z) = PAIRS[0][1]
    dlat = 250.0 / 110700.0
    dlon = 250.0 / (111320.0 * math.cos(math.radians(g_lat)))
    goals = [(g_lon - dlon, g_lat, g_z), (g_lon, g_lat + dlat, g_z), (g_lon, g_lat - dlat, g_z)]
    # Fig. 17's starts (its path 1 prints 119.6191 N, a typo for 19.6191 N: A15).
    starts = [(157.3558, 19.6191, -3308.69), (157.1790, 19.7455, -3308.69), (157.2043, 19.6552, -3308.69)]
    missions = []
    for (name, s, g) in zip(["auv-1", "auv-2", "auv-3"], starts, goals):
        missions.append("\n".join([
            "[[missions]]",
            f'name = "{name}"',
            f"start = [{s[0]:.4f}, {s[1]:.4f}, {s[2]:.2f}]",
            f"goal = [{g[0]:.4f}, {g[1]:.4f}, {g[2]:.2f}]",
        ]))
    fleet = "\n".join([
        "# Arrive together (within 60 s) and never closer than 100 m (A15: the paper gives no values).",
        "[fleet]",
        "separation_m = 100.0",
        'arrival = "together"',
        "arrival_tolerance_s = 60.0",
    ])
    body = "\n\n".join([world(0.2), vehicle(speed_range=True)] + missions + [fleet, cost(0.7, 0.3), encoding(), planner()])
    write("ijs-fleet", scenario(
        "ijs-fleet", "the multi-AUV experiment (section IV-C, Fig. 17)",
        "3-D: ijs2023's fleet (Fig. 17), three AUVs at 0.5-4 knots from three starts 3300 m deep to one goal, arriving together",
        body))


if __name__ == "__main__":
    main()
