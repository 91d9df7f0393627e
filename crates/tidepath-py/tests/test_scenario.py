"""Registry listings, loading scenarios, start/goal overrides, world queries and evaluation."""

import json
import math
import pathlib

import numpy as np
import pytest

import tidepath
from tidepath import Scenario


def test_scenarios_lists_the_builtin_table():
    table = tidepath.scenarios()
    ids = [s["id"] for s in table]
    assert "demo" in ids
    assert all(set(s) == {"id", "description", "citation"} for s in table)
    # Every listed scenario loads.
    for s in table[:5]:
        assert Scenario.builtin(s["id"]).name


def test_planners_lists_capabilities_and_parameters():
    table = {p["id"]: p for p in tidepath.planners()}
    pso = table["pso"]
    assert pso["capabilities"]["randomised"] is True
    assert "iterations" in pso["capabilities"]["counts"]
    names = {p["name"]: p for p in pso["parameters"]}
    assert "population" in names
    pop = names["population"]
    assert isinstance(pop["default"], int) and pop["default"] > 0
    assert pop["range"] and pop["help"] and pop["source"]
    # Graph planners are listed from the same table.
    assert table["theta-star"]["capabilities"]["randomised"] is False


def test_builtin_unknown_name_is_a_value_error_naming_the_field():
    with pytest.raises(ValueError, match=r"^name: .*no-such"):
        Scenario.builtin("no-such")


def test_to_toml_round_trips():
    s = Scenario.builtin("demo")
    again = Scenario.from_toml(s.to_toml(), source=s.source)
    assert again.name == s.name
    assert again.to_toml() == s.to_toml()
    assert again.start == s.start and again.goal == s.goal


def test_from_dict_round_trips_and_names_bad_fields():
    s = Scenario.builtin("glider-3")
    d = s.to_dict()
    assert d["vehicle"]["kind"] == "wave-glider" and d["world"]["waves"]["kind"] == "cells"
    again = Scenario.from_dict(d, source="mine")
    assert again.to_toml() == s.to_toml() and again.start == s.start
    d["vehicle"]["speed"] = -1.0
    d["vehicle"].pop("kind")
    with pytest.raises(ValueError, match=r"vehicle\.speed") as e:
        Scenario.from_dict(d)
    assert "\n" not in str(e.value)
    with pytest.raises(ValueError, match=r"^scenario: "):
        Scenario.from_dict([1, 2])


def test_load_reads_a_file(tmp_path: pathlib.Path):
    path = tmp_path / "mine.toml"
    path.write_text(Scenario.builtin("demo").to_toml())
    s = Scenario.load(path)
    assert s.name == "demo" and s.source == str(path)
    with pytest.raises(ValueError, match=r"^path: "):
        Scenario.load(tmp_path / "missing.toml")


def test_malformed_toml_is_a_value_error():
    with pytest.raises(ValueError) as e:
        Scenario.from_toml("name = [", source="bad.toml")
    assert "bad.toml" in str(e.value)
    assert "\n" not in str(e.value)


def test_with_mission_moves_start_and_goal_in_metres():
    s = Scenario.builtin("demo")
    lo, hi = s.bounds
    start = [lo[0] + 0.3 * (hi[0] - lo[0]), lo[1] + 0.2 * (hi[1] - lo[1])]
    moved = s.with_mission(start=start)
    assert moved.start[:2] == start
    assert moved.start[2] == s.start[2]  # z kept
    assert moved.goal == s.goal
    assert s.start != moved.start  # the original is unchanged


def test_nan_start_is_a_value_error_naming_start():
    s = Scenario.builtin("demo")
    with pytest.raises(ValueError, match=r"^start: .*finite"):
        s.with_mission(start=[math.nan, 0.0, 0.0])
    with pytest.raises(ValueError, match=r"^goal: "):
        s.with_mission(goal=[1e12, 0.0])


def test_seabed_current_and_clearance_are_vectorised():
    s = Scenario.builtin("demo")
    lo, hi = s.bounds
    x = np.linspace(lo[0], hi[0], 7)
    y = np.linspace(lo[1], hi[1], 5)
    X, Y = np.meshgrid(x, y)
    h = s.seabed(X, Y)
    assert h.shape == (5, 7) and h.dtype == np.float64
    # Broadcasting: a scalar y against a vector x.
    assert np.array_equal(s.seabed(x, y[2]), h[2])
    c = s.current(X, Y, -50.0, 0.0)
    assert c.shape == (5, 7, 3) and c.dtype == np.float64
    assert np.isfinite(c).all()
    pts = np.stack([X, Y, h + 10.0], axis=-1)
    cl = s.clearance(pts)
    assert cl.shape == (5, 7)
    # 10 m above the seabed: the clearance is at most 10 m (obstacles may be nearer).
    assert (cl <= 10.0 + 1e-6).all()
    below = np.stack([X, Y, h - 5.0], axis=-1)
    assert (s.clearance(below) < 0).all()
    with pytest.raises(ValueError, match=r"^points: "):
        s.clearance(np.zeros((4, 2)))


def test_evaluate_matches_the_plan_it_judges():
    s = Scenario.builtin("demo")
    plan = s.plan(planner="pso", seed=1, iterations=10)
    m = plan.missions[0]
    judged = s.evaluate(m.waypoints)
    assert judged["cost"] == pytest.approx(plan.cost, rel=1e-12)
    assert judged["feasible"] == plan.feasible
    assert judged["status"] in {"exact", "feasible", "infeasible"}
    assert set(judged["terms"]) == set(m.terms)
    assert judged["violations"] == m.violations
    # A list with one path per mission gives the same.
    assert s.evaluate([m.waypoints])["cost"] == judged["cost"]


def test_evaluate_matches_the_cli_eval(cli, tmp_path):
    from conftest import run_cli

    s = Scenario.builtin("demo")
    plan = s.plan(planner="pso", seed=2, iterations=5)
    path = tmp_path / "p.json"
    plan.save(path)
    out = run_cli(cli, "eval", "demo", str(path)).stdout
    total = [l for l in out.splitlines() if l.strip().startswith("total ")][0]
    assert float(total.split()[1]) == pytest.approx(s.evaluate(plan.missions[0].waypoints)["cost"], abs=1e-9)


def test_evaluate_rejects_a_bad_shape_and_a_wrong_count():
    s = Scenario.builtin("demo")
    with pytest.raises(ValueError, match=r"^waypoints: "):
        s.evaluate(np.zeros((3, 2)))
    p = np.array([s.start, s.goal])
    with pytest.raises(ValueError, match=r"^plan: "):
        s.evaluate([p, p])


def test_scenarios_pickle_as_toml():
    import pickle

    s = Scenario.builtin("demo")
    again = pickle.loads(pickle.dumps(s))
    assert again.to_toml() == s.to_toml() and again.source == "builtin:demo"
