//! Simulations on scenario files: the loop's settings from `[simulate]` and the request, the
//! simulation file, determinism, and a change that closes the way.

use super::*;

/// A 2-D channel 1000 m x 400 m; a disc parked off the route moves onto it at t = 100 s.
const CHANNEL: &str = include_str!("../../tests/data/channel_changes.toml");

fn channel(extra: &str) -> Scenario {
    Scenario::from_toml(&format!("{CHANNEL}{extra}"), "channel.toml").unwrap()
}

/// The file without its wall times, which alone may differ between runs.
fn without_wall_times(text: &str) -> serde_json::Value {
    let mut v: serde_json::Value = serde_json::from_str(text).unwrap();
    v["outcome"]["elapsed_s"] = serde_json::Value::Null;
    for p in v["phases"].as_array_mut().unwrap() {
        if p["replan"].is_object() {
            p["replan"]["planning_s"] = serde_json::Value::Null;
        }
    }
    v
}

#[test]
fn the_file_holds_every_phase_and_the_track() {
    let s = channel("");
    let r = s.simulate(&SimRequest { seed: 1, ..SimRequest::default() }).unwrap();
    assert!(r.sim.reached, "{}", r.sim.reason);
    let v: serde_json::Value = serde_json::from_str(&simulation_json(&s, &r)).unwrap();
    assert_eq!(v["tidepath_simulation"], SIMULATION_FORMAT_VERSION);
    assert_eq!(v["planner"], "theta-star");
    assert_eq!(v["outcome"]["reached"], true);
    let phases = v["phases"].as_array().unwrap();
    assert_eq!(phases.len(), 2);
    assert_eq!(phases[1]["time_s"], 100.0);
    assert_eq!(phases[1]["trigger"]["at_time_s"], 100.0);
    assert_eq!(phases[1]["changes"].as_array().unwrap().len(), 1);
    assert!(phases[1]["changes"][0]["description"].as_str().unwrap().contains("moved to"));
    assert_eq!(phases[0]["changes"], serde_json::json!([]), "the departure has no change");
    assert!(phases[1]["route_problem"].is_string(), "the disc blocks the route");
    assert!(["exact", "feasible"].contains(&phases[1]["replan"]["status"].as_str().unwrap()));
    assert_eq!(phases[1]["known_world"]["obstacles"][0]["center_now"], serde_json::json!([500.0, 200.0, 0.0]));
    let times = v["track"]["times_s"].as_array().unwrap();
    assert_eq!(times.len(), v["track"]["points"].as_array().unwrap().len());
    assert_eq!(v["outcome"]["arrival_s"], times.last().unwrap().clone());
    assert!(v["track"]["lonlat"].is_null(), "a local scenario has no longitude/latitude");
}

#[test]
fn the_request_overrides_the_scenario_loop_settings() {
    let s = channel("[simulate]\nwindow = 3\npolicy = \"always\"\n");
    assert_eq!(s.sim_params(&SimRequest::default()).unwrap().window, 3);
    let p = s
        .sim_params(&SimRequest {
            window: Some(7),
            policy: Some(ReplanPolicy::WhenInfeasible),
            growth: Some(Growth::Add(2)),
            ..SimRequest::default()
        })
        .unwrap();
    assert_eq!((p.window, p.policy, p.growth), (7, ReplanPolicy::WhenInfeasible, Growth::Add(2)));
    for (req, field) in [
        (SimRequest { window: Some(0), ..SimRequest::default() }, "--window"),
        (SimRequest { growth: Some(Growth::Add(0)), ..SimRequest::default() }, "--growth"),
        (SimRequest { sensor_range: Some(-1.0), ..SimRequest::default() }, "--sensor-range"),
        (SimRequest { total_time_limit_s: Some(0.0), ..SimRequest::default() }, "--total-time-limit"),
        (SimRequest { planner: Some("nope".into()), ..SimRequest::default() }, "planner"),
    ] {
        let e = s.check_sim_request(&req).unwrap_err().to_string();
        assert!(e.contains(field), "{field}: {e}");
    }
}

#[test]
fn the_same_seed_writes_the_same_file() {
    // Random moves of the disc, re-planned at every change by a randomised planner.
    let s = channel("random = { law = \"gaussian\", scale = 80.0 }\n[simulate]\npolicy = \"always\"\nwindow = 1\n");
    let req = SimRequest { planner: Some("rrt-star".into()), samples: Some(1500), seed: 5, ..SimRequest::default() };
    let a = without_wall_times(&simulation_json(&s, &s.simulate(&req).unwrap()));
    let b =
        without_wall_times(&simulation_json(&s, &s.simulate(&SimRequest { parallel: true, ..req.clone() }).unwrap()));
    assert_eq!(a, b);
    let c = without_wall_times(&simulation_json(&s, &s.simulate(&SimRequest { seed: 6, ..req }).unwrap()));
    assert_ne!(a["phases"][1]["changes"], c["phases"][1]["changes"], "another seed, another draw");
}

#[test]
fn a_change_that_closes_every_way_names_its_phase_and_the_bottleneck() {
    let wall = "[[changes]]\nafter_distance = 300.0\nkind = \"add-obstacle\"\nadd = { kind = \"box\", min = [590.0, -10.0, -1.0], max = [610.0, 410.0, 1.0] }\n";
    let s = channel(wall);
    let r = s.simulate(&SimRequest { seed: 1, ..SimRequest::default() }).unwrap();
    assert!(!r.sim.reached && r.sim.complete);
    assert!(r.sim.reason.starts_with("phase 2: no feasible window up to the goal"), "{}", r.sim.reason);
    assert!(r.sim.reason.contains("unreachable") || r.sim.reason.contains("cut"), "{}", r.sim.reason);
    let last = r.sim.phases.last().unwrap().replan.as_ref().unwrap();
    assert_eq!(last.status, tidepath::planner::Status::Unreachable, "{}", last.reason);
    // The water the vehicle reaches ends at the wall (x = 590 less the safety distance), on
    // the line to the goal.
    let at = last.focus.as_ref().expect("the cut is marked").at;
    assert!(at.x > 540.0 && at.x < 590.0 && (at.y - 200.0).abs() < 30.0, "{at:?}: {}", last.reason);
    assert!(last.reason.contains("nearest the goal"), "{}", last.reason);
}

#[test]
fn simulate_refuses_a_fleet() {
    let fleet = CHANNEL.replace(
        "[mission]\nstart = [50.0, 200.0, 0.0]\ngoal = [950.0, 200.0, 0.0]",
        "[[missions]]\nname = \"a\"\nstart = [50.0, 200.0, 0.0]\ngoal = [950.0, 200.0, 0.0]\n[[missions]]\nname = \"b\"\nstart = [50.0, 100.0, 0.0]\ngoal = [950.0, 100.0, 0.0]",
    );
    let s = Scenario::from_toml(&fleet, "fleet.toml").unwrap();
    let e = s.check_sim_request(&SimRequest::default()).unwrap_err().to_string();
    assert!(e.contains("one mission"), "{e}");
}
