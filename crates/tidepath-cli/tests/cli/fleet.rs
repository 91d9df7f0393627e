//! Fleets on the command line: `plan --fleet sequential`, the fleet line of `plan` and
//! `eval`, and a conflict reported naming both vehicles.

use std::path::Path;
use std::process::{Command, Output};

fn tidepath(args: &[&str], cwd: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tidepath")).args(args).current_dir(cwd).output().expect("tidepath runs")
}

#[test]
fn fleet_crossing_planned_one_after_another_keeps_its_separation() {
    let dir = tempfile::tempdir().unwrap();
    let o = tidepath(
        &["plan", "fleet-crossing", "--planner", "astar", "--fleet", "sequential", "--out", "s.json"],
        dir.path(),
    );
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{stdout}");
    assert!(stdout.contains("separation kept"), "{stdout}");
    let e = tidepath(&["eval", "fleet-crossing", "s.json"], dir.path());
    let eval = String::from_utf8_lossy(&e.stdout);
    assert_eq!(e.status.code(), Some(0), "{eval}");
    assert!(eval.contains("fleet: closest approach") && eval.contains("separation kept"), "{eval}");
}

#[test]
fn vehicles_planned_alone_collide_and_both_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let o = tidepath(&["plan", "fleet-crossing", "--planner", "astar", "--plot", "c.svg"], dir.path());
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{stdout}");
    assert!(stdout.contains("vehicles auv-east and auv-north come within"), "{stdout}");
    assert!(std::fs::read_to_string(dir.path().join("c.svg")).unwrap().contains("closest approach"));
    let v = tidepath(
        &["plan", "fleet-crossing", "--planner", "visibility", "--fleet", "sequential", "--out", "v.json"],
        dir.path(),
    );
    assert_eq!(v.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&v.stderr).starts_with("error: --fleet: "));
    assert!(!dir.path().join("v.json").exists());
}

/// The rendezvous planned jointly: arrivals within 60 s with each vehicle's speeds in its
/// range, printed and written; `eval` confirms both; a speed outside the range is refused in
/// one line naming the mission and segment, and `simulate` refuses a speed range.
#[test]
fn fleet_rendezvous_arrives_together_and_eval_confirms_it() {
    let dir = tempfile::tempdir().unwrap();
    let o = tidepath(&["plan", "fleet-rendezvous", "--planner", "de", "--out", "r.json"], dir.path());
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{stdout}");
    assert!(stdout.contains("together within 60 s: kept") && stdout.contains("separation kept"), "{stdout}");
    assert_eq!(stdout.matches("m/s through the water").count(), 3, "{stdout}");
    let e = tidepath(&["eval", "fleet-rendezvous", "r.json"], dir.path());
    let eval = String::from_utf8_lossy(&e.stdout);
    assert_eq!(e.status.code(), Some(0), "{eval}");
    assert_eq!(eval.matches("verdict: feasible").count(), 3, "{eval}");
    assert!(eval.contains("together within 60 s: kept"), "{eval}");

    let mut plan: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("r.json")).unwrap()).unwrap();
    let speeds = plan["missions"][0]["speeds"].as_array().unwrap();
    assert!(speeds.iter().all(|v| (0.257..=2.058).contains(&v.as_f64().unwrap())), "{speeds:?}");
    plan["missions"][0]["speeds"][0] = serde_json::json!(9.0);
    std::fs::write(dir.path().join("fast.json"), plan.to_string()).unwrap();
    let f = tidepath(&["eval", "fleet-rendezvous", "fast.json"], dir.path());
    let err = String::from_utf8_lossy(&f.stderr);
    assert_eq!(f.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("missions[0].speeds[0]") && err.contains("speed range [0.257, 2.058]"), "{err}");

    let one = "name = \"one\"\n[world]\ndimensions = 2\nbounds = { min = [0.0, 0.0, 0.0], max = [1000.0, 1000.0, 0.0] }\n[vehicle]\nspeed = 1.5\nspeed_max = 2.0\n[mission]\nstart = [100.0, 100.0, 0.0]\ngoal = [900.0, 900.0, 0.0]\n";
    std::fs::write(dir.path().join("one.toml"), one).unwrap();
    let s = tidepath(&["simulate", "one.toml", "--planner", "astar"], dir.path());
    let err = String::from_utf8_lossy(&s.stderr);
    assert_eq!(s.status.code(), Some(2), "{err}");
    assert!(err.starts_with("error: vehicle.speed_min: simulate flies every segment at the cruise speed"), "{err}");
}

/// ijs2023's fleet (section IV-C) planned by IJS with the paper's 45 jellyfish and 500
/// iterations: the three AUVs arrive within 60 s of each other and never come closer than
/// 100 m, and `eval` of the written plan confirms both. Then the paper's other acceptance
/// case: IJS's path through the jet at 0.5 x the AUV's speed, B-spline smoothed, is feasible
/// and plotted.
#[test]
fn ijs_fleet_arrives_together_and_eval_confirms_it() {
    let dir = tempfile::tempdir().unwrap();
    let o = tidepath(&["plan", "ijs-fleet", "--planner", "ijs", "--out", "f.json"], dir.path());
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{stdout}");
    assert!(stdout.contains("together within 60 s: kept") && stdout.contains("separation kept"), "{stdout}");
    let e = tidepath(&["eval", "ijs-fleet", "f.json"], dir.path());
    let eval = String::from_utf8_lossy(&e.stdout);
    assert_eq!(e.status.code(), Some(0), "{eval}");
    assert_eq!(eval.matches("verdict: feasible").count(), 3, "{eval}");
    assert!(eval.contains("together within 60 s: kept") && eval.contains("separation kept"), "{eval}");

    let o =
        tidepath(&["plan", "ijs-current", "--planner", "ijs", "--smooth", "bspline", "--plot", "ijs.svg"], dir.path());
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{stdout}");
    assert!(stdout.contains("feasible") && stdout.contains("smoothed"), "{stdout}");
    let svg = std::fs::read_to_string(dir.path().join("ijs.svg")).unwrap();
    assert!(svg.contains("current at z ="), "the plot draws the current field");
}
