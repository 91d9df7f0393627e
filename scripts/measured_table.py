#!/usr/bin/env python3
"""Regenerates README.md's "Measured" table from `tidepath compare` runs, or checks it.

    scripts/measured_table.py [--bin target/debug/tidepath] [--check]

For each built-in scenario it runs `tidepath compare SCENARIO --planners hybrid,pso,de
--runs 10` (master seed 1) and writes, per planner, the mean cost over all runs (penalties
included), the feasible runs, the gap of the mean cost over feasible runs to the reference,
and how the planner compares with hybrid (Wilcoxon rank-sum, two-sided, alpha 0.05). Every run is bounded by iterations, not time, so the numbers are the same on any
machine and any number of threads: `--check` regenerates them and fails, showing both
tables, when README.md differs (CI runs it).
"""

import argparse
import json
import pathlib
import subprocess
import sys
import tempfile

SCENARIOS = [
    ("demo", "demo (3-D, vortices, moving sphere)"),
    ("salish", "salish (real grid, tide)"),
    ("headland", "headland (must turn back)"),
    ("salish-strait", "salish-strait (3-D, real seabed, 20 m above it)"),
    ("salish-forecast", "salish-forecast (tide read from NetCDF)"),
]
PLANNERS = ["hybrid", "pso", "de"]
RUNS = 10
BEGIN = "<!-- measured-table -->"
END = "<!-- /measured-table -->"
ROOT = pathlib.Path(__file__).resolve().parent.parent


def num(v):
    """Four significant figures, as the compare table prints."""
    return f"{v:.4g}" if abs(v) < 1e4 else f"{v:.0f}"


def cell(row):
    runs, ok = row["runs"], row["feasible_runs"]
    text = f"{num(row['mean'])}, {ok}/{runs}"
    gap = row.get("gap_percent")
    if ok == 0:
        text += ", no feasible run"
    elif gap is not None:
        text += f", {gap:+.2f}%"
    # How this planner compares with the first (Wilcoxon rank-sum, two-sided, alpha 0.05).
    mark = row.get("mark")
    return text + (f", {mark}" if mark else "")


def table(binary):
    lines = [
        "| scenario | reference | " + " | ".join(PLANNERS) + " |",
        "|---|---|" + "---|" * len(PLANNERS),
    ]
    with tempfile.TemporaryDirectory() as tmp:
        for name, label in SCENARIOS:
            out = pathlib.Path(tmp) / name
            cmd = [binary, "compare", name, "--planners", ",".join(PLANNERS), "--runs", str(RUNS),
                   "--seed", "1", "--out", str(out)]
            subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
            result = json.loads((out / "results.json").read_text())
            ref = result.get("reference")
            ref_text = f"{ref['planner']}, {num(ref['cost'])}" if ref and ref["status"] in ("exact", "feasible") else (
                f"{ref['planner']}, no feasible plan" if ref else "no feasible reference")
            rows = {r["planner"]: r for r in result["rows"]}
            lines.append(f"| {label} | {ref_text} | " + " | ".join(cell(rows[p]) for p in PLANNERS) + " |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bin", default=str(ROOT / "target" / "release" / "tidepath"))
    ap.add_argument("--check", action="store_true", help="fail when README.md's table is not current")
    args = ap.parse_args()
    readme = ROOT / "README.md"
    text = readme.read_text()
    head, rest = text.split(BEGIN, 1)
    current, tail = rest.split(END, 1)
    fresh = table(args.bin)
    if args.check:
        if current.strip() != fresh.strip():
            print("README.md's measured table is not current; run scripts/measured_table.py", file=sys.stderr)
            print("README.md has:\n" + current.strip() + "\n\nthe runs give:\n" + fresh, file=sys.stderr)
            sys.exit(1)
        print("README.md's measured table is current")
        return
    readme.write_text(head + BEGIN + "\n" + fresh + "\n" + END + tail)
    print(fresh)


if __name__ == "__main__":
    main()
