"""optimize: registry optimizers on benchmark functions and on Python callables."""

import numpy as np
import pytest

import tidepath


def test_benchmark_function_at_full_speed():
    r = tidepath.optimize("sphere", dim=5, algo="de", evaluations=3000, seed=1)
    assert r["x"].shape == (5,) and r["x"].dtype == np.float64
    assert r["cost"] < 1e-2
    assert r["evaluations"] <= 3000 + 100
    assert r["history"].ndim == 1 and r["history"][-1] == r["cost"]
    again = tidepath.optimize("sphere", dim=5, algo="de", evaluations=3000, seed=1)
    assert np.array_equal(again["x"], r["x"])


def test_a_python_callable_gives_the_same_run_as_the_builtin():
    def sphere(x):
        return float(np.sum(x * x))

    ours = tidepath.optimize(sphere, bounds=[(-100.0, 100.0)] * 4, algo="pso", iterations=20, seed=2)
    builtin = tidepath.optimize("sphere", dim=4, bounds=(-100.0, 100.0), algo="pso", iterations=20, seed=2)
    assert ours["cost"] == pytest.approx(builtin["cost"], rel=1e-12)
    assert np.allclose(ours["x"], builtin["x"], rtol=0, atol=1e-12)


def test_every_optimizer_of_the_table_runs_on_a_callable():
    optimizers = [p["id"] for p in tidepath.planners() if "evaluations" in p["capabilities"]["counts"]]
    assert "de" in optimizers and "pso" in optimizers
    for algo in optimizers[:6]:
        r = tidepath.optimize(lambda x: float(np.abs(x).sum()), bounds=[(-1, 1)] * 3, algo=algo, evaluations=400, seed=0)
        assert np.isfinite(r["cost"]), algo


def test_callback_errors_propagate():
    def bad(x):
        raise RuntimeError("boom")

    with pytest.raises(RuntimeError, match="boom"):
        tidepath.optimize(bad, bounds=[(0, 1)], iterations=3)


def test_bad_arguments_are_value_errors():
    with pytest.raises(ValueError, match=r"^fun: .*unknown function"):
        tidepath.optimize("nope")
    with pytest.raises(ValueError, match=r"^algo: "):
        tidepath.optimize("sphere", algo="nope")
    with pytest.raises(ValueError, match=r"^bounds: "):
        tidepath.optimize(lambda x: 0.0)
    with pytest.raises(ValueError, match=r"^bounds\[0\]: "):
        tidepath.optimize(lambda x: 0.0, bounds=[(1, 0)])
