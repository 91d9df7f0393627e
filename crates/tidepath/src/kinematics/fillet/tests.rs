use super::*;
use crate::kinematics::{Pose, TangentPolygon};
use std::f64::consts::{FRAC_PI_2, PI};

fn v(x: f64, y: f64) -> Vec3 {
    Vec3::new(x, y, 0.0)
}

/// The flown curve's horizontal length, arcs exact.
fn flown_length(points: &[Vec3], r: f64) -> f64 {
    let mut len = 0.0;
    for_each_piece(points, r, |p| match p {
        FlownPiece::Line { a, b, .. } => len += (b - a).truncate().length(),
        FlownPiece::Arc(arc) => len += arc.horizontal_length(),
    });
    len
}

#[test]
fn right_angle_with_long_legs_by_hand() {
    let p = [v(0.0, 0.0), v(100.0, 0.0), v(100.0, 100.0)];
    let c = corner(&p, 1, 10.0);
    assert!((c.turn - FRAC_PI_2).abs() < 1e-15 && c.side == 1 && c.fits);
    assert!((c.tangent - 10.0).abs() < 1e-12 && (c.radius - 10.0).abs() < 1e-12);
    let mut arcs = Vec::new();
    for_each_piece(&p, 10.0, |pc| {
        if let FlownPiece::Arc(a) = pc {
            arcs.push(a)
        }
    });
    let a = arcs[0];
    assert!((a.a - v(90.0, 0.0)).length() < 1e-12 && (a.b - v(100.0, 10.0)).length() < 1e-12);
    assert!((a.center - Vec2::new(90.0, 10.0)).length() < 1e-12);
    // Halfway round the fillet: 45 degrees from the centre's south.
    let mid = a.point(0.5);
    let want = Vec2::new(90.0 + 10.0 * (PI / 4.0).cos(), 10.0 - 10.0 * (PI / 4.0).sin());
    assert!((mid.truncate() - want).length() < 1e-12, "{mid:?}");
    assert!((flown_length(&p, 10.0) - (180.0 + 5.0 * PI)).abs() < 1e-9);
}

#[test]
fn a_turn_too_sharp_for_its_legs_flies_the_radius_they_allow() {
    // A right angle needs 10 m of each leg at r = 10; the first leg has 5.
    let p = [v(0.0, 0.0), v(5.0, 0.0), v(5.0, -50.0)];
    let c = corner(&p, 1, 10.0);
    assert!(!c.fits && c.side == -1);
    assert!((c.tangent - 5.0).abs() < 1e-12 && (c.radius - 5.0).abs() < 1e-12);
}

#[test]
fn two_turns_share_their_common_leg_in_proportion() {
    // Left 90 then right 90 on a 10 m leg: each needs 10 m at r = 10, each gets 5.
    let p = [v(0.0, 0.0), v(100.0, 0.0), v(100.0, 10.0), v(200.0, 10.0)];
    let (c1, c2) = (corner(&p, 1, 10.0), corner(&p, 2, 10.0));
    assert!(!c1.fits && !c2.fits);
    assert!((c1.tangent - 5.0).abs() < 1e-12 && (c2.tangent - 5.0).abs() < 1e-12);
    // Unequal turns: 90 degrees (needs r) and 53.13 degrees (needs r/2) on a 12 m leg at
    // r = 10 share 12 as 8 and 4.
    let q = [v(0.0, 0.0), v(100.0, 0.0), v(100.0, 12.0), v(100.0 - 80.0, 12.0 + 60.0)];
    let d2 = 10.0 * (corner(&q, 2, 1e-6).turn * 0.5).tan();
    assert!((d2 - 5.0).abs() < 1e-9, "{d2}");
    assert!((corner(&q, 1, 10.0).tangent - 8.0).abs() < 1e-9 && (corner(&q, 2, 10.0).tangent - 4.0).abs() < 1e-9);
}

#[test]
fn a_straight_through_waypoint_is_no_turn() {
    let p = [v(0.0, 0.0), v(1.0, 0.0), v(2.0, 0.0)];
    let c = corner(&p, 1, 50.0);
    assert!(c.fits && c.turn == 0.0 && c.radius.is_infinite());
    assert!((flown_length(&p, 50.0) - 2.0).abs() < 1e-15);
}

#[test]
fn a_turn_next_to_a_vertical_leg_has_no_room() {
    let p = [
        Vec3::new(0.0, 0.0, -10.0),
        Vec3::new(50.0, 0.0, -10.0),
        Vec3::new(50.0, 0.0, -20.0),
        Vec3::new(50.0, 50.0, -20.0),
    ];
    let (c1, c2) = (corner(&p, 1, 5.0), corner(&p, 2, 5.0));
    assert!(!c1.fits && c1.radius == 0.0 && (c1.turn - FRAC_PI_2).abs() < 1e-15);
    assert!(!c2.fits && c2.radius == 0.0);
    // A vertical leg between legs of one heading turns nothing.
    let q = [
        Vec3::new(0.0, 0.0, -10.0),
        Vec3::new(50.0, 0.0, -10.0),
        Vec3::new(50.0, 0.0, -20.0),
        Vec3::new(90.0, 0.0, -20.0),
    ];
    assert!(corner(&q, 1, 5.0).fits && corner(&q, 2, 5.0).fits);
}

#[test]
fn tangent_polygons_fly_their_arcs_exactly() {
    let r = 25.0;
    let mut tp = TangentPolygon::new(Pose::new(Vec3::new(0.0, 0.0, -40.0), 0.3), r, 0.4);
    tp.straight(30.0, -2.0);
    tp.arc(2.5, -6.0);
    tp.arc(-4.0, 3.0);
    tp.straight(10.0, 0.0);
    let pts = tp.finish();
    for (i, c) in corners(&pts, r).iter().enumerate() {
        assert!(c.fits, "waypoint {i}: {c:?}");
        assert!(c.radius.is_infinite() || (c.radius - r).abs() < 1e-9 * r, "waypoint {i}: {c:?}");
    }
    let want = 30.0 + 2.5 * r + 4.0 * r + 10.0;
    assert!((flown_length(&pts, r) - want).abs() < 1e-9, "{} vs {want}", flown_length(&pts, r));
    // Heights: linear in arc length within each element; -48 at the second arc's start.
    let mut z_at_arc2 = None;
    for_each_piece(&pts, r, |p| {
        if let FlownPiece::Arc(a) = p {
            if a.sweep < 0.0 && z_at_arc2.is_none() {
                z_at_arc2 = Some(a.a.z);
            }
        }
    });
    assert!((z_at_arc2.unwrap() + 48.0).abs() < 1e-9, "{z_at_arc2:?} {pts:?}");
}

#[test]
fn chords_keep_the_sagitta_within_the_tolerance() {
    let p = [v(0.0, 0.0), v(100.0, 0.0), v(100.0, 100.0)];
    let mut arc = None;
    for_each_piece(&p, 30.0, |pc| {
        if let FlownPiece::Arc(a) = pc {
            arc = Some(a)
        }
    });
    let a = arc.unwrap();
    let k = a.chords(0.05);
    assert_eq!(k % 2, 0);
    let delta = FRAC_PI_2 / k as f64;
    assert!(30.0 * (1.0 - (delta * 0.5).cos()) <= 0.05, "k = {k}");
    // One chord fewer (pair) would not do.
    let delta = FRAC_PI_2 / (k - 2) as f64;
    assert!(30.0 * (1.0 - (delta * 0.5).cos()) > 0.05 || k == 2, "k = {k}");
}
