#!/usr/bin/env python3
"""The side-by-side table of scripts/ompl_bench/run.sh, as Markdown on standard output.

  python3 scripts/ompl_bench/summarize.py DIR/results.csv [DIR/optimum.csv]

One table per OMPL variant in the rows (its default k-nearest RRTstar, and the radius form):
per world, the median time per run and the median final length of OMPL's RRTstar and of
tidepath's rrt-star, their ratios (tidepath / OMPL), how many runs found a path, and the exact
shortest length (tidepath's visibility planner) when optimum.csv is given. A last row pools
every run. Times are each planner's own solve time (see docs/ompl-benchmark.md).
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

    def stats(rs, planner):
        mine = [r for r in rs if r['planner'] == planner]
        solved = [r for r in mine if r['solved'] == '1']
        times = [float(r['time_s']) for r in mine]
        lengths = [float(r['length_m']) for r in solved]
        return med(times), med(lengths), len(solved), len(mine)

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
        for label, rs in [(w, [r for r in rows if r['world'] == w]) for w in worlds] + [('all', rows)]:
            ot, ol, on, oruns = stats(rs, ompl)
            tt, tl, tn, truns = stats(rs, TIDEPATH)
            opt = optimum.get(label, float('nan'))
            print(f'| {label} | {fmt(opt, 1)} | {fmt(ot, 3)} | {fmt(tt, 3)} | {fmt(tt / ot if truns else float("nan"), 2)} '
                  f'| {fmt(ol, 1)} | {fmt(tl, 1)} | {fmt(tl / ol if tn else float("nan"), 4)} '
                  f'| {on}/{oruns}, {tn}/{truns} |')
        print()
    print(f'Medians over seeds ("all": over every run); iterations per run: {", ".join(map(str, iterations))} '
          '(OMPL: numIterations(); tidepath: the plan\'s samples). Lengths over runs that found a path; '
          'optimum: the exact shortest path (tidepath\'s visibility planner).')
    bad = [r for r in rows if r['planner'] != TIDEPATH and r['solved'] == '1' and r['tidepath_verdict'] != 'feasible']
    if bad:
        print()
        print(f'{len(bad)} OMPL path(s) that tidepath eval does not find feasible: '
              + ', '.join(f'{r["world"]} seed {r["seed"]} ({r["tidepath_verdict"]})' for r in bad))


if __name__ == '__main__':
    main()
