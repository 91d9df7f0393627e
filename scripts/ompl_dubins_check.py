#!/usr/bin/env python3
"""Dubins lengths from OMPL, for tidepath's agreement check (issue #27).

Writes seeded random pose pairs with OMPL's lengths to a CSV; the ignored Rust test
crates/tidepath/tests/dubins_ompl.rs reads it (TIDEPATH_DUBINS_PAIRS=FILE) and compares
tidepath's lengths with them:

  python3 scripts/ompl_dubins_check.py --out pairs.csv
  TIDEPATH_DUBINS_PAIRS=pairs.csv cargo test -p tidepath --test dubins_ompl -- --ignored --nocapture

Needs the `ompl` wheel (pip install ompl==2.0.1). Rows:

* dims 2: OMPL's DubinsStateSpace(r) distance (the non-symmetric default) between SE(2)
  poses. Half the pairs lie within 4 r of each other, where the CCC words (LRL, RLR) win
  often; the rest within 20 r.
* dims 3: OMPL's OwenStateSpace(r, max_pitch) (the Dubins airplane of Owen, Beard & McLain
  2014) distance and path category (LOW_ALTITUDE, MEDIUM_ALTITUDE, HIGH_ALTITUDE, or NONE
  when OMPL finds no path and reports its maximum extent instead), with the path's phi,
  number of whole turns and radius.

Columns: dims,r,pitch,x0,y0,z0,th0,x1,y1,z1,th1,length,category,phi,turns,radius. Floats are
written with repr, which reads back exactly.
"""

import argparse
import math
import random
import sys


def pairs_2d(ob, rng, n):
    rows = []
    for i in range(n):
        r = rng.uniform(1.0, 50.0)
        reach = 4.0 if i % 2 == 0 else 20.0
        d, ang = rng.uniform(0.0, reach * r), rng.uniform(-math.pi, math.pi)
        x0, y0 = rng.uniform(-500.0, 500.0), rng.uniform(-500.0, 500.0)
        x1, y1 = x0 + d * math.cos(ang), y0 + d * math.sin(ang)
        th0, th1 = rng.uniform(-math.pi, math.pi), rng.uniform(-math.pi, math.pi)
        space = ob.DubinsStateSpace(r)
        a, b = space.allocState(), space.allocState()
        for state, (x, y, th) in ((a, (x0, y0, th0)), (b, (x1, y1, th1))):
            state.setX(x)
            state.setY(y)
            state.setYaw(th)
        length = space.distance(a, b)
        rows.append([2, r, 0.0, x0, y0, 0.0, th0, x1, y1, 0.0, th1, length, "PLANAR", 0.0, 0, r])
    return rows


def pairs_3d(ob, rng, n):
    rows = []
    for i in range(n):
        r = rng.uniform(1.0, 50.0)
        pitch = rng.uniform(0.1, 0.7)
        space = ob.OwenStateSpace(r, pitch)
        bounds = ob.RealVectorBounds(3)
        bounds.setLow(-1e6)
        bounds.setHigh(1e6)
        space.setBounds(bounds)
        d, ang = rng.uniform(0.0, 6.0 * r), rng.uniform(-math.pi, math.pi)
        # Height changes from a small fraction of the radius to ten radii: all three cases.
        dz = rng.uniform(-1.0, 1.0) * [0.5, 2.0, 10.0][i % 3] * r
        x0, y0, z0 = rng.uniform(-500.0, 500.0), rng.uniform(-500.0, 500.0), rng.uniform(-500.0, 0.0)
        p0 = (x0, y0, z0, rng.uniform(-math.pi, math.pi))
        p1 = (x0 + d * math.cos(ang), y0 + d * math.sin(ang), z0 + dz, rng.uniform(-math.pi, math.pi))
        states = []
        for p in (p0, p1):
            s = space.allocState()
            # OMPL 2.0.1's copyFromReals crashes on this space; the state indexes its x, y, z.
            s[0], s[1], s[2] = p[0], p[1], p[2]
            s.setYaw(p[3])
            states.append(s)
        path = space.getPath(states[0], states[1])
        length = space.distance(states[0], states[1])
        if path is None:
            category, phi, turns, radius = "NONE", 0.0, 0, r
        else:
            category = str(path.category()).split(".")[-1]
            phi, turns, radius = path.phi_, path.numTurns_, path.turnRadius_
        rows.append([3, r, pitch, *p0[:3], p0[3], *p1[:3], p1[3], length, category, phi, turns, radius])
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True, help="CSV file to write")
    ap.add_argument("--pairs", type=int, default=1000, help="pairs of each kind (2-D and 3-D)")
    ap.add_argument("--seed", type=int, default=27)
    args = ap.parse_args()
    try:
        from ompl import base as ob
    except ImportError as e:
        sys.exit(f"the ompl wheel is not installed here ({e})")
    rng = random.Random(args.seed)
    rows = pairs_2d(ob, rng, args.pairs) + pairs_3d(ob, rng, args.pairs)
    with open(args.out, "w") as f:
        f.write("dims,r,pitch,x0,y0,z0,th0,x1,y1,z1,th1,length,category,phi,turns,radius\n")
        for row in rows:
            f.write(",".join(repr(v) if isinstance(v, float) else str(v) for v in row) + "\n")
    cats = {}
    for row in rows:
        cats[row[12]] = cats.get(row[12], 0) + 1
    print(f"ompl: wrote {len(rows)} pairs to {args.out} ({', '.join(f'{k} {v}' for k, v in sorted(cats.items()))})")


if __name__ == "__main__":
    main()
