//! Geographic scenarios end to end: the built-in `salish-strait` AUV transit is feasible and
//! re-checked on the real seabed; a depth band below the strait's sill is reported unreachable
//! with the sill named in degrees; boxes and positions in degrees are checked.

use crate::common;

use tidepath::planner::Status;
use tidepath_io::scenario::{builtin, load, PlanRequest, Scenario};

#[test]
fn salish_strait_default_plan_is_feasible_and_stays_in_the_water() {
    let s = load("salish-strait").unwrap();
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    for seed in 1..=3 {
        let r = s.plan(&PlanRequest { seed, ..PlanRequest::default() }, &mut |_| {}).unwrap();
        assert!(r.status.is_success(), "seed {seed}: {}", r.reason);
        // Dense re-check at the vehicle's clock: 20 m above the seabed everywhere.
        assert!(common::recheck_plan(&s, &r).unwrap() > 100);
        let m = r.missions[0].metrics.as_ref().unwrap();
        let c = m.min_clearance_m.unwrap();
        assert!(c >= 20.0 - 1e-6, "{c}");
        let geo = r.geographic.as_ref().unwrap();
        let first = geo.paths[0][0];
        assert!((first[0] + 125.0).abs() < 1e-6 && (first[1] - 48.3).abs() < 1e-6 && (first[2] - 40.0).abs() < 1e-6);
    }
}

#[test]
fn a_band_below_the_sill_is_unreachable_and_the_sill_is_named_in_degrees() {
    let text =
        builtin("salish-strait").unwrap().replace("depth_min = 10.0", "depth_min = 60.0").replace("-40.0]", "-65.0]");
    let s = Scenario::from_toml(&text, "builtin:deep").unwrap();
    let r = s.plan(&PlanRequest::default(), &mut |_| {}).unwrap();
    assert_eq!(r.status, Status::Unreachable, "{}", r.reason);
    assert!(r.reason.contains("63.6 m at (48.4030 N, 123.1707 W)"), "{}", r.reason);
}

#[test]
fn geographic_inputs_are_checked() {
    let base = builtin("salish").unwrap();
    let e = |from: &str, to: &str| {
        Scenario::from_toml(&base.replace(from, to), "t.toml").map(|_| ()).unwrap_err().to_string()
    };
    assert!(e("min = [-124.97, 48.03", "min = [-124.97, 49.5").contains("world.bounds"));
    assert!(e("min = [-124.97", "min = [-190.0").contains("world.bounds.west"));
    assert!(e("start = [-124.67, 48.47", "start = [-124.67, 95.0").contains("mission.start: latitude"));
    assert!(e("start = [-124.67, 48.47", "start = [-120.0, 48.47").contains("mission.start"));
    assert!(e("path = \"salish_topobathy.nc\"", "path = \"nowhere.nc\"").contains("nowhere.nc"));
    assert!(e("path = \"salish_topobathy.nc\"", "path = \"x.shp\"").contains("unknown data format"));
    assert!(e("frame = \"geographic\"\n", "").contains("set world.frame = \"geographic\""));
    assert!(e("goal = [-123.28, 48.40, 0.0]", "goal = [-123.28, 48.40, 0.0]\ndeparture = \"noon\"")
        .contains("mission.departure: `noon` is not an ISO 8601"));
}

/// `salish-forecast`: the Copernicus-style file is read end to end. The current at a sea point
/// at whole hours is the script's tide (to the packing step and the frame's small rotation),
/// linear between hours; the plan is feasible and re-checked on the forecast's clock.
#[test]
fn salish_forecast_reads_the_tide_from_netcdf() {
    let s = load("salish-forecast").unwrap();
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    assert_eq!(s.epoch.unwrap().to_rfc3339(), "2025-11-12T03:00:00+00:00");
    let f = s.frame.as_ref().unwrap();
    let (x, y) = f.forward(-124.0, 48.3333, "p").unwrap();
    let tide = |h: f64| {
        let speed = 1.2 * (2.0 * std::f64::consts::PI / 12.42 * h).cos() - 0.1;
        let a = 100f64.to_radians();
        (speed * a.sin(), speed * a.cos())
    };
    for h in [0.0, 6.0, 9.0, 20.0] {
        let c = s.world.current.velocity(tidepath::geom::Vec3::new(x, y, 0.0), (h - 3.0) * 3600.0);
        let (e, n) = tide(h);
        assert!(
            (c.x - e).abs() < 0.01 + 0.01 * e.abs() && (c.y - n).abs() < 0.01 + 0.01 * n.abs(),
            "hour {h}: {c:?} vs ({e}, {n})"
        );
    }
    // Half past: the mean of the two hours (linear in time).
    let c = s.world.current.velocity(tidepath::geom::Vec3::new(x, y, 0.0), 3.5 * 3600.0);
    let (a, b) = (tide(6.0), tide(7.0));
    assert!((c.x - (a.0 + b.0) / 2.0).abs() < 0.01, "{c:?}");
    let r = s.plan(&PlanRequest::default(), &mut |_| {}).unwrap();
    assert!(r.status.is_success(), "{}", r.reason);
    common::recheck_plan(&s, &r).unwrap();
}

/// The forecast's clock is the vehicle's: the same route through the tidal current read from
/// file takes a different time as its departure moves through the tide, and a later departure
/// within one tidal cycle (12.42 h) gives back nearly the same time.
#[test]
fn departure_time_moves_the_travel_time_through_a_forecast_tide() {
    let mut s = load("salish-forecast").unwrap();
    let r = s.plan(&PlanRequest::default(), &mut |_| {}).unwrap();
    let path = r.missions[0].points();
    let mut times = Vec::new();
    for hour in [0.0, 3.0, 6.0, 9.0, 12.42] {
        s.missions[0].departure_time = hour * 3600.0;
        let m = s.evaluate(&path).unwrap();
        assert!(m.feasible, "{:?}", m.violations);
        times.push(m.times.last().unwrap() - m.times[0]);
    }
    let (lo, hi) = times.iter().fold((f64::MAX, 0.0f64), |(a, b), &t| (a.min(t), b.max(t)));
    assert!(hi > 1.05 * lo, "the tide should change the passage time: {times:?}");
    // One M2 period later the tide repeats, up to the forecast's hourly sampling.
    assert!((times[4] - times[0]).abs() < 0.01 * times[0], "{times:?}");
}

/// A forecast that lacks data at a water node (land or fill in its file): a route that needs
/// the current there is refused with a violation naming the place; a goal there is invalid.
#[test]
fn routes_through_current_gaps_are_refused_naming_where() {
    let text = r#"
name = "gap"
[world]
dimensions = 2
bounds = { min = [0.0, 0.0, 0.0], max = [4000.0, 4000.0, 0.0] }
[world.current]
kind = "grid"
origin = [0.0, 0.0]
spacing = [1000.0, 1000.0]
shape = [5, 5]
times = [0.0]
u = [[0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2]]
v = [[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]]
no_data = [12]
[vehicle]
speed = 2.0
[mission]
start = [500.0, 2000.0, 0.0]
goal = [3500.0, 2000.0, 0.0]
[planner]
id = "astar"
"#;
    let s = Scenario::from_toml(text, "gap.toml").unwrap();
    let straight = s.evaluate(&[s.missions[0].start, s.missions[0].goal]).unwrap();
    assert!(!straight.feasible);
    let v = &straight.violations[0];
    assert!(v.message.contains("no data") && v.message.ends_with("first at 1500, 2000"), "{}", v.message);
    // A* goes around the four cells next to the gap and says it is feasible; the re-check agrees.
    let r = s.plan(&PlanRequest::default(), &mut |_| {}).unwrap();
    assert!(r.status.is_success(), "{}", r.reason);
    common::recheck_plan(&s, &r).unwrap();
    let bad =
        Scenario::from_toml(&text.replace("goal = [3500.0, 2000.0, 0.0]", "goal = [2500.0, 2500.0, 0.0]"), "gap.toml")
            .unwrap();
    let r = bad.plan(&PlanRequest::default(), &mut |_| {}).unwrap();
    assert_eq!(r.status, Status::InvalidGoal, "{}", r.reason);
    assert!(r.reason.contains("no current data"), "{}", r.reason);
    let e = Scenario::from_toml(&text.replace("no_data = [12]", "no_data = [25]"), "gap.toml").unwrap_err();
    assert!(e.to_string().contains("world.current.no_data"), "{e}");
}

/// Fleet positions and obstacles given in degrees land where the projection puts them: centres
/// and mission ends exactly, boxes as the rectangle holding their projected corners, radii in
/// metres unchanged, velocities (east, north) turned into the frame with their speed kept.
#[test]
fn fleet_and_obstacles_in_degrees_are_projected() {
    let text = r#"
name = "geo-fleet"
[world]
dimensions = 3
frame = "geographic"
bounds = { min = [-125.0, 48.0, -500.0], max = [-123.0, 49.0, 0.0] }
[[world.obstacles]]
kind = "sphere"
center = [-124.5, 48.2, -100.0]
radius = 800.0
velocity = [0.5, 0.0, 0.0]
[[world.obstacles]]
kind = "box"
min = [-123.6, 48.6, -300.0]
max = [-123.4, 48.7, -50.0]
[[world.obstacles]]
kind = "cylinder"
center = [-123.9, 48.5]
radius = 500.0
[[missions]]
name = "a"
start = [-124.9, 48.1, -50.0]
goal = [-123.1, 48.9, -60.0]
departure = "2026-01-01T00:00:00Z"
[[missions]]
name = "b"
start = [-124.9, 48.9, -70.0]
goal = [-123.1, 48.1, -80.0]
departure = "2026-01-01T00:30:00Z"
"#;
    let s = Scenario::from_toml(text, "geo-fleet.toml").unwrap();
    let f = s.frame.as_ref().unwrap();
    let at = |lon: f64, lat: f64| f.forward(lon, lat, "t").unwrap();
    let close = |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).abs() < 1e-6 && (a.1 - b.1).abs() < 1e-6;
    let ends = [((-124.9, 48.1), (-123.1, 48.9)), ((-124.9, 48.9), (-123.1, 48.1))];
    for (m, (a, b)) in s.missions.iter().zip(ends) {
        assert!(close((m.start.x, m.start.y), at(a.0, a.1)) && close((m.goal.x, m.goal.y), at(b.0, b.1)));
    }
    assert_eq!((s.missions[0].start.z, s.missions[1].goal.z), (-50.0, -80.0));
    // Without an epoch the first ISO departure is the clock's zero; the second leaves 30 min later.
    assert_eq!(s.missions[1].departure_time - s.missions[0].departure_time, 1800.0);
    use tidepath::world::Shape;
    match &s.world.obstacles[0].shape {
        Shape::Sphere { center, radius } => {
            assert!(close((center.x, center.y), at(-124.5, 48.2)) && center.z == -100.0 && *radius == 800.0);
            let v = s.world.obstacles[0].velocity;
            assert!((v.length() - 0.5).abs() < 1e-9 && v.x > 0.49 && v.y.abs() > 1e-4, "{v:?}");
        }
        other => panic!("{other:?}"),
    }
    match &s.world.obstacles[1].shape {
        Shape::Box { min, max } => {
            for (lon, lat) in [(-123.6, 48.6), (-123.6, 48.7), (-123.4, 48.6), (-123.4, 48.7)] {
                let (x, y) = at(lon, lat);
                assert!(x >= min.x - 1e-6 && x <= max.x + 1e-6 && y >= min.y - 1e-6 && y <= max.y + 1e-6);
            }
            assert_eq!((min.z, max.z), (-300.0, -50.0));
        }
        other => panic!("{other:?}"),
    }
    match &s.world.obstacles[2].shape {
        Shape::Cylinder { center, radius, .. } => {
            assert!(close((center.x, center.y), at(-123.9, 48.5)) && *radius == 500.0)
        }
        other => panic!("{other:?}"),
    }
}
