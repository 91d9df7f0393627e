"""Writes the built-in scenarios of acopf2016 (docs/papers/acopf2016.md), a wave glider on a grid
map: crates/tidepath-io/scenarios/glider-1.toml .. glider-4.toml and glider-ocean.toml, with
glider-ocean's synthetic data, crates/tidepath-io/data/glider_ocean.nc (wave and current
forecast) and crates/tidepath-io/data/glider_ocean_topo.nc (elevation). Edit this script, not
the files, and run it again:

    python3 -m venv /tmp/venv && /tmp/venv/bin/pip install netCDF4 numpy
    /tmp/venv/bin/python scripts/make_acopf2016_scenarios.py

The TOML files need only Python; the two NetCDF files need numpy and netCDF4 (imported only to
write them; `--toml-only` writes the TOML files alone). Everything is deterministic: running the script again rewrites the same bytes
(checked with netCDF4 1.7.5, netCDF 4.10.1, HDF5 2.2.0, numpy 2.4).

glider-1 .. glider-4: the paper's 20 x 20 grid (section 4). What is ours, not the paper's:

- Cell size a = 1000 m (the paper gives none): a 20 km square, about a day's glide at
  0.3 m/s, the speed of acopf2016's regression (eq. 1) in 2 m waves.
- The obstacle layout (Fig. 2's is not printed): 73 of the 400 cells blocked (18.25 %), drawn
  from rectangles below (OBSTACLES), every one mirrored in the diagonal x = y, so the map is
  symmetric under exchanging x and y: a reef in the north-west corner and its mirror in the
  south-east, a plus-shaped island on the diagonal in the south-west quarter, a reef across the
  diagonal in the middle, bars west and south of it and a pair of islands that leave a diagonal
  gate to the goal. The 3 x 3 cells around the start and the goal are free. Since the start
  and the goal lie on the diagonal, every route has a mirror image of the same length, and no
  route is its own mirror (the diagonal is blocked): in glider-1 the shortest route comes as two
  optimal paths of equal length, as Fig. 3 shows.
- Start cell 1 and goal cell 400 (eq. 3 numbering; the paper's s_str = 0 is not a cell: A1).
- Waves `kind = "cells"`, one height per cell at its centre (bilinear between centres):
  - glider-1: 2.0 m everywhere (the paper: "the wave remains unchanged"; 2.0 m, the height of
    the unchanged half of environments 2 and 3, so that glider-1 is glider-2 without the fall).
  - glider-2: 2.0 m where the cell's centre has x <= 10 cells, falling linearly to 0.5 m at
    x = 20: h = 2.0 - 1.5 (x - 10) / 10 (docs/papers/acopf2016.md, A11), so 1.925 m in column
    11 (centre x = 10.5) down to 0.575 m in column 20 (x = 19.5). No current.
  - glider-3: glider-2's waves plus a current of 0.5 m/s toward the south-east (+x, -y, y
    north: u = 0.5/sqrt(2), v = -0.5/sqrt(2)) in the cells whose centres lie in the paper's
    {10 < x <= 20, 8 <= y <= 16} (columns 11-20, rows 9-16 from the south), zero elsewhere.
  - glider-4 (the paper announces a fourth environment without describing it; this one is
    tidepath's design): a swell from the north-west, h = 2.0 + 0.05 (row - column) m (cell
    indices from the south-west), 2.95 m in the north-west corner cell down to 1.05 m in the
    south-east one, and a clockwise (anticyclonic) eddy, a Lamb-Oseen vortex (`kind =
    "vortices"`) centred at (8 km, 12 km), core radius 6 km, circulation -23,629 m^2/s, so it is
    fastest, 0.40 m/s, 6.7 km from its centre. The eddy flows north along the west edge and east
    along the north edge, and south-west across the diagonal south-east of its centre. So the
    shortest route, through the middle, meets 2 m waves and a head current, while the longer
    route round the west and north edges rides 2.5-3 m waves and a following current: the
    time-optimal and the shortest paths differ by a clear margin in time. The glider never
    stalls: 0.1623 x 1.05 m > 0.266 x 0.40 m/s, so even the lowest waves beat the strongest
    head current.
- Vehicle `kind = "wave-glider"` with the paper's regression (eq. 1: 0.1623 per metre of
  wave, 0.2660 per m/s of current along the heading, floor 0.05 m/s), safety distance 50 m
  (the blocked cells are the obstacles; a free cell's centre is 500 m from its neighbours'
  edges), no turn limit (max_turn_deg = 180: the grid's moves turn by up to 135 degrees and the
  paper limits none). The free cells are 100 m deep (the safety distance also holds below).
- `[model] current_step = 250` m: a 1 km move is flown in 4 pieces (a diagonal in 6), each at
  the waves and current of its place.
- Cost `general` with weights length 0, time 1, collision 10, turn 0, pitch 0: the objective is
  the glider's travel time (plus the collision penalty that keeps infeasible routes behind).
  The paper's ants minimise length (Q / L deposits) and it judges the routes by eye; time is
  our measure (docs/papers/acopf2016.md, cost).
- `[planner] id = "acopf"`, the paper's planner with its parameters (T = 60, K = 30); grid
  planners search the map's own cells by default.

glider-ocean: the same glider in a geographic world, the open Pacific around Nihoa in the
north-western Hawaiian Islands. The box is 2 x 2 degrees, 162.92-160.92 W, 22.06-24.06 N (about 205 x 222 km),
planned on a raster of 200 cells along its longer side (about 1.1 km). Everything in its data
is synthetic (neither a forecast nor a survey):

- glider_ocean_topo.nc: elevation (m, up positive) every 0.02 degrees, a 4000 m deep plain and
  one seamount at Nihoa's position (161.92 W, 23.06 N) whose top, 273 m (Nihoa's height),
  stands out of the water within 4 km of it: a small island (the real Nihoa is about 1 km long).
- glider_ocean.nc: a forecast in the layout of Copernicus Marine's products (CF-1.8; time in
  hours since 1950-01-01, every 6 h for 8 days from 2026-06-01T00:00Z, 33 steps; latitude,
  longitude every 0.02 degrees, 119 x 119 nodes over 163.10-160.74 W, 21.88-24.24 N, wider
  than the box so the scenario's cover of it is whole), three int16 packed variables with
  _FillValue:
  - VHM0 (sea_surface_wave_significant_height, scale 0.01 m): a swell band of 1.0 to 3.5 m,
    h = 1 + 2.5 exp(-((s - s0(t)) / 30 km)^2) (0.8 + 0.2 cos(2 pi a / 150 km)), where a and s
    are the distances along and to the left of (north-west of) the straight start-goal line from
    its middle; the band's axis lies 40 km north-west of the line at the first step and drifts
    south-east by 3 km a day.
  - uo, vo (eastward_sea_water_velocity, northward_sea_water_velocity, scale 0.001 m/s): a
    clockwise (anticyclonic) eddy of the Gaussian profile v(r) = 0.6 (r / R) exp((1 - r^2 / R^2)
    / 2) m/s, R = 30 km (fastest, 0.6 m/s, at 30 km), centred on the middle of the start-goal
    line at the first step and drifting west by 2 km a day, as eddies do.
  - Fill (land) at every node within 4 km of Nihoa in all three variables, so the readers'
    gaps are exercised; the elevation file's island covers them, so they are land, not
    water without data, in the scenario.
  Nowhere does a head current stop the glider: 0.1623 x 1.0 m > 0.266 x 0.6 m/s.
- Start 162.55 W, 22.55 N; goal 161.55 W, 23.60 N, 155 km apart, departing at the forecast's
  first step. The straight line passes 11 km north-west of the island, through the eddy's
  centre (its flow crosses the line there and does not help) and south-east of the swell band:
  the time-optimal route bends north-west into higher waves and the eddy's following flank.
- The planner is `acopf` as in glider-1 .. glider-4 (60 iterations of 30 ants take 0.4 s on
  this raster); `astar` finds the time-optimal route on it. Cost and vehicle as above, with a
  safety distance of 100 m from the island's shore.
- The metric grids of the forecast are 2000 m (the file's own spacing) and of the elevation
  1000 m.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "crates", "tidepath-io", "scenarios")
DATA = os.path.join(HERE, "..", "crates", "tidepath-io", "data")

N = 20  # cells per side (paper)
CELL = 1000.0  # m (ours)
SAFETY = 50.0  # m
WATER_DEPTH = 100.0  # m, under the free cells
CURRENT_STEP = 250.0  # m

# Blocked rectangles (column_min, column_max, row_min, row_max), 0-based cell indices from the
# south-west corner, inclusive; each is blocked together with its mirror in the diagonal.
OBSTACLES = [
    (0, 3, 16, 18),  # the north-west reef (and the south-east one)
    (11, 13, 15, 17),  # the pair of islands either side of the gate to the goal
    (5, 8, 6, 7),  # the plus-shaped island on the diagonal (two bars crossing)
    (6, 7, 5, 8),
    (2, 3, 10, 12),  # the west bar (and the south bar)
    (10, 11, 9, 10),  # the reef across the diagonal in the middle
]

# glider-2 and glider-3 (A11): 2.0 m up to x = 10 cells, falling linearly to 0.5 m at x = 20.
H_WEST, H_EAST, X_FALL = 2.0, 0.5, 10.0
# glider-3: 0.5 m/s toward the south-east in {10 < x <= 20, 8 <= y <= 16} (cell units).
BAND_SPEED = 0.5
# glider-4: swell from the north-west and a clockwise Lamb-Oseen eddy.
SWELL_MID, SWELL_PER_CELL = 2.0, 0.05
EDDY_X, EDDY_Y, EDDY_CORE, EDDY_PEAK = 8000.0, 12000.0, 6000.0, 0.40
# Peak speed of a Lamb-Oseen vortex: strength (1 - e^{-r*^2}) / (2 pi r* core), r* = 1.1209.
LAMB_PEAK_R = 1.1209064232
EDDY_STRENGTH = -round(
    EDDY_PEAK * 2.0 * math.pi * LAMB_PEAK_R * EDDY_CORE / (1.0 - math.exp(-LAMB_PEAK_R**2))
)


def blocked():
    """The set of blocked (column, row) cells."""
    cells = set()
    for (c0, c1, r0, r1) in OBSTACLES:
        for c in range(c0, c1 + 1):
            for r in range(r0, r1 + 1):
                cells.add((c, r))
                cells.add((r, c))
    return cells


def grid_map():
    cells = blocked()
    return ["".join("#" if (c, r) in cells else "." for c in range(N)) for r in reversed(range(N))]


def num(v):
    """A number as TOML: the shortest text of it rounded to 8 decimals."""
    v = round(v, 8) + 0.0
    text = repr(v)
    return text if ("." in text or "e" in text) else text + ".0"


def rows_toml(key, value):
    """`key = [[...], ...]`: one row of the grid per line, north first; value(column, row)."""
    lines = [f"{key} = ["]
    for r in reversed(range(N)):
        lines.append("  [" + ", ".join(num(value(c, r)) for c in range(N)) + "],")
    lines.append("]")
    return "\n".join(lines)


def glider2_height(c, r):
    x = c + 0.5
    return H_WEST if x <= X_FALL else H_WEST - (H_WEST - H_EAST) * (x - X_FALL) / (N - X_FALL)


def in_band(c, r):
    x, y = c + 0.5, r + 0.5
    return 10.0 < x <= 20.0 and 8.0 <= y <= 16.0


def world(waves, current):
    lines = [
        "[world]",
        "dimensions = 2",
        f"bounds = {{ min = [0.0, 0.0, 0.0], max = [{N * CELL:.1f}, {N * CELL:.1f}, 0.0] }}",
        "",
        f"# The grid map: {len(blocked())} of {N * N} cells blocked ('#'), rows from north to south,",
        "# symmetric in the diagonal x = y.",
        "[world.terrain]",
        'kind = "cells"',
        "origin = [0.0, 0.0]",
        f"resolution = {CELL:.1f}",
        f"water_depth = {WATER_DEPTH:.1f}                # open sea under the free cells, deeper than the safety distance",
        "map = [",
    ]
    lines += [f'  "{row}",' for row in grid_map()]
    lines.append("]")
    lines += ["", waves]
    if current:
        lines += ["", current]
    return "\n".join(lines)


def cells_header(what):
    return "\n".join([what, "[world.waves]", 'kind = "cells"', "origin = [0.0, 0.0]", f"resolution = {CELL:.1f}"])


def waves_uniform(h):
    return "\n".join(["# The wave remains unchanged (environment 1).", "[world.waves]", 'kind = "uniform"', f"height = {num(h)}"])


def waves_glider2():
    return "\n".join([
        cells_header("# Significant wave height (m) per cell: 2.0 where the centre's x <= 10 km, then\n"
                     "# 2.0 - 1.5 (x - 10 km) / 10 km, down to 0.575 m in the last column (rows north first)."),
        rows_toml("heights", glider2_height),
    ])


def current_glider3():
    u = BAND_SPEED / math.sqrt(2.0)
    return "\n".join([
        "# 0.5 m/s toward the south-east (u = 0.5/sqrt 2, v = -0.5/sqrt 2) in the cells whose centre lies in",
        "# {10 < x <= 20, 8 <= y <= 16} km: columns 11-20, rows 9-16 from the south; zero elsewhere.",
        "[world.current]",
        'kind = "cells"',
        "origin = [0.0, 0.0]",
        f"resolution = {CELL:.1f}",
        rows_toml("u", lambda c, r: u if in_band(c, r) else 0.0),
        rows_toml("v", lambda c, r: -u if in_band(c, r) else 0.0),
    ])


def waves_glider4():
    return "\n".join([
        cells_header("# A swell from the north-west: 2.0 + 0.05 (row - column) m, 2.95 m in the north-west\n"
                     "# corner cell down to 1.05 m in the south-east one (rows north first)."),
        rows_toml("heights", lambda c, r: SWELL_MID + SWELL_PER_CELL * (r - c)),
    ])


def current_glider4():
    return "\n".join([
        f"# A clockwise (anticyclonic) eddy: a Lamb-Oseen vortex, fastest ({EDDY_PEAK:.2f} m/s) {LAMB_PEAK_R * EDDY_CORE / 1000:.1f} km from",
        "# its centre; north along the west edge, east along the north edge, south-west across the",
        "# diagonal south-east of its centre.",
        "[world.current]",
        'kind = "vortices"',
        f"vortices = [{{ x = {EDDY_X:.1f}, y = {EDDY_Y:.1f}, strength = {EDDY_STRENGTH:.1f}, core_radius = {EDDY_CORE:.1f} }}]",
    ])


def vehicle(safety=SAFETY, why="the blocked cells are the obstacles"):
    return "\n".join([
        "# The paper's wave glider: speed over ground max(0.05, 0.1623 H + 0.2660 c_along) m/s (eq. 1).",
        "[vehicle]",
        'kind = "wave-glider"',
        "max_turn_deg = 180.0               # the grid's moves turn by up to 135 degrees; the paper limits none",
        f"safety_distance = {safety:.1f}             # {why}",
    ])


def mission_cells():
    return "\n".join([
        "# Cells numbered 1..400 row by row from the south-west (eq. 3): from the south-west corner",
        "# cell's centre (500, 500) to the north-east one's (19500, 19500).",
        "[mission]",
        "start_cell = 1",
        "goal_cell = 400",
    ])


def model_cost(step):
    return "\n".join([
        "[model]",
        f"current_step = {step:.1f}              # pieces flown at the waves and current of their place",
        "",
        "# The objective is the glider's travel time (the collision penalty keeps infeasible routes behind).",
        "[cost]",
        'model = "general"',
        "weights = { length = 0.0, time = 1.0, collision = 10.0, turn = 0.0, pitch = 0.0 }",
    ])


def planner_acopf():
    return "\n".join([
        "# The paper's improved ACOPF (T = 60 iterations, K = 30 ants) on the map's own cells.",
        "[planner]",
        'id = "acopf"',
        "iterations = 60",
    ])


HEADER = """# tidepath built-in scenario "{name}": {what} of acopf2016 (docs/papers/acopf2016.md).
# Written by scripts/make_acopf2016_scenarios.py: edit the script, not this file.
# Copy it with `tidepath scenario {name} > my.toml`.
#
# The paper's 20 x 20 grid of 1 km cells (the cell size is ours), a wave glider from cell 1 to
# cell 400, the objective its travel time. The obstacle layout (Fig. 2's is not printed) is ours,
# the same in glider-1 .. glider-4. What is ours and what is the paper's: the script's
# docstring and docs/papers/acopf2016.md (A1, A11).
{extra}"""


def scenario(name, what, description, body, extra=""):
    head = HEADER.format(name=name, what=what, extra=extra)
    return head + f'\nname = "{name}"\ndescription = "{description}"\n\n' + body + "\n"


def write(name, text):
    with open(os.path.join(OUT, f"{name}.toml"), "w") as f:
        f.write(text)


def grid_scenarios():
    tail = [vehicle(), mission_cells(), model_cost(CURRENT_STEP), planner_acopf()]
    write("glider-1", scenario(
        "glider-1", "environment 1 (fixed wave height, no current; Fig. 3)",
        "2-D: acopf2016's environment 1, a wave glider on a 20 x 20 grid map in 2 m waves everywhere, no current: two optimal paths of equal length",
        "\n\n".join([world(waves_uniform(H_WEST), None)] + tail)))
    write("glider-2", scenario(
        "glider-2", "environment 2 (variable wave height, no current; Fig. 4)",
        "2-D: acopf2016's environment 2, 2 m waves up to x = 10 km falling to 0.5 m at x = 20 km, no current: the quickest route keeps to the larger waves",
        "\n\n".join([world(waves_glider2(), None)] + tail)))
    write("glider-3", scenario(
        "glider-3", "environment 3 (variable wave height, fixed current; Fig. 5)",
        "2-D: acopf2016's environment 3, glider-2's waves and a 0.5 m/s south-east current in {10 < x <= 20, 8 <= y <= 16} km",
        "\n\n".join([world(waves_glider2(), current_glider3())] + tail)))
    extra = (
        "#\n# The fourth environment is tidepath's (the paper announces one without describing it): a\n"
        "# swell from the north-west and a clockwise eddy, so the shortest route through the middle\n"
        "# meets a head current in 2 m waves while the longer route round the west and north edges\n"
        "# rides 2.5-3 m waves and a following current.\n"
    )
    write("glider-4", scenario(
        "glider-4", "a fourth environment (tidepath's design)",
        "2-D: a wave glider on acopf2016's grid map in a north-west swell and a clockwise eddy: the short route meets a head current, the long one rides the eddy",
        "\n\n".join([world(waves_glider4(), current_glider4())] + tail), extra))


# ---------------------------------------------------------------------------------------------
# glider-ocean

BOX = ((-162.92, 22.06), (-160.92, 24.06))
NIHOA = (-161.92, 23.06)
START = (-162.55, 22.55)
GOAL = (-161.55, 23.60)
DEPARTURE = "2026-06-01T00:00:00Z"
T0_HOURS = 669840.0  # hours since 1950-01-01 of 2026-06-01T00:00Z (checked in main)
STEP_HOURS, STEPS = 6, 33
FILE_LON = (-163.10, 119)  # first longitude, count (0.02 degrees)
FILE_LAT = (21.88, 119)
SPACING = 0.02
ISLAND_FILL_KM = 4.0
ISLAND_TOP, FLOOR = 273.0, -4000.0
OCEAN_SAFETY = 100.0  # m
KM_PER_DEG_LAT = 110.75
KM_PER_DEG_LON = 111.32 * math.cos(math.radians(NIHOA[1]))


def km(lon, lat):
    """Local km east and north of Nihoa (equirectangular: ample for smooth synthetic fields)."""
    return ((lon - NIHOA[0]) * KM_PER_DEG_LON, (lat - NIHOA[1]) * KM_PER_DEG_LAT)


def ocean_fields(np):
    lon = np.round(FILE_LON[0] + SPACING * np.arange(FILE_LON[1]), 6)
    lat = np.round(FILE_LAT[0] + SPACING * np.arange(FILE_LAT[1]), 6)
    x, y = km(lon[None, :], lat[:, None])
    sx, sy = km(*START)
    gx, gy = km(*GOAL)
    mx, my = (sx + gx) / 2.0, (sy + gy) / 2.0
    length = math.hypot(gx - sx, gy - sy)
    dx, dy = (gx - sx) / length, (gy - sy) / length  # along the line
    nx, ny = -dy, dx  # to its left: north-west
    along = (x - mx) * dx + (y - my) * dy
    across = (x - mx) * nx + (y - my) * ny
    island = np.hypot(x, y) <= ISLAND_FILL_KM
    hs, us, vs = [], [], []
    for k in range(STEPS):
        days = k * STEP_HOURS / 24.0
        s0 = 40.0 - 3.0 * days
        h = 1.0 + 2.5 * np.exp(-(((across - s0) / 30.0) ** 2)) * (0.8 + 0.2 * np.cos(2.0 * math.pi * along / 150.0))
        ex, ey = mx - 2.0 * days, my
        rx, ry = x - ex, y - ey
        r = np.hypot(rx, ry)
        R = 30.0
        speed = 0.6 * (r / R) * np.exp(0.5 * (1.0 - (r / R) ** 2))
        with np.errstate(invalid="ignore", divide="ignore"):
            u = np.where(r > 0, speed * ry / r, 0.0)  # clockwise: (ry, -rx) / r
            v = np.where(r > 0, -speed * rx / r, 0.0)
        hs.append(np.ma.masked_where(island, h))
        us.append(np.ma.masked_where(island, u))
        vs.append(np.ma.masked_where(island, v))
    return lon, lat, np.ma.stack(hs), np.ma.stack(us), np.ma.stack(vs)


def write_ocean():
    import numpy as np
    from netCDF4 import Dataset

    lon, lat, h, u, v = ocean_fields(np)
    out = os.path.join(DATA, "glider_ocean.nc")
    with Dataset(out, "w", format="NETCDF4") as ds:
        ds.title = "Synthetic swell and eddy off Nihoa, north-western Hawaiian Islands (tidepath test data, not a forecast)"
        ds.Conventions = "CF-1.8"
        ds.source = "scripts/make_acopf2016_scenarios.py"
        ds.createDimension("time", STEPS)
        ds.createDimension("latitude", len(lat))
        ds.createDimension("longitude", len(lon))
        t = ds.createVariable("time", "f8", ("time",))
        t.units, t.calendar, t.standard_name, t.axis = "hours since 1950-01-01", "gregorian", "time", "T"
        t[:] = T0_HOURS + STEP_HOURS * np.arange(STEPS)
        yv = ds.createVariable("latitude", "f4", ("latitude",))
        yv.units, yv.standard_name, yv.axis = "degrees_north", "latitude", "Y"
        yv[:] = lat
        xv = ds.createVariable("longitude", "f4", ("longitude",))
        xv.units, xv.standard_name, xv.axis = "degrees_east", "longitude", "X"
        xv[:] = lon
        for name, std, scale, units, data in [
            ("VHM0", "sea_surface_wave_significant_height", 0.01, "m", h),
            ("uo", "eastward_sea_water_velocity", 0.001, "m s-1", u),
            ("vo", "northward_sea_water_velocity", 0.001, "m s-1", v),
        ]:
            var = ds.createVariable(
                name, "i2", ("time", "latitude", "longitude"), zlib=True, complevel=9, shuffle=True,
                fill_value=np.int16(-32767), chunksizes=(1, len(lat), len(lon)),
            )
            var.scale_factor, var.add_offset, var.units, var.standard_name = scale, 0.0, units, std
            var.set_auto_maskandscale(True)
            var[:] = data
    print(out, os.path.getsize(out), "bytes")

    # The elevation: a 4000 m plain and a seamount whose top stands out of the water within
    # ISLAND_FILL_KM of Nihoa (a Gaussian whose 0 m contour is that circle).
    x, y = km(lon[None, :], lat[:, None])
    r2 = x**2 + y**2
    width2 = ISLAND_FILL_KM**2 / math.log((ISLAND_TOP - FLOOR) / -FLOOR)
    z = FLOOR + (ISLAND_TOP - FLOOR) * np.exp(-r2 / width2)
    out = os.path.join(DATA, "glider_ocean_topo.nc")
    with Dataset(out, "w", format="NETCDF4") as ds:
        ds.title = "Synthetic elevation off Nihoa: a 4000 m plain and one islet (tidepath test data, not a survey)"
        ds.Conventions = "CF-1.8"
        ds.source = "scripts/make_acopf2016_scenarios.py"
        ds.createDimension("lat", len(lat))
        ds.createDimension("lon", len(lon))
        yv = ds.createVariable("lat", "f8", ("lat",))
        yv.units, yv.standard_name = "degrees_north", "latitude"
        yv[:] = lat
        xv = ds.createVariable("lon", "f8", ("lon",))
        xv.units, xv.standard_name = "degrees_east", "longitude"
        xv[:] = lon
        e = ds.createVariable("elevation", "f4", ("lat", "lon"), zlib=True, complevel=9, shuffle=True)
        e.units, e.standard_name, e.long_name = "m", "height_above_reference_ellipsoid", "Elevation relative to sea level"
        e[:] = z.astype("f4")
    print(out, os.path.getsize(out), "bytes")


def ocean_scenario():
    (w, s), (e, n) = BOX
    body = "\n".join([
        "[world]",
        "dimensions = 2",
        'frame = "geographic"',
        f"bounds = {{ min = [{w:.2f}, {s:.2f}, 0.0], max = [{e:.2f}, {n:.2f}, 0.0] }}",
        "",
        "# A 4000 m plain and an islet at Nihoa's position (synthetic).",
        "[world.terrain]",
        'kind = "file"',
        'path = "glider_ocean_topo.nc"',
        "resolution = 1000.0",
        "",
        "# Significant wave height (VHM0) and surface currents (uo, vo): synthetic, every 6 h for 8 days.",
        "[world.waves]",
        'kind = "file"',
        'path = "glider_ocean.nc"',
        "resolution = 2000.0",
        "",
        "[world.current]",
        'kind = "file"',
        'path = "glider_ocean.nc"',
        "resolution = 2000.0",
        "",
        vehicle(OCEAN_SAFETY, "from the island's shore"),
        "",
        "[mission]",
        f"start = [{START[0]:.2f}, {START[1]:.2f}, 0.0]",
        f"goal = [{GOAL[0]:.2f}, {GOAL[1]:.2f}, 0.0]",
        f'departure = "{DEPARTURE}"  # the forecast\'s first step',
        "",
        model_cost(500.0),
        "",
        "# The paper's improved ACOPF (T = 60, K = 30) on a raster of 200 cells along the box's longer",
        "# side (about 1.1 km); `--planner astar` finds the time-optimal route on the same raster.",
        "[planner]",
        'id = "acopf"',
        "iterations = 60",
    ])
    head = "\n".join([
        '# tidepath built-in scenario "glider-ocean": acopf2016\'s wave glider (docs/papers/acopf2016.md)',
        "# in the open Pacific around Nihoa, north-western Hawaiian Islands, on a wave and current",
        "# forecast read from NetCDF (VHM0, uo, vo packed int16, CF time in hours since 1950-01-01,",
        "# the island as fill). The data are synthetic, made by scripts/make_acopf2016_scenarios.py: a",
        "# swell band north-west of the straight start-goal line and a clockwise eddy centred on it, so",
        "# the quickest route bends north-west; a user's Copernicus Marine wave and current files read",
        "# the same way.",
        "# Written by scripts/make_acopf2016_scenarios.py: edit the script, not this file.",
        "# Copy it with `tidepath scenario glider-ocean > my.toml`.",
        "",
        'name = "glider-ocean"',
        'description = "2-D: a wave glider crossing 155 km of open Pacific off Nihoa (Hawaii) on a synthetic swell and eddy forecast (NetCDF)"',
        "",
        "",
    ])
    write("glider-ocean", head + body + "\n")


def main():
    import datetime

    hours = (datetime.datetime(2026, 6, 1) - datetime.datetime(1950, 1, 1)).total_seconds() / 3600.0
    assert hours == T0_HOURS, hours
    assert abs(len(blocked()) / (N * N) - 0.1825) < 1e-12
    grid_scenarios()
    ocean_scenario()
    if "--toml-only" not in sys.argv[1:]:
        write_ocean()


if __name__ == "__main__":
    main()
