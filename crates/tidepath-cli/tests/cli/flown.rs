//! A vehicle with a turning radius from the command line: the plan JSON and the exports carry
//! the curve it flies beside the waypoints, the summaries say how tight its turns are, and an
//! exported route is read back by `eval` as its waypoints.

use std::path::Path;
use std::process::{Command, Output};

fn tidepath(args: &[&str], cwd: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tidepath")).args(args).current_dir(cwd).output().expect("tidepath runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Writes built-in `name` to `file` in `dir`, with `turn_radius` (m) for its vehicle if given.
fn scenario(dir: &Path, name: &str, radius: Option<f64>, file: &str) {
    let o = tidepath(&["scenario", name], dir);
    assert_eq!(o.status.code(), Some(0));
    let mut text = stdout(&o);
    if let Some(r) = radius {
        assert!(text.contains("[vehicle]\n"), "{text}");
        text = text.replace("[vehicle]\n", &format!("[vehicle]\nturn_radius = {r}\n"));
    }
    std::fs::write(dir.join(file), text).unwrap();
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// With a radius the plan JSON holds each mission's flown curve and the summary a turns line;
/// without one neither.
#[test]
fn plan_json_has_the_flown_curve_only_with_a_radius() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    scenario(d, "headland", Some(60.0), "r.toml");
    scenario(d, "headland", None, "plain.toml");
    let o = tidepath(&["plan", "r.toml", "--planner", "astar", "--out", "r.json"], d);
    // The corners of a raster path do not fit a 60 m radius: infeasible, flown all the same.
    assert_eq!(o.status.code(), Some(1), "{}", String::from_utf8_lossy(&o.stderr));
    let out = stdout(&o);
    let line = out.lines().find(|l| l.trim_start().starts_with("turns")).unwrap_or_else(|| panic!("{out}"));
    assert!(line.contains("radius >= ") && line.contains("/m), vehicle 60 m"), "{line}");
    assert!(out.contains("violation      waypoint "), "{out}");
    let plan = json(&d.join("r.json"));
    let m = &plan["missions"][0];
    let (points, times) = (m["flown"]["points"].as_array().unwrap(), m["flown"]["times"].as_array().unwrap());
    assert!(points.len() > m["waypoints"].as_array().unwrap().len());
    assert_eq!(points.len(), times.len());
    // The flown curve runs from the start to the goal, on the plan's clock.
    assert_eq!(points[0], m["waypoints"][0]);
    assert_eq!(points.last(), m["waypoints"].as_array().unwrap().last());
    assert_eq!(times.last(), m["times"].as_array().unwrap().last());

    let o = tidepath(&["plan", "plain.toml", "--planner", "astar", "--out", "plain.json"], d);
    assert_eq!(o.status.code(), Some(0));
    assert!(!stdout(&o).contains("turns"), "{}", stdout(&o));
    let plan = json(&d.join("plain.json"));
    assert!(plan["missions"][0].get("flown").is_none());
    assert!(plan["missions"][0]["metrics"].get("min_turn_radius_m").is_none());
}

/// A GeoJSON export with a radius has the flown curve as a feature of its own, and `eval` of
/// that file (and of the GPX, KML and CSV) reads the waypoints back, not the flown curve.
#[test]
fn exports_carry_the_flown_curve_and_read_back_as_waypoints() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    scenario(d, "salish", Some(500.0), "s.toml");
    let o = tidepath(&["plan", "s.toml", "--planner", "astar", "--out", "p.json"], d);
    assert!(matches!(o.status.code(), Some(0 | 1)), "{}", String::from_utf8_lossy(&o.stderr));
    let plan = json(&d.join("p.json"));
    let waypoints = plan["missions"][0]["waypoints"].as_array().unwrap().len();
    let flown = plan["missions"][0]["flown"]["points"].as_array().unwrap().len();
    assert!(flown > waypoints);
    for ext in ["geojson", "gpx", "kml", "csv"] {
        let file = format!("p.{ext}");
        let o = tidepath(&["plan", "s.toml", "--planner", "astar", "--out", &file], d);
        assert!(matches!(o.status.code(), Some(0 | 1)), "{ext}: {}", String::from_utf8_lossy(&o.stderr));
        let o = tidepath(&["eval", "s.toml", &file], d);
        let out = stdout(&o);
        assert!(out.contains(&format!("\n  {waypoints} waypoints\n")), "{ext}: {out}");
        assert!(out.contains("  turns: radius >= "), "{ext}: {out}");
    }
    let g = json(&d.join("p.geojson"));
    let features = g["features"].as_array().unwrap();
    assert_eq!(features.len(), 2);
    assert_eq!(features[0]["properties"]["kind"], "waypoints");
    assert_eq!(features[1]["properties"]["kind"], "flown");
    assert_eq!(features[1]["geometry"]["type"], "LineString");
    assert_eq!(features[1]["geometry"]["coordinates"].as_array().unwrap().len(), flown);
    assert_eq!(features[0]["geometry"]["coordinates"].as_array().unwrap().len(), waypoints);
}

/// The issue's acceptance runs from the command line: Hybrid-A* on `salish-strait-turns` with
/// a figure, Theta* smoothed by `dubins`, and Hybrid-A* as the reference of a plan; each
/// feasible with every turn at the vehicle's radius or wider.
#[test]
fn salish_strait_turns_plans_flyable_routes_from_the_command_line() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for args in [
        &["plan", "salish-strait-turns", "--planner", "hybrid-astar", "--plot", "t.svg", "--out", "t.gpx"][..],
        // The route read back from the GPX file, rounded to centimetres, is still flyable.
        &["eval", "salish-strait-turns", "t.gpx"][..],
        &["plan", "salish-strait-turns", "--planner", "theta-star", "--smooth", "dubins"][..],
        &["plan", "salish-strait-turns", "--planner", "astar", "--reference", "hybrid-astar"][..],
    ] {
        let o = tidepath(args, d);
        let out = stdout(&o);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {out}{}", String::from_utf8_lossy(&o.stderr));
        let verdict = if args[0] == "eval" { "verdict: feasible" } else { ": feasible" };
        assert!(out.contains(verdict), "{args:?}: {out}");
        let turns = out.lines().find(|l| l.trim_start().starts_with("turns")).unwrap_or_else(|| panic!("{out}"));
        // `eval` prints "turns: radius >= ...", `plan` "turns          radius >= ...".
        assert!(turns.contains("radius >= 40.0 m") && !turns.contains("tighter"), "{args:?}: {turns}");
        if args.contains(&"--reference") {
            assert!(out.contains("reference      hybrid-astar (feasible): cost"), "{out}");
        }
    }
    let svg = std::fs::read_to_string(d.join("t.svg")).unwrap();
    assert!(svg.contains("hybrid-astar: flown, turns of radius 40 m"), "the figure draws the flown curve");
}

/// A corner sharper than the radius allows is a violation naming the waypoint and the radius
/// its legs allow (exit 1); the same scenario without a radius judges the same route feasible.
#[test]
fn eval_names_a_corner_too_sharp_for_the_radius() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let open = "name = \"open-water\"\n[world]\ndimensions = 2\nbounds = { min = [0.0, 0.0, 0.0], max = [10000.0, 10000.0, 0.0] }\n[vehicle]\nspeed = 1.5\nmax_turn_deg = 120.0\n[mission]\nstart = [1000.0, 5000.0, 0.0]\ngoal = [9000.0, 5000.0, 0.0]\n";
    std::fs::write(d.join("plain.toml"), open).unwrap();
    std::fs::write(
        d.join("r.toml"),
        open.replace("max_turn_deg = 120.0", "max_turn_deg = 120.0\nturn_radius = 8000.0"),
    )
    .unwrap();
    std::fs::write(d.join("corner.json"), r#"{"waypoints": [[1000, 5000, 0], [5000, 8000, 0], [9000, 5000, 0]]}"#)
        .unwrap();
    let o = tidepath(&["eval", "plain.toml", "corner.json"], d);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert!(stdout(&o).contains("verdict: feasible"), "{}", stdout(&o));
    let o = tidepath(&["eval", "r.toml", "corner.json"], d);
    assert_eq!(o.status.code(), Some(1));
    // 73.7 degrees at r = 8 km needs 6 km of each 5 km leg: a radius of 6.67 km fits.
    assert!(
        stdout(&o).contains(
            "- waypoint 1: the 73.7 deg turn needs 6000.0 m of each leg at the vehicle's 8000 m turning radius; its legs (5000.0 m and 5000.0 m) allow a radius of at most 6666.7 m"
        ),
        "{}",
        stdout(&o)
    );
}
