//! `tidepath simulate`: per-phase lines, the simulation file and figure, exit codes by the
//! outcome, determinism for any `--jobs`, and bad input refused before anything is written.

use std::path::Path;
use std::process::{Command, Output};

fn tidepath(args: &[&str], cwd: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tidepath")).args(args).current_dir(cwd).output().expect("tidepath runs")
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The file without the wall times, which alone may differ between runs.
fn without_wall_times(mut v: serde_json::Value) -> serde_json::Value {
    v["outcome"]["elapsed_s"] = serde_json::Value::Null;
    for p in v["phases"].as_array_mut().unwrap() {
        if p["replan"].is_object() {
            p["replan"]["planning_s"] = serde_json::Value::Null;
        }
    }
    v
}

#[test]
fn coastal_traffic_reaches_the_goal_with_a_figure_panel_per_phase() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["simulate", "coastal-traffic", "--planner", "hybrid", "--plot", "sim.svg", "--out", "sim.json"];
    let o = tidepath(&args, dir.path());
    let stdout = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{stdout}{}", text(&o.stderr));
    let sim = json(&dir.path().join("sim.json"));
    assert_eq!(sim["outcome"]["reached"], true);
    assert_eq!(sim["outcome"]["track_violations"].as_array().unwrap().len(), 0);
    let phases = sim["phases"].as_array().unwrap();
    assert!(phases.len() >= 3, "departure, a sighting and course changes");
    for k in 0..phases.len() {
        assert!(stdout.contains(&format!("  phase {k:<3}")), "{stdout}");
    }
    assert!(stdout.contains("outcome   reached the goal"), "{stdout}");
    let svg = std::fs::read_to_string(dir.path().join("sim.svg")).unwrap();
    for k in 0..phases.len() {
        assert!(svg.contains(&format!("data-phase=\"{k}\"")), "panel {k}");
    }
}

#[test]
fn the_same_seed_gives_the_same_simulation_for_any_jobs() {
    let dir = tempfile::tempdir().unwrap();
    let mut files = Vec::new();
    for jobs in ["1", "2"] {
        let out = format!("s{jobs}.json");
        let o = tidepath(
            &[
                "simulate",
                "coastal-traffic",
                "--planner",
                "pso",
                "--iterations",
                "30",
                "--jobs",
                jobs,
                "--seed",
                "4",
                "--out",
                &out,
            ],
            dir.path(),
        );
        assert!(matches!(o.status.code(), Some(0 | 1)), "{}", text(&o.stderr));
        files.push(without_wall_times(json(&dir.path().join(out))));
    }
    assert_eq!(files[0], files[1]);
}

#[test]
fn forecast_update_replans_when_the_new_forecast_arrives() {
    let dir = tempfile::tempdir().unwrap();
    let o = tidepath(&["simulate", "forecast-update", "--out", "f.json"], dir.path());
    let stdout = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{stdout}{}", text(&o.stderr));
    assert!(stdout.contains("a new current forecast arrived"), "{stdout}");
    let sim = json(&dir.path().join("f.json"));
    let phase = &sim["phases"][1];
    assert_eq!(phase["time_utc"], "2025-11-12T05:00:00.000Z");
    assert_eq!(phase["known_world"]["current_forecasts_received"], 2);
    assert!(phase["replan"]["status"] == "feasible" || phase["replan"]["status"] == "exact");
    assert!(sim["outcome"]["arrival_utc"].as_str().unwrap().starts_with("2025-11-1"));
}

#[test]
fn a_change_that_closes_the_way_exits_1_naming_the_phase_and_where() {
    let dir = tempfile::tempdir().unwrap();
    let wall = "\n[[changes]]\nafter_distance = 300.0\nkind = \"add-obstacle\"\nadd = { kind = \"box\", min = [590.0, -10.0, -1.0], max = [610.0, 410.0, 1.0] }\n";
    let scenario = format!("{}{wall}", include_str!("../../../tidepath-io/tests/data/channel_changes.toml"));
    std::fs::write(dir.path().join("walled.toml"), scenario).unwrap();
    let o = tidepath(&["simulate", "walled.toml", "--plot", "w.svg"], dir.path());
    let stdout = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{stdout}");
    assert!(stdout.contains("outcome   phase 2: no feasible window up to the goal"), "{stdout}");
    assert!(stdout.contains("nearest the goal at"), "{stdout}");
    let svg = std::fs::read_to_string(dir.path().join("w.svg")).unwrap();
    assert!(svg.contains("sim-failed"), "the failed phase is marked");
}

#[test]
fn bad_input_is_one_line_exit_2_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    for (args, field) in [
        (vec!["--window", "0"], "--window"),
        (vec!["--growth", "triple"], "--growth"),
        (vec!["--sensor-range", "nan"], "--sensor-range"),
        (vec!["--planner", "nope"], "nope"),
        (vec!["--total-time-limit", "0"], "--total-time-limit"),
        (vec!["--target-cost", "1"], "--target-cost"),
        (vec!["--out", "sim.txt"], "--out"),
    ] {
        let mut all = vec!["simulate", "coastal-traffic", "--plot", "p.svg"];
        all.extend(args);
        let o = tidepath(&all, dir.path());
        let err = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{all:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(err.contains(field), "{field}: {err}");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0, "{all:?} wrote something");
    }
}
