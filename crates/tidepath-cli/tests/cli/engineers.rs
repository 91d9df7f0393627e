//! An engineer's own data from the command line: exclusion boxes in longitude/latitude hold
//! every point written, routes are read in the frame their file says (and from every export),
//! places are given back in degrees and arrivals in UTC.

use std::path::Path;
use std::process::{Command, Output};

fn tidepath(args: &[&str], cwd: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tidepath")).args(args).current_dir(cwd).output().expect("tidepath runs")
}

fn text(o: &Output) -> (String, String) {
    (String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned())
}

/// A 4 x 2 degree exclusion box; the start lies inside it 1.1 km north of its south edge, on
/// the meridian through its middle, where the edge (a parallel) bows furthest south of the
/// rectangle of its corners.
const EXCLUSION: &str = r#"
name = "exclusion"
[world]
dimensions = 2
frame = "geographic"
bounds = { min = [-127.0, 47.0, -100.0], max = [-121.0, 51.0, 0.0] }
[[world.obstacles]]
kind = "box"
min = [-126.0, 48.0, -100.0]
max = [-122.0, 50.0, 0.0]
[vehicle]
speed = 1.5
[mission]
name = "survey-leg"
start = [-124.0, 48.01, 0.0]
goal = [-124.0, 47.5, 0.0]
"#;

#[test]
fn a_start_inside_a_lon_lat_box_near_its_curved_edge_is_invalid() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("x.toml"), EXCLUSION).unwrap();
    let o = tidepath(&["plan", "x.toml", "--planner", "astar"], dir.path());
    let (out, err) = text(&o);
    assert_eq!(o.status.code(), Some(1), "{out}{err}");
    assert!(
        out.contains("invalid-start: mission.start: (48.0100 N, 124.0000 W, depth 0.0 m) is inside obstacle 0"),
        "{out}"
    );
    // The cover is larger than the box; the note says by how much and what to do.
    assert!(
        err.contains("world.obstacles[0]: the lon/lat box is covered by a frame-aligned box 2.9 % larger"),
        "{err}"
    );
}

#[test]
fn places_are_given_back_in_degrees_and_arrivals_in_utc() {
    let dir = tempfile::tempdir().unwrap();
    let o = tidepath(&["plan", "salish-strait", "--from", "-124.5,48.9,30"], dir.path());
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(
        err.trim_end(),
        "error: --from: mission.start: 48.9000 N, 124.5000 W, depth 30.0 m is outside the domain 48.0947 N to 48.8052 N, 125.2152 W to 122.9848 W, depth 0.0 to 300.0 m"
    );
    let o = tidepath(&["plan", "salish-forecast", "--planner", "theta-star"], dir.path());
    let (out, _) = text(&o);
    let line = out.lines().find(|l| l.contains("travel time")).unwrap();
    // The forecast's scenario departs at 2025-11-12T03:00:00Z.
    assert!(line.contains("arrives at t = ") && line.contains(" (2025-11-12T"), "{line}");
    assert!(line.trim_end().ends_with("Z)"), "{line}");
}

#[test]
fn a_hand_written_route_is_read_in_the_frame_it_names() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // The salish mission's own start and goal, in degrees.
    std::fs::write(d.join("ll.json"), r#"{"frame": "lonlat", "waypoints": [[-124.67, 48.47, 0], [-123.28, 48.4, 0]]}"#)
        .unwrap();
    let (out, err) = text(&tidepath(&["eval", "salish", "ll.json"], d));
    assert!(!out.contains("is not the mission start") && !out.contains("is not the mission goal"), "{out}{err}");
    assert!(out.contains("length 1"), "{out}");
    // No frame said, in a geographic scenario: refused, naming the field.
    std::fs::write(d.join("bare.json"), r#"{"waypoints": [[-124.67, 48.47, 0], [-123.28, 48.4, 0]]}"#).unwrap();
    let o = tidepath(&["eval", "salish", "bare.json"], d);
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(2));
    assert!(err.starts_with("error: bare.json: frame: scenario 'salish' is geographic"), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1);
    // Degrees for a local scenario: refused.
    let o = tidepath(&["eval", "demo", "ll.json"], d);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o).1.contains("is in longitude/latitude, but scenario 'demo' is local"));
}

#[test]
fn every_export_is_read_back_by_eval_and_plan_init() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for ext in ["json", "geojson", "gpx", "kml", "csv"] {
        let out = format!("route.{ext}");
        let o = tidepath(&["plan", "salish-forecast", "--planner", "theta-star", "--out", &out], d);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        let o = tidepath(&["eval", "salish-forecast", &out], d);
        let (stdout, stderr) = text(&o);
        assert_eq!(o.status.code(), Some(0), "{ext}: {stdout}{stderr}");
        assert!(stdout.contains("verdict: feasible"), "{ext}: {stdout}");
        let o = tidepath(&["plan", "salish-forecast", "--planner", "pso", "--iterations", "2", "--init", &out], d);
        assert!(matches!(o.status.code(), Some(0 | 1)), "{ext}: {}", text(&o).1);
    }
    // A malformed export: one line naming the file and the place.
    std::fs::write(d.join("bad.gpx"), r#"<gpx><trk><trkseg><trkpt lat="48.5" lon="west"/></trkseg></trk></gpx>"#)
        .unwrap();
    let o = tidepath(&["eval", "salish", "bad.gpx"], d);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(text(&o).1.trim_end(), "error: bad.gpx: lon 'west' at byte 18 is not a finite number");
}
