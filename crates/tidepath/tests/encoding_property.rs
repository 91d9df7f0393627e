//! Encodings own their bounds: any vector inside them decodes to waypoints inside the domain
//! and depth band, for any start and goal, and the path always runs from start to goal.

use proptest::prelude::*;
use tidepath::encoding::{Encoding, FreeWaypoints, Posture, Sliced, StepLimit};
use tidepath::geom::{Aabb, Vec3};

fn domain() -> Aabb {
    Aabb::new(Vec3::new(-500.0, 200.0, -300.0), Vec3::new(4500.0, 2200.0, 0.0))
}

fn point() -> impl Strategy<Value = Vec3> {
    (-500.0..4500.0f64, 200.0..2200.0f64, -250.0..-10.0f64).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

/// A vector inside the encoding's box, from unit draws.
fn inside(enc: &dyn Encoding, u: &[f64]) -> Vec<f64> {
    enc.lower().iter().zip(enc.upper()).zip(u.iter().cycle()).map(|((lo, hi), t)| lo + t * (hi - lo)).collect()
}

proptest! {
    #[test]
    fn sliced_waypoints_stay_in_the_domain(
        start in point(),
        goal in point(),
        n in 1usize..25,
        u in prop::collection::vec(0.0..=1.0f64, 1..60),
    ) {
        prop_assume!((goal - start).truncate().length() > 1.0);
        let band = (-280.0, -5.0);
        let enc = Sliced::new(start, goal, n, &domain(), Some(band)).unwrap();
        let path = enc.decode(&inside(&enc, &u));
        prop_assert_eq!(path.len(), n + 2);
        prop_assert_eq!(path[0], start);
        prop_assert_eq!(path[n + 1], goal);
        let d = domain();
        for p in &path[1..=n] {
            prop_assert!(d.contains(*p), "{:?} outside the domain", p);
            prop_assert!(p.z >= band.0 && p.z <= band.1, "{:?} outside the depth band", p);
        }
        // Waypoints advance monotonically along the start-goal axis.
        let axis = (goal - start).truncate().normalize();
        let s: Vec<f64> = path.iter().map(|p| (p.truncate() - start.truncate()).dot(axis)).collect();
        prop_assert!(s.windows(2).all(|w| w[1] > w[0] - 1e-9), "stations not increasing: {:?}", s);
    }

    #[test]
    fn free_waypoints_stay_in_the_domain(
        start in point(),
        goal in point(),
        n in 1usize..25,
        u in prop::collection::vec(0.0..=1.0f64, 1..90),
    ) {
        let enc = FreeWaypoints::new(start, goal, n, &domain(), Some((-280.0, -5.0))).unwrap();
        let path = enc.decode(&inside(&enc, &u));
        prop_assert_eq!(path.len(), n + 2);
        for p in &path {
            prop_assert!(domain().contains(*p), "{:?}", p);
        }
    }
}

/// Every encoding, any axis: waypoint k decodes to `waypoint_at(k, its variables)`, and
/// `set_waypoint` with a decoded waypoint gives back its variables (what lfhh2019's smooth
/// method relies on to write a smoothed path back without moving anything else).
fn waypoints_round_trip(enc: &dyn Encoding, x: &[f64]) -> Result<(), TestCaseError> {
    let path = enc.decode(x);
    let per = enc.waypoint_dim();
    prop_assert_eq!(per * (path.len() - 2), enc.dim());
    let mut y = vec![f64::NAN; x.len()];
    for k in 0..path.len() - 2 {
        let v = &x[per * k..per * (k + 1)];
        prop_assert!((enc.waypoint_at(k, v) - path[k + 1]).length() < 1e-9);
        enc.set_waypoint(&mut y, k, path[k + 1]);
    }
    for (a, b) in x.iter().zip(&y) {
        prop_assert!((a - b).abs() < 1e-6 * (1.0 + a.abs()), "{:?} -> {:?}", x, y);
    }
    Ok(())
}

proptest! {
    #[test]
    fn waypoints_are_set_and_read_one_at_a_time(
        start in point(),
        goal in point(),
        n in 1usize..12,
        axis in 0usize..3,
        two_d in any::<bool>(),
        u in prop::collection::vec(0.0..=1.0f64, 1..40),
    ) {
        use tidepath::encoding::SliceAxis;
        let band = (!two_d).then_some((-280.0, -5.0));
        let axis = [SliceAxis::Path, SliceAxis::X, SliceAxis::Y][axis];
        let d = goal - start;
        prop_assume!(d.x.abs() > 1.0 && d.y.abs() > 1.0);
        let sliced = Sliced::along(start, goal, n, &domain(), band, axis).unwrap();
        waypoints_round_trip(&sliced, &inside(&sliced, &u))?;
        let free = FreeWaypoints::new(start, goal, n, &domain(), band).unwrap();
        waypoints_round_trip(&free, &inside(&free, &u))?;
    }
}

/// Lateral offset of `p` from the start-goal line (left of travel positive) and its height.
fn lateral_and_z(start: Vec3, goal: Vec3, p: Vec3) -> (f64, f64) {
    let axis = (goal - start).truncate().normalize();
    ((p.truncate() - start.truncate()).dot(axis.perp()), p.z)
}

proptest! {
    /// ijs2023 eq. 14: between consecutive planes (the start counting as plane 0) the decoded
    /// path moves at most UB sideways and UR vertically, for any vector at all (inside the box
    /// or not, repaired or not), and repairing changes nothing the decoding would not.
    #[test]
    fn sliced_posture_limits_hold_for_any_vector(
        start in point(),
        goal in point(),
        n in 1usize..40,
        ub in 5.0..800.0f64,
        ur in 1.0..120.0f64,
        raw in prop::collection::vec(-6000.0..6000.0f64, 1..80),
    ) {
        prop_assume!((goal - start).truncate().length() > 100.0);
        let band = (-280.0, -5.0);
        let posture = Posture { lateral: Some(StepLimit::Metres(ub)), vertical: Some(StepLimit::Metres(ur)) };
        let Ok(enc) = Sliced::new(start, goal, n, &domain(), Some(band)).and_then(|e| e.with_posture(posture)) else {
            // Only when the start lies outside the band by more than the steps can reach.
            prop_assume!(false);
            unreachable!()
        };
        let x: Vec<f64> = raw.iter().cycle().take(enc.dim()).copied().collect();
        let path = enc.decode(&x);
        let tol = 1e-9 * (1.0 + ub + ur + 6000.0);
        for w in path[..=n].windows(2) {
            let (l0, z0) = lateral_and_z(start, goal, w[0]);
            let (l1, z1) = lateral_and_z(start, goal, w[1]);
            prop_assert!((l1 - l0).abs() <= ub + tol, "lateral step {} > {}", (l1 - l0).abs(), ub);
            prop_assert!((z1 - z0).abs() <= ur + tol, "vertical step {} > {}", (z1 - z0).abs(), ur);
        }
        for p in &path[1..=n] {
            prop_assert!(domain().contains(*p), "{:?} outside the domain", p);
            prop_assert!(p.z >= band.0 - tol && p.z <= band.1 + tol, "{:?} outside the band", p);
        }
        let mut repaired = x.clone();
        enc.repair(&mut repaired);
        prop_assert_eq!(enc.decode(&repaired), path);
        let mut twice = repaired.clone();
        enc.repair(&mut twice);
        prop_assert_eq!(twice, repaired);
    }
}
