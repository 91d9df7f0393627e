"""Planning: results, numpy shapes, equality with the CLI, outputs, errors."""

import json

import numpy as np
import pytest

from conftest import run_cli
from tidepath import Plan, Scenario


def test_plan_has_numpy_results():
    plan = Scenario.builtin("demo").plan(planner="pso", seed=3, iterations=20)
    assert isinstance(plan, Plan)
    assert plan.status in {"exact", "feasible", "infeasible"}
    assert plan.reason
    assert isinstance(plan.cost, float)
    assert sum(plan.terms.values()) == pytest.approx(plan.cost, rel=1e-9)
    h = plan.history
    assert h.dtype == np.float64 and h.ndim == 1 and len(h) == plan.iterations + 1
    assert plan.iterations == 20 and plan.planner == "pso" and plan.seed == 3
    (m,) = plan.missions
    w = m.waypoints
    assert w.dtype == np.float64 and w.ndim == 2 and w.shape[1] == 3
    assert m.times.shape == (len(m.path),)
    assert m.lonlat is None  # a local scenario
    assert m.metrics["length_m"] > 0


def test_plan_equals_the_cli_bit_for_bit(cli, tmp_path):
    out = tmp_path / "x.json"
    r = run_cli(cli, "plan", "demo", "--planner", "pso", "--seed", "3", "--iterations", "20", "--out", str(out))
    assert out.exists(), r.stderr
    theirs = json.loads(out.read_text())
    plan = Scenario.builtin("demo").plan(planner="pso", seed=3, iterations=20)
    ours = json.loads(plan.to_json())
    assert ours["missions"][0]["waypoints"] == theirs["missions"][0]["waypoints"]
    assert np.array_equal(plan.missions[0].waypoints, np.array(theirs["missions"][0]["waypoints"]))
    assert ours["cost"] == theirs["cost"] and ours["history"] == theirs["history"]
    for k in ("elapsed_s", "scenario_source"):
        ours.pop(k), theirs.pop(k)
    assert ours == theirs


def test_same_seed_same_plan_other_seed_other_plan():
    s = Scenario.builtin("demo")
    a = s.plan(planner="de", seed=5, iterations=10)
    b = s.plan(planner="de", seed=5, iterations=10)
    c = s.plan(planner="de", seed=6, iterations=10)
    assert np.array_equal(a.missions[0].waypoints, b.missions[0].waypoints)
    assert not np.array_equal(a.missions[0].waypoints, c.missions[0].waypoints)


def test_save_writes_every_format_the_cli_writes(tmp_path):
    plan = Scenario.builtin("demo").plan(planner="pso", seed=3, iterations=5)
    plan.save(tmp_path / "p.json")
    assert json.loads((tmp_path / "p.json").read_text()) == json.loads(plan.to_json())
    plan.save(tmp_path / "p.csv")
    assert (tmp_path / "p.csv").read_text().count("\n") > len(plan.missions[0].waypoints)
    with pytest.raises(ValueError, match=r"^path: .*latitude/longitude"):
        plan.save(tmp_path / "p.gpx")
    with pytest.raises(ValueError, match=r"^path: .*unknown extension"):
        plan.save(tmp_path / "p.txt")


def geographic_name():
    import tidepath

    for s in tidepath.scenarios():
        sc = Scenario.builtin(s["id"])
        if sc.geographic and len(sc.mission_names) == 1:
            return s["id"]
    pytest.skip("no single-mission geographic built-in scenario")


def test_geographic_plan_has_lonlat_and_writes_gpx(tmp_path):
    name = geographic_name()
    s = Scenario.builtin(name)
    plan = s.plan(planner="pso", seed=1, iterations=3, time_limit=60)
    m = plan.missions[0]
    assert m.lonlat is not None and m.lonlat.shape == (len(m.path), 2)
    assert np.all(np.abs(m.lonlat[:, 1]) <= 90)
    plan.save(tmp_path / "p.gpx")
    plan.save(tmp_path / "p.geojson")
    plan.save(tmp_path / "p.kml")
    assert "<gpx" in (tmp_path / "p.gpx").read_text()
    # lon/lat overrides of the start, as `plan --from LON,LAT`.
    lon, lat = m.lonlat[0]
    moved = s.with_mission(start=[lon, lat])
    assert moved.start[0] == pytest.approx(s.start[0], abs=1e-6)


def test_params_smoother_and_init():
    s = Scenario.builtin("demo")
    a = s.plan(planner="pso", seed=1, iterations=5, population=12)
    assert a.evaluations == 12 * 6
    # `params` updates [planner.params.pso], as a scenario file would.
    default = s.plan(planner="pso", seed=1, iterations=5)
    tuned = s.plan(planner="pso", seed=1, iterations=5, params={"c1": 0.1})
    assert tuned.cost != default.cost
    via_toml = Scenario.from_toml(s.to_toml().replace("vmax_fraction = 0.2", "vmax_fraction = 0.2\nc1 = 0.1"))
    assert via_toml.plan(planner="pso", seed=1, iterations=5).cost == tuned.cost
    b = s.plan(planner="pso", seed=1, iterations=5, smoother="shortcut")
    assert b.missions[0].smoothed is not None
    warm = s.plan(planner="pso", seed=1, iterations=5, init=a.missions[0].waypoints)
    assert warm.cost <= a.cost + 1e-12 or warm.status == a.status
    with pytest.raises(ValueError, match=r"c1"):
        s.plan(planner="pso", iterations=5, params={"c1": -3.0})


def test_unknown_planner_is_a_value_error_with_the_cli_message(cli):
    with pytest.raises(ValueError) as e:
        Scenario.builtin("demo").plan(planner="no-such-planner")
    ours = str(e.value)
    r = run_cli(cli, "plan", "demo", "--planner", "no-such-planner")
    assert r.returncode != 0
    # The CLI prints the same one-line message (the library's error), after "error: ".
    assert ours in r.stderr
    assert "no-such-planner" in ours and "\n" not in ours


def test_a_bad_budget_is_a_value_error():
    with pytest.raises(ValueError, match=r"iterations"):
        Scenario.builtin("demo").plan(planner="pso", iterations=0)
    with pytest.raises(ValueError, match=r"time"):
        Scenario.builtin("demo").plan(planner="pso", time_limit=-1.0)


def test_progress_lines_go_to_python_stderr(capsys):
    s = Scenario.builtin("demo")
    quiet = s.plan(planner="pso", seed=3, iterations=30)
    assert capsys.readouterr().err == ""
    loud = s.plan(planner="pso", seed=3, iterations=30, progress=True)
    err = capsys.readouterr().err
    assert err.startswith("tidepath: iteration ") and "best cost" in err, err
    # Watching changes nothing.
    assert np.array_equal(quiet.missions[0].waypoints, loud.missions[0].waypoints)
