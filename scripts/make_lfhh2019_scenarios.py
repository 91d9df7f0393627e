"""Writes the built-in scenarios of lfhh2019 (docs/papers/lfhh2019.md):
crates/tidepath-io/scenarios/lfhh-2d.toml, lfhh-3d-1.toml, lfhh-3d-2.toml and lfhh-3d-3.toml.

The paper prints no obstacle, vortex or seabed values (A4), so they are drawn here once, with
Python's own `random.Random(<scenario name>)` (deterministic for a string seed), and written into
the files. Edit this script, not the files, and run it again:

    python3 scripts/make_lfhh2019_scenarios.py

What is drawn, and what a draw must satisfy (else it is redrawn from the same stream):

- 2-D: 12 circles, radius U[0.8, 1.5] km, centre uniform in the 40 x 20 km box. 3-D: 10
  spheres, radius U[1, 2] km, centre uniform in the 40 x 20 x 20 km box. Each lies whole inside
  the box with 0.5 km to spare, keeps 1 km clear of every start and target of the scenario
  (Tables 2 and 3), and keeps 0.5 km from every other one. Disjoint shapes clear of the box's
  edges leave the water around them connected, so no draw makes a pair unreachable (the
  seabed peaks below stay far below the surface).
- The set as a whole is redrawn until the straight line of the scenario's first pair (its
  [mission]) crosses a circle, a sphere or the seabed: planning matters.
- 4 Lamb-Oseen vortices, centre uniform in the box 2 km inside its edges, 4 km apart.
- Values are rounded to 10 m.

The seabed peaks of the 3-D scenarios (eq. 11) are chosen by hand, below (PEAKS).
"""
import math
import os
import random
import re
import textwrap

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "crates", "tidepath-io", "scenarios")

KM = 1000.0
LENGTH_X, WIDTH_Y, DEPTH = 40 * KM, 20 * KM, 20 * KM  # tidepath x (paper Y), y (paper X), depth
ETA, ZETA = 2000.0, 1200.0  # eta = 2.0 km m/s in m^2/s, zeta = 1.2 km in m (see the header)
CLEAR_ENDS, GAP, EDGE = 1 * KM, 0.5 * KM, 0.5 * KM
MOVE = 1 * KM
CHANGES_AT = [6 * KM * k for k in range(1, 6)]

# Start/target pairs, (X, Y[, Z]) km as printed; scenarios of Table 5 (A11).
PAIRS = {
    "lfhh-2d": [((13, 0), (6, 39)), ((6, 0), (8, 39)), ((5, 0), (12, 39))],
    "lfhh-3d-1": [((12, 0, 7), (3, 39, 15)), ((14, 0, 8), (5, 39, 13))],
    "lfhh-3d-2": [((13, 0, 7), (7, 39, 5)), ((12, 0, 7), (13, 39, 5))],
    "lfhh-3d-3": [((9, 0, 6), (15, 39, 4)), ((12, 0, 5), (5, 39, 8))],
}

# Seabed peaks of eq. 11, Z_s = h exp(-((Y - y0)^2 a^2 + (X - x0)^2 b^2) / (2 sigma^2)), in the
# paper's km: (x0, y0, h, a, b, sigma). Chosen: one, two and three peaks, each under the middle
# of the scenario's first straight line, standing above it there, and far below every start
# and target.
PEAKS = {
    "lfhh-3d-1": [(8, 20, 14, 1.0, 1.0, 4.0)],
    "lfhh-3d-2": [(12, 12, 10, 1.0, 1.5, 3.0), (9, 27, 9, 1.5, 1.0, 3.0)],
    "lfhh-3d-3": [(11, 10, 9, 1.0, 1.0, 3.0), (8, 22, 11, 1.2, 0.8, 3.5), (14, 31, 8, 1.0, 1.0, 2.5)],
}


def to_tidepath(p):
    """A paper point (X, Y[, Z]) km as tidepath [x, y, z] m: x = Y, y = X, z = Z - 20 km."""
    if len(p) == 2:
        return (p[1] * KM, p[0] * KM, 0.0)
    return (p[1] * KM, p[0] * KM, p[2] * KM - DEPTH)


def peak_sigmas(pk):
    """eq. 11 as tidepath's h exp(-(dx/sigma_x)^2 - (dy/sigma_y)^2), with x = Y and y = X:
    sigma_x = sqrt(2) sigma / a (a multiplies Y), sigma_y = sqrt(2) sigma / b (b multiplies X)."""
    x0, y0, h, a, b, s = pk
    return (y0 * KM, x0 * KM, h * KM, math.sqrt(2) * s * KM / a, math.sqrt(2) * s * KM / b)


def seabed(name, x, y):
    z = -DEPTH
    for pk in PEAKS.get(name, []):
        px, py, h, sx, sy = peak_sigmas(pk)
        z += h * math.exp(-(((x - px) / sx) ** 2) - ((y - py) / sy) ** 2)
    return z


def r10(v):
    return round(v / 10.0) * 10.0


def dist(a, b):
    return math.sqrt(sum((p - q) ** 2 for p, q in zip(a, b)))


def segment_hits_ball(a, b, c, r):
    ab = [q - p for p, q in zip(a, b)]
    ac = [q - p for p, q in zip(a, c)]
    t = max(0.0, min(1.0, sum(u * v for u, v in zip(ab, ac)) / sum(u * u for u in ab)))
    closest = [p + t * u for p, u in zip(a, ab)]
    return dist(closest, c) < r


def draw_obstacles(name, rng, three):
    n, (rlo, rhi) = (10, (1 * KM, 2 * KM)) if three else (12, (0.8 * KM, 1.5 * KM))
    ends = [to_tidepath(p) for pair in PAIRS[name] for p in pair]
    dims = 3 if three else 2
    while True:
        shapes = []
        while len(shapes) < n:
            r = r10(rng.uniform(rlo, rhi))
            c = [r10(rng.uniform(0, LENGTH_X)), r10(rng.uniform(0, WIDTH_Y))]
            if three:
                c.append(r10(rng.uniform(-DEPTH, 0)))
            lo, hi = [0.0, 0.0, -DEPTH][:dims], [LENGTH_X, WIDTH_Y, 0.0][:dims]
            if any(c[i] - r < lo[i] + EDGE or c[i] + r > hi[i] - EDGE for i in range(dims)):
                continue
            if any(dist(c, e[:dims]) < r + CLEAR_ENDS for e in ends):
                continue
            if any(dist(c, o[0]) < r + o[1] + GAP for o in shapes):
                continue
            shapes.append((c, r))
        a, b = (to_tidepath(p)[:dims] for p in PAIRS[name][0])
        blocked = any(segment_hits_ball(a, b, c, r) for c, r in shapes)
        if three:
            line = [[p + k / 1000 * (q - p) for p, q in zip(a, b)] for k in range(1001)]
            blocked = blocked or any(p[2] < seabed(name, p[0], p[1]) for p in line)
        if blocked:
            return shapes


def draw_vortices(rng):
    vs = []
    while len(vs) < 4:
        c = [r10(rng.uniform(2 * KM, LENGTH_X - 2 * KM)), r10(rng.uniform(2 * KM, WIDTH_Y - 2 * KM))]
        if all(dist(c, v) >= 4 * KM for v in vs):
            vs.append(c)
    return vs


def peak_speed():
    """Peak speed of one vortex: at r = 1.1209 zeta (root of 2 q = e^q - 1, q = r^2/zeta^2)."""
    q = 1.2564312086261
    r = math.sqrt(q) * ZETA
    return ETA * (1 - math.exp(-q)) / (2 * math.pi * r), r


def fmt(v):
    return f"{v:.1f}"


def point(p):
    return "[" + ", ".join(fmt(v) for v in p) + "]"


def paper(p):
    return "(" + ", ".join(f"{v:g}" for v in p) + ")"


def header(name, three, shapes):
    """The file's header: paragraphs wrapped at 92 columns, and literal lines (lists)."""
    vmax, rmax = peak_speed()
    kind = "spheres" if three else "circles"
    text = []  # (paragraph, wrap?)

    def para(t):
        text.append((t, True))

    def lines(*ls):
        text.append(("\n".join(ls), False))

    if three:
        para(
            f'tidepath built-in scenario "{name}": 3-D scenario {name[-1]} of lfhh2019 (Tables 3 and 5; '
            "docs/papers/lfhh2019.md): an AUV crosses a 40 x 20 x 20 km deep-sea box over a Gaussian "
            "seabed (eq. 11), past 10 spheres, through 4 horizontal Lamb-Oseen vortices; spheres and "
            f"vortex centres move five times. Copy it with `tidepath scenario {name} > my.toml`. "
            "Written by scripts/make_lfhh2019_scenarios.py: edit the script, not this file."
        )
    else:
        para(
            'tidepath built-in scenario "lfhh-2d": the 2-D experiment of lfhh2019 (Table 2; '
            "docs/papers/lfhh2019.md): an AUV crosses a 40 x 20 km stretch of sea surface past 12 "
            "circular obstacles, through 4 Lamb-Oseen vortices; obstacles and vortex centres move "
            "five times. Copy it with `tidepath scenario lfhh-2d > my.toml`. Written by "
            "scripts/make_lfhh2019_scenarios.py: edit the script, not this file."
        )
    para(
        "Units: metres, seconds, m/s, degrees. Axes: the paper's horizontal axis Y (the direction of "
        "travel, 0-39 km) is tidepath's x (east); its vertical axis X (0-20 km) is tidepath's y "
        "(north). The box is the paper's, 40 km long: x in 0-40 km, the lines Y = 0 ... 39 (A13) at "
        "x = 0 ... 39 km, so the targets lie 1 km inside the east edge. "
        + (
            "The paper's Z (0-20 km, up from the bottom) is z = Z - 20 km: the surface is z = 0, the "
            "bottom of the box z = -20 km. A paper point (X, Y, Z) km is [1000 Y, 1000 X, 1000 Z - 20000] m "
            "here."
            if three
            else "A paper point (X, Y) km is [1000 Y, 1000 X] m here."
        )
    )
    pairs = ["Start/target pairs (paper km -> metres here); [mission] is the first:"]
    for s, g in PAIRS[name]:
        pairs.append(f"  {paper(s)} -> {paper(g)}: start = {point(to_tidepath(s))}, goal = {point(to_tidepath(g))}")
    pairs += [
        "`tidepath plan` takes another pair with --from X,Y[,Z] --to X,Y[,Z] (metres); `simulate`",
        "has no such option: copy the file and edit [mission].",
    ]
    lines(*pairs)
    if three:
        ends = [to_tidepath(p) for pair in PAIRS[name] for p in pair]
        clear = min(e[2] - seabed(name, e[0], e[1]) for e in ends)
        peaks = [
            "Seabed (eq. 11), chosen by hand (the paper prints none): under the middle of the first",
            "pair's straight line and above it there, far below every start and target (the nearest",
            f"is {clear / KM:.1f} km above the seabed). In the paper's km as (x0, y0, h, a, b, sigma) and as",
            "tidepath's peaks h exp(-((x - x_p)/sigma_x)^2 - ((y - y_p)/sigma_y)^2) on the base",
            "z = -20 km, with x_p = y0, y_p = x0, sigma_x = sqrt(2) sigma / a (a multiplies Y) and",
            "sigma_y = sqrt(2) sigma / b (b multiplies X): Peak::from_seabed_eq11 with the axes swapped.",
        ]
        for pk in PEAKS[name]:
            px, py, h, sx, sy = peak_sigmas(pk)
            peaks.append(
                f"  {paper(pk)} -> x = {fmt(px)}, y = {fmt(py)}, height = {fmt(h)}, sigma_x = {sx:.1f}, sigma_y = {sy:.1f}"
            )
        lines(*peaks)
    lo, hi = ("1", "2") if three else ("0.8", "1.5")
    para(
        f"Obstacles (A4, counts and radii chosen): {len(shapes)} {kind}, radius U[{lo}, {hi}] km, drawn once by "
        f'the script (random.Random("{name}")): whole inside the box with 0.5 km to spare, 1 km clear of '
        "every start and target, 0.5 km apart, so every pair is connected at departure; redrawn until "
        "the straight line of the first pair is blocked"
        + (" (by a sphere or the seabed)." if three else " (by a circle).")
    )
    para(
        "Currents: 4 Lamb-Oseen vortices (eqs. 3-5, docs/papers/shared.md#lamb-oseen), all of the "
        "paper's eta = 2.0 and zeta = 1.2, counter-clockwise, centres drawn 2 km inside the box and "
        "4 km apart" + (", horizontal at every depth. " if three else ". ")
        + "Reading of the units: lengths in the paper are km and the formula's velocity is read as m/s, "
        "so eta = 2.0 km m/s = 2000 m^2/s (strength) and zeta = 1.2 km = 1200 m (core_radius). One "
        f"vortex peaks at {vmax:.3f} m/s, {rmax:.0f} m from its centre (r = 1.1209 zeta); four together "
        f"cannot exceed {4 * vmax:.2f} m/s."
    )
    para(
        "Vehicle: the paper gives no speed; 1.5 m/s, 8.9 times a vortex's peak speed and 2.2 times "
        "the four peaks added, so the vehicle always makes headway. max_turn_deg = 150: the paper's "
        "curvature rule flags an interior angle below pi/6 (A2), a heading change above 150 deg. No "
        "pitch limit (90 deg)"
        + (", the whole water column (depth 0-20 km)" if three else "")
        + ", no safety distance (the paper tests the segments against the shapes themselves)."
    )
    para(
        "Changes (A4, A5): every 6 km travelled along the route (after_distance = 6, 12, 18, 24 and "
        "30 km, the paper's literal wording), five change events, six phases. At each, "
        + (
            'every sphere moves by U[-1, 1] km per axis (law "uniform") and every vortex centre by '
            'N(0, 1 km) per axis (law "gaussian", standard deviation 1 km).'
            if three
            else 'every obstacle and every vortex centre moves by N(0, 1 km) per axis (law "gaussian", '
            "standard deviation 1 km)."
        )
        + " The entries of one change share their trigger, and `tidepath simulate` applies them as one "
        "event (one phase, one re-plan). The entries give no centre, so each move steps from where "
        "the obstacle or vortex is when the change applies (a random walk from change to change), "
        "clipped to the box. A draw that covers the vehicle or the goal is redrawn, at most 100 "
        "times (A9)."
    )
    para(
        'Cost, encoding, planner and loop: the paper\'s cost F (eq. 6, [cost] model = "lfhh2019"); '
        "Dim = 40 points, the 38 free ones on the lines x = 1 ... 38 km (sliced on axis x); LFHH with "
        f"NP = 200 and {300 if three else 100} generations per planning; with --planner rrt-star or prm-star, the "
        "paper's 300 samples and radius 15 km (RRT*'s range caps both its step and its rewiring "
        "radius; PRM*'s max_radius its connection radius, A8); lfhh2019's re-planning window "
        "([simulate] preset: W = 20, W + 1 on failure, a fresh re-plan at every change)."
    )
    out = []
    for t, wrap in text:
        if wrap:
            # No break inside "a = b" or between a number and its unit.
            glued = re.sub(r"(\d) (km|m/s|m|deg)\b", "\\1\xa0\\2", t.replace(" = ", "\xa0=\xa0"))
            out += [l.replace("\xa0", " ") for l in textwrap.wrap(glued, 92, break_on_hyphens=False)]
        else:
            out += t.split("\n")
        out.append("")
    return "\n".join(("# " + l).rstrip() for l in out[:-1]) + "\n"


def scenario(name):
    three = name != "lfhh-2d"
    rng = random.Random(name)
    shapes = draw_obstacles(name, rng, three)
    vortices = draw_vortices(rng)
    (s, g) = PAIRS[name][0]
    out = [header(name, three, shapes)]
    if three:
        desc = f"lfhh2019's 3-D scenario {name[-1]}: 10 moving spheres over a Gaussian seabed in 4 vortices, {paper(s)} -> {paper(g)} km"
    else:
        desc = f"lfhh2019's 2-D experiment: 12 moving circles in 4 moving vortices, (X, Y) {paper(s)} -> {paper(g)} km"
    out.append(f'name = "{name}"\ndescription = "{desc}"\n')
    out.append("[world]")
    if three:
        out.append("dimensions = 3\nbounds = { min = [0.0, 0.0, -20000.0], max = [40000.0, 20000.0, 0.0] }\n")
        out.append('[world.terrain]\nkind = "peaks"\nbase = -20000.0   # Z = 0\npeaks = [')
        for pk in PEAKS[name]:
            px, py, h, sx, sy = peak_sigmas(pk)
            out.append(
                f"  {{ x = {fmt(px)}, y = {fmt(py)}, height = {fmt(h)}, sigma_x = {sx:.1f}, sigma_y = {sy:.1f} }},   # eq. 11 {paper(pk)}"
            )
        out.append("]\n")
    else:
        out.append("dimensions = 2\nbounds = { min = [0.0, 0.0, 0.0], max = [40000.0, 20000.0, 0.0] }\n")
    for i, (c, r) in enumerate(shapes):
        out.append(f"[[world.obstacles]]   # obstacle {i}")
        out.append(f'kind = "{"sphere" if three else "circle"}"\ncenter = {point(c)}\nradius = {fmt(r)}\n')
    out.append('[world.current]\nkind = "vortices"\nvortices = [')
    for v in vortices:
        out.append(f"  {{ x = {fmt(v[0])}, y = {fmt(v[1])}, strength = {fmt(ETA)}, core_radius = {fmt(ZETA)} }},")
    out.append("]\n")
    out.append("[vehicle]\nspeed = 1.5\nmax_turn_deg = 150.0\nmax_pitch_deg = 90.0")
    if three:
        out.append("depth_min = 0.0\ndepth_max = 20000.0")
    out.append("safety_distance = 0.0\n")
    out.append(
        "# The travel clock reads the current once per segment (segments up to 2 km long, the lines\n"
        "# being 1 km apart), as the paper's cost does: its flow has no time in it, and nothing moves\n"
        "# between two changes, so a finer clock would change no verdict and cost 35 % more time."
    )
    out.append("[model]\ncurrent_step = 2000.0\n")
    out.append(f"[mission]\nstart = {point(to_tidepath(s))}   # {paper(s)} km\ngoal = {point(to_tidepath(g))}   # {paper(g)} km\n")
    out.append('[cost]\nmodel = "lfhh2019"\n')
    out.append("# Dim = 40: start, 38 free points on the lines x = 1 ... 38 km, target.")
    out.append('[encoding]\nkind = "sliced"\nwaypoints = 38\naxis = "x"\n')
    out.append(f'[planner]\nid = "lfhh"\npopulation = 200\niterations = {300 if three else 100}\n')
    out.append("# The baselines' settings (docs/papers/lfhh2019.md, Baselines): 300 samples, radius 15 km.")
    out.append("[planner.params.rrt-star]\nsamples = 300\nrange = 15000.0\n")
    out.append("[planner.params.prm-star]\nsamples = 300\nmax_radius = 15000.0\n")
    out.append('[simulate]\npreset = "lfhh2019"\n')
    for k, d in enumerate(CHANGES_AT, start=1):
        out.append(f"# Change {k} of 5, after {d / KM:g} km travelled: every obstacle and vortex centre moves.")
        for i, (c, r) in enumerate(shapes):
            law = "uniform" if three else "gaussian"
            out.append(
                f'[[changes]]\nafter_distance = {fmt(d)}\nkind = "move-obstacle"\nobstacle = {i}\n'
                f'random = {{ law = "{law}", scale = {fmt(MOVE)} }}\n'
            )
        for j, v in enumerate(vortices):
            out.append(
                f'[[changes]]\nafter_distance = {fmt(d)}\nkind = "move-vortex"\nvortex = {j}\n'
                f'random = {{ law = "gaussian", scale = {fmt(MOVE)} }}\n'
            )
    return "\n".join(out).rstrip() + "\n"


def main():
    for name in PAIRS:
        path = os.path.join(OUT, f"{name}.toml")
        with open(path, "w") as f:
            f.write(scenario(name))
        print(path)


if __name__ == "__main__":
    main()
