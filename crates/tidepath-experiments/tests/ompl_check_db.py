#!/usr/bin/env python3
"""Checks the SQLite database that OMPL's `ompl_benchmark_statistics` built from the fixture log
of tidepath's `experiments::ompl_log` (the ignored test `write_fixture_log_for_ompl_script`).

Optional CI step, needs `pip install ompl` (verified with 2.0.1):

    TIDEPATH_OMPL_LOG=/tmp/tidepath_ompl.log \
        cargo test -p tidepath --lib experiments::ompl_log -- --ignored
    ompl_benchmark_statistics /tmp/tidepath_ompl.log -d /tmp/tidepath_ompl.db
    python3 crates/tidepath/tests/ompl_check_db.py /tmp/tidepath_ompl.db

The expected values mirror `fixture()` in crates/tidepath/src/experiments/ompl_log/tests.rs.
Standard library only.
"""

import sqlite3
import sys

failures = []


def check(what, got, want):
    if got != want:
        failures.append(f"{what}: got {got!r}, want {want!r}")


def main(path):
    db = sqlite3.connect(path)
    tables = {r[0] for r in db.execute("SELECT name FROM sqlite_master WHERE type='table'")}
    for t in ("experiments", "plannerConfigs", "runs", "progress", "enums"):
        check(f"table {t} exists", t in tables, True)

    exp = db.execute(
        "SELECT name, hostname, date, seed, timelimit, memorylimit, runcount, totaltime, "
        "setup, cpuinfo, version FROM experiments"
    ).fetchall()
    check("experiment count", len(exp), 1)
    name, host, date, seed, timelimit, memlimit, runcount, total, setup, cpu, version = exp[0]
    check("experiment name", name, "harbour")
    check("host", host, "vm")
    check("date", date, "2026-06-21 00:00:00")
    check("master seed", seed, "42")
    check("time limit", timelimit, 60.0)
    check("memory limit", memlimit, 0.0)
    check("runs per planner", runcount, 3)
    check("total time", total, 3.375)
    check("setup", setup, "scenario harbour\nbudget: 2 iterations\n")
    check("cpu info", cpu, "fixture cpu\n")
    check("version prefix", version.split()[0], "tidepath")

    planners = [r[0] for r in db.execute("SELECT name FROM plannerConfigs ORDER BY id")]
    check("planners", planners, ["tidepath_pso", "tidepath_ga"])

    cols = "time, simplification_time, solved, approximate_solution, status, solution_length, solution_segments, " \
        "best_cost, travel_time, evaluations, iterations, stop_reason, seed, typeof(seed)"
    rows = db.execute(
        f"SELECT plannerConfigs.name, {cols} FROM runs JOIN plannerConfigs "
        "ON runs.plannerid = plannerConfigs.id ORDER BY runs.id"
    ).fetchall()
    want = [
        ("tidepath_pso", 0.5, 0.0, 1, 0, 6, 1000.25, 2, 12.5, 800.5, 120, 2, 0, "11", "text"),
        ("tidepath_pso", 0.25, 0.0, 0, 1, 5, 1500.0, 3, 30.0, 1300.0, 120, 2, 1,
         "18446744073709551615", "text"),
        ("tidepath_pso", 2.0, 0.0, 1, 0, 6, 990.0, 4, 11.0, 790.0, 80, 1, 2,
         "9223372036854775808", "text"),
        ("tidepath_ga", 0.125, 0.0, 1, 0, 6, None, None, 0.75, None, 120, 2, 0, "7", "text"),
        ("tidepath_ga", 0.5, 0.0, 0, None, 4, None, None, None, None, 0, 0, 0, "8", "text"),
        ("tidepath_ga", 0.0, 0.0, 1, 0, 6, None, None, 2.5e-7, None, 80, 1, 1, "9", "text"),
    ]
    check("run count", len(rows), len(want))
    for i, (got, w) in enumerate(zip(rows, want)):
        check(f"run {i}", got, w)

    prog = db.execute(
        "SELECT runid, time, iterations, best_cost FROM progress ORDER BY runid, time"
    ).fetchall()
    check("progress rows", len(prog), 3 + 3 + 2 + 3)
    check("progress of pso run 1", prog[3:6], [
        (2, 0.08333333333333333, 0, None),
        (2, 0.16666666666666666, 1, 40.0),
        (2, 0.25, 2, 30.0),
    ])
    check("progress of ga run 0", prog[8:], [
        (4, 0.041666666666666664, 0, 3.0),
        (4, 0.08333333333333333, 1, 1.5),
        (4, 0.125, 2, 0.75),
    ])

    enums = db.execute("SELECT name, value, description FROM enums ORDER BY name, value").fetchall()
    check("stop_reason enum", [e for e in enums if e[0] == "stop_reason"], [
        ("stop_reason", 0, "max iterations"),
        ("stop_reason", 1, "max evaluations"),
        ("stop_reason", 2, "wall time"),
        ("stop_reason", 3, "max expansions"),
        ("stop_reason", 4, "max samples"),
        ("stop_reason", 5, "target cost"),
        ("stop_reason", 6, "cancelled"),
        ("stop_reason", 7, "completed"),
    ])
    status = {v: d for n, v, d in enums if n == "status"}
    check("status 4/5/6", (status.get(4), status.get(5), status.get(6)),
          ("Timeout", "Approximate solution", "Exact solution"))

    # The script's views need the `time` and `solved` columns.
    best = db.execute(
        "SELECT plannerid, avg_solved, avg_total_time FROM bestPlannerConfigs ORDER BY plannerid"
    ).fetchall()
    check("bestPlannerConfigs", best, [(1, 2 / 3, 2.75 / 3), (2, 2 / 3, 0.625 / 3)])

    if failures:
        print("\n".join(failures))
        print(f"ompl db check: 0 passed, {len(failures)} failed")
        return 1
    print("ompl db check: 1 passed, 0 failed")
    return 0


if __name__ == "__main__":
    try:
        code = main(sys.argv[1] if len(sys.argv) > 1 else "benchmark.db")
    except (sqlite3.Error, ValueError, IndexError) as e:
        print(f"ompl db check: {type(e).__name__}: {e}")
        print("ompl db check: 0 passed, 1 failed")
        code = 1
    sys.exit(code)
