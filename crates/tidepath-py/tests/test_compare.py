"""compare: equal to the CLI's results.json, and bit-identical through any executor."""

import concurrent.futures
import json

import pytest

import tidepath
from conftest import run_cli
from tidepath import Scenario

PLANNERS = ["pso", "de"]
SETTINGS = dict(runs=3, seed=7, iterations=8)


def strip(results):
    """results.json without its wall times (the only fields two runs may differ in):
    `tidepath.TIMING_FIELDS`."""
    out = {k: v for k, v in results.items() if k not in ("total_wall_s", "dataframe")}
    out["records"] = [{k: v for k, v in r.items() if k != "elapsed_s"} for r in results["records"]]
    out["rows"] = [{k: v for k, v in r.items() if k != "mean_wall_s"} for r in results["rows"]]
    return out


@pytest.fixture(scope="module")
def local():
    return tidepath.compare("demo", PLANNERS, **SETTINGS)


def test_compare_returns_records_and_the_summary_table(local):
    assert local["planners"] == PLANNERS and local["runs"] == 3 and local["master_seed"] == 7
    assert len(local["records"]) == 6
    assert [(r["planner"], r["run"]) for r in local["records"]] == [(p, i) for p in PLANNERS for i in range(3)]
    assert [row["planner"] for row in local["rows"]] == PLANNERS
    assert local["complete"] is True
    assert local["reference"] is not None  # the CLI's default reference planner ran


def test_compare_equals_the_cli(cli, tmp_path, local):
    r = run_cli(
        cli, "compare", "demo", "--planners", ",".join(PLANNERS), "--runs", "3", "--seed", "7",
        "--iterations", "8", "--out", str(tmp_path / "out"),
    )
    assert r.returncode == 0, r.stderr
    theirs = json.loads((tmp_path / "out" / "results.json").read_text())
    assert strip(local) == strip(theirs)


def test_compare_is_the_same_with_one_thread(local):
    assert strip(tidepath.compare("demo", PLANNERS, jobs=1, **SETTINGS)) == strip(local)


def test_compare_on_a_process_pool_is_bit_identical(local):
    with concurrent.futures.ProcessPoolExecutor(2) as pool:
        remote = tidepath.compare(Scenario.builtin("demo"), PLANNERS, executor=pool, **SETTINGS)
    assert strip(remote) == strip(local)


def test_compare_on_a_dask_cluster_is_bit_identical(local):
    distributed = pytest.importorskip(
        "distributed", reason="dask[distributed] is not installed (pip install 'dask[distributed]')"
    )
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            remote = tidepath.compare("demo", PLANNERS, executor=client, **SETTINGS)
    assert strip(remote) == strip(local)


def test_compare_dataframe_only_with_pandas(local):
    try:
        import pandas  # noqa: F401
    except ImportError:
        assert "dataframe" not in local
        return
    df = local["dataframe"]
    assert len(df) == 6 and list(df["planner"]) == [r["planner"] for r in local["records"]]


def test_compare_errors_name_the_argument():
    with pytest.raises(ValueError, match=r"^planners: .*nope"):
        tidepath.compare("demo", ["pso", "nope"], runs=1)
    with pytest.raises(ValueError, match=r"^runs: "):
        tidepath.compare("demo", ["pso"], runs=0)
    with pytest.raises(ValueError, match=r"listed twice"):
        tidepath.compare("demo", ["pso", "pso"], runs=1, iterations=2)
