//! The dubins smoother on hand-made worlds, checked by an independent curvature sampler.

use super::*;
use crate::cost::{GeneralCost, GeneralWeights};
use crate::geom::Aabb;
use crate::kinematics::fillet::{for_each_piece, FlownPiece};
use crate::mission::Mission;
use crate::path::ModelSettings;
use crate::vehicle::Vehicle;
use crate::world::{Obstacle, Shape, World};
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

const R: f64 = 30.0;

/// A flat 2-D world 1000 m square at depth 50.
fn plane() -> World {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -50.0), Vec3::new(1000.0, 1000.0, -50.0)));
    w.dims = Dims::Two;
    w
}

fn vehicle(radius: Option<f64>) -> Vehicle {
    Vehicle { turn_radius: radius, safety_distance: 2.0, ..Vehicle::default() }
}

fn cost() -> GeneralCost {
    GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap())
}

fn smoother() -> DubinsSmoother {
    DubinsSmoother::default()
}

/// Feasibility and cost of `points` under `m`.
fn judge(m: &PathModel<'_>, points: &[Vec3]) -> (bool, f64) {
    let feasible = m.assess(points, &mut Vec::new()).feasible();
    (feasible, cost().cost(m, points, &mut Scratch::default()))
}

/// The flown curve of `points` at radius `r`, sampled densely in the horizontal plane.
fn samples(points: &[Vec3], r: f64) -> Vec<Vec2> {
    let mut out: Vec<Vec2> = Vec::new();
    let mut push = |p: Vec3| {
        let q = p.truncate();
        if out.last().is_none_or(|l| l.distance(q) > 1e-6 * r) {
            out.push(q);
        }
    };
    for_each_piece(points, r, |piece| match piece {
        FlownPiece::Line { a, b, .. } => {
            for k in 0..=4 {
                push(a + (b - a) * (k as f64 / 4.0));
            }
        }
        FlownPiece::Arc(arc) => {
            for k in 0..=16 {
                push(arc.point(k as f64 / 16.0));
            }
        }
    });
    out
}

/// The smallest circumradius of three consecutive samples: at least r on a curve whose
/// curvature never exceeds 1 / r.
fn min_circumradius(s: &[Vec2]) -> f64 {
    s.windows(3)
        .map(|w| {
            let (a, b, c) = (w[0].distance(w[1]), w[1].distance(w[2]), w[0].distance(w[2]));
            let area2 = (w[1] - w[0]).perp_dot(w[2] - w[0]).abs();
            if area2 <= 1e-12 * a * b {
                f64::INFINITY
            } else {
                a * b * c / (2.0 * area2)
            }
        })
        .fold(f64::INFINITY, f64::min)
}

fn assert_flyable(points: &[Vec3], r: f64) {
    let s = samples(points, r);
    assert!(s.len() >= 2, "too few samples");
    let min = min_circumradius(&s);
    assert!(min >= r * (1.0 - 1e-6), "a curvature radius {min} below {r}");
}

#[test]
fn zigzag_in_open_water_becomes_flyable() {
    let w = plane();
    let p: Vec<Vec3> = (0..=10)
        .map(|i| Vec3::new(100.0 + 60.0 * i as f64, 500.0 + if i % 2 == 1 { 40.0 } else { 0.0 }, -50.0))
        .collect();
    let mission = Mission::new("m", vehicle(Some(R)), p[0], p[10], 0.0);
    let s = ModelSettings::default();
    let m = PathModel::new(&w, &mission, &s);
    // The zigzag's corners (67 degrees on 72 m legs) need 40 m of each leg at r = 30.
    assert!(!judge(&m, &p).0, "the zigzag should not be flyable");
    let out = smoother().smooth(&m, &cost(), &p, &Termination::default());
    assert_eq!((out[0], *out.last().unwrap()), (p[0], p[10]));
    assert!(judge(&m, &out).0, "{:?}", m.violations(&out));
    assert_flyable(&out, R);
    // In open water nothing stops the straight line's bearing: the result is no longer
    // than a detour of the zigzag's amplitude.
    assert!(PathModel::length(&out) < 600.0 + 10.0, "{}", PathModel::length(&out));
}

#[test]
fn the_curvature_sampler_catches_a_sharp_corner() {
    // The sampler is independent of the smoother: a right angle flown at radius 10 has
    // circumradius 10 on its fillet, below 30.
    let p = [Vec3::new(0.0, 0.0, 0.0), Vec3::new(100.0, 0.0, 0.0), Vec3::new(100.0, 100.0, 0.0)];
    let min = min_circumradius(&samples(&p, 10.0));
    assert!((min - 10.0).abs() < 1e-6, "{min}");
}

#[test]
fn a_detour_round_a_disc_stays_clear_and_flyable() {
    let mut w = plane();
    w.obstacles.push(Obstacle::fixed(Shape::Circle { center: Vec2::new(500.0, 500.0), radius: 80.0 }));
    // A planner's polyline round the disc's north side, with tight corners.
    let p = vec![
        Vec3::new(200.0, 500.0, -50.0),
        Vec3::new(400.0, 500.0, -50.0),
        Vec3::new(420.0, 620.0, -50.0),
        Vec3::new(580.0, 620.0, -50.0),
        Vec3::new(600.0, 500.0, -50.0),
        Vec3::new(800.0, 500.0, -50.0),
    ];
    let mission = Mission::new("m", vehicle(Some(R)), p[0], p[5], 0.0);
    let s = ModelSettings::default();
    let m = PathModel::new(&w, &mission, &s);
    let (before, _) = judge(&m, &p);
    assert!(!before, "the polyline's corners should not fit");
    let out = smoother().smooth(&m, &cost(), &p, &Termination::default());
    assert_eq!((out[0], *out.last().unwrap()), (p[0], p[5]));
    assert!(judge(&m, &out).0, "{:?}", m.violations(&out));
    assert_flyable(&out, R);
}

#[test]
fn a_deep_dive_becomes_a_helix() {
    let w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -600.0), Vec3::new(400.0, 400.0, 0.0)));
    let v = Vehicle { max_pitch: 20f64.to_radians(), ..vehicle(Some(20.0)) };
    // 60 m ahead and 300 m down: the straight dive is 78.7 degrees.
    let p = vec![Vec3::new(170.0, 200.0, -50.0), Vec3::new(230.0, 200.0, -350.0)];
    let mission = Mission::new("m", v.clone(), p[0], p[1], 0.0);
    let s = ModelSettings::default();
    let m = PathModel::new(&w, &mission, &s);
    assert!(!judge(&m, &p).0);
    let out = smoother().smooth(&m, &cost(), &p, &Termination::default());
    assert_eq!((out[0], *out.last().unwrap()), (p[0], p[1]));
    assert!(judge(&m, &out).0, "{:?}", m.violations(&out));
    assert_flyable(&out, 20.0);
    // At most 20 degrees needs 300 / tan(20 deg) = 824 m of horizontal curve: several turns
    // of 126 m, so the flown curve turns through more than 4 full circles.
    let mut turned = 0.0;
    for_each_piece(&out, 20.0, |piece| {
        if let FlownPiece::Arc(arc) = piece {
            turned += arc.sweep.abs();
        }
    });
    assert!(turned > 4.0 * std::f64::consts::TAU, "{turned}");
    let a = m.assess(&out, &mut Vec::new());
    assert!(a.max_pitch <= v.max_pitch && a.max_pitch > 19.9f64.to_radians(), "{}", a.max_pitch.to_degrees());
}

#[test]
fn a_termination_that_fires_at_once_returns_no_worse() {
    let w = plane();
    let p: Vec<Vec3> = (0..=6)
        .map(|i| Vec3::new(100.0 + 50.0 * i as f64, 500.0 + if i % 2 == 1 { 30.0 } else { 0.0 }, -50.0))
        .collect();
    let mission = Mission::new("m", vehicle(Some(R)), p[0], p[6], 0.0);
    let s = ModelSettings::default();
    let m = PathModel::new(&w, &mission, &s);
    let stop = Arc::new(AtomicBool::new(true));
    let out = smoother().smooth(&m, &cost(), &p, &Termination::default().with_stop_flag(stop));
    let ((f0, c0), (f1, c1)) = (judge(&m, &p), judge(&m, &out));
    assert_eq!((out[0], *out.last().unwrap()), (p[0], p[6]));
    assert!(f1 || !f0, "became infeasible");
    assert!(f1 && !f0 || c1 <= c0, "worse: {c1} > {c0}");
}

#[test]
fn a_flyable_input_is_never_made_worse() {
    // A straight line is flyable and the cheapest path: the result costs no more.
    let w = plane();
    let p = vec![Vec3::new(100.0, 100.0, -50.0), Vec3::new(300.0, 200.0, -50.0), Vec3::new(500.0, 300.0, -50.0)];
    let mission = Mission::new("m", vehicle(Some(R)), p[0], p[2], 0.0);
    let s = ModelSettings::default();
    let m = PathModel::new(&w, &mission, &s);
    let ((f0, c0), out) = (judge(&m, &p), smoother().smooth(&m, &cost(), &p, &Termination::default()));
    let (f1, c1) = judge(&m, &out);
    assert!(f0 && f1 && c1 <= c0, "{c1} vs {c0}");
}

#[test]
fn without_a_radius_the_input_comes_back() {
    let w = plane();
    let p = vec![Vec3::new(100.0, 100.0, -50.0), Vec3::new(150.0, 200.0, -50.0), Vec3::new(300.0, 200.0, -50.0)];
    let mission = Mission::new("m", vehicle(None), p[0], p[2], 0.0);
    let s = ModelSettings::default();
    let m = PathModel::new(&w, &mission, &s);
    assert_eq!(smoother().smooth(&m, &cost(), &p, &Termination::default()), p);
}

#[test]
fn a_radius_parameter_serves_a_vehicle_without_one() {
    let w = plane();
    let p: Vec<Vec3> = (0..=4)
        .map(|i| Vec3::new(100.0 + 80.0 * i as f64, 500.0 + if i % 2 == 1 { 60.0 } else { 0.0 }, -50.0))
        .collect();
    let mut t = toml::Table::new();
    t.insert("radius".into(), toml::Value::Float(R));
    let sm = DubinsSmoother::new(DubinsParams::from_table(&t, "planner.smoother_params.dubins").unwrap());
    let mission = Mission::new("m", vehicle(None), p[0], p[4], 0.0);
    let s = ModelSettings::default();
    let m = PathModel::new(&w, &mission, &s);
    let out = sm.smooth(&m, &cost(), &p, &Termination::default());
    assert_ne!(out, p);
    // Flown at the parameter's radius, the result is flyable.
    assert_flyable(&out, R);
    let radius_vehicle = Mission::new("m", vehicle(Some(R)), p[0], p[4], 0.0);
    assert!(PathModel::new(&w, &radius_vehicle, &s).assess(&out, &mut Vec::new()).feasible());
}

#[test]
fn a_level_detour_in_a_3d_world_goes_round_a_cylinder() {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -300.0), Vec3::new(1000.0, 1000.0, 0.0)));
    w.obstacles.push(Obstacle::fixed(Shape::Cylinder {
        center: Vec2::new(500.0, 500.0),
        radius: 80.0,
        z_min: -300.0,
        z_max: 0.0,
    }));
    let p = vec![
        Vec3::new(200.0, 500.0, -100.0),
        Vec3::new(400.0, 500.0, -100.0),
        Vec3::new(420.0, 620.0, -100.0),
        Vec3::new(580.0, 620.0, -100.0),
        Vec3::new(600.0, 500.0, -100.0),
        Vec3::new(800.0, 500.0, -100.0),
    ];
    let mission = Mission::new("m", vehicle(Some(R)), p[0], p[5], 0.0);
    let s = ModelSettings::default();
    let m = PathModel::new(&w, &mission, &s);
    assert!(!judge(&m, &p).0);
    let out = smoother().smooth(&m, &cost(), &p, &Termination::default());
    assert_eq!((out[0], *out.last().unwrap()), (p[0], p[5]));
    assert!(judge(&m, &out).0, "{:?}", m.violations(&out));
    assert_flyable(&out, R);
    assert!(out.iter().all(|q| q.z == -100.0), "a level path stays level");
}
