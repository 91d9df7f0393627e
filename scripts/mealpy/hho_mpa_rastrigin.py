"""MEALPY 3's HHO.OriginalHHO and MPA.OriginalMPA on Rastrigin in 30 dimensions, one run of
about 60,000 evaluations each, repeated; prints one line per run: the algorithm, the run's wall
time (s), its best cost and MEALPY's own evaluation count (nfe_counter).

Run by scripts/hho_mpa_vs_mealpy.sh, which installs MEALPY in a virtual environment first. The
setting: population 40, range [-5.12, 5.12], each algorithm's default parameters.

Both algorithms schedule by epoch (HHO's E = 2 E0 (1 - epoch/T), MPA's phases and CF), so the
budget is set by the epoch count, not by an evaluation limit (which would cut the schedule
short). The counts, read from MEALPY 3.0.3's source (mealpy/swarm_based/HHO.py, MPA.py,
optimizer.py; default mode "single"):
* initialisation: 40 evaluations;
* OriginalHHO, per epoch: the 40 new positions (get_target in evolve), plus Y and Z of every
  diving hawk (both always evaluated). A hawk dives with probability 0.5 P(|E| < 1); over a run
  P(|E| < 1) averages 0.5 ln 2 + 0.5 = 0.8466 (|E0| ~ U(0, 1), E = 2 E0 (1 - s)), so about
  40 (1 + 2 x 0.4233) = 73.9 evaluations per epoch: 812 epochs give about 60,000;
* OriginalMPA, per epoch: the 40 new positions, once (MEALPY folds eq. 16 into the same
  move; the authors' code evaluates twice per iteration): 1499 epochs give 40 + 1499 x 40 =
  60,000 exactly.
The printed nfe_counter shows the count each run actually spent.
"""
import sys
import time

import numpy as np
from mealpy import FloatVar, HHO, MPA

DIM = 30
POPULATION = 40
EPOCHS = {"hho": 812, "mpa": 1499}


def rastrigin(x):
    return float(np.sum(x * x - 10.0 * np.cos(2.0 * np.pi * x) + 10.0))


def main():
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    problem = {
        "obj_func": rastrigin,
        "bounds": FloatVar(lb=(-5.12,) * DIM, ub=(5.12,) * DIM),
        "minmax": "min",
        "log_to": None,
    }
    for name, make in [("hho", HHO.OriginalHHO), ("mpa", MPA.OriginalMPA)]:
        for run in range(runs):
            model = make(epoch=EPOCHS[name], pop_size=POPULATION)
            t0 = time.perf_counter()
            best = model.solve(problem, seed=run + 1)
            took = time.perf_counter() - t0
            print(f"{name} {took:.6f} {best.target.fitness:.6g} {model.nfe_counter}")


if __name__ == "__main__":
    main()
