//! End-to-end tests of the `tidepath` binary: plan, eval, listings, the bad-input contract and
//! the status exit codes.

// `plan --graph` (its own file; one test binary builds faster than two).
#[path = "cli/graph.rs"]
mod graph;

// `simulate`, likewise.
#[path = "cli/simulate.rs"]
mod simulate;

// Fleets, likewise.
#[path = "cli/fleet.rs"]
mod fleet;

// The other end-to-end suites: one test binary links once, where eight took eight links.
#[path = "cli/contract.rs"]
mod contract;
#[path = "cli/engineers.rs"]
mod engineers;
#[path = "cli/experiments.rs"]
mod experiments;
#[path = "cli/flown.rs"]
mod flown;
#[path = "cli/hardening.rs"]
mod hardening;
#[path = "cli/no_route.rs"]
mod no_route;
#[path = "cli/numbers.rs"]
mod numbers;
#[path = "cli/repair.rs"]
mod repair;
#[path = "cli/shard.rs"]
mod shard;
#[path = "cli/vehicles.rs"]
mod vehicles;
#[path = "cli/view.rs"]
mod view;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn tidepath(args: &[&str], envs: &[(&str, &str)]) -> Output {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_tidepath"));
    cmd.args(args);
    for (k, v) in envs {
        cmd.env(k, v);
    }
    cmd.output().expect("tidepath runs")
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn demo_text() -> String {
    String::from_utf8(tidepath(&["scenario", "demo"], &[]).stdout).unwrap()
}

/// Plans the demo with a small budget into `dir`, returning the JSON path.
fn plan_demo(dir: &Path, name: &str, seed: &str, envs: &[(&str, &str)]) -> PathBuf {
    let out = dir.join(name);
    let o = tidepath(&["plan", "demo", "--planner", "pso", "--seed", seed, "--out", out.to_str().unwrap()], envs);
    assert!(o.status.code() == Some(0) || o.status.code() == Some(1), "{}", String::from_utf8_lossy(&o.stderr));
    out
}

#[test]
fn demo_plan_is_feasible_and_writes_json_and_svg() {
    let dir = tempfile::tempdir().unwrap();
    let (out, svg) = (dir.path().join("plan.json"), dir.path().join("demo.svg"));
    let o = tidepath(
        &["plan", "demo", "--planner", "pso", "--out", out.to_str().unwrap(), "--plot", svg.to_str().unwrap()],
        &[],
    );
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "stdout: {stdout}\nstderr: {}", String::from_utf8_lossy(&o.stderr));
    assert!(stdout.contains("feasible") && stdout.contains("cost") && stdout.contains("evaluations"), "{stdout}");
    let plan = json(&out);
    assert_eq!(plan["feasible"], true);
    assert_eq!(plan["status"], "feasible");
    assert_eq!(plan["version"], 3);
    assert_eq!(plan["missions"][0]["status"], "feasible");
    for key in
        ["planner", "seed", "scenario", "status", "reason", "cost", "missions", "evaluations", "elapsed_s", "history"]
    {
        assert!(plan.get(key).is_some(), "missing {key}");
    }
    let m = &plan["missions"][0];
    for key in ["name", "waypoints", "times", "cost", "cost_terms", "violations", "metrics"] {
        assert!(m.get(key).is_some(), "missing missions[0].{key}");
    }
    assert_eq!(m["times"].as_array().unwrap().len(), m["waypoints"].as_array().unwrap().len());
    for key in ["length_m", "travel_time_s", "max_turn_deg", "max_pitch_deg", "min_clearance_m", "collisions"] {
        assert!(m["metrics"].get(key).is_some(), "missing metrics.{key}");
    }
    let svg_text = std::fs::read_to_string(&svg).unwrap();
    assert!(svg_text.starts_with("<svg") || svg_text.starts_with("<?xml"));
}

#[test]
fn eval_reproduces_the_plan_cost() {
    let dir = tempfile::tempdir().unwrap();
    let out = plan_demo(dir.path(), "plan.json", "3", &[]);
    let cost = json(&out)["cost"].as_f64().unwrap();
    let o = tidepath(&["eval", "demo", out.to_str().unwrap()], &[]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    let total_line = stdout.lines().find(|l| l.trim_start().starts_with("total")).expect("total line");
    let total: f64 = total_line.split_whitespace().nth(1).unwrap().parse().unwrap();
    assert!(((total - cost) / cost).abs() < 1e-9, "eval {total} vs plan {cost}");
    assert!(stdout.contains("relative difference 0.00e0"), "{stdout}");
}

#[test]
fn same_seed_gives_identical_json_apart_from_elapsed() {
    let dir = tempfile::tempdir().unwrap();
    let strip = |p: PathBuf| {
        let mut v = json(&p);
        v.as_object_mut().unwrap().remove("elapsed_s");
        v
    };
    let a = strip(plan_demo(dir.path(), "a.json", "7", &[]));
    let b = strip(plan_demo(dir.path(), "b.json", "7", &[]));
    assert_eq!(a, b);
    let c = strip(plan_demo(dir.path(), "c.json", "8", &[]));
    assert!(a["missions"][0]["waypoints"].is_array());
    assert_ne!(a["missions"][0]["waypoints"], c["missions"][0]["waypoints"]);
}

#[test]
fn thread_count_does_not_change_the_plan() {
    let dir = tempfile::tempdir().unwrap();
    let one = json(&plan_demo(dir.path(), "one.json", "5", &[("RAYON_NUM_THREADS", "1")]));
    let two = json(&plan_demo(dir.path(), "two.json", "5", &[("RAYON_NUM_THREADS", "2")]));
    assert_eq!(one["missions"], two["missions"]);
    assert_eq!(one["history"], two["history"]);
}

/// Runs `plan` on a scenario text and checks the bad-input contract: exit 2, one line on
/// stderr naming `field` and `value`, no panic, no output files.
fn assert_bad_input(scenario: &str, extra: &[&str], field: &str, value: &str) {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("s.toml");
    std::fs::write(&file, scenario).unwrap();
    let (out, svg) = (dir.path().join("p.json"), dir.path().join("p.svg"));
    let mut args =
        vec!["plan", file.to_str().unwrap(), "--out", out.to_str().unwrap(), "--plot", svg.to_str().unwrap()];
    args.extend_from_slice(extra);
    let o = tidepath(&args, &[]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "stderr: {stderr}");
    assert_eq!(stderr.trim_end().lines().count(), 1, "one line expected: {stderr}");
    assert!(stderr.contains(field) && stderr.contains(value), "expected {field} and {value} in: {stderr}");
    assert!(!stderr.contains("panicked"));
    let left: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(left, vec![std::ffi::OsString::from("s.toml")], "files left behind");
}

#[test]
fn malformed_toml_is_reported_with_its_line() {
    assert_bad_input("name = \"x\"\n[world\n", &[], "malformed TOML", "line 2");
}

#[test]
fn unknown_planner_is_named() {
    assert_bad_input(&demo_text(), &["--planner", "warp-drive"], "planner", "warp-drive");
}

/// Runs `plan` on a scenario text that loads but cannot be planned: exit 1, the status and a
/// one-line reason naming `field` and `what` on stdout, no panic.
fn assert_status(scenario: &str, status: &str, field: &str, what: &str) {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("s.toml");
    std::fs::write(&file, scenario).unwrap();
    let out = dir.path().join("p.json");
    let o = tidepath(&["plan", file.to_str().unwrap(), "--out", out.to_str().unwrap()], &[]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "stdout: {stdout} stderr: {}", String::from_utf8_lossy(&o.stderr));
    let first = stdout.lines().next().unwrap_or_default();
    assert!(first.contains(&format!(": {status}: {field}")) && first.contains(what), "{first}");
    assert_eq!(json(&out)["status"], status);
}

#[test]
fn start_inside_an_obstacle_is_named() {
    let text = demo_text().replace("start = [1000.0, 6000.0, -400.0]", "start = [9500.0, 6800.0, -450.0]");
    assert_status(&text, "invalid-start", "mission.start", "inside obstacle 0");
}

#[test]
fn start_below_the_seabed_is_named() {
    let text = demo_text().replace("start = [1000.0, 6000.0, -400.0]", "start = [6000.0, 6000.0, -500.0]");
    assert_status(&text, "invalid-start", "mission.start", "below the seabed");
}

#[test]
fn time_limits_that_make_no_sense_are_input_errors() {
    for bad in ["1e20", "-1", "nan", "inf", "0"] {
        let flag = format!("--time-limit={bad}");
        assert_bad_input(&demo_text(), &[flag.as_str()], "--time-limit", "must");
    }
}

/// With no time limit anywhere the default cap applies, is printed, and stops a run that would
/// otherwise go on for hours (the cap is lowered through its environment variable here).
#[test]
fn plan_without_a_limit_stops_at_the_default_cap_and_says_so() {
    let o = tidepath(&["plan", "demo", "--iterations", "100000000"], &[("TIDEPATH_DEFAULT_TIME_LIMIT", "0.5")]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(matches!(o.status.code(), Some(0) | Some(1)), "{stdout}");
    assert!(stdout.contains("time limit     0.5 s (default cap"), "{stdout}");
    assert!(stdout.contains("stopped by the default wall-time cap"), "{stdout}");
    let o = tidepath(&["plan", "demo", "--iterations", "3"], &[]);
    assert!(String::from_utf8_lossy(&o.stdout).contains("time limit     600 s (default cap"));
}

/// A plan file written by version 1 (one path at the top level, before missions and statuses)
/// still loads in `eval` and reproduces its recorded cost.
#[test]
fn version_one_plan_files_still_evaluate() {
    let v1 = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/plan_v1_demo.json");
    let o = tidepath(&["eval", "demo", v1], &[]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(matches!(o.status.code(), Some(0) | Some(1)), "{stdout} {}", String::from_utf8_lossy(&o.stderr));
    assert!(stdout.contains("plan format version 1"), "{stdout}");
    assert!(stdout.contains("relative difference"), "{stdout}");
}

/// `plan --init` reads a plan (either version) and starts from it: the run can only end at a
/// cost no worse than the file's path, since that path is in the first population.
#[test]
fn warm_start_from_a_plan_file() {
    let dir = tempfile::tempdir().unwrap();
    let first = plan_demo(dir.path(), "first.json", "3", &[]);
    let cost0 = json(&first)["cost"].as_f64().unwrap();
    let out = dir.path().join("second.json");
    let o = tidepath(
        &[
            "plan",
            "demo",
            "--planner",
            "de",
            "--iterations",
            "5",
            "--init",
            first.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ],
        &[],
    );
    assert!(matches!(o.status.code(), Some(0) | Some(1)), "{}", String::from_utf8_lossy(&o.stderr));
    let cost1 = json(&out)["cost"].as_f64().unwrap();
    assert!(cost1 <= cost0 * (1.0 + 1e-12), "warm start lost ground: {cost1} > {cost0}");
    let o = tidepath(&["plan", "demo", "--init", "/nonexistent/plan.json"], &[]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn goal_outside_the_bounds_is_named() {
    let text = demo_text().replace("goal = [19000.0, 6500.0, -300.0]", "goal = [25000.0, 6500.0, -300.0]");
    assert_bad_input(&text, &[], "mission.goal", "25000");
}

#[test]
fn nan_and_inf_are_rejected_anywhere() {
    let text = demo_text().replace("speed = 1.5", "speed = nan");
    assert_bad_input(&text, &[], "vehicle.speed", "NaN");
    let text = demo_text().replace("radius = 500.0", "radius = inf");
    assert_bad_input(&text, &[], "world.obstacles[1].radius", "inf");
    let text = demo_text().replace("{ x = 8000.0, y = 3500.0,", "{ x = -inf, y = 3500.0,");
    assert_bad_input(&text, &[], "world.current.vortices[0].x", "-inf");
}

#[test]
fn every_subcommand_has_help() {
    for sub in [
        "scenarios",
        "scenario",
        "planners",
        "vehicles",
        "plan",
        "simulate",
        "eval",
        "compare",
        "merge",
        "bench",
        "reproduce",
    ] {
        let o = tidepath(&[sub, "--help"], &[]);
        assert_eq!(o.status.code(), Some(0), "{sub} --help");
        assert!(String::from_utf8_lossy(&o.stdout).contains("Usage"), "{sub}");
    }
}

#[test]
fn listings_show_the_demo_and_the_planners() {
    let s = String::from_utf8(tidepath(&["scenarios"], &[]).stdout).unwrap();
    // Every built-in, with the descriptions in one column however long the ids.
    let column: Vec<usize> = tidepath_io::scenario::BUILTIN
        .iter()
        .map(|e| {
            let line = s.lines().find(|l| l.split_whitespace().next() == Some(e.id)).expect(e.id);
            line.find(e.description).expect(e.description)
        })
        .collect();
    assert!(column.windows(2).all(|w| w[0] == w[1]), "{s}");
    let p = String::from_utf8(tidepath(&["planners"], &[]).stdout).unwrap();
    for e in tidepath::planner::PLANNERS {
        assert!(p.lines().any(|l| l.trim_start().starts_with(e.id)), "{} missing from {p}", e.id);
    }
    // The printed TOML loads back as a scenario file.
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("demo.toml");
    std::fs::write(&f, demo_text()).unwrap();
    let o = tidepath(&["plan", f.to_str().unwrap(), "--iterations", "2"], &[]);
    assert!(matches!(o.status.code(), Some(0) | Some(1)), "{}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn smoothed_plans_are_evaluated_as_smoothed() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("s.json");
    let o = tidepath(&["plan", "demo", "--smooth", "shortcut", "--seed", "2", "--out", out.to_str().unwrap()], &[]);
    assert!(matches!(o.status.code(), Some(0) | Some(1)), "{}", String::from_utf8_lossy(&o.stderr));
    let plan = json(&out);
    let m = &plan["missions"][0];
    let smoothed = m["smoothed"].as_array().expect("smoothed path");
    assert!(smoothed.len() <= m["waypoints"].as_array().unwrap().len());
    assert!(m["cost"].as_f64().unwrap() <= m["raw_cost"].as_f64().unwrap());
    let o = tidepath(&["eval", "demo", out.to_str().unwrap()], &[]);
    assert!(String::from_utf8_lossy(&o.stdout).contains("relative difference 0.00e0"));
    let o = tidepath(&["plan", "demo", "--smooth", "spline-magic"], &[]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("spline-magic"));
}

/// A fleet scenario: `plan` writes one timed path per mission and `eval` reports both.
#[test]
fn fleet_plans_and_evaluations_report_every_mission() {
    let fleet = concat!(env!("CARGO_MANIFEST_DIR"), "/../tidepath-io/tests/data/fleet.toml");
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("fleet.json");
    let o = tidepath(&["plan", fleet, "--planner", "de", "--seed", "2", "--out", out.to_str().unwrap()], &[]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(matches!(o.status.code(), Some(0) | Some(1)), "{stdout} {}", String::from_utf8_lossy(&o.stderr));
    assert!(stdout.contains("mission auv-a") && stdout.contains("mission auv-b"), "{stdout}");
    let plan = json(&out);
    let missions = plan["missions"].as_array().unwrap();
    assert_eq!(missions.len(), 2);
    assert_eq!(missions[1]["times"][0], 600.0);
    let o = tidepath(&["eval", fleet, out.to_str().unwrap()], &[]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(stdout.contains("mission auv-a") && stdout.contains("mission auv-b"), "{stdout}");
    assert!(stdout.contains("relative difference 0.00e0"), "{stdout}");
    // The fleet's plan does not fit the one-mission demo.
    let o = tidepath(&["eval", "demo", out.to_str().unwrap()], &[]);
    assert_eq!(o.status.code(), Some(2));
}

/// `--out` by extension: every format from a geographic scenario; latitude/longitude formats
/// refused (exit 2, no file) for a local one; `--from`/`--to` in degrees, checked.
#[test]
fn plan_exports_by_extension_and_takes_from_and_to() {
    let dir = tempfile::tempdir().unwrap();
    for ext in ["geojson", "csv", "kml", "gpx", "json"] {
        let out = dir.path().join(format!("s.{ext}"));
        let o = tidepath(
            &["plan", "salish", "--from", "-124.6,48.45", "--to=-123.3,48.35", "--out", out.to_str().unwrap()],
            &[],
        );
        assert_eq!(o.status.code(), Some(0), "{ext}: {}", String::from_utf8_lossy(&o.stderr));
        let text = std::fs::read_to_string(&out).unwrap();
        assert!(text.contains("-124.6"), "{ext}: the start is not in the file");
    }
    let kml = dir.path().join("d.kml");
    let o = tidepath(&["plan", "demo", "--out", kml.to_str().unwrap()], &[]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("geographic scenario"));
    assert!(!kml.exists());
    for (args, needle) in [
        (vec!["plan", "salish", "--to", "-124.0"], "--to: '-124.0' is not LON,LAT[,DEPTH]"),
        (vec!["plan", "salish", "--to", "-130,48"], "--to: mission.goal"),
        (vec!["plan", "salish", "--out", "x.shp"], "unknown extension"),
    ] {
        let o = tidepath(&args, &[]);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(needle) && err.lines().count() == 1, "{args:?}: {err}");
    }
    // A goal on land is invalid-goal (exit 1) and says so.
    let o = tidepath(&["plan", "salish", "--to", "-124.0,48.9"], &[]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stdout).contains("on land"));
}

/// A built-in geographic scenario printed and planned from a file still finds its data.
#[test]
fn a_copied_geographic_scenario_finds_its_data() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("mine.toml");
    std::fs::write(&path, String::from_utf8(tidepath(&["scenario", "salish"], &[]).stdout).unwrap()).unwrap();
    let o = tidepath(&["plan", path.to_str().unwrap(), "--iterations", "5"], &[]);
    assert!(o.status.code() == Some(0) || o.status.code() == Some(1), "{}", String::from_utf8_lossy(&o.stderr));
}

/// The acceptance command of the real-data issue: a feasible AUV route on the real seabed, a
/// plot with latitude/longitude axes and the coastline, a GeoJSON that parses.
#[test]
fn salish_strait_plot_has_degree_axes_and_the_coastline() {
    let dir = tempfile::tempdir().unwrap();
    let (svg, gj) = (dir.path().join("s.svg"), dir.path().join("s.geojson"));
    let o = tidepath(&["plan", "salish-strait", "--plot", svg.to_str().unwrap(), "--out", gj.to_str().unwrap()], &[]);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(&svg).unwrap();
    for needle in ["longitude", "latitude", "124.5°W", "48.4°N", "coastline"] {
        assert!(text.contains(needle), "the figure lacks {needle}");
    }
    let g: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&gj).unwrap()).unwrap();
    assert_eq!(g["type"], "FeatureCollection");
    assert_eq!(g["features"][0]["properties"]["status"], "feasible");
}
