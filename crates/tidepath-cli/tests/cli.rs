//! End-to-end tests of the `tidepath` binary: the acceptance list of issue #2.

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
    for key in [
        "planner",
        "seed",
        "scenario",
        "waypoints",
        "cost",
        "cost_terms",
        "violations",
        "metrics",
        "evaluations",
        "elapsed_s",
        "history",
    ] {
        assert!(plan.get(key).is_some(), "missing {key}");
    }
    for key in ["length_m", "travel_time_s", "max_turn_deg", "max_pitch_deg", "min_clearance_m", "collisions"] {
        assert!(plan["metrics"].get(key).is_some(), "missing metrics.{key}");
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
    assert_ne!(a["waypoints"], c["waypoints"]);
}

#[test]
fn thread_count_does_not_change_the_plan() {
    let dir = tempfile::tempdir().unwrap();
    let one = json(&plan_demo(dir.path(), "one.json", "5", &[("RAYON_NUM_THREADS", "1")]));
    let two = json(&plan_demo(dir.path(), "two.json", "5", &[("RAYON_NUM_THREADS", "2")]));
    assert_eq!(one["waypoints"], two["waypoints"]);
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

#[test]
fn start_inside_an_obstacle_is_named() {
    let text = demo_text().replace("start = [1000.0, 6000.0, -400.0]", "start = [9500.0, 6800.0, -450.0]");
    assert_bad_input(&text, &[], "mission.start", "inside obstacle 0");
}

#[test]
fn start_below_the_seabed_is_named() {
    let text = demo_text().replace("start = [1000.0, 6000.0, -400.0]", "start = [6000.0, 6000.0, -500.0]");
    assert_bad_input(&text, &[], "mission.start", "below the seabed");
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
    for sub in ["scenarios", "scenario", "planners", "plan", "eval", "compare", "bench", "reproduce"] {
        let o = tidepath(&[sub, "--help"], &[]);
        assert_eq!(o.status.code(), Some(0), "{sub} --help");
        assert!(String::from_utf8_lossy(&o.stdout).contains("Usage"), "{sub}");
    }
}

#[test]
fn listings_show_the_demo_and_the_planners() {
    let s = String::from_utf8(tidepath(&["scenarios"], &[]).stdout).unwrap();
    assert!(s.lines().any(|l| l.starts_with("demo")));
    let p = String::from_utf8(tidepath(&["planners"], &[]).stdout).unwrap();
    for id in ["pso", "ga", "de"] {
        assert!(p.lines().any(|l| l.starts_with(id)), "{id} missing from {p}");
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
    let smoothed = plan["smoothed"].as_array().expect("smoothed path");
    assert!(smoothed.len() <= plan["waypoints"].as_array().unwrap().len());
    assert!(plan["cost"].as_f64().unwrap() <= plan["raw_cost"].as_f64().unwrap());
    let o = tidepath(&["eval", "demo", out.to_str().unwrap()], &[]);
    assert!(String::from_utf8_lossy(&o.stdout).contains("relative difference 0.00e0"));
    let o = tidepath(&["plan", "demo", "--smooth", "spline-magic"], &[]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("spline-magic"));
}
