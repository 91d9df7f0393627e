use super::*;

const TOL: f64 = 1e-9;

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= TOL * (1.0 + b.abs())
}

fn v(x: f64, y: f64, z: f64) -> Vec3 {
    Vec3::new(x, y, z)
}

fn sphere() -> Obstacle {
    Obstacle::fixed(Shape::Sphere { center: v(0.0, 0.0, -10.0), radius: 2.0 })
}

#[test]
fn sphere_segment_distance_hand_cases() {
    let o = sphere();
    // Passing 5 m above the centre: clearance 3.
    let (a, b) = (v(-10.0, 0.0, -5.0), v(10.0, 0.0, -5.0));
    assert!(close(o.segment_clearance(a, b, 0.0, 1.0), 3.0));
    assert!(o.segment_hits(a, b, 0.0, 1.0, 3.5));
    assert!(!o.segment_hits(a, b, 0.0, 1.0, 2.5));
    // Touching the top tangentially: distance 0, a hit even with zero margin.
    let (a, b) = (v(-10.0, 0.0, -8.0), v(10.0, 0.0, -8.0));
    assert_eq!(o.segment_clearance(a, b, 0.0, 1.0), 0.0);
    assert!(o.segment_hits(a, b, 0.0, 1.0, 0.0));
    // Piercing through the centre.
    let (a, b) = (v(0.0, -10.0, -10.0), v(0.0, 10.0, -10.0));
    assert_eq!(o.segment_clearance(a, b, 0.0, 1.0), 0.0);
    assert!(o.segment_hits(a, b, 0.0, 1.0, 0.0));
    // Segment ending short of the sphere: closest point is the end, 3 - 2 = 1 away.
    let (a, b) = (v(-10.0, 0.0, -10.0), v(-3.0, 0.0, -10.0));
    assert!(close(o.segment_clearance(a, b, 0.0, 1.0), 1.0));
    // Degenerate zero-length segment: point distance sqrt(3^2 + 4^2) - 2 = 3.
    let p = v(3.0, 4.0, -10.0);
    assert!(close(o.segment_clearance(p, p, 0.0, 1.0), 3.0));
    assert!(o.contains(p, 0.0, 3.1) && !o.contains(p, 0.0, 2.9));
}

#[test]
fn circle_ignores_depth() {
    let o = Obstacle::fixed(Shape::Circle { center: Vec2::new(5.0, 5.0), radius: 1.0 });
    // Horizontal distance from (5,5) to the line y = 8 is 3: clearance 2, whatever the depth.
    let (a, b) = (v(0.0, 8.0, -1000.0), v(10.0, 8.0, 50.0));
    assert!(close(o.segment_clearance(a, b, 0.0, 1.0), 2.0));
    assert!(!o.segment_hits(a, b, 0.0, 1.0, 1.9));
    assert!(o.segment_hits(a, b, 0.0, 1.0, 2.1));
    // A vertical segment through the circle.
    assert!(o.segment_hits(v(5.5, 5.0, -1e6), v(5.5, 5.0, 1e6), 0.0, 1.0, 0.0));
    // Zero-length segment on the rim.
    let p = v(6.0, 5.0, 3.0);
    assert!(o.segment_hits(p, p, 0.0, 0.0, 0.0));
    assert_eq!(o.segment_clearance(p, p, 0.0, 0.0), 0.0);
}

#[test]
fn infinite_cylinder_equals_circle() {
    let cyl = Obstacle::fixed(Shape::Cylinder {
        center: Vec2::new(5.0, 5.0),
        radius: 1.0,
        z_min: f64::NEG_INFINITY,
        z_max: f64::INFINITY,
    });
    let (a, b) = (v(0.0, 8.0, -1000.0), v(10.0, 8.0, 50.0));
    assert!(close(cyl.segment_clearance(a, b, 0.0, 1.0), 2.0));
    assert!(cyl.segment_hits(v(5.0, 0.0, -3.0), v(5.0, 10.0, -3.0), 0.0, 1.0, 0.0));
}

fn finite_cylinder() -> Obstacle {
    Obstacle::fixed(Shape::Cylinder { center: Vec2::ZERO, radius: 2.0, z_min: -20.0, z_max: -10.0 })
}

#[test]
fn finite_cylinder_hand_cases() {
    let o = finite_cylinder();
    // Horizontal pass beside the side wall, inside the slab: 5 - 2 = 3.
    assert!(close(o.segment_clearance(v(-10.0, 5.0, -15.0), v(10.0, 5.0, -15.0), 0.0, 1.0), 3.0));
    // Horizontal pass over the top cap, 4 above it: 4.
    assert!(close(o.segment_clearance(v(-10.0, 0.0, -6.0), v(10.0, 0.0, -6.0), 0.0, 1.0), 4.0));
    // Pass above and beside: nearest point is the rim; 3 out and 4 up -> 5.
    let (a, b) = (v(-10.0, 5.0, -6.0), v(10.0, 5.0, -6.0));
    assert!(close(o.segment_clearance(a, b, 0.0, 1.0), 5.0));
    assert!(o.segment_hits(a, b, 0.0, 1.0, 5.01));
    assert!(!o.segment_hits(a, b, 0.0, 1.0, 4.99));
    // Slanted segment above the cap, moving away from the rim point (2, 0, -10) along the
    // 45-degree line through it: closest at its start, sqrt(1 + 1) from the rim.
    let (a, b) = (v(3.0, 0.0, -9.0), v(7.0, 0.0, -5.0));
    assert!(close(o.segment_clearance(a, b, 0.0, 1.0), 2f64.sqrt()));
    // Piercing the cap vertically.
    assert!(o.segment_hits(v(0.5, 0.5, 0.0), v(0.5, 0.5, -12.0), 0.0, 1.0, 0.0));
    assert_eq!(o.segment_clearance(v(0.5, 0.5, 0.0), v(0.5, 0.5, -12.0), 0.0, 1.0), 0.0);
    // Vertical segment beside the cylinder, spanning its height: 3 away.
    assert!(close(o.segment_clearance(v(5.0, 0.0, 0.0), v(5.0, 0.0, -30.0), 0.0, 1.0), 3.0));
    // Degenerate segment below the bottom cap: 1 below and 1 out -> sqrt(2).
    let p = v(3.0, 0.0, -21.0);
    assert!(close(o.segment_clearance(p, p, 0.0, 1.0), 2f64.sqrt()));
    assert!(o.contains(p, 0.0, 1.5) && !o.contains(p, 0.0, 1.4));
}

#[test]
fn box_hand_cases() {
    let o = Obstacle::fixed(Shape::Box { min: v(0.0, 0.0, -10.0), max: v(4.0, 2.0, -5.0) });
    // Parallel to x, 3 north of the box, inside its depth range: 3.
    assert!(close(o.segment_clearance(v(-5.0, 5.0, -7.0), v(10.0, 5.0, -7.0), 0.0, 1.0), 3.0));
    // Parallel to x, 3 north and 4 above: 5 (edge distance).
    let (a, b) = (v(-5.0, 5.0, -1.0), v(10.0, 5.0, -1.0));
    assert!(close(o.segment_clearance(a, b, 0.0, 1.0), 5.0));
    assert!(o.segment_hits(a, b, 0.0, 1.0, 5.1) && !o.segment_hits(a, b, 0.0, 1.0, 4.9));
    // Towards a corner, stopping short: from (8, 6, 0) to (5, 3, -4): nearest corner
    // (4, 2, -5) at distance sqrt(1 + 1 + 1).
    assert!(close(o.segment_clearance(v(8.0, 6.0, 0.0), v(5.0, 3.0, -4.0), 0.0, 1.0), 3f64.sqrt()));
    // Passing a vertical edge diagonally: the line x + y = 8 at z = -7 is |4 + 2 - 8| / sqrt 2
    // from the edge x = 4, y = 2.
    assert!(close(o.segment_clearance(v(8.0, 0.0, -7.0), v(0.0, 8.0, -7.0), 0.0, 1.0), 2f64.sqrt()));
    // Touching a face.
    assert_eq!(o.segment_clearance(v(-1.0, 2.0, -7.0), v(5.0, 2.0, -7.0), 0.0, 1.0), 0.0);
    assert!(o.segment_hits(v(-1.0, 2.0, -7.0), v(5.0, 2.0, -7.0), 0.0, 1.0, 0.0));
    // Piercing.
    assert!(o.segment_hits(v(2.0, -3.0, -7.0), v(2.0, 5.0, -7.0), 0.0, 1.0, 0.0));
    // Degenerate point inside and outside.
    assert_eq!(o.segment_clearance(v(1.0, 1.0, -6.0), v(1.0, 1.0, -6.0), 0.0, 1.0), 0.0);
    assert!(close(o.segment_clearance(v(1.0, 1.0, 0.0), v(1.0, 1.0, 0.0), 0.0, 1.0), 5.0));
}

#[test]
fn moving_sphere_changes_the_answer() {
    // A fixed sphere at the origin blocks the segment along x at y = 0.
    let shape = Shape::Sphere { center: v(0.0, 0.0, -10.0), radius: 1.0 };
    let (a, b) = (v(-10.0, 0.0, -10.0), v(10.0, 0.0, -10.0));
    assert!(Obstacle::fixed(shape.clone()).segment_hits(a, b, 0.0, 10.0, 0.0));
    // Moving north at 1 m/s: at t = 5 (when we pass x = 0) it is at y = 5, 4 m clear.
    let moving = Obstacle { shape: shape.clone(), velocity: v(0.0, 1.0, 0.0), window: None };
    assert!(!moving.segment_hits(a, b, 0.0, 10.0, 0.0));
    // In the sphere's frame the segment runs from (-10, 0) to (10, -10).
    let c = moving.segment_clearance(a, b, 0.0, 10.0);
    // Relative positions p(s) = (-10 + 20 s, -10 s): distance^2 = (20 s - 10)^2 + 100 s^2,
    // minimised at s = 0.4: 4 + 16 = 20 -> sqrt(20) = 4.4721.
    assert!(close(c, 20f64.sqrt() - 1.0), "{c}");
    // And vice versa: a sphere starting 5 m south and moving north crosses our path just
    // as we get there.
    let incoming = Obstacle {
        shape: Shape::Sphere { center: v(0.0, -5.0, -10.0), radius: 1.0 },
        velocity: v(0.0, 1.0, 0.0),
        window: None,
    };
    assert!(!Obstacle::fixed(incoming.shape.clone()).segment_hits(a, b, 0.0, 10.0, 0.0));
    assert!(incoming.segment_hits(a, b, 0.0, 10.0, 0.0));
    assert_eq!(incoming.segment_clearance(a, b, 0.0, 10.0), 0.0);
    assert!(incoming.contains(v(0.0, 0.0, -10.0), 5.0, 0.0));
    assert!(!incoming.contains(v(0.0, 0.0, -10.0), 0.0, 0.0));
    assert_eq!(incoming.shape_at(5.0), Shape::Sphere { center: v(0.0, 0.0, -10.0), radius: 1.0 });
}

#[test]
fn non_finite_times_are_conservative_for_moving_obstacles_only() {
    let shape = Shape::Sphere { center: v(100.0, 100.0, 100.0), radius: 1.0 };
    let (a, b) = (v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0));
    let fixed = Obstacle::fixed(shape.clone());
    assert!(!fixed.segment_hits(a, b, 0.0, f64::INFINITY, 0.0));
    let moving = Obstacle { shape, velocity: v(0.0, 0.0, 1.0), window: None };
    assert!(moving.segment_hits(a, b, 0.0, f64::INFINITY, 0.0));
    assert_eq!(moving.segment_clearance(a, b, f64::NAN, 1.0), 0.0);
    assert!(moving.contains(a, f64::INFINITY, 0.0));
    // NaN points are hits, unless their finite coordinates alone keep them away.
    assert!(fixed.segment_hits(Vec3::NAN, b, 0.0, 1.0, 0.0));
    assert!(fixed.segment_hits(v(f64::NAN, 100.0, 100.0), v(0.0, 100.0, 100.0), 0.0, 1.0, 0.0));
    assert!(!fixed.segment_hits(v(f64::NAN, 0.0, 0.0), b, 0.0, 1.0, 0.0));
}

#[test]
fn translated_cylinder_and_circle() {
    let o = Obstacle {
        shape: Shape::Cylinder { center: Vec2::ZERO, radius: 1.0, z_min: -5.0, z_max: f64::INFINITY },
        velocity: v(1.0, 0.0, -1.0),
        window: None,
    };
    assert_eq!(
        o.shape_at(2.0),
        Shape::Cylinder { center: Vec2::new(2.0, 0.0), radius: 1.0, z_min: -7.0, z_max: f64::INFINITY }
    );
    let c =
        Obstacle { shape: Shape::Circle { center: Vec2::ZERO, radius: 1.0 }, velocity: v(0.0, 2.0, 5.0), window: None };
    assert_eq!(c.shape_at(1.0), Shape::Circle { center: Vec2::new(0.0, 2.0), radius: 1.0 });
}

#[test]
fn an_obstacle_with_a_time_window_exists_only_inside_it() {
    // A disc of radius 10 at (50, 0), moving east at 1 m/s, present for t in [100, 200]:
    // at t = 100 it is at (150, 0).
    let o = Obstacle {
        shape: Shape::Circle { center: Vec2::new(50.0, 0.0), radius: 10.0 },
        velocity: Vec3::new(1.0, 0.0, 0.0),
        window: Some((100.0, 200.0)),
    };
    assert!(!o.is_fixed());
    let at = |x: f64| Vec3::new(x, 0.0, 0.0);
    assert!(o.contains(at(150.0), 100.0, 0.0) && !o.contains(at(150.0), 99.0, 0.0));
    assert!(!o.contains(at(260.0), 210.0, 0.0), "gone after its window");
    // A vehicle crossing x = 150 north to south at t = 50..150: it passes (150, 0) at
    // t = 100, when the disc is there: a hit.
    let (a, b) = (Vec3::new(150.0, 50.0, 0.0), Vec3::new(150.0, -50.0, 0.0));
    assert!(o.segment_hits(a, b, 50.0, 150.0, 0.0));
    // The same crossing at t = 0..100 passes (150, 0) at t = 50, before the window: the
    // disc, were it there, would be at (100, 0); clipped to [100, 100] the vehicle is at
    // (150, -50): clear.
    assert!(!o.segment_hits(a, b, 0.0, 100.0, 0.0));
    assert!(o.segment_clearance(a, b, 0.0, 100.0) > 30.0);
    // Entirely before or after the window: nothing to meet.
    assert!(!o.segment_hits(at(0.0), at(300.0), 0.0, 99.0, 1e9));
    assert_eq!(o.segment_clearance(at(0.0), at(300.0), 201.0, 300.0), f64::INFINITY);
    assert!(!o.may_come_within(at(-1e6), at(1e6), 0.0, 99.0));
    // A fixed obstacle is one without velocity or window.
    assert!(Obstacle::fixed(Shape::Circle { center: Vec2::ZERO, radius: 1.0 }).is_fixed());
}
