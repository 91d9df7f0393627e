"""The 3-D view from Python: the same page as `tidepath view`, written all or nothing."""

import json

import pytest

from conftest import run_cli
from tidepath import Scenario


def scene(html):
    open_tag = '<script id="tp-scene" type="application/json">'
    start = html.index(open_tag) + len(open_tag)
    return json.loads(html[start : html.index("</script>", start)])


def test_view_holds_the_plan_and_matches_the_cli(cli, tmp_path):
    sc = Scenario.builtin("demo")
    plan = sc.plan(planner="pso", seed=2, iterations=15)
    out = tmp_path / "v.html"
    html = sc.view([plan], path=out, title="demo from Python")
    assert out.read_text() == html
    s = scene(html)
    assert s["title"] == "demo from Python"
    (route,) = s["routes"]
    assert route["label"] == "pso"
    assert len(route["x"]) == len(plan.missions[0].path)
    assert route["t"][-1] == pytest.approx(plan.missions[0].times[-1], abs=0.005)
    # The CLI's view of the same plan holds the same scene (titles aside).
    plan.save(tmp_path / "p.json")
    r = run_cli(cli, "view", "demo", str(tmp_path / "p.json"), "-o", str(tmp_path / "c.html"))
    assert r.returncode == 0, r.stderr
    theirs = scene((tmp_path / "c.html").read_text())
    assert theirs["routes"][0]["x"] == route["x"] and theirs["routes"][0]["t"] == route["t"]
    assert theirs["seabed"] == s["seabed"]


def test_view_refuses_a_wrong_target_or_a_plan_of_another_scenario(tmp_path):
    sc = Scenario.builtin("demo")
    with pytest.raises(ValueError, match="path.*html"):
        sc.view([], path=tmp_path / "v.png")
    assert not (tmp_path / "v.png").exists()
    other = Scenario.builtin("headland").plan(planner="astar")
    with pytest.raises(ValueError, match="plans.*headland"):
        sc.view([other])
    # A scenario alone is a view too.
    assert scene(sc.view())["routes"] == []
