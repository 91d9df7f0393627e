//! The planner contract from the command line: budgets held, requests a planner cannot honour
//! refused naming the flag, capabilities listed, older plan files still read.

use std::process::{Command, Output};

fn tidepath(args: &[&str], cwd: &std::path::Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tidepath")).args(args).current_dir(cwd).output().expect("tidepath runs")
}

fn refused(o: &Output, flag: &str) {
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with(&format!("error: {flag}:")), "{stderr}");
}

/// A generation of 20,000 path evaluations is cut by a 0.05 s limit: the run's wall time stays
/// far below what one generation takes.
#[test]
fn a_huge_generation_keeps_a_tiny_time_limit() {
    let dir = tempfile::tempdir().unwrap();
    let o =
        tidepath(&["plan", "demo", "--planner", "pso", "--population", "20000", "--time-limit", "0.05"], dir.path());
    let stdout = String::from_utf8_lossy(&o.stdout);
    let wall: f64 = stdout
        .lines()
        .find_map(|l| l.split("wall time ").nth(1))
        .and_then(|rest| rest.split(' ').next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("no wall time in {stdout}"));
    assert!(wall < 0.3, "wall time {wall} s: {stdout}");
    assert!(stdout.contains("stopped by wall_time"), "{stdout}");
}

#[test]
fn requests_a_planner_cannot_honour_are_refused_naming_the_flag() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    refused(&tidepath(&["plan", "demo", "--planner", "astar", "--iterations", "3"], d), "--iterations");
    let o = tidepath(&["plan", "headland", "--planner", "pso", "--iterations", "2", "--out", "p.json"], d);
    assert!(o.status.code().is_some_and(|c| c <= 1));
    refused(&tidepath(&["plan", "headland", "--planner", "astar", "--init", "p.json"], d), "--init");
    refused(&tidepath(&["plan", "headland", "--planner", "visibility", "--population", "7"], d), "--population");
    refused(&tidepath(&["plan", "headland", "--planner", "visibility", "--expansions", "7"], d), "--expansions");
    refused(
        &tidepath(&["compare", "headland", "--planners", "pso,astar", "--runs", "2", "--iterations", "3"], d),
        "--iterations",
    );
    // Nothing was written by the refusals.
    let names: Vec<_> = std::fs::read_dir(d).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names, ["p.json"]);
}

#[test]
fn planners_lists_capabilities_and_each_default_once() {
    let dir = tempfile::tempdir().unwrap();
    let o = tidepath(&["planners", "--params"], dir.path());
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("can: 2-D only; fleets one mission after another; no warm start; counts nothing"), "{out}");
    assert!(out.contains("counts expansions"), "{out}");
    for line in out.lines().filter(|l| l.contains("default")) {
        assert_eq!(line.matches("default").count(), 1, "{line}");
    }
}

/// Plan files of format versions 1, 2 and 3 all load in `eval`.
#[test]
fn plan_files_of_every_version_load() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let o = tidepath(&["plan", "demo", "--planner", "de", "--iterations", "30", "--out", "v3.json"], d);
    assert!(o.status.code().is_some_and(|c| c <= 1), "{}", String::from_utf8_lossy(&o.stderr));
    let mut v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(d.join("v3.json")).unwrap()).unwrap();
    assert_eq!(v["version"], 3);
    // Version 2: no per-mission status, no counts.
    v["version"] = 2.into();
    for key in ["state_checks", "motion_checks", "graph_nodes", "graph_edges", "warm_start"] {
        v.as_object_mut().unwrap().remove(key);
    }
    for m in v["missions"].as_array_mut().unwrap() {
        for key in ["status", "reason", "goal_distance_m"] {
            m.as_object_mut().unwrap().remove(key);
        }
    }
    std::fs::write(d.join("v2.json"), v.to_string()).unwrap();
    let v1 = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/plan_v1_demo.json");
    for file in ["v3.json", "v2.json", v1] {
        let o = tidepath(&["eval", "demo", file], d);
        let stdout = String::from_utf8_lossy(&o.stdout);
        assert!(o.status.code().is_some_and(|c| c <= 1), "{file}: {}", String::from_utf8_lossy(&o.stderr));
        assert!(stdout.contains("cost terms") && stdout.contains("verdict"), "{file}: {stdout}");
    }
}
