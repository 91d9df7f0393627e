"""Plan the `demo` scenario from Python, draw the path over the seabed, compare three planners,
and (when dask is installed) run a small sweep on a local Dask cluster.

    python examples/python/plan_demo.py [--out plan_demo.png]

Needs the `tidepath` wheel (scripts/test_python.sh builds one) and matplotlib.
"""

from __future__ import annotations

import argparse
from typing import Any, Dict, List

import numpy as np

import tidepath


def draw(scenario: tidepath.Scenario, plan: tidepath.Plan, out: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    (lo, hi) = scenario.bounds
    x = np.linspace(lo[0], hi[0], 200)
    y = np.linspace(lo[1], hi[1], 200)
    X, Y = np.meshgrid(x, y)
    seabed = scenario.seabed(X, Y)
    fig, ax = plt.subplots(figsize=(8, 6.5))
    shade = ax.contourf(X, Y, seabed, levels=30, cmap="Blues_r")
    fig.colorbar(shade, ax=ax, label="seabed elevation (m)")
    # The current at mid-depth, on a coarse grid.
    cx, cy = np.meshgrid(np.linspace(lo[0], hi[0], 15), np.linspace(lo[1], hi[1], 15))
    z = 0.5 * (lo[2] + hi[2])
    c = scenario.current(cx, cy, z, 0.0)
    ax.quiver(cx, cy, c[..., 0], c[..., 1], color="0.3", alpha=0.6, width=0.002)
    for m in plan.missions:
        path = m.path
        ax.plot(path[:, 0], path[:, 1], "-o", color="tab:red", ms=3, lw=2, label=f"{plan.planner} ({m.status})")
    ax.plot(*scenario.start[:2], "g^", ms=10, label="start")
    ax.plot(*scenario.goal[:2], "k*", ms=12, label="goal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_aspect("equal")
    ax.set_title(f"{scenario.name}: {plan.planner}, seed {plan.seed}, cost {plan.cost:.4f}")
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def summary(results: Dict[str, Any]) -> List[str]:
    lines = []
    for row in results["rows"]:
        lines.append(
            f"  {row['planner']:<6} mean {row['mean']:.4f}  best {row['best']:.4f}  "
            f"feasible {row['feasible_runs']}/{row['runs']}"
        )
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", default="plan_demo.png")
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()

    demo = tidepath.Scenario.builtin("demo")
    plan = demo.plan(planner="pso", seed=3, iterations=200)
    print(f"{demo.name}: {plan.planner} {plan.status}, cost {plan.cost:.4f} ({plan.reason})")
    print(f"  {len(plan.missions[0].waypoints)} waypoints, terms {plan.terms}")
    draw(demo, plan, args.out)
    print(f"  wrote {args.out}")

    results = tidepath.compare(demo, ["pso", "de", "ga"], runs=args.runs, seed=1, iterations=50)
    print(f"compare, {args.runs} runs each:")
    print("\n".join(summary(results)))

    try:
        from distributed import Client, LocalCluster
    except ImportError:
        print("dask[distributed] is not installed: the cluster sweep is skipped")
        return
    # dask ships no type hints for these two: the ignores keep `mypy --strict` clean.
    with LocalCluster(  # type: ignore[no-untyped-call]
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster:
        with Client(cluster) as client:  # type: ignore[no-untyped-call]
            sweep = tidepath.compare(demo, ["pso", "de", "ga"], runs=args.runs, seed=1, iterations=50, executor=client)
    same = [r["cost"] for r in sweep["records"]] == [r["cost"] for r in results["records"]]
    print(f"the same sweep on a local Dask cluster (2 workers): identical costs: {same}")


if __name__ == "__main__":
    main()
