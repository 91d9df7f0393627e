"""How much a Python call costs over the CLI on the same optimizer run (issue #36): DE on
Rastrigin-30 with 60,000 evaluations, the same seeds, one thread each, timed from inside each
(the CLI's per-run `elapsed_s` in its results.json; `optimize`'s `elapsed_s` and the wall time
of the Python call around it). Prints medians and their ratio.

    python scripts/python_overhead.py --bin target/release/tidepath [--runs 20]

Needs the `tidepath` wheel in the running interpreter (scripts/test_python.sh builds one; for
a fair figure build both in the same profile: `maturin build --release` and `cargo build
--release`).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time

import tidepath

DIM, EVALUATIONS, ALGO, FUNC = 30, 60_000, "de", "rastrigin"


def cli_times(binary: str, runs: int, seed: int) -> list[float]:
    with tempfile.TemporaryDirectory() as out:
        subprocess.run(
            [binary, "bench", "functions", "--algos", ALGO, "--funcs", FUNC, "--dim", str(DIM),
             "--evaluations", str(EVALUATIONS), "--runs", str(runs), "--jobs", "1", "--seed", str(seed),
             "--out", out],
            check=True, stdout=subprocess.DEVNULL, env={**os.environ, "RAYON_NUM_THREADS": "1"},
        )
        with open(os.path.join(out, "results.json")) as f:
            records = json.load(f)["records"]
    return [r["elapsed_s"] for r in records]


def python_times(runs: int, seed: int) -> tuple[list[float], list[float]]:
    inside, around = [], []
    for k in range(runs):
        t0 = time.perf_counter()
        r = tidepath.optimize(FUNC, dim=DIM, algo=ALGO, evaluations=EVALUATIONS, seed=seed + k)
        around.append(time.perf_counter() - t0)
        inside.append(r["elapsed_s"])
    return inside, around


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bin", default="target/release/tidepath")
    parser.add_argument("--runs", type=int, default=20)
    parser.add_argument("--seed", type=int, default=1)
    a = parser.parse_args()
    cli = statistics.median(cli_times(a.bin, a.runs, a.seed))
    inside, around = (statistics.median(v) for v in python_times(a.runs, a.seed))
    print(f"{ALGO} on {FUNC}-{DIM}, {EVALUATIONS} evaluations, median of {a.runs} runs:")
    print(f"  CLI (bench functions, per-run elapsed_s): {cli * 1e3:.2f} ms")
    print(f"  Python optimize, elapsed_s:                {inside * 1e3:.2f} ms ({inside / cli:.3f} x the CLI)")
    print(f"  Python optimize, wall time of the call:    {around * 1e3:.2f} ms ({around / cli:.3f} x the CLI)")


if __name__ == "__main__":
    main()
