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
