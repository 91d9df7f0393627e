"""MEALPY 3's FFA.OriginalFFA on Rastrigin in 30 dimensions, one run of 60,000 evaluations,
repeated; prints one line per run: the run's wall time (s) and its best cost.

Run by scripts/amfa_vs_mealpy.sh, which installs MEALPY in a virtual environment first. The
setting mirrors amfa2015's benchmark: population 40, 60,000 evaluations, amfa2015's small
Rastrigin range [-5.12, 5.12]; the algorithm is MEALPY's own FFA with its default parameters.
"""
import sys
import time

import numpy as np
from mealpy import FloatVar, FFA

DIM = 30
EVALUATIONS = 60_000
POPULATION = 40


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
    for run in range(runs):
        # The epoch count is a ceiling; the evaluation limit ends the run.
        model = FFA.OriginalFFA(epoch=100_000, pop_size=POPULATION)
        t0 = time.perf_counter()
        best = model.solve(problem, termination={"max_fe": EVALUATIONS}, seed=run + 1)
        took = time.perf_counter() - t0
        print(f"{took:.6f} {best.target.fitness:.6g} {model.nfe_counter}")


if __name__ == "__main__":
    main()
