//! Analytic answers for the visibility graph.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use super::*;

const STEP: f64 = 0.05;

fn solve(scene: &Scene, s: Point, t: Point) -> VisPath {
    shortest_path(scene, s, t, STEP).unwrap().expect("a path")
}

fn circle(x: f64, y: f64, r: f64) -> Circle {
    Circle { centre: [x, y], radius: r }
}

fn close(a: f64, b: f64) {
    assert!((a - b).abs() < 1e-9, "{a} vs {b}");
}

/// Polyline length plus the chord deficit of arcs must match the exact length;
/// every polyline vertex must lie outside every circle's interior.
fn check_polyline(scene: &Scene, p: &VisPath) {
    for q in &p.polyline {
        for c in &scene.circles {
            assert!(dist(*q, c.centre) >= c.radius - 1e-9, "{q:?} inside {c:?}");
        }
    }
    let exact: f64 = p
        .pieces
        .iter()
        .map(|piece| match *piece {
            Piece::Segment { from, to } => dist(from, to),
            Piece::Arc { radius, sweep, .. } => radius * sweep.abs(),
        })
        .sum();
    close(exact, p.length);
    let poly: f64 = p.polyline.windows(2).map(|w| dist(w[0], w[1])).sum();
    assert!(poly <= p.length + 1e-9 && poly >= p.length * (1.0 - STEP * STEP / 8.0) - 1e-9);
}

#[test]
fn no_obstacles_is_a_straight_line() {
    let p = solve(&Scene::default(), [1.0, 2.0], [4.0, 6.0]);
    close(p.length, 5.0);
    assert_eq!(p.polyline, vec![[1.0, 2.0], [4.0, 6.0]]);
}

#[test]
fn around_one_circle() {
    // Start and goal symmetric about a unit circle at distance a = 3:
    // two tangents of length sqrt(a² − r²) and the arc between the tangent
    // points, whose angle is π − 2·acos(r / a).
    let scene = Scene { circles: vec![circle(0.0, 0.0, 1.0)], ..Scene::default() };
    let p = solve(&scene, [-3.0, 0.0], [3.0, 0.0]);
    close(p.length, 2.0 * 8f64.sqrt() + (PI - 2.0 * (1.0f64 / 3.0).acos()));
    assert_eq!(p.pieces.len(), 3);
    assert!(matches!(p.pieces[1], Piece::Arc { .. }));
    check_polyline(&scene, &p);
}

#[test]
fn around_an_axis_aligned_box() {
    let square = Polygon { vertices: vec![[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]] };
    let scene = Scene { polygons: vec![square], ..Scene::default() };
    let p = solve(&scene, [-3.0, 0.0], [3.0, 0.5]);
    close(p.length, 5f64.sqrt() + 2.0 + 4.25f64.sqrt());
    assert_eq!(p.polyline, vec![[-3.0, 0.0], [-1.0, 1.0], [1.0, 1.0], [3.0, 0.5]]);
    // Clockwise input is accepted too.
    let cw = Polygon { vertices: vec![[-1.0, -1.0], [-1.0, 1.0], [1.0, 1.0], [1.0, -1.0]] };
    let q = solve(&Scene { polygons: vec![cw], ..Scene::default() }, [-3.0, 0.0], [3.0, 0.5]);
    close(q.length, p.length);
}

#[test]
fn out_of_a_u_shaped_polygon() {
    // Start in the cavity of a U opening upward, goal below it: the path leaves
    // over an arm, along its top and down its outer side (touching edges), and
    // never bends at the reflex vertices of the cavity floor.
    let u = Polygon {
        vertices: vec![
            [-2.0, -2.0],
            [2.0, -2.0],
            [2.0, 2.0],
            [1.0, 2.0],
            [1.0, -1.0],
            [-1.0, -1.0],
            [-1.0, 2.0],
            [-2.0, 2.0],
        ],
    };
    let scene = Scene { polygons: vec![u], ..Scene::default() };
    let p = solve(&scene, [0.0, 0.0], [0.0, -3.0]);
    close(p.length, 2.0 * 5f64.sqrt() + 5.0);
    assert_eq!(p.polyline.len(), 5);
}

#[test]
fn two_circles_in_a_row() {
    // Tangent to the first circle, quarter-ish arc, the outer bitangent y = 1,
    // arc, tangent to the goal.
    let scene = Scene { circles: vec![circle(-2.0, 0.0, 1.0), circle(2.0, 0.0, 1.0)], ..Scene::default() };
    let p = solve(&scene, [-5.0, 0.0], [5.0, 0.0]);
    close(p.length, 2.0 * 8f64.sqrt() + 2.0 * (FRAC_PI_2 - (1.0f64 / 3.0).acos()) + 4.0);
    check_polyline(&scene, &p);
}

#[test]
fn weaving_between_two_circles_uses_an_inner_bitangent() {
    // Circles at (-2, 1) and (2, -1): with r = 1 the line y = 0 just touches
    // both (allowed); with r = 1.2 the path passes below the first and above the
    // second, crossing at the origin (point symmetry) on an inner bitangent.
    let (s, t) = ([-5.0, 0.0], [5.0, 0.0]);
    let scene = Scene { circles: vec![circle(-2.0, 1.0, 1.0), circle(2.0, -1.0, 1.0)], ..Scene::default() };
    close(solve(&scene, s, t).length, 10.0);

    let r = 1.2;
    let scene = Scene { circles: vec![circle(-2.0, 1.0, r), circle(2.0, -1.0, r)], ..Scene::default() };
    let p = solve(&scene, s, t);
    let a = [-2.0, 1.0];
    let tangent = |q: Point| {
        let d = dist(q, a);
        let phi = (q[1] - a[1]).atan2(q[0] - a[0]);
        ((d * d - r * r).sqrt(), phi, (r / d).acos())
    };
    let (ls, phi_s, al_s) = tangent(s);
    let (lo, phi_o, al_o) = tangent([0.0, 0.0]);
    // Lower tangent points: counter-clockwise of the start's direction,
    // clockwise of the origin's.
    let sweep = (phi_o - al_o - (phi_s + al_s)).rem_euclid(TAU);
    close(p.length, 2.0 * (ls + r * sweep + lo));
    check_polyline(&scene, &p);
}

#[test]
fn domain_forces_the_other_side() {
    let scene = Scene { circles: vec![circle(0.0, 0.0, 1.0)], ..Scene::default() };
    let (s, t) = ([-3.0, 0.2], [3.0, 0.2]);
    let d = dist(s, [0.0, 0.0]);
    let theta_s = 0.2f64.atan2(-3.0);
    let alpha = (1.0 / d).acos();
    let up = 2.0 * ((d * d - 1.0).sqrt() + (theta_s - alpha - FRAC_PI_2));
    let down = 2.0 * ((d * d - 1.0).sqrt() + (1.5 * PI - (theta_s + alpha)));
    assert!(up < down);
    close(solve(&scene, s, t).length, up);
    let boxed = Scene { domain: Some(Rect { min: [-5.0, -5.0], max: [5.0, 0.5] }), ..scene };
    let p = solve(&boxed, s, t);
    close(p.length, down);
    assert!(p.polyline.iter().all(|q| q[1] <= 0.5));
    // A circle spanning the whole corridor: proved unreachable.
    let blocked = Scene {
        circles: vec![circle(0.0, 0.0, 2.0)],
        domain: Some(Rect { min: [-5.0, -1.0], max: [5.0, 1.0] }),
        ..Scene::default()
    };
    assert_eq!(shortest_path(&blocked, [-3.0, 0.0], [3.0, 0.0], STEP), Ok(None));
}

#[test]
fn start_on_a_circle_and_bad_inputs() {
    let scene = Scene { circles: vec![circle(0.0, 0.0, 1.0)], ..Scene::default() };
    // Start on the boundary at angle π: the path follows the arc up, then the tangent.
    let p = solve(&scene, [-1.0, 0.0], [3.0, 0.0]);
    close(p.length, (PI - (1.0f64 / 3.0).acos()) + 8f64.sqrt());
    assert!(matches!(
        shortest_path(&scene, [0.5, 0.0], [3.0, 0.0], STEP),
        Err(VisError::EndpointNotFree { which: "start", .. })
    ));
    assert_eq!(shortest_path(&scene, [-3.0, 0.0], [3.0, 0.0], 0.0), Err(VisError::BadArcStep(0.0)));
    let bad = Scene { circles: vec![circle(0.0, 0.0, -1.0)], ..Scene::default() };
    assert_eq!(shortest_path(&bad, [-3.0, 0.0], [3.0, 0.0], STEP), Err(VisError::BadCircle(0)));
    let line =
        Scene { polygons: vec![Polygon { vertices: vec![[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]] }], ..Scene::default() };
    assert_eq!(shortest_path(&line, [-3.0, 0.0], [3.0, 0.0], STEP), Err(VisError::BadPolygon(0)));
}

#[test]
fn overlapping_circles_are_passed_as_one_obstacle() {
    // Two overlapping unit circles at (±0.5, 0): the path hugs the outer arcs
    // and crosses between them on the outer bitangent y = 1.
    let scene = Scene { circles: vec![circle(-0.5, 0.0, 1.0), circle(0.5, 0.0, 1.0)], ..Scene::default() };
    let p = solve(&scene, [-3.5, 0.0], [3.5, 0.0]);
    close(p.length, 2.0 * 8f64.sqrt() + 2.0 * (FRAC_PI_2 - (1.0f64 / 3.0).acos()) + 1.0);
    check_polyline(&scene, &p);
}
