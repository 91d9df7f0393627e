//! ijs2023's built-in scenarios: the paper's area and start/goal pairs over a synthetic seamount
//! field with cylinders, spheres and boxes; the jet at the paper's ratios of the AUV's speed;
//! the three-vehicle fleet.

use tidepath::geom::Vec3;
use tidepath_io::scenario::{load, PlanRequest, Scenario};

const STATIC: [&str; 4] = ["ijs-static-1", "ijs-static-2", "ijs-static-3", "ijs-static-4"];
const CURRENT: [(&str, f64); 3] = [("ijs-current", 0.5), ("ijs-strong-0.8", 0.8), ("ijs-strong-1.2", 1.2)];

fn plan(s: &Scenario, planner: &str, iterations: Option<u64>, seed: u64) -> tidepath_io::PlanReport {
    let req = PlanRequest { planner: Some(planner.into()), iterations, seed, ..PlanRequest::default() };
    s.plan(&req, &mut |_| {}).unwrap()
}

/// Every scenario loads without warnings with the paper's setting: IJS with 45 jellyfish and
/// 500 iterations, 38 interior points on planes across x with eq. 14's window, the ijs2023
/// cost with the same window, eq. 17's travel time; each start and goal clear of the seabed
/// and every threat.
#[test]
fn every_scenario_has_the_papers_setting() {
    let all = STATIC.iter().copied().chain(CURRENT.iter().map(|c| c.0)).chain(["ijs-fleet"]);
    for name in all {
        let s = load(name).unwrap();
        assert!(s.warnings.is_empty(), "{name}: {:?}", s.warnings);
        assert_eq!((s.planner.id.as_str(), s.cost.model.as_str()), ("ijs", "ijs2023"), "{name}");
        assert_eq!((s.planner.population, s.planner.iterations), (Some(45), Some(500)), "{name}");
        assert_eq!((s.encoding.kind.as_str(), s.encoding.waypoints), ("sliced", 38), "{name}");
        assert_eq!((s.encoding.lateral_step, s.encoding.vertical_step), (Some(1665.0), Some(325.0)), "{name}");
        assert_eq!(s.settings.travel, tidepath::path::TravelModel::VectorSum, "{name}");
        assert!((s.vehicle.speed - 1.542).abs() < 1e-12, "{name}");
        for m in &s.missions {
            for p in [m.start, m.goal] {
                let seabed = s.world.terrain.elevation(p.x, p.y);
                assert!(p.z > seabed + s.vehicle.safety_distance + 100.0, "{name}: {p:?} over {seabed}");
                for o in &s.world.obstacles {
                    assert!(o.shape.distance_to_point(p) > 1500.0, "{name}: {p:?} near {o:?}");
                }
            }
        }
    }
}

/// The jet moves at the stated ratio of the AUV's 1.542 m/s wherever it flows.
#[test]
fn the_jet_runs_at_the_papers_ratios() {
    for (name, ratio) in CURRENT.into_iter().chain([("ijs-fleet", 0.2)]) {
        let s = load(name).unwrap();
        let c = s.world.bounds.center();
        let v = s.world.current.velocity(Vec3::new(c.x + 3000.0, c.y - 2000.0, -500.0), 0.0).truncate().length();
        assert!((v - ratio * 1.542).abs() < 1e-9, "{name}: {v}");
    }
    assert_eq!(load("ijs-static-1").unwrap().world.current.velocity(Vec3::ZERO, 0.0), Vec3::ZERO);
}

/// Planning matters: each static pair's straight line runs into the seabed's safety envelope
/// or a threat, and Theta* finds a route in the water.
#[test]
fn static_pairs_are_blocked_and_connected() {
    for name in STATIC {
        let s = load(name).unwrap();
        let m = &s.missions[0];
        let blocked = (0..=2000).any(|i| {
            let p = m.start + (m.goal - m.start) * (i as f64 / 2000.0);
            p.z < s.world.terrain.elevation(p.x, p.y) + s.vehicle.safety_distance
                || s.world.obstacles.iter().any(|o| o.shape.distance_to_point(p) < s.vehicle.safety_distance)
        });
        assert!(blocked, "{name}: the straight line is clear");
        let r = plan(&s, "theta-star", None, 1);
        assert!(r.missions[0].feasible, "{name}: {}", r.reason);
    }
}
