//! Vehicles with a turning radius, end to end (issue "kinematics"): every planner's plans with
//! the `dubins` smoother pass the independent flown-curve re-checker (curvature of the sampled
//! curve at most 1 / radius, clearance at the vehicle's own clock), Hybrid-A* and Theta* with
//! Dubins smoothing are feasible on `salish-strait-turns`, and without a radius nothing changes.

use crate::common;

use tidepath::planner::PLANNERS;
use tidepath_io::scenario::{builtin, PlanRequest, Scenario};

/// Built-in `name` with `turn_radius` added to its vehicle and the waypoint angle limit lifted.
fn with_radius(name: &str, radius: f64) -> Scenario {
    let text = builtin(name).unwrap();
    let line = text.lines().find(|l| l.starts_with("max_turn_deg")).expect("a max_turn_deg line");
    let text = text.replacen(line, &format!("max_turn_deg = 180.0\nturn_radius = {radius}"), 1);
    Scenario::from_toml(&text, &format!("{name}-r{radius}.toml")).unwrap()
}

/// A short run where the planner counts iterations; searches run whole.
fn request(planner: &str, smoother: Option<&str>, seed: u64) -> PlanRequest {
    let registry = tidepath::planner::registry();
    let entry = registry.find(planner);
    let counts_iterations = entry.is_some_and(|p| p.build.caps.counts_unit(tidepath::planner::Unit::Iterations));
    // An evaluation cap that one-population-per-iteration optimizers do not reach (at most
    // 50 x 41): the wolf packs repeat scouting and raiding within an iteration.
    let optimizer = entry.is_some_and(|p| p.build.is_optimizer());
    PlanRequest {
        planner: Some(planner.into()),
        smoother: smoother.map(str::to_string),
        seed,
        iterations: counts_iterations.then_some(40),
        evaluations: optimizer.then_some(60 * 41),
        parallel: true,
        ..PlanRequest::default()
    }
}

/// Every planner of the table, with a radius and the `dubins` smoother, on three worlds (3-D
/// with vortices and a moving sphere, a real 2-D grid with a tide, a 2-D bay to turn back
/// into): the same plan on 1 and 4 threads, each mission's status agreeing with its
/// feasibility, and every feasible plan passing the independent re-checker. Planners that do
/// not plan a world say why; at least one plan per world must be feasible and re-checked.
#[test]
fn every_planner_with_a_radius_and_dubins_smoothing_passes_the_rechecker() {
    let pools = common::one_and_four_threads();
    for (name, radius) in [("demo", 150.0), ("salish", 200.0), ("headland", 60.0)] {
        let s = with_radius(name, radius);
        let mut feasible = Vec::new();
        for entry in PLANNERS {
            let req = request(entry.id, Some("dubins"), 11);
            let runs = common::in_each_pool(&pools, || s.plan(&req, &mut |_| {}));
            let runs = match runs.into_iter().collect::<Result<Vec<_>, _>>() {
                Ok(r) => r,
                Err(e) => {
                    let e = e.to_string();
                    assert!(e.contains("needs") || e.contains("only"), "{} on {name}: {e}", entry.id);
                    continue;
                }
            };
            let strip = |r: &tidepath_io::PlanReport| {
                let mut r = r.clone();
                r.elapsed_s = 0.0;
                r
            };
            assert_eq!(strip(&runs[0]), strip(&runs[1]), "{}: 1 and 4 threads differ on {name}", entry.id);
            let r = &runs[0];
            for m in &r.missions {
                assert_eq!(m.status.is_success(), m.feasible, "{} on {name}: {} vs {}", entry.id, m.status, m.reason);
            }
            common::recheck_plan(&s, r).unwrap_or_else(|e| panic!("{} on {name}: {e}", entry.id));
            if r.status.is_success() {
                feasible.push(entry.id);
            }
        }
        assert!(feasible.contains(&"hybrid-astar"), "hybrid-astar not feasible on {name} with a {radius} m radius");
        assert!(feasible.len() >= 4, "only {feasible:?} feasible on {name} with a {radius} m radius");
        eprintln!("{name} with a {radius} m radius, dubins-smoothed: feasible {feasible:?}");
    }
}

/// The acceptance runs: Hybrid-A* and Theta* smoothed by `dubins` on `salish-strait-turns`
/// are feasible, and the independent re-checker (which measures the curvature of the densely
/// sampled flown curve itself) agrees.
#[test]
fn salish_strait_turns_is_flown_by_hybrid_astar_and_by_dubins_smoothed_theta_star() {
    let s = tidepath_io::scenario::load("salish-strait-turns").unwrap();
    let r0 = s.missions[0].vehicle.turn_radius.unwrap();
    for (planner, smoother) in [("hybrid-astar", None), ("theta-star", Some("dubins"))] {
        let r = s.plan(&request(planner, smoother, 1), &mut |_| {}).unwrap();
        assert!(r.status.is_success(), "{planner}: {} {}", r.status, r.reason);
        let m = &r.missions[0];
        let c =
            common::flown::recheck_flown(&s.world, &s.missions[0].vehicle, &s.settings, &m.points(), &m.times, &[], r0)
                .unwrap_or_else(|e| panic!("{planner}: {e}"));
        assert!(c.samples > 10_000, "{planner}: only {} samples", c.samples);
        // The sampled curve's own curvature: at most 1 / radius, with no slack.
        assert!(c.min_circumradius >= r0 * (1.0 - 1e-6), "{planner}: {c:?}");
    }
}

/// A polyline whose corner is too sharp for the radius is reported, naming the waypoint; the
/// same scenario without a radius judges the same polyline feasible, as before.
#[test]
fn a_corner_too_sharp_for_the_radius_is_named_and_fine_without_one() {
    let plain = tidepath_io::scenario::load("headland").unwrap();
    let turns = with_radius("headland", 2000.0);
    let (a, b) = (plain.missions[0].start, plain.missions[0].goal);
    // Out to a point north of the start, then to the goal: a 95 degree corner whose fillet at
    // r = 2 km needs 2.2 km of each leg; the first has 1.5 km.
    let corner = tidepath::geom::Vec3::new(a.x + 300.0, a.y + 1500.0, a.z);
    let path = vec![a, corner, b];
    let without = plain.evaluate_paths(std::slice::from_ref(&path)).unwrap();
    let with = turns.evaluate_paths(std::slice::from_ref(&path)).unwrap();
    // Without a radius this path is only judged by the waypoint angle (120 degrees there).
    let turn_violations = |m: &tidepath::planner::MissionPlan| {
        m.violations.iter().filter(|v| v.kind == tidepath::path::ViolationKind::Turn).count()
    };
    assert_eq!(turn_violations(&without[0]), 0, "{:?}", without[0].violations);
    let v: Vec<_> = with[0].violations.iter().filter(|v| v.kind == tidepath::path::ViolationKind::Turn).collect();
    assert_eq!(v.len(), 1, "{:?}", with[0].violations);
    assert_eq!(v[0].index, 1);
    assert!(
        v[0].message.starts_with("waypoint 1: the ") && v[0].message.contains("2000 m turning radius"),
        "{}",
        v[0].message
    );
    assert!(with[0].flown.is_some() && without[0].flown.is_none());
}
