//! Hand-computed checks of the evaluation on the flown curve (vehicles with a turning radius).

use super::*;
use crate::geom::{Aabb, Vec2, Vec3};
use crate::mission::Mission;
use crate::world::terrain::GaussianPeaks;
use crate::world::{Current, Obstacle, Shape, Terrain};
use std::f64::consts::PI;

fn world() -> World {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(200.0, 200.0, 0.0)));
    w.terrain = Terrain::Peaks(GaussianPeaks { base: -90.0, peaks: vec![], ceiling: None });
    w
}

fn vehicle(radius: Option<f64>) -> Vehicle {
    Vehicle {
        propulsion: Default::default(),
        speed: 2.0,
        max_turn: PI,
        max_pitch: 30f64.to_radians(),
        depth_min: 0.0,
        depth_max: 100.0,
        safety_distance: 1.0,
        turn_radius: radius,
        speed_range: None,
    }
}

fn judge(w: &World, radius: Option<f64>, points: &[Vec3]) -> (Assessment, Vec<f64>, Metrics, Vec<Violation>) {
    let s = ModelSettings { current_step: 10.0, ..ModelSettings::default() };
    let mission = Mission::new("m", vehicle(radius), points[0], *points.last().unwrap(), 0.0);
    let m = PathModel::new(w, &mission, &s);
    let mut times = Vec::new();
    let a = m.assess(points, &mut times);
    (a, times, m.metrics(points), m.violations(points))
}

const RIGHT_ANGLE: [Vec3; 3] =
    [Vec3::new(10.0, 10.0, -50.0), Vec3::new(110.0, 10.0, -50.0), Vec3::new(110.0, 110.0, -50.0)];

#[test]
fn a_right_angle_is_flown_round_a_quarter_circle() {
    // r = 20: 80 m straight, a quarter circle of 10 pi m, 80 m straight; 2 m/s.
    let (a, times, m, v) = judge(&world(), Some(20.0), &RIGHT_ANGLE);
    let len = 160.0 + 10.0 * PI;
    assert!(a.feasible(), "{v:?}");
    assert!((a.length - len).abs() < 1e-9, "{}", a.length);
    assert!((a.travel_time - len / 2.0).abs() < 1e-9, "{}", a.travel_time);
    // Waypoint 1 is passed halfway round the turn.
    assert!((times[1] - (80.0 + 5.0 * PI) / 2.0).abs() < 1e-9, "{times:?}");
    assert!((times[2] - len / 2.0).abs() < 1e-9);
    assert_eq!(m.min_turn_radius_m, Some(20.0));
    assert!((m.max_curvature_per_m.unwrap() - 0.05).abs() < 1e-12);
    // The waypoint angle is still reported (and checked against max_turn).
    assert!((m.max_turn_deg - 90.0).abs() < 1e-9);
}

#[test]
fn a_corner_sharper_than_the_radius_allows_is_a_violation_naming_the_waypoint() {
    // r = 150 needs 150 m of each leg; the legs have 100.
    let (a, _, m, v) = judge(&world(), Some(150.0), &RIGHT_ANGLE);
    assert_eq!((a.radius_violations, a.violation_count()), (1, 1));
    assert!((a.radius_excess - (1.0 - 100.0 / 150.0)).abs() < 1e-12);
    assert_eq!((v[0].kind, v[0].index), (ViolationKind::Turn, 1));
    assert!(v[0].message.starts_with("waypoint 1: the 90.0 deg turn needs 150.0 m of each leg"), "{}", v[0].message);
    assert!(v[0].message.ends_with("allow a radius of at most 100.0 m"), "{}", v[0].message);
    assert!((m.min_turn_radius_m.unwrap() - 100.0).abs() < 1e-9);
    // The same path without a radius flies its corner: feasible, as before.
    let (a, _, m, v) = judge(&world(), None, &RIGHT_ANGLE);
    assert!(a.feasible() && v.is_empty() && m.min_turn_radius_m.is_none());
    assert!((a.length - 200.0).abs() < 1e-12);
}

#[test]
fn the_flown_curve_not_the_polyline_meets_the_obstacles() {
    // A disc of radius 5 at the corner: the polyline runs through it, the r = 40 fillet passes
    // 40 (sqrt 2 - 1) = 16.6 m inside the corner, clear of it.
    let mut w = world();
    w.obstacles.push(Obstacle::fixed(Shape::Circle { center: Vec2::new(110.0, 10.0), radius: 5.0 }));
    let (a, _, m, v) = judge(&w, Some(40.0), &RIGHT_ANGLE);
    assert!(a.feasible(), "{v:?}");
    let clear = 40.0 * (2f64.sqrt() - 1.0) - 5.0;
    assert!((m.min_clearance_m.unwrap() - clear).abs() < 0.06, "{:?} vs {clear}", m.min_clearance_m);
    let (a, ..) = judge(&w, None, &RIGHT_ANGLE);
    assert!(!a.feasible());
    // A disc on the fillet itself: the violation names the turn.
    let mut w = world();
    let mid = Vec2::new(70.0 + 40.0 * (PI / 4.0).sin(), 50.0 - 40.0 * (PI / 4.0).cos());
    w.obstacles.push(Obstacle::fixed(Shape::Circle { center: mid, radius: 2.0 }));
    let (a, _, _, v) = judge(&w, Some(40.0), &RIGHT_ANGLE);
    assert!(!a.feasible());
    let hits: Vec<_> = v.iter().filter(|x| x.kind == ViolationKind::Obstacle).collect();
    assert_eq!(hits.len(), 1, "one report per turn and obstacle: {v:?}");
    assert!(hits[0].message.starts_with("the turn at waypoint 1 passes"), "{}", hits[0].message);
}

#[test]
fn a_following_current_speeds_the_whole_flown_curve_on_its_chords() {
    // A uniform 0.5 m/s current east: the first leg's straight part goes at 2.5 m/s, the last
    // (north) at sqrt(4 - 0.25) m/s; the turn in between somewhere between.
    let mut w = world();
    w.current = Current::Uniform(Vec3::new(0.5, 0.0, 0.0));
    let (a, ..) = judge(&w, Some(20.0), &RIGHT_ANGLE);
    let straight = 80.0 / 2.5 + 80.0 / (4.0f64 - 0.25).sqrt();
    let turn = a.travel_time - straight;
    assert!(turn > 10.0 * PI / 2.5 && turn < 10.0 * PI / (4.0f64 - 0.25).sqrt(), "{turn}");
}

#[test]
fn pitch_on_a_climbing_turn_is_its_climb_over_its_length() {
    // A 90 degree turn at r = 20 with the corner 20 m up: the legs climb at 20/100 each, the
    // fillet climbs from 20*20/100 = 4 m below to 4 m above the corner's height over 10 pi m.
    let p = [Vec3::new(10.0, 10.0, -60.0), Vec3::new(110.0, 10.0, -40.0), Vec3::new(110.0, 110.0, -20.0)];
    let (a, ..) = judge(&world(), Some(20.0), &p);
    assert!(a.feasible());
    let want = (8.0f64 / (10.0 * PI)).atan().max(0.2f64.atan());
    assert!((a.max_pitch - want).abs() < 1e-12, "{} vs {want}", a.max_pitch);
    // Length: legs' straight parts (80 m at slope 0.2) and the helix piece.
    let len = 2.0 * 80.0 * (1.0f64 + 0.04).sqrt() + (10.0 * PI).hypot(8.0);
    assert!((a.length - len).abs() < 1e-9);
}

#[test]
fn assess_and_violations_agree_on_random_paths() {
    let mut w = world();
    w.obstacles.push(Obstacle::fixed(Shape::Circle { center: Vec2::new(100.0, 100.0), radius: 20.0 }));
    let mut rng = crate::rng::run_rng(7, 0);
    let mut u = move || crate::rng::unit_f64(rand::RngCore::next_u64(&mut rng));
    for _ in 0..300 {
        let n = 2 + (u() * 5.0) as usize;
        let pts: Vec<Vec3> = (0..n).map(|_| Vec3::new(200.0 * u(), 200.0 * u(), -80.0 * u() - 5.0)).collect();
        let (a, times, _, v) = judge(&w, Some(15.0), &pts);
        assert_eq!(a.feasible(), v.is_empty(), "{pts:?}: {v:?}");
        assert_eq!(times.len(), pts.len());
        assert!(times.windows(2).all(|t| t[1] >= t[0]), "{times:?}");
    }
}

#[test]
fn a_turn_a_hair_too_tight_passes_only_within_the_arc_tolerance() {
    // A 4 degree turn at r = 40 needs 1.397 m of each leg; legs of 2 x 1.2 m allow 34.4 m. The
    // vehicle's own 40 m fillet would lie (40 - 34.4)(sec 2 deg - 1) = 3.4 mm from it: within
    // the 5 cm tolerance, so it passes; the metrics leave such a turn out (it is what rounding
    // in a file makes).
    let h = 4f64.to_radians();
    let p = [
        Vec3::new(10.0, 10.0, -50.0),
        Vec3::new(11.2, 10.0, -50.0),
        Vec3::new(11.2 + 1.2 * h.cos(), 10.0 + 1.2 * h.sin(), -50.0),
    ];
    let (a, _, m, v) = judge(&world(), Some(40.0), &p);
    assert!(a.feasible(), "{v:?}");
    assert!(1.2 / (h / 2.0).tan() < 40.0);
    assert_eq!(m.min_turn_radius_m, None, "{m:?}");
    // A right angle at 39 m instead of 40 would stray 1 (sqrt 2 - 1) = 0.41 m: a violation.
    let q = [Vec3::new(10.0, 10.0, -50.0), Vec3::new(49.0, 10.0, -50.0), Vec3::new(49.0, 49.0, -50.0)];
    let (a, ..) = judge(&world(), Some(40.0), &q);
    assert_eq!(a.radius_violations, 1);
}
