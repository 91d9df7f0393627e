//! The `bspline` smoother: its basis against hand-computed values, the curve's properties, and
//! the smoother contract on hand-made worlds.

use super::curve::{control_polygon, sample, Samples};
use super::*;
use crate::cost::{GeneralCost, GeneralWeights};
use crate::geom::{Aabb, Vec2};
use crate::mission::Mission;
use crate::path::ModelSettings;
use crate::vehicle::Vehicle;
use crate::world::{Dims, Obstacle, Shape, World};
use std::sync::atomic::AtomicBool;
use std::sync::Arc;
use std::time::Duration;

fn close(a: f64, b: f64) {
    assert!((a - b).abs() < 1e-12, "{a} vs {b}");
}

/// All m basis functions of degree p at u.
fn basis_row(knots: &[f64], m: usize, p: usize, u: f64) -> Vec<f64> {
    (0..m).map(|i| basis(knots, i, p, u)).collect()
}

/// Five control points, cubic: knots 0 0 0 0 ½ 1 1 1 1. By hand from the recursion (eq. 26,
/// A11's numerator), at u = ½ (the interior knot, span [½, 1)):
///   B₃,₁ = 1; B₂,₂ = B₃,₂ = ½; B₁,₃ = ½·½ = ¼, B₂,₃ = ½·½ + ½·½ = ½, B₃,₃ = ½·½ = ¼;
/// at u = ¼ (span [0, ½)): B₂,₁ = B₃,₁ = ½; B₁,₂ = ¼, B₂,₂ = ⅝, B₃,₂ = ⅛;
///   B₀,₃ = ½·¼ = ⅛, B₁,₃ = ½·¼ + ¾·⅝ = 19/32, B₂,₃ = ¼·⅝ + ¾·⅛ = ¼, B₃,₃ = ¼·⅛ = 1/32.
#[test]
fn the_cubic_basis_by_hand() {
    let mut knots = Vec::new();
    clamped_knots(5, 3, &mut knots);
    assert_eq!(knots, [0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0]);
    for (got, want) in basis_row(&knots, 5, 3, 0.5).iter().zip([0.0, 0.25, 0.5, 0.25, 0.0]) {
        close(*got, want);
    }
    for (got, want) in basis_row(&knots, 5, 3, 0.25).iter().zip([0.125, 19.0 / 32.0, 0.25, 1.0 / 32.0, 0.0]) {
        close(*got, want);
    }
    // The ends: only the first, then only the last control point.
    assert_eq!(basis_row(&knots, 5, 3, 0.0), [1.0, 0.0, 0.0, 0.0, 0.0]);
    assert_eq!(basis_row(&knots, 5, 3, 1.0), [0.0, 0.0, 0.0, 0.0, 1.0]);
}

/// Four control points, cubic: one span, the Bernstein polynomials (1/8, 3/8, 3/8, 1/8) at ½.
#[test]
fn four_control_points_give_the_bezier_basis() {
    let mut knots = Vec::new();
    clamped_knots(4, 3, &mut knots);
    for (got, want) in basis_row(&knots, 4, 3, 0.5).iter().zip([0.125, 0.375, 0.375, 0.125]) {
        close(*got, want);
    }
}

#[test]
fn the_basis_is_a_partition_of_unity_and_de_boor_agrees() {
    let mut knots = Vec::new();
    for m in 2..12 {
        let ctrl: Vec<Vec3> =
            (0..m).map(|i| Vec3::new(i as f64 * 10.0, ((i * 7) % 5) as f64 * 13.0, -(((i * 3) % 4) as f64))).collect();
        for p in 1..=(m - 1).min(MAX_DEGREE) {
            clamped_knots(m, p, &mut knots);
            assert_eq!(knots.len(), m + p + 1);
            for j in 0..=64 {
                let u = j as f64 / 64.0;
                let row = basis_row(&knots, m, p, u);
                assert!(row.iter().all(|&b| b >= 0.0), "m {m} p {p} u {u}: {row:?}");
                close(row.iter().sum::<f64>(), 1.0);
                let by_sum: Vec3 = ctrl.iter().zip(&row).map(|(c, b)| *c * *b).sum();
                let s = span_of(&knots, m, p, u);
                let by_de_boor = de_boor(&ctrl, &knots, p, s, u);
                assert!(by_sum.distance(by_de_boor) < 1e-9, "m {m} p {p} u {u}: {by_sum} vs {by_de_boor}");
            }
        }
    }
}

/// A zigzag: its control polygon with each leg cut into 2^level pieces, sampled.
fn curve_of(points: &[Vec3], level: u8, degree: usize, per_span: usize) -> Vec<Vec3> {
    let (mut ctrl, mut legs, mut knots, mut out) = (Vec::new(), Vec::new(), Vec::new(), Samples::default());
    control_polygon(points, &vec![level; points.len() - 1], &mut ctrl, &mut legs);
    let p = degree.min(ctrl.len() - 1);
    clamped_knots(ctrl.len(), p, &mut knots);
    sample(&ctrl, &knots, p, per_span, 1e-9, &mut out);
    assert_eq!(out.points.len(), out.spans.len());
    out.points
}

fn zigzag() -> Vec<Vec3> {
    (0..=6).map(|i| Vec3::new(100.0 * i as f64, if i % 2 == 1 { 80.0 } else { 0.0 }, -10.0)).collect()
}

#[test]
fn the_curve_keeps_both_ends_exactly() {
    let p = zigzag();
    for level in 0..3 {
        for degree in 1..=5 {
            let c = curve_of(&p, level, degree, 5);
            assert_eq!((c[0], *c.last().unwrap()), (p[0], p[6]), "level {level} degree {degree}");
        }
    }
}

/// Andrew's monotone chain, counter-clockwise.
fn convex_hull(points: &[Vec2]) -> Vec<Vec2> {
    let mut p = points.to_vec();
    p.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    let mut hull: Vec<Vec2> = Vec::new();
    for pass in 0..2 {
        let start = hull.len();
        for &q in &p {
            while hull.len() >= start + 2
                && (hull[hull.len() - 1] - hull[hull.len() - 2]).perp_dot(q - hull[hull.len() - 2]) <= 0.0
            {
                hull.pop();
            }
            hull.push(q);
        }
        hull.pop();
        if pass == 0 {
            p.reverse();
        }
    }
    hull
}

#[test]
fn the_curve_lies_in_the_convex_hull_of_its_control_points() {
    let p: Vec<Vec3> = [(0.0, 0.0), (50.0, 120.0), (90.0, -30.0), (160.0, 60.0), (170.0, 200.0), (260.0, 90.0)]
        .iter()
        .map(|&(x, y)| Vec3::new(x, y, 0.0))
        .collect();
    let hull = convex_hull(&p.iter().map(|q| q.truncate()).collect::<Vec<_>>());
    for (level, degree) in [(0, 3), (1, 3), (0, 2), (2, 5)] {
        for q in curve_of(&p, level, degree, 16) {
            let q = q.truncate();
            for k in 0..hull.len() {
                let (a, b) = (hull[k], hull[(k + 1) % hull.len()]);
                assert!((b - a).perp_dot(q - a) >= -1e-9, "{q} outside the hull at level {level}, degree {degree}");
            }
        }
    }
}

/// The symmetric Hausdorff distance between two polylines, both sampled every metre or so.
fn hausdorff(a: &[Vec3], b: &[Vec3]) -> f64 {
    let dense = |p: &[Vec3]| -> Vec<Vec3> {
        let mut out = vec![p[0]];
        for w in p.windows(2) {
            let k = w[0].distance(w[1]).ceil().max(1.0) as usize;
            out.extend((1..=k).map(|j| w[0].lerp(w[1], j as f64 / k as f64)));
        }
        out
    };
    let (a, b) = (dense(a), dense(b));
    let one_way = |x: &[Vec3], y: &[Vec3]| {
        x.iter().map(|p| y.iter().map(|q| p.distance(*q)).fold(f64::INFINITY, f64::min)).fold(0.0, f64::max)
    };
    one_way(&a, &b).max(one_way(&b, &a))
}

/// Fig. 8: with the midpoints inserted the curve follows the polyline more closely, and each
/// further level closer still.
#[test]
fn midpoint_insertion_keeps_the_curve_closer_to_the_polyline() {
    let p = zigzag();
    let d: Vec<f64> = (0..4).map(|level| hausdorff(&p, &curve_of(&p, level, 3, 16))).collect();
    assert!(d[1] < 0.75 * d[0], "{d:?}");
    assert!(d[2] < d[1] && d[3] < d[2], "{d:?}");
}

fn cost() -> GeneralCost {
    GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap())
}

fn judge(m: &PathModel<'_>, points: &[Vec3]) -> (bool, f64) {
    (m.assess(points, &mut Vec::new()).feasible(), cost().cost(m, points, &mut Scratch::default()))
}

fn smoother(t: &[(&str, toml::Value)]) -> BsplineSmoother {
    let table: toml::Table = t.iter().map(|(k, v)| (k.to_string(), v.clone())).collect();
    BsplineSmoother::new(BsplineParams::from_table(&table, "planner.smoother_params.bspline").unwrap())
}

/// A flat 2-D world 1000 m square at depth 50, with the box [400, 600]² when `boxed`.
fn plane(boxed: bool) -> World {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -50.0), Vec3::new(1000.0, 1000.0, -50.0)));
    w.dims = Dims::Two;
    if boxed {
        w.obstacles.push(Obstacle::fixed(Shape::Box {
            min: Vec3::new(400.0, 400.0, -60.0),
            max: Vec3::new(600.0, 600.0, -40.0),
        }));
    }
    w
}

fn vehicle() -> Vehicle {
    Vehicle { safety_distance: 2.0, max_turn: 100f64.to_radians(), ..Vehicle::default() }
}

/// Round the box's north-east corner 10 m off both faces: feasible, and the plain spline
/// (no midpoints, no repair) cuts deep into the box.
fn hugging() -> Vec<Vec3> {
    vec![Vec3::new(300.0, 610.0, -50.0), Vec3::new(610.0, 610.0, -50.0), Vec3::new(610.0, 300.0, -50.0)]
}

#[test]
fn a_curve_that_cuts_a_corner_is_refitted_clear_of_it() {
    let w = plane(true);
    let p = hugging();
    let mission = Mission::new("m", vehicle(), p[0], p[2], 0.0);
    let s = ModelSettings::default();
    let m = PathModel::new(&w, &mission, &s);
    let (f0, c0) = judge(&m, &p);
    assert!(f0, "{:?}", m.violations(&p));
    assert!(!judge(&m, &curve_of(&p, 0, 3, 8)).0, "the plain spline should cut the box");
    assert!(!judge(&m, &curve_of(&p, 1, 3, 8)).0, "the midpoint spline should cut the box too");
    let out = BsplineSmoother::default().smooth(&m, &cost(), &p, &Termination::default());
    assert_ne!(out, p, "the refitted curve should be kept");
    assert_eq!((out[0], *out.last().unwrap()), (p[0], p[2]));
    let (f1, c1) = judge(&m, &out);
    assert!(f1, "{:?}", m.violations(&out));
    assert!(c1 <= c0, "{c1} > {c0}");
    // Smooth: the sharpest joint is far below the polyline's right angle.
    let a = m.assess(&out, &mut Vec::new());
    assert!(a.max_turn < 30f64.to_radians(), "{}", a.max_turn.to_degrees());
}

#[test]
fn without_repairs_a_curve_that_cuts_the_corner_is_declined() {
    let w = plane(true);
    let p = hugging();
    let mission = Mission::new("m", vehicle(), p[0], p[2], 0.0);
    let s = ModelSettings::default();
    let m = PathModel::new(&w, &mission, &s);
    for midpoints in [true, false] {
        let sm = smoother(&[("repair_depth", toml::Value::Integer(0)), ("midpoints", toml::Value::Boolean(midpoints))]);
        assert_eq!(sm.smooth(&m, &cost(), &p, &Termination::default()), p);
    }
}

#[test]
fn a_zigzag_in_open_water_becomes_a_smooth_cheaper_curve() {
    let w = plane(false);
    let p: Vec<Vec3> = zigzag().iter().map(|q| Vec3::new(q.x + 100.0, q.y + 400.0, -50.0)).collect();
    let mission = Mission::new("m", vehicle(), p[0], p[6], 0.0);
    let s = ModelSettings::default();
    let m = PathModel::new(&w, &mission, &s);
    let (f0, c0) = judge(&m, &p);
    let out = BsplineSmoother::default().smooth(&m, &cost(), &p, &Termination::default());
    let (f1, c1) = judge(&m, &out);
    assert!(f0 && f1 && c1 < c0, "{c1} vs {c0}");
    assert_eq!((out[0], *out.last().unwrap()), (p[0], p[6]));
    let (a0, a1) = (m.assess(&p, &mut Vec::new()), m.assess(&out, &mut Vec::new()));
    assert!(a1.max_turn < 0.25 * a0.max_turn, "{} vs {}", a1.max_turn, a0.max_turn);
}

/// The zigzag's corners are beyond a 30 degree turn limit; the curve spreads each turn over
/// many joints and makes an infeasible input feasible.
#[test]
fn an_infeasible_input_of_sharp_turns_is_replaced() {
    let w = plane(false);
    let p: Vec<Vec3> = zigzag().iter().map(|q| Vec3::new(q.x + 100.0, q.y + 400.0, -50.0)).collect();
    let v = Vehicle { max_turn: 30f64.to_radians(), ..vehicle() };
    let mission = Mission::new("m", v, p[0], p[6], 0.0);
    let s = ModelSettings::default();
    let m = PathModel::new(&w, &mission, &s);
    assert!(!judge(&m, &p).0);
    let out = BsplineSmoother::default().smooth(&m, &cost(), &p, &Termination::default());
    assert!(judge(&m, &out).0, "{:?}", m.violations(&out));
}

#[test]
fn a_fired_termination_returns_the_input() {
    let w = plane(true);
    let p = hugging();
    let mission = Mission::new("m", vehicle(), p[0], p[2], 0.0);
    let s = ModelSettings::default();
    let m = PathModel::new(&w, &mission, &s);
    let stop = Arc::new(AtomicBool::new(true));
    let flagged = Termination::default().with_stop_flag(stop);
    assert_eq!(BsplineSmoother::default().smooth(&m, &cost(), &p, &flagged), p);
    let timed = Termination::default().with_wall_time(Duration::from_nanos(1)).started_now();
    std::thread::sleep(Duration::from_millis(2));
    assert_eq!(BsplineSmoother::default().smooth(&m, &cost(), &p, &timed), p);
}

#[test]
fn two_points_come_back_and_the_table_builds_it() {
    let w = plane(false);
    let p = vec![Vec3::new(100.0, 100.0, -50.0), Vec3::new(300.0, 200.0, -50.0)];
    let mission = Mission::new("m", vehicle(), p[0], p[1], 0.0);
    let s = ModelSettings::default();
    let m = PathModel::new(&w, &mission, &s);
    let sm = crate::smoothing::build_smoother("bspline", None).unwrap();
    assert_eq!(sm.id(), "bspline");
    assert_eq!(sm.smooth(&m, &cost(), &p, &Termination::default()), p);
    let d = BsplineParams::default();
    assert_eq!((d.degree, d.midpoints, d.samples, d.repair_depth), (3, true, 8, 4));
}

/// Random paths through a 3-D box with spheres, some flown at chosen segment speeds (carried
/// onto the curve as the caller does): never costlier, never infeasible from a feasible
/// input, the ends kept.
#[test]
fn random_paths_honour_the_smoother_contract() {
    use rand::Rng as _;
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(100.0, 100.0, 0.0)));
    // Off the straight line, which random detours may hit.
    for (c, r) in [((30.0, 55.0, -50.0), 12.0), ((70.0, 45.0, -45.0), 12.0), ((50.0, 50.0, -80.0), 8.0)] {
        w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(c.0, c.1, c.2), radius: r }));
    }
    let v = Vehicle { max_turn: 2.0, max_pitch: 0.6, safety_distance: 1.0, depth_max: 100.0, ..Vehicle::default() };
    let (s, g) = (Vec3::new(5.0, 5.0, -50.0), Vec3::new(95.0, 95.0, -50.0));
    let mission = Mission::new("m", v, s, g, 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    let sm = BsplineSmoother::default();
    let mut rng = crate::rng::run_rng(11, 0);
    let (mut changed, mut feasible_inputs) = (0, 0);
    for trial in 0..150 {
        let n = 1 + trial % 7;
        let mut p = vec![s];
        for k in 0..n {
            let base = s.lerp(g, (k + 1) as f64 / (n + 1) as f64);
            let d = Vec3::new(rng.random::<f64>() - 0.5, rng.random::<f64>() - 0.5, 0.3 * (rng.random::<f64>() - 0.5));
            let jitter = if trial % 2 == 0 { 15.0 } else { 40.0 };
            p.push((base + d * jitter).clamp(Vec3::new(0.0, 0.0, -100.0), Vec3::new(100.0, 100.0, 0.0)));
        }
        p.push(g);
        let speeds: Vec<f64> = (0..p.len() - 1).map(|i| 1.0 + 0.25 * (i % 3) as f64).collect();
        let m = if trial % 3 == 0 { model.with_speeds(Some(&speeds)) } else { model.clone() };
        let (f0, c0) = judge(&m, &p);
        feasible_inputs += usize::from(f0);
        let out = sm.smooth(&m, &cost(), &p, &Termination::default());
        assert_eq!((out[0], *out.last().unwrap()), (s, g));
        let moved = m.speeds.map(|v| crate::path::resample_speeds(&p, v, &out));
        let (f1, c1) = judge(&m.with_speeds(moved.as_deref()), &out);
        assert!(f1 || !f0, "trial {trial}: became infeasible");
        assert!(c1 <= c0 || (f1 && !f0), "trial {trial}: {c1} > {c0}");
        changed += usize::from(out != p);
    }
    assert!(changed > 60 && feasible_inputs > 40, "changed {changed}, feasible inputs {feasible_inputs}");
}
