//! Ships seen only within sensor range, and the after-the-fact check against the true world
//! of each moment.

use super::tests::{vehicle, world_2d};
use super::*;
use crate::geom::Vec2;
use crate::vehicle::Vehicle;
use crate::world::Shape;

fn v(x: f64, y: f64) -> Vec3 {
    Vec3::new(x, y, 0.0)
}

/// A ship of radius 40 m crossing the route northwards at 1 m/s from (600, -170) at t = 0:
/// it is on the route (y = 200) at t = 370 s, when a vehicle at 1.5 m/s from (50, 200) on
/// the straight route is at x = 605: a straight run hits it.
fn ship() -> Obstacle {
    Obstacle {
        shape: Shape::Circle { center: Vec2::new(600.0, -170.0), radius: 40.0 },
        velocity: v(0.0, 1.0),
        window: None,
    }
}

fn run(world: &World, changes: &[Change], params: SimParams) -> Simulation {
    super::tests::fly("theta-star", world, changes, params, 1)
}

#[test]
fn a_sighting_fires_where_the_distance_reaches_the_sensor_range() {
    // Vehicle from (0, 0) to (100, 0) over 10 s; a fixed disc of radius 10 at (100, 40):
    // seen at reach 50 + 10 = 60, i.e. where x satisfies (100 - x)^2 + 40^2 = 60^2:
    // x = 100 - sqrt(2000) = 55.28, at t = 5.528 s.
    let disc = Obstacle::fixed(Shape::Circle { center: Vec2::new(100.0, 40.0), radius: 10.0 });
    let world = world_2d();
    let veh = Vehicle { speed: 10.0, ..vehicle() };
    let settings = ModelSettings::default();
    let val = Validator::new(&world, &veh, &settings);
    let mut track = Track::new(Vec3::ZERO, 0.0);
    let events = [Event::sighting(&disc, 50.0)];
    let (k, ahead) = advance(&val, &[Vec3::ZERO, v(100.0, 0.0)], &events, &mut track).unwrap();
    let x = 100.0 - 2000f64.sqrt();
    assert_eq!(k, 0);
    assert!((ahead[0].x - x).abs() < 1e-9, "{:?}", ahead[0]);
    assert!((track.now().1 - x / 10.0).abs() < 1e-9);
    // Already within range: due at once; a box's reach is half its diagonal.
    assert!(due(&events[0], v(90.0, 0.0), 0.0, 0.0));
    assert!(!due(&events[0], v(40.0, 0.0), 0.0, 0.0));
    let b = Shape::Box { min: Vec3::new(0.0, 0.0, 0.0), max: Vec3::new(6.0, 8.0, 0.0) };
    assert_eq!(bounding_radius(&b), 5.0);
}

#[test]
fn a_ship_beyond_sensor_range_is_unknown_until_sighted_then_avoided() {
    let world = World { obstacles: vec![ship()], ..world_2d() };
    let params = SimParams { sensor_range: Some(150.0), ..SimParams::default() };
    let sim = run(&world, &[], params);
    assert!(sim.reached, "{}", sim.reason);
    assert!(sim.track_violations.is_empty(), "{:?}", sim.track_violations);
    assert_eq!(sim.phases[0].seen, vec![false], "the ship is out of range at departure");
    let sighting = sim.phases.iter().find(|p| p.sighted == Some(0)).expect("a sighting phase");
    assert!(sighting.event.contains("sighted"), "{}", sighting.event);
    assert_eq!(sighting.seen, vec![true]);
    let known = sim.known(&world, 0).0;
    assert!(known.obstacles.is_empty());
    // Without a sensor range the ship is known from the start: one phase, no sighting.
    let all = run(&world, &[], SimParams::default());
    assert!(all.reached && all.phases.len() == 1, "{}", all.reason);
}

#[test]
fn the_true_world_check_catches_a_ship_seen_too_late() {
    // A sensor that sees 1 m: the vehicle flies straight into the ship's way and the
    // after-the-fact check, which knows the ship all along, refuses the track.
    let world = World { obstacles: vec![ship()], ..world_2d() };
    let params = SimParams { sensor_range: Some(1.0), ..SimParams::default() };
    let sim = run(&world, &[], params);
    assert!(!sim.reached);
    assert!(!sim.track_violations.is_empty());
    assert!(sim.reason.contains("obstacle 0") || sim.reason.contains("no feasible"), "{}", sim.reason);
}

#[test]
fn a_course_change_holds_from_its_time_in_the_true_world() {
    // The ship turns back south at t = 50 s: it never reaches the route. The old course
    // would have crossed it; the check uses the course in force at each moment.
    let world = World { obstacles: vec![ship()], ..world_2d() };
    let turn = Change {
        trigger: Trigger::AtTime(50.0),
        kind: ChangeKind::ObstacleVelocity { index: 0, velocity: v(0.0, -2.0) },
        random: None,
    };
    let sim = run(&world, &[turn], SimParams::default());
    assert!(sim.reached, "{}", sim.reason);
    assert_eq!(sim.epochs.len(), 2);
    assert_eq!(sim.epochs[1].from, 50.0);
    let before = sim.truth(&world, 0).obstacles[0].shape_at(50.0);
    let after = sim.truth(&world, 1).obstacles[0].shape_at(50.0);
    assert_eq!(before, after, "the ship does not jump at the change");
    assert_eq!(
        sim.truth(&world, 1).obstacles[0].shape_at(100.0),
        Shape::Circle { center: Vec2::new(600.0, -220.0), radius: 40.0 }
    );
}

#[test]
fn a_stop_mid_segment_in_a_varying_current_keeps_the_track_on_its_own_clock() {
    // A vortex makes the ground speed vary along the segment, flown in pieces of 20 m: a
    // segment cut at the stop is flown in pieces of its own, and the stop is placed so that
    // its arrival is exactly the trigger's time.
    let vortex = crate::world::current::LambOseen { x: 500.0, y: 300.0, strength: 2000.0, core_radius: 150.0 };
    let world = World { current: crate::world::Current::Vortices(vec![vortex]), ..world_2d() };
    let settings = ModelSettings { current_step: 20.0, ..ModelSettings::default() };
    let veh = vehicle();
    let val = Validator::new(&world, &veh, &settings);
    let (a, b) = (v(50.0, 200.0), v(950.0, 200.0));
    let mut track = Track::new(a, 0.0);
    let events = [Event::Trigger(Trigger::AtTime(333.0))];
    let (_, ahead) = advance(&val, &[a, b], &events, &mut track).unwrap();
    let (p, t) = track.now();
    assert_eq!(ahead[0], p);
    assert!((t - 333.0).abs() < 1e-6, "{t}");
    assert_eq!(val.for_each_piece(a, p, 0.0, |_| {}).0, t, "the cut segment re-flown arrives at the track's time");
}
