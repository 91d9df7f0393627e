//! amfa2015's two path experiments mirrored on the Salish slope (`amfa-salish-1`, same depth;
//! `amfa-salish-2`, 230 m -> 450 m): the setting the paper gives, a straight line that hits
//! the seabed, a route in the water, and AMFA plans whose GeoJSON lies in the box.

use tidepath::geom::Vec3;
use tidepath_io::export::{export, ExportFormat, Georef};
use tidepath_io::scenario::{load, PlanRequest, Scenario};

const BOX: ([f64; 3], [f64; 3]) = ([-125.98, 48.02, -1500.0], [-125.55, 48.45, 0.0]);

fn plan(s: &Scenario, planner: &str, iterations: Option<u64>, seed: u64) -> tidepath_io::PlanReport {
    let req = PlanRequest { planner: Some(planner.into()), iterations, seed, ..PlanRequest::default() };
    s.plan(&req, &mut |_| {}).unwrap()
}

/// Both load without warnings with the paper's setting: the amfa2015 cost, AMFA with 40
/// fireflies, 30 free route points; start and goal at the paper's depths, clear of the seabed;
/// the straight line between them passes under the seabed's safety envelope.
#[test]
fn both_experiments_load_with_the_papers_setting() {
    for (name, depths) in [("amfa-salish-1", (300.0, 300.0)), ("amfa-salish-2", (230.0, 450.0))] {
        let s = load(name).unwrap();
        assert!(s.warnings.is_empty(), "{name}: {:?}", s.warnings);
        assert_eq!((s.planner.id.as_str(), s.cost.model.as_str()), ("amfa", "amfa2015"), "{name}");
        assert_eq!((s.encoding.kind.as_str(), s.encoding.waypoints), ("free", 30), "{name}");
        let amfa = s.planner.params.get("amfa").expect("[planner.params.amfa]");
        assert_eq!(amfa.get("population").and_then(|v| v.as_integer()), Some(40), "{name}");
        assert_eq!((-s.start.z, -s.goal.z), depths, "{name}");
        let seabed = |p: Vec3| s.world.terrain.elevation(p.x, p.y);
        let safety = s.vehicle.safety_distance;
        for p in [s.start, s.goal] {
            assert!(p.z > seabed(p) + safety, "{name}: {p:?} is not clear of the seabed");
        }
        let blocked = (0..=1000).any(|i| {
            let p = s.start + (s.goal - s.start) * (i as f64 / 1000.0);
            p.z < seabed(p) + safety
        });
        assert!(blocked, "{name}: the straight line must hit the seabed");
    }
}

/// A route in the water exists: Theta* finds a feasible one on both, Hybrid on
/// `amfa-salish-2`. (On `amfa-salish-1` Hybrid's refinement, minimising the amfa2015 cost,
/// cuts into the sphere between two evaluation points: the cost samples points, and
/// tidepath's exact check says infeasible.)
#[test]
fn a_route_in_the_water_exists() {
    for name in ["amfa-salish-1", "amfa-salish-2"] {
        let s = load(name).unwrap();
        let r = plan(&s, "theta-star", None, 1);
        assert!(r.missions[0].feasible, "{name}: {}", r.reason);
        // Longer than the straight line: the route goes round the spur and the mooring.
        assert!(r.length_m().unwrap() > 1.1 * s.start.distance(s.goal), "{name}");
    }
    let s = load("amfa-salish-2").unwrap();
    let r = plan(&s, "hybrid", None, 1);
    assert!(r.missions[0].feasible, "{}", r.reason);
}

/// AMFA with 3 iterations (about 2400 evaluations): of five seeds on `amfa-salish-1`, at
/// least one plan is feasible; each has 30 route points and its GeoJSON coordinates are
/// longitude, latitude (and depth) inside the Salish box.
#[test]
fn a_short_amfa_run_is_feasible_and_its_geojson_lies_in_the_box() {
    let s = load("amfa-salish-1").unwrap();
    let mut feasible = 0;
    for seed in 1..=5 {
        let r = plan(&s, "amfa", Some(3), seed);
        let m = &r.missions[0];
        assert_eq!(m.waypoints.len(), 32, "seed {seed}: start, 30 route points, goal");
        feasible += usize::from(m.feasible);
        let text = export(&r, ExportFormat::GeoJson, Georef { frame: s.frame.as_ref(), epoch: s.epoch }).unwrap();
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        let coords = v["features"][0]["geometry"]["coordinates"].as_array().expect("a LineString");
        assert_eq!(coords.len(), 32);
        for c in coords {
            let c: Vec<f64> = c.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
            let (lon, lat) = (c[0], c[1]);
            // The metric domain is the smallest east-north box holding the projected lon/lat
            // rectangle, so near its corners it reaches past the rectangle's edges (meridians
            // converge; about 100 m here): inside the domain in metres, and inside the
            // rectangle to 0.005 degrees.
            let slack = 5e-3;
            assert!(lon >= BOX.0[0] - slack && lon <= BOX.1[0] + slack, "seed {seed}: longitude {lon}");
            assert!(lat >= BOX.0[1] - slack && lat <= BOX.1[1] + slack, "seed {seed}: latitude {lat}");
            let (x, y) = s.frame.as_ref().unwrap().forward(lon, lat, "t").unwrap();
            let (lo, hi) = (s.world.bounds.min, s.world.bounds.max);
            let m = 0.01;
            assert!(x >= lo.x - m && x <= hi.x + m && y >= lo.y - m && y <= hi.y + m, "seed {seed}: {lon}, {lat}");
            if let Some(z) = c.get(2) {
                assert!(z.abs() <= 1500.0 + slack, "seed {seed}: depth {z}");
            }
        }
    }
    assert!(feasible >= 1, "no feasible plan of five");
}
