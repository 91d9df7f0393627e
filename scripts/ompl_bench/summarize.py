#!/usr/bin/env python3
"""The side-by-side table of scripts/ompl_bench/run.sh, as Markdown on standard output.

  python3 scripts/ompl_bench/summarize.py DIR/results.csv [DIR/optimum.csv]

One table per OMPL variant in the rows (its default k-nearest RRTstar, and the radius form):
per world, the median over seeds of each run's time (its fastest repeat) and the median final
length of OMPL's RRTstar and of tidepath's rrt-star, their ratios (tidepath / OMPL), how
many runs found a path, and the exact shortest length (tidepath's visibility planner) when
optimum.csv is given. A last row pools every world. Times are each planner's own solve time (see docs/ompl-benchmark.md).
"""

import csv
import statistics
import sys

OMPL, OMPL_RADIUS, TIDEPATH = 'ompl-rrtstar', 'ompl-rrtstar-radius', 'tidepath-rrt-star'


def med(values):
    return statistics.median(values) if values else float('nan')


def fmt(x, digits):
    return '–' if x != x else f'{x:.{digits}f}'


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        rows = list(csv.DictReader(f))
    optimum = {}
    if len(sys.argv) == 3:
        with open(sys.argv[2]) as f:
            optimum = {r['world']: float(r['optimum_m']) for r in csv.DictReader(f)}
    worlds = sorted({r['world'] for r in rows}, key=lambda w: (len(w), w))
    iterations = sorted({int(r['iterations']) for r in rows})

    # One entry per (world, seed, planner): the fastest of its repeats (a run is deterministic,
    # so its repeats differ only by the machine's load) and its length (the same in every repeat).
    runs = {}
    for r in rows:
        runs.setdefault((r['world'], r['seed'], r['planner']), []).append(r)
    differing = [key for key, reps in runs.items() if len({(x['length_m'], x['solved']) for x in reps}) > 1]
    repeats = sorted({len(reps) for reps in runs.values()})

    def stats(world, planner):
        mine = [reps for (w, _, p), reps in runs.items() if p == planner and world in (None, w)]
        times = [min(float(x['time_s']) for x in reps) for reps in mine]
        lengths = [float(reps[0]['length_m']) for reps in mine if reps[0]['solved'] == '1']
        return med(times), med(lengths), len(lengths), len(mine)

    present = {r['planner'] for r in rows}
    for ompl, title in [(OMPL, "OMPL's RRTstar as it comes (k-nearest rewiring)"),
                        (OMPL_RADIUS, "OMPL's RRTstar with setKNearest(false): the radius form tidepath's rrt-star uses")]:
        if ompl not in present:
            continue
        print(f'{title}:')
        print()
        print('| world | optimum (m) | OMPL time/run (s) | tidepath time/run (s) | time tidepath/OMPL '
              '| OMPL length (m) | tidepath length (m) | length tidepath/OMPL | paths found OMPL, tidepath |')
        print('| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |')
        for label, world in [(w, w) for w in worlds] + [('all', None)]:
            ot, ol, on, oruns = stats(world, ompl)
            tt, tl, tn, truns = stats(world, TIDEPATH)
            opt = optimum.get(label, float('nan'))
            print(f'| {label} | {fmt(opt, 1)} | {fmt(ot, 3)} | {fmt(tt, 3)} | {fmt(tt / ot if truns else float("nan"), 2)} '
                  f'| {fmt(ol, 1)} | {fmt(tl, 1)} | {fmt(tl / ol if tn else float("nan"), 4)} '
                  f'| {on}/{oruns}, {tn}/{truns} |')
        print()
    print(f'Medians over seeds ("all": over every world and seed) of each run\'s fastest of '
          f'{"/".join(map(str, repeats))} repeat(s); iterations per run: {", ".join(map(str, iterations))} '
          '(OMPL: numIterations(); tidepath: the plan\'s samples). Lengths over runs that found a path; '
          'optimum: the exact shortest path (tidepath\'s visibility planner).')
    if differing:
        print()
        print('Runs whose repeats ended differently (not deterministic): '
              + ', '.join(f'{p} {w} seed {sd}' for w, sd, p in sorted(differing)))
    bad = [r for r in rows if r['planner'] != TIDEPATH and r['solved'] == '1' and r['tidepath_verdict'] != 'feasible']
    if bad:
        print()
        print(f'{len(bad)} OMPL path(s) that tidepath eval does not find feasible: '
              + ', '.join(f'{r["world"]} seed {r["seed"]} ({r["tidepath_verdict"]})' for r in bad))


if __name__ == '__main__':
    main()
