//! Hand-computed checks of every metric the shared path evaluation reports.

use super::*;
use crate::geom::{Aabb, Vec2, Vec3};
use crate::mission::Mission;
use crate::world::terrain::{GaussianPeaks, Peak};
use crate::world::{Current, Obstacle, Shape, Terrain};

fn world() -> World {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(100.0, 100.0, 0.0)));
    w.terrain = Terrain::Peaks(GaussianPeaks { base: -90.0, peaks: vec![], ceiling: None });
    w
}

fn vehicle() -> Vehicle {
    Vehicle {
        propulsion: Default::default(),
        speed: 2.0,
        max_turn: 60f64.to_radians(),
        max_pitch: 30f64.to_radians(),
        depth_min: 0.0,
        depth_max: 100.0,
        safety_distance: 1.0,
        turn_radius: None,
        speed_range: None,
    }
}

fn metrics_of(w: &World, points: &[Vec3]) -> (Metrics, Vec<Violation>) {
    let v = vehicle();
    let s = ModelSettings { current_step: 10.0, ..ModelSettings::default() };
    let mission = Mission::new("m", v, points[0], *points.last().unwrap(), 0.0);
    let m = PathModel::new(w, &mission, &s);
    (m.metrics(points), m.violations(points))
}

#[test]
fn length_time_and_angles_of_a_right_angle_path() {
    let w = world();
    // 30 m east, then 40 m north: length 70, time 35 s at 2 m/s, one 90 degree turn.
    let p = [Vec3::new(10.0, 10.0, -50.0), Vec3::new(40.0, 10.0, -50.0), Vec3::new(40.0, 50.0, -50.0)];
    let (m, v) = metrics_of(&w, &p);
    assert!((m.length_m - 70.0).abs() < 1e-12);
    assert!((m.travel_time_s - 35.0).abs() < 1e-12);
    assert!((m.max_turn_deg - 90.0).abs() < 1e-9);
    assert_eq!(m.max_pitch_deg, 0.0);
    // Seabed flat at -90: vertical clearance 40 m.
    assert!((m.min_clearance_m.unwrap() - 40.0).abs() < 1e-6);
    assert_eq!(m.collisions, 0);
    assert_eq!(v.len(), 1);
    assert_eq!((v[0].kind, v[0].index), (ViolationKind::Turn, 1));
}

#[test]
fn pitch_of_a_45_degree_dive_is_a_violation() {
    let w = world();
    let p = [Vec3::new(10.0, 10.0, -10.0), Vec3::new(40.0, 10.0, -40.0)];
    let (m, v) = metrics_of(&w, &p);
    assert!((m.max_pitch_deg - 45.0).abs() < 1e-9);
    assert!((m.length_m - 30.0 * 2f64.sqrt()).abs() < 1e-12);
    assert_eq!(v.iter().map(|x| x.kind).collect::<Vec<_>>(), vec![ViolationKind::Pitch]);
}

#[test]
fn crab_travel_time_through_a_cross_current() {
    let mut w = world();
    // 1.2 m/s across the track with v = 2: ground speed sqrt(4 - 1.44) = 1.6 m/s; 80 m take 50 s.
    w.current = Current::Uniform(Vec3::new(0.0, 1.2, 0.0));
    let (m, v) = metrics_of(&w, &[Vec3::new(10.0, 10.0, -50.0), Vec3::new(90.0, 10.0, -50.0)]);
    assert!((m.travel_time_s - 50.0).abs() < 1e-9);
    assert!(v.is_empty());
    // 2.5 m/s across: the vehicle cannot hold the track.
    w.current = Current::Uniform(Vec3::new(0.0, 2.5, 0.0));
    let (_, v) = metrics_of(&w, &[Vec3::new(10.0, 10.0, -50.0), Vec3::new(90.0, 10.0, -50.0)]);
    assert_eq!(v.iter().map(|x| x.kind).collect::<Vec<_>>(), vec![ViolationKind::Current]);
}

#[test]
fn a_head_current_driving_a_wave_glider_back_is_said_so() {
    let mut w = world();
    // 0.5 m waves and 0.4 m/s against the heading: 0.1623 * 0.5 - 0.2660 * 0.4 = -0.02535 m/s
    // (acopf2016 eq. 1), so the glider cannot hold the track on the one piece of a uniform field.
    w.waves = crate::world::Waves::Uniform(0.5);
    w.current = Current::Uniform(Vec3::new(-0.4, 0.0, 0.0));
    let v = Vehicle { propulsion: crate::vehicle::Propulsion::WaveGlider(Default::default()), ..vehicle() };
    let s = ModelSettings { current_step: 100.0, ..ModelSettings::default() };
    let (a, b) = (Vec3::new(10.0, 10.0, -50.0), Vec3::new(90.0, 10.0, -50.0));
    let mission = Mission::new("m", v, a, b, 0.0);
    let found = PathModel::new(&w, &mission, &s).violations(&[a, b]);
    assert_eq!(found.iter().map(|x| x.kind).collect::<Vec<_>>(), vec![ViolationKind::Current]);
    assert_eq!(found[0].message, "segment 0: the head current drives the wave glider back on 1 piece(s)");
    // With the current behind it the glider makes 0.08115 + 0.1064 m/s and nothing is violated.
    w.current = Current::Uniform(Vec3::new(0.4, 0.0, 0.0));
    assert!(PathModel::new(&w, &mission, &s).violations(&[a, b]).is_empty());
}

#[test]
fn vector_sum_travel_time_follows_seed_003_eq_17() {
    let mut w = world();
    w.current = Current::Uniform(Vec3::new(0.0, 1.5, 0.0));
    let v = vehicle();
    let s = ModelSettings { travel: TravelModel::VectorSum, current_step: 10.0, ..ModelSettings::default() };
    let (a, b) = (Vec3::new(0.0, 10.0, -50.0), Vec3::new(100.0, 10.0, -50.0));
    let mission = Mission::new("m", v, a, b, 0.0);
    let m = PathModel::new(&w, &mission, &s);
    // |v d + c| = |(2, 1.5)| = 2.5 at both ends: 100 m / 2.5 = 40 s.
    let t = m.metrics(&[a, b]).travel_time_s;
    assert!((t - 40.0).abs() < 1e-12);
}

#[test]
fn obstacle_clearance_and_collision_count() {
    let mut w = world();
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(50.0, 20.0, -50.0), radius: 5.0 }));
    w.obstacles.push(Obstacle::fixed(Shape::Circle { center: Vec2::new(50.0, 60.0), radius: 3.0 }));
    // Passes 10 m from the sphere centre: 5 m clearance.
    let (m, v) = metrics_of(&w, &[Vec3::new(10.0, 30.0, -50.0), Vec3::new(90.0, 30.0, -50.0)]);
    assert!((m.min_clearance_m.unwrap() - 5.0).abs() < 1e-9);
    assert!(v.is_empty());
    // Through the circle's column: one collision; 0 clearance.
    let (m, v) = metrics_of(&w, &[Vec3::new(10.0, 60.0, -50.0), Vec3::new(90.0, 60.0, -50.0)]);
    assert_eq!(m.collisions, 1);
    assert_eq!(m.min_clearance_m, Some(0.0));
    assert_eq!((v[0].kind, v[0].index), (ViolationKind::Obstacle, 0));
}

#[test]
fn seabed_and_bounds_violations() {
    let mut w = world();
    w.terrain = Terrain::Peaks(GaussianPeaks {
        base: -90.0,
        peaks: vec![Peak { x: 50.0, y: 50.0, height: 60.0, sigma_x: 10.0, sigma_y: 10.0 }],
        ceiling: None,
    });
    // Level at -40 over a peak reaching -30: 10 m below its top.
    let (m, v) = metrics_of(&w, &[Vec3::new(10.0, 50.0, -40.0), Vec3::new(90.0, 50.0, -40.0)]);
    assert!((m.min_clearance_m.unwrap() + 10.0).abs() < 1e-4);
    assert_eq!(m.collisions, 1);
    assert_eq!(v[0].kind, ViolationKind::Terrain);
    // A waypoint outside the domain.
    let (_, v) = metrics_of(&w, &[Vec3::new(10.0, 10.0, -40.0), Vec3::new(120.0, 10.0, -40.0)]);
    assert!(v.iter().any(|x| x.kind == ViolationKind::Bounds && x.index == 1));
}

#[test]
fn moving_obstacle_is_met_at_the_right_time() {
    let mut w = world();
    // The sphere starts 20 m north of the track and moves south at 1 m/s; the vehicle (2 m/s)
    // reaches x = 50 after 20 s, when the sphere has arrived on the track.
    w.obstacles.push(Obstacle {
        shape: Shape::Sphere { center: Vec3::new(50.0, 30.0, -50.0), radius: 3.0 },
        velocity: Vec3::new(0.0, -1.0, 0.0),
        window: None,
    });
    let p = [Vec3::new(10.0, 10.0, -50.0), Vec3::new(90.0, 10.0, -50.0)];
    assert_eq!(metrics_of(&w, &p).0.collisions, 1);
    // Moving north instead, it never comes near.
    w.obstacles[0].velocity = Vec3::new(0.0, 1.0, 0.0);
    assert_eq!(metrics_of(&w, &p).0.collisions, 0);
}

#[test]
fn general_cost_terms_by_hand() {
    use crate::cost::{CostModel, GeneralCost, GeneralWeights};
    let w = world();
    let v = vehicle();
    let s = ModelSettings::default();
    let p = [Vec3::new(10.0, 10.0, -50.0), Vec3::new(40.0, 10.0, -50.0), Vec3::new(40.0, 50.0, -50.0)];
    let mission = Mission::new("m", v, p[0], p[2], 0.0);
    let m = PathModel::new(&w, &mission, &s);
    let weights = GeneralWeights { length: 1.0, time: 2.0, collision: 10.0, turn: 3.0, pitch: 1.0 };
    let cost = GeneralCost::new(weights.checked("cost.weights").unwrap());
    let (total, terms) = cost.breakdown(&m, &p);
    // Straight distance 50 m, 25 s. Path 70 m, 35 s. One turn of 90 degrees against 60.
    let expect = [1.4, 2.0 * 1.4, 0.0, 3.0 * (1.0 + 30f64.to_radians()), 0.0];
    for ((name, got), want) in terms.iter().zip(expect) {
        assert!((got - want).abs() < 1e-9, "{name}: {got} vs {want}");
    }
    assert!((total - expect.iter().sum::<f64>()).abs() < 1e-12);
}

/// A plan's segment speeds set its clock: 30 m at 1 m/s then 40 m at 4 m/s take 30 + 10 s,
/// the time term follows (T0 = 50 m at the cruise 2 m/s = 25 s), and a moving obstacle met at
/// cruise speed is missed at another.
#[test]
fn segment_speeds_set_the_clock_the_cost_and_the_encounters() {
    use crate::cost::{CostModel, GeneralCost, GeneralWeights};
    let w = world();
    let v = Vehicle { speed_range: Some((1.0, 4.0)), ..vehicle() };
    let s = ModelSettings::default();
    let p = [Vec3::new(10.0, 10.0, -50.0), Vec3::new(40.0, 10.0, -50.0), Vec3::new(40.0, 50.0, -50.0)];
    let mission = Mission::new("m", v, p[0], p[2], 0.0);
    let base = PathModel::new(&w, &mission, &s);
    let speeds = [1.0, 4.0];
    let m = base.with_speeds(Some(&speeds));
    let mut times = Vec::new();
    let a = m.assess(&p, &mut times);
    assert_eq!(times, vec![0.0, 30.0, 40.0]);
    assert_eq!(a.travel_time, 40.0);
    assert_eq!((m.segment_speed(0), m.segment_speed(1), m.segment_speed(7)), (1.0, 4.0, 4.0));
    let cost = GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap());
    let (_, terms) = cost.breakdown(&m, &p);
    assert!((terms[1].1 - 40.0 / 25.0).abs() < 1e-12, "{terms:?}");
    // At cruise speed the same path takes 15 + 20 s.
    base.assess(&p, &mut times);
    assert_eq!(times, vec![0.0, 15.0, 35.0]);

    // A sphere crossing the first segment's x = 25 at t = 7.5 s (when a 2 m/s vehicle is there)
    // hits at cruise speed; at 1 m/s the vehicle reaches x = 25 at t = 15 s, long after.
    let mut w = world();
    w.obstacles.push(Obstacle {
        shape: Shape::Sphere { center: Vec3::new(25.0, 17.5, -50.0), radius: 2.0 },
        velocity: Vec3::new(0.0, -1.0, 0.0),
        window: None,
    });
    let base = PathModel::new(&w, &mission, &s);
    assert_eq!(base.assess(&p, &mut times).collisions, 1);
    assert_eq!(base.with_speeds(Some(&speeds)).assess(&p, &mut times).collisions, 0);
    assert!(base.violations(&p).iter().any(|x| x.kind == ViolationKind::Obstacle));
    assert!(!base.with_speeds(Some(&speeds)).violations(&p).iter().any(|x| x.kind == ViolationKind::Obstacle));
    // The edge-by-edge choice: at the fastest level (4 m/s) the vehicle passes ahead of the
    // sphere (closest at t = 135/34 s, 1.64 m from its surface, outside the 1 m safety):
    // valid and cheapest, so chosen; at cruise speed the motion is invalid.
    let (_, arrival, speed) = crate::cost::cheapest_motion(&cost, &base, p[0], p[1], 0.0).unwrap();
    assert_eq!((speed, arrival), (4.0, 7.5));
    assert!(cost.motion_cost(&base, p[0], p[1], 0.0).is_none());
    // Without a range the only choice is the cruise speed, here invalid.
    let fixed = Mission::new("m", vehicle(), p[0], p[2], 0.0);
    assert!(crate::cost::cheapest_motion(&cost, &PathModel::new(&w, &fixed, &s), p[0], p[1], 0.0).is_none());
}
