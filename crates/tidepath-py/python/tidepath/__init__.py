"""tidepath: marine-robot path planning from Python.

Plan, evaluate and compare the planners of the tidepath toolkit with numpy arrays in and out.
Everything runs in the Rust library, as the ``tidepath`` command line runs it: the same seed
gives the same plan, bit for bit.

>>> import tidepath
>>> plan = tidepath.Scenario.builtin("demo").plan(planner="pso", seed=3, iterations=20)
>>> plan.missions[0].waypoints.shape[1]
3
"""

from __future__ import annotations

import json
from typing import Any, Dict, List, Mapping, Optional, Sequence

from ._tidepath import (
    Mission,
    Plan,
    Scenario,
    __version__,
    optimize,
    planners,
    scenarios,
)
from . import _tidepath
import os as _os

if hasattr(_os, "register_at_fork"):
    # A forked child inherits the library's thread pools without their threads.
    _os.register_at_fork(after_in_child=_tidepath.after_fork_in_child)

__all__ = [
    "Mission",
    "Plan",
    "Scenario",
    "__version__",
    "compare",
    "optimize",
    "planners",
    "scenarios",
]

# Fields of results.json that measure wall time: they differ between two runs of the same
# comparison, everything else is identical.
TIMING_FIELDS = ("total_wall_s", "records[].elapsed_s", "rows[].mean_wall_s")


def _budget(
    iterations: Optional[int],
    evaluations: Optional[int],
    population: Optional[int],
    time_limit: Optional[float],
    smoother: Optional[str],
    smoother_params: Optional[Mapping[str, Any]],
) -> str:
    budget: Dict[str, Any] = {
        "iterations": iterations,
        "evaluations": evaluations,
        "population": population,
        "time_limit_s": time_limit,
        "target_cost": None,
        "smoother": None,
    }
    if smoother is not None:
        budget["smoother"] = {"id": smoother, "params": dict(smoother_params) if smoother_params else None}
    return json.dumps(budget)


def _run_share(
    toml: str,
    source: str,
    planners: List[str],
    runs: int,
    seed: int,
    budget: str,
    reference: Optional[str],
    k: int,
    n: int,
) -> str:
    """One task of a distributed ``compare``: share ``k`` of ``n`` of its runs (run ``i`` is in
    share ``i % n + 1``, with the seed it has in a whole compare); returns the shard's
    results.json text. Module-level so executors can pickle it."""
    return _tidepath.compare_share_json(toml, source, planners, runs, seed, budget, reference, k, n)


def compare(
    scenario: Any,
    planners: Sequence[str],
    runs: int = 30,
    seed: int = 0,
    iterations: Optional[int] = None,
    evaluations: Optional[int] = None,
    population: Optional[int] = None,
    time_limit: Optional[float] = None,
    smoother: Optional[str] = None,
    smoother_params: Optional[Mapping[str, Any]] = None,
    reference: Optional[str] = "default",
    jobs: Optional[int] = None,
    executor: Any = None,
) -> Dict[str, Any]:
    """Runs every planner ``runs`` times on ``scenario`` (a ``Scenario`` or a built-in name), as
    ``tidepath compare SCENARIO --planners ... --runs ... --seed ... --out DIR`` does.

    Returns the CLI's ``results.json`` as plain Python objects: ``records`` (one per run, in
    canonical order: planner, then run index), ``rows`` (the summary table, one per planner),
    ``reference``, the settings, and ``dataframe`` (the records as a pandas DataFrame) when
    pandas is installed. For the same seed it equals the CLI's results except the wall-time
    fields (``TIMING_FIELDS``).

    ``reference``: the planner of the gap column, ``"default"`` for the CLI's default, None for
    none. ``jobs``: threads of a local run (default: all cores).

    ``executor``: any ``concurrent.futures``-style object with ``submit`` (a
    ``ProcessPoolExecutor``, a Dask ``distributed.Client``, ...). Each run is then submitted as
    its own task (the scenario travels as TOML text) and the records are joined in canonical
    order by the library's merge (as ``tidepath merge``), which summarises them with the same
    code as a local run: the results are bit-identical to a local ``compare``, timings aside.
    Task ``k`` (``k = 1..runs``) runs run ``k - 1`` of every planner (the share ``k/runs`` of
    ``compare --shard``); task 1 also runs the reference planner.
    """
    if isinstance(scenario, str):
        scenario = Scenario.builtin(scenario)
    planners = list(planners)
    budget = _budget(iterations, evaluations, population, time_limit, smoother, smoother_params)
    if executor is None:
        text = _tidepath.compare_json(scenario, planners, runs, seed, budget, reference, jobs)
    else:
        toml, source = scenario.to_toml(), scenario.source
        # Task k runs run k-1 of every planner (share k of `runs`, round robin over the runs in
        # canonical order), with the seeds of a whole compare.
        n = max(runs, 1)
        futures = [
            executor.submit(_run_share, toml, source, planners, runs, seed, budget, reference, k, n)
            for k in range(1, n + 1)
        ]
        text = _tidepath.merge_json([f.result() for f in futures])
    result: Dict[str, Any] = json.loads(text)
    try:
        import pandas  # noqa: F401  (optional)
    except ImportError:
        return result
    result["dataframe"] = _dataframe(result)
    return result


def _dataframe(result: Mapping[str, Any]) -> Any:
    import pandas

    columns = [
        "problem", "planner", "run", "seed", "cost", "feasible", "status", "length_m",
        "travel_time_s", "evaluations", "iterations", "elapsed_s", "stop_reason",
    ]
    rows = [{c: r.get(c) for c in columns} for r in result["records"]]
    return pandas.DataFrame(rows, columns=columns)
