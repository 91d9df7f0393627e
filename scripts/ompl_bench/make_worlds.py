#!/usr/bin/env python3
"""Seeded random-disc worlds for the OMPL RRT* comparison (scripts/ompl_bench/run.sh).

Each world is one list of circles written twice, from that one list:

* WORLD.toml: a tidepath scenario (2-D, still water, safety distance 0, cost = length), the
  file `tidepath plan` reads;
* WORLD.txt: the same world for scripts/ompl_bench/ompl_rrtstar.cpp, one line of bounds,
  start and goal, then one circle per line.

tidepath has no command that writes a scenario's obstacles in another form, so the generator
writes both files; after writing, it reads the TOML back (tomllib) and checks that it holds
exactly the circles, bounds, start and goal of the text file. Floats are written with repr,
which reads back bit for bit.

World k (1-based) is drawn from random.Random(WORLD_SEED_BASE + k): the same k always gives
the same world, on any machine.

  python3 scripts/ompl_bench/make_worlds.py --worlds 3 --out DIR [--samples 10000]
"""

import argparse
import math
import os
import random
import sys

WORLD_SEED_BASE = 20240600
XMAX, YMAX = 20000.0, 40000.0
START = (10000.0, 1000.0)
GOAL = (10000.0, 39000.0)
N_CIRCLES = 40
R_MIN, R_MAX = 400.0, 1500.0
# Every circle keeps at least this much water between its edge and the start and the goal.
ENDPOINT_MARGIN = 100.0
SAFETY_DISTANCE = 0.0
RANGE_M = 1000.0
RESOLUTION_M = 25.0


def circles_for(k):
    rng = random.Random(WORLD_SEED_BASE + k)
    out = []
    while len(out) < N_CIRCLES:
        r = rng.uniform(R_MIN, R_MAX)
        cx, cy = rng.uniform(0.0, XMAX), rng.uniform(0.0, YMAX)
        if any(math.hypot(cx - px, cy - py) < r + SAFETY_DISTANCE + ENDPOINT_MARGIN for px, py in (START, GOAL)):
            continue
        out.append((cx, cy, r))
    return out


def toml_text(name, circles, samples, planner_params, planner_id='rrt-star'):
    lines = [
        f'# Written by scripts/ompl_bench/make_worlds.py (world seed {name}); the same world as {name}.txt.',
        '# 2-D, 20 km x 40 km, 40 discs, still water, safety distance 0: cost = length / start-goal distance.',
        f'name = "{name}"',
        'description = "OMPL RRT* comparison world: random discs between start and goal at opposite ends"',
        '',
        '[world]',
        'dimensions = 2',
        f'bounds = {{ min = [0.0, 0.0, 0.0], max = [{XMAX!r}, {YMAX!r}, 0.0] }}',
        '',
    ]
    for cx, cy, r in circles:
        lines += ['[[world.obstacles]]', 'kind = "circle"', f'center = [{cx!r}, {cy!r}]', f'radius = {r!r}', '']
    lines += [
        '[vehicle]',
        'speed = 1.5',
        '# No turn limit and no clearance: the planners test the same discs as OMPL, and only length counts.',
        'max_turn_deg = 180.0',
        f'safety_distance = {SAFETY_DISTANCE!r}',
        '',
        '[mission]',
        f'start = [{START[0]!r}, {START[1]!r}, 0.0]',
        f'goal = [{GOAL[0]!r}, {GOAL[1]!r}, 0.0]',
        '',
        '[cost]',
        'model = "general"',
        '# Length only (over the straight start-goal distance); a collision would add 10 per hit.',
        'weights = { length = 1.0, time = 0.0, collision = 10.0, turn = 0.0, pitch = 0.0 }',
        '',
        '[planner]',
        f'id = "{planner_id}"',
        f'samples = {samples}',
        '',
    ]
    if planner_params:
        lines += ['[planner.params.rrt-star]']
        lines += [f'{key} = {value}' for key, value in planner_params]
        lines += ['']
    return '\n'.join(lines)


def txt_text(name, circles):
    lines = [
        f'# {name}: xmin ymin xmax ymax start_x start_y goal_x goal_y, then cx cy r per circle (metres)',
        f'0.0 0.0 {XMAX!r} {YMAX!r} {START[0]!r} {START[1]!r} {GOAL[0]!r} {GOAL[1]!r}',
    ]
    lines += [f'{cx!r} {cy!r} {r!r}' for cx, cy, r in circles]
    return '\n'.join(lines) + '\n'


def check_same(toml_path, txt_path):
    """The TOML, read as tidepath reads TOML, holds exactly the text file's world."""
    try:
        import tomllib
    except ImportError:  # Python before 3.11
        try:
            import tomli as tomllib
        except ImportError:
            print(f'no tomllib (Python < 3.11) nor tomli: {toml_path} not read back', file=sys.stderr)
            return
    with open(toml_path, 'rb') as f:
        doc = tomllib.load(f)
    with open(txt_path) as f:
        rows = [[float(v) for v in line.split()] for line in f if line.strip() and not line.startswith('#')]
    head, circles = rows[0], rows[1:]
    bounds = doc['world']['bounds']
    assert [bounds['min'][0], bounds['min'][1], bounds['max'][0], bounds['max'][1]] == head[:4], toml_path
    assert doc['mission']['start'][:2] == head[4:6] and doc['mission']['goal'][:2] == head[6:8], toml_path
    got = [[*o['center'], o['radius']] for o in doc['world']['obstacles'] if o['kind'] == 'circle']
    assert got == circles and len(got) == len(doc['world']['obstacles']), toml_path


def parse_param(text):
    key, _, value = text.partition('=')
    if not key or not value:
        raise argparse.ArgumentTypeError(f'expected KEY=VALUE, got {text!r}')
    return key.strip(), value.strip()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--worlds', type=int, default=3, help='number of worlds (default 3)')
    ap.add_argument('--samples', type=int, default=10000, help='[planner] samples in the TOML (default 10000)')
    ap.add_argument('--param', type=parse_param, action='append', default=None,
                    help='a [planner.params.rrt-star] line KEY=VALUE (TOML value); repeatable. '
                    f'Default: range = {RANGE_M!r}, resolution = {RESOLUTION_M!r}')
    ap.add_argument('--planner-id', default='rrt-star', help='[planner] id in the TOML (default rrt-star)')
    ap.add_argument('--no-params', action='store_true', help='write no [planner.params.rrt-star] section')
    ap.add_argument('--out', required=True, help='folder for wK.toml and wK.txt')
    args = ap.parse_args()
    params = args.param
    if params is None:
        params = [('range', repr(RANGE_M)), ('resolution', repr(RESOLUTION_M))]
    if args.no_params:
        params = []
    os.makedirs(args.out, exist_ok=True)
    for k in range(1, args.worlds + 1):
        name = f'w{k}'
        circles = circles_for(k)
        toml_path, txt_path = os.path.join(args.out, name + '.toml'), os.path.join(args.out, name + '.txt')
        with open(toml_path, 'w') as f:
            f.write(toml_text(name, circles, args.samples, params, args.planner_id))
        with open(txt_path, 'w') as f:
            f.write(txt_text(name, circles))
        check_same(toml_path, txt_path)
        print(f'{name}: {len(circles)} circles -> {toml_path}, {txt_path}', file=sys.stderr)


if __name__ == '__main__':
    main()
