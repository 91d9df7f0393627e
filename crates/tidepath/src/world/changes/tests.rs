//! Hand-computed checks of world changes.

use super::*;
use crate::geom::Aabb;
use crate::rng::run_rng;
use crate::world::current::LambOseen;
use crate::world::{Dims, Terrain};

fn world() -> World {
    World {
        waves: Default::default(),
        bounds: Aabb::new(Vec3::ZERO, Vec3::new(1000.0, 1000.0, 0.0)),
        dims: Dims::Two,
        terrain: Terrain::None,
        obstacles: vec![
            Obstacle {
                shape: Shape::Circle { center: Vec2::ZERO, radius: 10.0 },
                velocity: Vec3::new(1.0, 0.0, 0.0),
                window: None,
            },
            Obstacle::fixed(Shape::Circle { center: Vec2::new(500.0, 500.0), radius: 50.0 }),
        ],
        current: Current::Vortices(vec![LambOseen { x: 100.0, y: 100.0, strength: 2.0, core_radius: 50.0 }]),
        frame: None,
    }
}

fn fixed(kind: ChangeKind) -> Change {
    Change { trigger: Trigger::AtTime(0.0), kind, random: None }
}

fn apply(c: &Change, w: &mut World, t: f64) -> Result<AppliedChange> {
    c.apply(w, t, Vec3::new(900.0, 900.0, 0.0), Vec3::new(950.0, 50.0, 0.0), 5.0, &mut run_rng(1, 0))
}

fn circle_center(o: &Obstacle, t: f64) -> Vec2 {
    match o.shape_at(t) {
        Shape::Circle { center, .. } => center,
        s => panic!("{s:?}"),
    }
}

#[test]
fn a_moved_moving_obstacle_is_at_its_new_centre_at_the_change_time() {
    // At t = 20 the disc moving east at 1 m/s must be at (50, 10): its t = 0 place is
    // (50 - 20, 10) = (30, 10), and at t = 30 it is at (60, 10).
    let mut w = world();
    let c = fixed(ChangeKind::MoveObstacle { index: 0, center: Vec3::new(50.0, 10.0, 0.0) });
    let a = apply(&c, &mut w, 20.0).unwrap();
    assert_eq!(circle_center(&w.obstacles[0], 0.0), Vec2::new(30.0, 10.0));
    assert_eq!(circle_center(&w.obstacles[0], 20.0), Vec2::new(50.0, 10.0));
    assert_eq!(circle_center(&w.obstacles[0], 30.0), Vec2::new(60.0, 10.0));
    assert_eq!(w.obstacles[0].velocity, Vec3::new(1.0, 0.0, 0.0));
    assert_eq!(a.description, "obstacle 0 moved to [50.0, 10.0, 0.0] at t = 20.0 s");
    assert_eq!((a.draws, a.skipped), (0, None));
}

#[test]
fn a_new_velocity_keeps_the_place_at_the_change_time() {
    // At t = 10 the disc is at (10, 0); turning north at 2 m/s, its t = 0 reference is
    // (10, 0) - (0, 2) * 10 = (10, -20), and at t = 15 it is at (10, 10).
    let mut w = world();
    let c = fixed(ChangeKind::ObstacleVelocity { index: 0, velocity: Vec3::new(0.0, 2.0, 0.0) });
    apply(&c, &mut w, 10.0).unwrap();
    assert_eq!(circle_center(&w.obstacles[0], 0.0), Vec2::new(10.0, -20.0));
    assert_eq!(circle_center(&w.obstacles[0], 10.0), Vec2::new(10.0, 0.0));
    assert_eq!(circle_center(&w.obstacles[0], 15.0), Vec2::new(10.0, 10.0));
}

#[test]
fn obstacles_appear_and_disappear_and_vortices_change() {
    let mut w = world();
    let ship = Obstacle::fixed(Shape::Circle { center: Vec2::new(200.0, 300.0), radius: 20.0 });
    let a = apply(&fixed(ChangeKind::AddObstacle(ship.clone())), &mut w, 5.0).unwrap();
    assert_eq!(w.obstacles.len(), 3);
    assert_eq!(a.description, "obstacle 2 appeared at [200.0, 300.0, 0.0] at t = 5.0 s");
    apply(&fixed(ChangeKind::RemoveObstacle { index: 0 }), &mut w, 5.0).unwrap();
    assert_eq!(w.obstacles[1], ship, "later obstacles shift down by one");
    let e = apply(&fixed(ChangeKind::RemoveObstacle { index: 2 }), &mut w, 5.0).unwrap_err().to_string();
    assert_eq!(e, "changes: obstacle 2 does not exist (the world has 2 obstacles at this change)");

    apply(&fixed(ChangeKind::MoveVortex { index: 0, center: Vec2::new(400.0, 600.0) }), &mut w, 1.0).unwrap();
    apply(&fixed(ChangeKind::VortexStrength { index: 0, strength: -3.0 }), &mut w, 1.0).unwrap();
    assert_eq!(w.current, Current::Vortices(vec![LambOseen { x: 400.0, y: 600.0, strength: -3.0, core_radius: 50.0 }]));
    let forecast = Current::Uniform(Vec3::new(0.3, 0.0, 0.0));
    apply(&fixed(ChangeKind::ReplaceCurrent(forecast.clone())), &mut w, 1.0).unwrap();
    assert_eq!(w.current, forecast);
    let e = apply(&fixed(ChangeKind::MoveVortex { index: 0, center: Vec2::ZERO }), &mut w, 1.0).unwrap_err();
    assert!(e.to_string().contains("needs a current made of vortices"), "{e}");
}

fn random_move(index: usize, center: Vec3, law: Law, scale: f64) -> Change {
    Change {
        trigger: Trigger::AfterDistance(100.0),
        kind: ChangeKind::MoveObstacle { index, center },
        random: Some(RandomShift { law, scale, max_draws: RandomShift::LFHH2019_MAX_DRAWS, from_current: false }),
    }
}

/// A disc of radius 50 aimed at the vehicle, displaced by a draw of scale 80: many draws land
/// on the vehicle or the goal; the applied ones never do, stay in the domain and repeat
/// under the same seed.
#[test]
fn random_moves_never_cover_the_vehicle_or_the_goal() {
    let (vehicle, goal, safety) = (Vec3::new(300.0, 300.0, 0.0), Vec3::new(340.0, 300.0, 0.0), 5.0);
    let mut redrawn = 0;
    for law in [Law::Gaussian, Law::Uniform] {
        for seed in 0..200 {
            let c = random_move(1, Vec3::new(320.0, 300.0, 0.0), law, 80.0);
            let mut w = world();
            let mut rng = run_rng(seed, 0);
            let a = c.apply(&mut w, 7.0, vehicle, goal, safety, &mut rng).unwrap();
            assert!(a.skipped.is_none());
            redrawn += (a.draws > 1) as u32;
            let o = &w.obstacles[1];
            assert!(!o.contains(vehicle, 7.0, safety) && !o.contains(goal, 7.0, safety), "seed {seed}");
            let c0 = circle_center(o, 7.0);
            assert!(c0.cmpge(Vec2::ZERO).all() && c0.cmple(Vec2::splat(1000.0)).all());
            assert_eq!(a.resolved, ChangeKind::MoveObstacle { index: 1, center: c0.extend(0.0) });
            let mut again = world();
            c.apply(&mut again, 7.0, vehicle, goal, safety, &mut run_rng(seed, 0)).unwrap();
            assert_eq!(again.obstacles, w.obstacles);
        }
    }
    assert!(redrawn > 20, "the test must exercise redraws, got {redrawn}");
}

#[test]
fn a_change_that_always_covers_is_skipped_and_clipped_to_the_domain() {
    // Scale 0: every draw puts the disc on the vehicle; after 100 draws the world is unchanged.
    let vehicle = Vec3::new(320.0, 300.0, 0.0);
    let c = random_move(1, vehicle, Law::Uniform, 0.0);
    let mut w = world();
    let a = c.apply(&mut w, 0.0, vehicle, Vec3::new(950.0, 50.0, 0.0), 5.0, &mut run_rng(3, 0)).unwrap();
    assert_eq!(a.draws, 100);
    assert!(a.skipped.as_deref().unwrap().contains("all 100 random draws"), "{a:?}");
    assert_eq!(w.obstacles, world().obstacles);
    // A centre pushed past the domain's corner is clipped onto it.
    let c = random_move(1, Vec3::new(990.0, 5.0, 0.0), Law::Uniform, 0.0);
    let corner = Change { kind: ChangeKind::MoveObstacle { index: 1, center: Vec3::new(2000.0, -50.0, 0.0) }, ..c };
    let mut w = world();
    apply(&corner, &mut w, 0.0).unwrap();
    assert_eq!(circle_center(&w.obstacles[1], 0.0), Vec2::new(1000.0, 0.0));
    let bad = Change { kind: ChangeKind::RemoveObstacle { index: 0 }, ..corner };
    assert!(apply(&bad, &mut world(), 0.0).unwrap_err().to_string().contains("needs a change that sets a centre"));
}

#[test]
fn draws_follow_the_stated_law() {
    // Uniform on [-2, 2]: every draw inside; Gaussian with sd 2: sample variance near 4.
    let mut rng = run_rng(9, 0);
    let u = RandomShift { law: Law::Uniform, scale: 2.0, max_draws: 1, from_current: false };
    assert!((0..1000).map(|_| u.draw(&mut rng, true)).all(|d| d.abs().max_element() <= 2.0));
    let g = RandomShift { law: Law::Gaussian, ..u };
    let xs: Vec<f64> = (0..20_000).map(|_| g.draw(&mut rng, false)).flat_map(|d| [d.x, d.y]).collect();
    let var = xs.iter().map(|x| x * x).sum::<f64>() / xs.len() as f64;
    assert!((var - 4.0).abs() < 0.15, "{var}");
    assert_eq!(g.draw(&mut rng, false).z, 0.0);
}

/// With `from_current`, a uniform draw of scale 2 m steps from where the obstacle or vortex is
/// at the change's time, not from the written centre: two changes add up. Draw by draw: each
/// axis is 2 (2u - 1) for the stream's u, so the steps are recomputed here from the same seed.
#[test]
fn random_steps_from_the_current_centre_add_up() {
    let step = |from_current| RandomShift { law: Law::Uniform, scale: 2.0, max_draws: 1, from_current };
    let mut w = world();
    let mut rng = run_rng(5, 0);
    let (vehicle, goal) = (Vec3::new(900.0, 900.0, 0.0), Vec3::new(950.0, 50.0, 0.0));
    let written = Vec3::new(1.0, 1.0, 0.0);
    let walk = Change {
        trigger: Trigger::AtTime(0.0),
        kind: ChangeKind::MoveObstacle { index: 1, center: written },
        random: Some(step(true)),
    };
    walk.apply(&mut w, 0.0, vehicle, goal, 0.0, &mut rng).unwrap();
    walk.apply(&mut w, 0.0, vehicle, goal, 0.0, &mut rng).unwrap();
    let mut again = run_rng(5, 0);
    let d1 = step(true).draw(&mut again, false);
    let d2 = step(true).draw(&mut again, false);
    let want = Vec2::new(500.0, 500.0) + (d1 + d2).truncate();
    assert!((circle_center(&w.obstacles[1], 0.0) - want).length() < 1e-9, "{:?}", w.obstacles[1]);
    assert!(d1.length() > 0.0 && d2.length() > 0.0);
    // The moving disc: at t = 10 it is at (10, 0); the step starts there (clipped to y >= 0).
    let mut w = world();
    let c = Change { kind: ChangeKind::MoveObstacle { index: 0, center: written }, ..walk.clone() };
    c.apply(&mut w, 10.0, vehicle, goal, 0.0, &mut run_rng(6, 0)).unwrap();
    let d = step(true).draw(&mut run_rng(6, 0), false);
    let want = (Vec2::new(10.0, 0.0) + d.truncate()).max(Vec2::ZERO);
    assert!((circle_center(&w.obstacles[0], 10.0) - want).length() < 1e-9);
    // A vortex steps from its centre (100, 100); without from_current from the written one.
    let mut w = world();
    let v = Change { kind: ChangeKind::MoveVortex { index: 0, center: Vec2::ZERO }, ..walk.clone() };
    v.apply(&mut w, 0.0, vehicle, goal, 0.0, &mut run_rng(7, 0)).unwrap();
    let d = step(true).draw(&mut run_rng(7, 0), false).truncate();
    let Current::Vortices(vs) = &w.current else { panic!() };
    assert!((Vec2::new(vs[0].x, vs[0].y) - (Vec2::new(100.0, 100.0) + d)).length() < 1e-9);
    let mut w = world();
    let fixed_base = Change { random: Some(step(false)), ..walk };
    fixed_base.apply(&mut w, 0.0, vehicle, goal, 0.0, &mut run_rng(8, 0)).unwrap();
    let d = step(false).draw(&mut run_rng(8, 0), false);
    assert!((circle_center(&w.obstacles[1], 0.0) - (written + d).truncate().max(Vec2::ZERO)).length() < 1e-9);
}
