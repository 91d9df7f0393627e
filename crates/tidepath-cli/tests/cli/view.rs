//! `tidepath view` and the `--view` output of `plan`, `simulate` and `compare`: one offline
//! HTML file whose scene holds what the run found (the browser side is checked by
//! scripts/test_viewer.sh in headless Chromium).

use std::path::Path;
use std::process::{Command, Output};

fn tidepath(args: &[&str], cwd: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tidepath")).args(args).current_dir(cwd).output().expect("tidepath runs")
}

/// The scene embedded in a view.
fn scene(path: &Path) -> serde_json::Value {
    let html = std::fs::read_to_string(path).unwrap();
    let open = r#"<script id="tp-scene" type="application/json">"#;
    let start = html.find(open).expect("a scene element") + open.len();
    let end = start + html[start..].find("</script>").unwrap();
    serde_json::from_str(&html[start..end]).expect("the scene is JSON")
}

fn floats(v: &serde_json::Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect()
}

#[test]
fn a_plan_file_is_shown_on_its_scenario_s_clock() {
    let dir = tempfile::tempdir().unwrap();
    let o = tidepath(&["plan", "demo", "--planner", "pso", "--iterations", "40", "--out", "p.json"], dir.path());
    assert!(matches!(o.status.code(), Some(0 | 1)), "{}", String::from_utf8_lossy(&o.stderr));
    let v = tidepath(&["view", "demo", "p.json", "-o", "v.html"], dir.path());
    assert_eq!(v.status.code(), Some(0), "{}", String::from_utf8_lossy(&v.stderr));
    let html = std::fs::read_to_string(dir.path().join("v.html")).unwrap();
    assert!(!html.contains("<script src") && !html.contains("<link"), "the page links a file");
    assert!(html.len() < 5_000_000, "demo view is {} bytes", html.len());
    let s = scene(&dir.path().join("v.html"));
    let plan: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("p.json")).unwrap()).unwrap();
    let r = &s["routes"][0];
    assert_eq!(r["label"], "pso (p)");
    // The drawn points are the plan's waypoints (to a tenth of a metre), with the plan's times.
    let wp = plan["missions"][0]["waypoints"].as_array().unwrap();
    let x = floats(&r["x"]);
    assert_eq!(x.len(), wp.len());
    for (k, p) in wp.iter().enumerate() {
        assert!((x[k] - p[0].as_f64().unwrap()).abs() <= 0.05 + 1e-9);
    }
    let t = floats(&r["t"]);
    let want_t = floats(&plan["missions"][0]["times"]);
    for (a, b) in t.iter().zip(&want_t) {
        assert!((a - b).abs() <= 0.005 + 1e-9, "{a} vs {b}");
    }
    assert!(t.windows(2).all(|w| w[0] <= w[1]));
    assert_eq!(r["hover"].as_array().unwrap().len(), x.len());
    let first = r["hover"][0].as_str().unwrap();
    assert!(first.contains("depth") && first.contains("above the seabed") && first.contains("segment 1 of"), "{first}");
    assert!(first.contains("segment terms: length"), "{first}");
    // The slider runs to the arrival; the demo's moving sphere is there to move.
    assert_eq!(s["time"]["end"].as_f64().unwrap(), *plan["missions"][0]["times"].as_array().unwrap().last().unwrap());
    assert!(s["obstacles"].as_array().unwrap().iter().any(|o| o["moving"] == true));
    assert!(s["seabed"]["z"].as_array().unwrap().len() > 10);
    assert!(!s["currents"]["frames"].as_array().unwrap().is_empty());
}

#[test]
fn a_bad_view_target_or_plan_writes_nothing_and_names_the_field() {
    let dir = tempfile::tempdir().unwrap();
    let o = tidepath(&["view", "demo", "-o", "v.svg"], dir.path());
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("--out") && err.contains(".html"), "{err}");
    assert!(!dir.path().join("v.svg").exists());
    // A plan that cannot be read leaves an existing view as it was.
    std::fs::write(dir.path().join("v.html"), "keep me").unwrap();
    let o = tidepath(&["view", "demo", "missing.json", "-o", "v.html"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("missing.json"));
    assert_eq!(std::fs::read_to_string(dir.path().join("v.html")).unwrap(), "keep me");
    let o = tidepath(&["view", "no-such-scenario", "-o", "w.html"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(!dir.path().join("w.html").exists());
    // --view on plan is checked before any planning.
    let o = tidepath(&["plan", "demo", "--planner", "pso", "--view", "v.png"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--view"));
}

#[test]
fn a_fleet_plan_gives_each_vehicle_its_colour_and_clock() {
    let dir = tempfile::tempdir().unwrap();
    let o = tidepath(
        &["plan", "fleet-crossing", "--planner", "astar", "--fleet", "sequential", "--view", "f.html"],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let s = scene(&dir.path().join("f.html"));
    let routes = s["routes"].as_array().unwrap();
    assert_eq!(routes.len(), 2);
    assert_ne!(routes[0]["group"], routes[1]["group"]);
    assert_eq!(s["dims"], 2);
    assert_eq!(s["markers"]["starts"].as_array().unwrap().len(), 2);
    let end = s["time"]["end"].as_f64().unwrap();
    let last = |r: &serde_json::Value| *floats(&r["t"]).last().unwrap();
    // Route times are written to the hundredth of a second.
    assert!((end - last(&routes[0]).max(last(&routes[1]))).abs() <= 0.005, "{end}");
}

#[test]
fn a_simulation_plays_back_its_phases_and_epochs() {
    let dir = tempfile::tempdir().unwrap();
    let o = tidepath(&["simulate", "coastal-traffic", "--view", "s.html", "--out", "s.json"], dir.path());
    assert!(matches!(o.status.code(), Some(0 | 1)), "{}", String::from_utf8_lossy(&o.stderr));
    let s = scene(&dir.path().join("s.html"));
    let sim: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("s.json")).unwrap()).unwrap();
    assert_eq!(s["phases"].as_array().unwrap().len(), sim["phases"].as_array().unwrap().len());
    let track_t = floats(&sim["track"]["times_s"]);
    assert_eq!(floats(&s["routes"][0]["t"]).len(), track_t.len());
    assert!((s["time"]["end"].as_f64().unwrap() - track_t.last().unwrap()).abs() < 1e-9);
    // The ships cross the lane: moving obstacles with their velocities.
    let ships: Vec<&serde_json::Value> =
        s["obstacles"].as_array().unwrap().iter().filter(|o| o["moving"] == true).collect();
    assert!(!ships.is_empty());
    assert!(ships.iter().all(|o| floats(&o["velocity"]).iter().any(|v| *v != 0.0)));
}

#[test]
fn compare_shows_each_planner_s_best_run() {
    let dir = tempfile::tempdir().unwrap();
    let o = tidepath(
        &[
            "compare",
            "demo",
            "--planners",
            "pso,de",
            "--runs",
            "2",
            "--iterations",
            "10",
            "--reference",
            "none",
            "--view",
            "c.html",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let s = scene(&dir.path().join("c.html"));
    let labels: Vec<&str> = s["routes"].as_array().unwrap().iter().map(|r| r["label"].as_str().unwrap()).collect();
    assert_eq!(labels.len(), 2, "{labels:?}");
    assert!(labels[0].starts_with("pso (best of 2 runs") && labels[1].starts_with("de (best of 2 runs"), "{labels:?}");
}

#[test]
fn a_geographic_scenario_has_longitude_and_latitude_axes() {
    let dir = tempfile::tempdir().unwrap();
    let o = tidepath(&["view", "salish-strait", "-o", "g.html"], dir.path());
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let s = scene(&dir.path().join("g.html"));
    let lon: Vec<&str> = s["geo_ticks"]["x"]["text"].as_array().unwrap().iter().map(|v| v.as_str().unwrap()).collect();
    assert!(lon.len() >= 3 && lon.iter().all(|t| t.ends_with("°W")), "{lon:?}");
    assert!(s["seabed"]["lonlat"][0][0][1].as_f64().unwrap() > 48.0);
    // Nothing timed and nothing moving: one instant.
    assert_eq!(s["time"]["start"], s["time"]["end"]);
}

#[test]
fn a_long_route_keeps_full_hover_text_on_every_kth_point() {
    let dir = tempfile::tempdir().unwrap();
    let o = tidepath(&["plan", "demo", "--planner", "pso", "--iterations", "20", "--out", "p.json"], dir.path());
    assert!(matches!(o.status.code(), Some(0 | 1)));
    let plan: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("p.json")).unwrap()).unwrap();
    // The plan's path cut into 6,000 points along the same segments.
    let wp: Vec<[f64; 3]> = serde_json::from_value(plan["missions"][0]["waypoints"].clone()).unwrap();
    let per = 6000 / (wp.len() - 1);
    let mut dense = Vec::new();
    for w in wp.windows(2) {
        for k in 0..per {
            let s = k as f64 / per as f64;
            dense.push([0, 1, 2].map(|i| w[0][i] + s * (w[1][i] - w[0][i])));
        }
    }
    dense.push(*wp.last().unwrap());
    std::fs::write(dir.path().join("dense.json"), serde_json::json!({ "waypoints": dense }).to_string()).unwrap();
    let v = tidepath(&["view", "demo", "dense.json", "-o", "v.html"], dir.path());
    assert_eq!(v.status.code(), Some(0), "{}", String::from_utf8_lossy(&v.stderr));
    let s = scene(&dir.path().join("v.html"));
    let hover: Vec<&str> = s["routes"][0]["hover"].as_array().unwrap().iter().map(|h| h.as_str().unwrap()).collect();
    assert_eq!(hover.len(), dense.len());
    let full = hover.iter().filter(|h| h.contains("segment")).count();
    // Every third point of 6,000-odd (the stride that keeps 2,000), and the last.
    assert!((2000..=2100).contains(&full), "{full} full hover texts");
    assert!(hover[0].contains("segment") && !hover[1].contains("segment") && hover[1].contains("t = "));
    assert!(hover.last().unwrap().contains("segment"));
}
