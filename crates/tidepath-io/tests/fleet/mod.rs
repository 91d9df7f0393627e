//! Fleets keeping their separation: the exact check of the plans against the independent
//! sampler of `common/`, on `fleet-crossing`.

use tidepath::geom::Vec3;
use tidepath::path::ViolationKind;
use tidepath_io::scenario::{PlanRequest, Scenario};

use crate::common::{recheck_plan, recheck_separation};

fn crossing() -> Scenario {
    tidepath_io::scenario::load("fleet-crossing").unwrap()
}

#[test]
fn the_straight_line_plan_is_infeasible_naming_both_vehicles_and_the_time() {
    let s = crossing();
    let straight: Vec<Vec<Vec3>> = s.missions.iter().map(|m| vec![m.start, m.goal]).collect();
    let judged = s.evaluate_paths(&straight).unwrap();
    for m in &judged {
        assert!(!m.feasible, "{}", m.name);
        let v = m.violations.iter().find(|v| v.kind == ViolationKind::Separation).unwrap();
        // Both at (2000, 2000) at t = 1000 s: 1500 m at 1.5 m/s.
        assert!(v.message.contains("auv-east and auv-north come within 0.0 m"), "{}", v.message);
        assert!(v.message.contains("t = 1000.0 s"), "{}", v.message);
    }
    let check = s.fleet_check(&judged).unwrap();
    assert_eq!(check.conflicts.len(), 1);
    assert!((check.closest.unwrap().2.time - 1000.0).abs() < 1e-6);
}

#[test]
fn jointly_planned_vehicles_keep_their_separation_on_the_independent_clock() {
    let s = crossing();
    let r =
        s.plan(&PlanRequest { planner: Some("de".into()), seed: 1, ..PlanRequest::default() }, &mut |_| {}).unwrap();
    assert!(r.status.is_success(), "{}", r.reason);
    let fleet = r.fleet.as_ref().unwrap();
    assert!(fleet.conflicts.is_empty() && fleet.closest.as_ref().unwrap().distance_m >= 150.0, "{fleet:?}");
    // One pair, every 0.25 s over about 2000 s.
    assert!(recheck_separation(&s, &r).unwrap() > 7000);
    recheck_plan(&s, &r).unwrap();
}

#[test]
fn the_independent_sampler_sees_the_conflict_the_exact_check_reports() {
    // A* plans the two vehicles one after another, each alone: they meet at the crossing.
    let s = crossing();
    let r = s.plan(&PlanRequest { planner: Some("astar".into()), ..PlanRequest::default() }, &mut |_| {}).unwrap();
    let fleet = r.fleet.as_ref().unwrap();
    assert_eq!(fleet.conflicts.len(), 1, "{fleet:?}");
    assert!(!r.status.is_success());
    let e = recheck_separation(&s, &r).unwrap_err();
    assert!(e.contains("auv-east and auv-north"), "{e}");
    // The plan's cost is the missions' plus the fleet's terms: 10, and 10 more for meeting
    // at the very point (the whole separation short).
    assert_eq!(fleet.cost_terms["separation"], 20.0);
    assert_eq!(fleet.cost_terms["arrival"], 0.0);
    let missions: f64 = r.missions.iter().map(|m| m.cost.unwrap()).sum();
    assert!((r.cost.unwrap() - missions - 20.0).abs() < 1e-9, "{:?} vs {missions}", r.cost);
}

#[test]
fn every_planner_planning_one_after_another_keeps_the_separation() {
    use tidepath::planner::{FleetMode, Unit, PLANNERS};
    let s = crossing();
    let mut feasible = Vec::new();
    for e in PLANNERS {
        let caps = e.build.caps;
        let req = PlanRequest {
            planner: Some(e.id.into()),
            seed: 2,
            fleet: FleetMode::Sequential,
            iterations: caps.counts_unit(Unit::Iterations).then_some(60),
            samples: caps.counts_unit(Unit::Samples).then_some(1500),
            ..PlanRequest::default()
        };
        if let Err(err) = s.check_request(&req) {
            // A planner that cannot take moving obstacles is refused before planning, in one
            // line naming --fleet.
            let err = err.to_string();
            assert!(err.starts_with("--fleet: ") && !err.contains('\n'), "{}: {err}", e.id);
            continue;
        }
        let r = s.plan(&req, &mut |_| {}).unwrap();
        if r.status.is_success() {
            recheck_plan(&s, &r).unwrap_or_else(|x| panic!("{}: {x}", e.id));
            assert!(recheck_separation(&s, &r).unwrap() > 0);
            feasible.push(e.id);
        }
    }
    for id in ["astar", "theta-star", "hybrid", "rrt-star", "hybrid-astar"] {
        assert!(feasible.contains(&id), "{id} not feasible: {feasible:?}");
    }
}

#[test]
fn jointly_planned_vehicles_arrive_together_when_asked() {
    let s = Scenario::from_toml(include_str!("../data/fleet_together.toml"), "fleet_together.toml").unwrap();
    let r = s.plan(&PlanRequest { seed: 1, ..PlanRequest::default() }, &mut |_| {}).unwrap();
    assert!(r.status.is_success(), "{}", r.reason);
    let a = r.fleet.as_ref().unwrap().arrival.as_ref().unwrap();
    assert!(a.kept && a.spread_s <= 60.0, "{a:?}");
    recheck_plan(&s, &r).unwrap();
    crate::common::recheck_arrivals(&s, &r).unwrap();
    // Planned one after another without regard to the others' arrivals, they break the rule,
    // and every vehicle says so.
    let alone = s.plan(&PlanRequest { planner: Some("astar".into()), ..PlanRequest::default() }, &mut |_| {}).unwrap();
    assert!(!alone.status.is_success());
    for m in &alone.missions {
        assert!(
            m.violations.iter().any(|v| v.kind == ViolationKind::Arrival && v.message.contains("together within 60 s")),
            "{m:?}"
        );
    }
    assert!(crate::common::recheck_arrivals(&s, &alone).is_err());
}

/// `fleet-rendezvous` planned jointly by DE: three AUVs arrive within 60 s of each other with
/// every segment's speed inside 0.5-4 kn, the nearer ones slower; the independent re-checker
/// flies the same speeds; the plan file read back and evaluated gives the same verdict, and
/// at the cruise speed (the same routes without their speeds) the rule breaks.
#[test]
fn the_rendezvous_arrives_together_by_choosing_speeds() {
    let s = tidepath_io::scenario::load("fleet-rendezvous").unwrap();
    let r =
        s.plan(&PlanRequest { planner: Some("de".into()), seed: 1, ..PlanRequest::default() }, &mut |_| {}).unwrap();
    assert!(r.status.is_success(), "{}", r.reason);
    let a = r.fleet.as_ref().unwrap().arrival.as_ref().unwrap();
    assert!(a.kept && a.spread_s <= 60.0, "{a:?}");
    let (lo, hi) = s.vehicle.speed_range.unwrap();
    let mut mean = Vec::new();
    for m in &r.missions {
        let v = m.speeds.as_ref().expect("a vehicle with a speed range gets speeds");
        assert_eq!(v.len() + 1, m.points().len());
        assert!(v.iter().all(|x| (lo..=hi).contains(x)), "{v:?}");
        mean.push(m.metrics.unwrap().length_m / m.metrics.unwrap().travel_time_s);
    }
    // auv-south has 7.3 km to go, auv-west 14.3 km: the nearer one is slower over ground.
    assert!(mean[2] < mean[0], "{mean:?}");
    recheck_plan(&s, &r).unwrap();
    crate::common::recheck_arrivals(&s, &r).unwrap();

    // Read back from the plan file: the same times and verdict.
    let file = tidepath_io::plan_json::PlanFile::parse(&r.to_json(), "r.json").unwrap();
    let judged = s.evaluate_routes(&file.mission_paths(), &file.speeds).unwrap();
    for (j, m) in judged.iter().zip(&r.missions) {
        assert!(j.feasible, "{}: {:?}", j.name, j.violations);
        let (t_file, t_plan) = (*j.times.last().unwrap(), *m.times.last().unwrap());
        assert!((t_file - t_plan).abs() < 1e-6 * t_plan, "{t_file} vs {t_plan}");
    }
    // Without the speeds every vehicle flies at its cruise speed: no longer together.
    let cruise = s.evaluate_paths(&file.mission_paths()).unwrap();
    assert!(cruise.iter().all(|m| m.violations.iter().any(|v| v.kind == ViolationKind::Arrival)));
    // A speed outside the range is bad input naming the segment.
    let mut fast = file.speeds.clone();
    fast[1].as_mut().unwrap()[2] = 3.0;
    let e = s.evaluate_routes(&file.mission_paths(), &fast).unwrap_err().to_string();
    assert!(e.contains("missions[1].speeds[2]") && e.contains("3 m/s is outside"), "{e}");
}

/// A graph search picks each edge's speed: with length and time to minimise and nothing to
/// slow for, every edge is flown at the top of the range.
#[test]
fn a_graph_search_flies_each_edge_at_the_cheapest_speed() {
    let text = include_str!("../data/fleet_together.toml")
        .replace("speed = 1.5", "speed = 1.5\nspeed_min = 0.5\nspeed_max = 2.5")
        .replace("arrival = \"together\"\narrival_tolerance_s = 60.0", "arrival = \"free\"");
    let s = Scenario::from_toml(&text, "fleet_free.toml").unwrap();
    let r = s.plan(&PlanRequest { planner: Some("astar".into()), ..PlanRequest::default() }, &mut |_| {}).unwrap();
    for m in &r.missions {
        let v = m.speeds.as_ref().unwrap();
        assert!(v.iter().all(|&x| x == 2.5), "{}: {v:?}", m.name);
        let x = m.metrics.unwrap();
        assert!((x.travel_time_s - x.length_m / 2.5).abs() < 1e-6, "{x:?}");
    }
    recheck_plan(&s, &r).unwrap();
}
