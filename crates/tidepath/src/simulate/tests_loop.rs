//! The whole loop on a small 2-D world: a disc moves onto the route mid-mission and the loop
//! re-plans around it; the same seed gives the same simulation.

use super::tests::world_2d;
use super::*;
use crate::geom::Vec2;
use crate::world::changes::{ChangeKind, Law, RandomShift};
use crate::world::{Obstacle, Shape};

fn v(x: f64, y: f64) -> Vec3 {
    Vec3::new(x, y, 0.0)
}

/// The disc parked off the route at (200, 330).
fn parked() -> World {
    World { obstacles: vec![disc(200.0, 330.0)], ..world_2d() }
}

fn disc(x: f64, y: f64) -> Obstacle {
    Obstacle::fixed(Shape::Circle { center: Vec2::new(x, y), radius: 60.0 })
}

/// At t = 100 s (the vehicle 150 m along the straight route) the disc parked at (200, 330)
/// turns out to sit at (500, 200), across the route.
fn moved_disc(random: Option<RandomShift>) -> Change {
    Change {
        trigger: Trigger::AtTime(100.0),
        kind: ChangeKind::MoveObstacle { index: 0, center: v(500.0, 200.0) },
        random,
    }
}

/// Runs the loop on `world` (the world at departure) with `changes`.
fn run(id: &str, changes: &[Change], world: &World, params: SimParams, seed: u64) -> Simulation {
    super::tests::fly(id, world, changes, params, seed)
}

/// No jump in space or time: times never decrease, no step is faster than the vehicle in
/// still water, and each re-plan starts where and when the vehicle was.
fn assert_continuous(sim: &Simulation) {
    let t = &sim.track;
    for (w, tt) in t.points.windows(2).zip(t.times.windows(2)) {
        assert!(tt[1] >= tt[0], "{tt:?}");
        assert!(w[0].distance(w[1]) <= 1.5 * (tt[1] - tt[0]) * (1.0 + 1e-9) + 1e-9, "{w:?} {tt:?}");
    }
    for p in sim.phases.iter().skip(1) {
        let k = t.times.iter().rposition(|&x| x <= p.time).unwrap();
        assert_eq!((t.points[k], t.times[k]), (p.position, p.time));
        if let Some(r) = p.replan.as_ref().filter(|r| r.status.is_success()) {
            assert!(r.piece[0].distance(p.position) < 1e-6, "{:?} vs {:?}", r.piece[0], p.position);
        }
    }
}

#[test]
fn the_loop_replans_around_a_disc_that_moves_onto_the_route() {
    let world = parked();
    for id in ["astar", "theta-star"] {
        let sim = run(id, &[moved_disc(None)], &world, SimParams::default(), 1);
        assert!(sim.reached && sim.complete, "{id}: {}", sim.reason);
        assert!(sim.track_violations.is_empty(), "{id}: {:?}", sim.track_violations);
        assert_eq!(sim.phases.len(), 2);
        let p = &sim.phases[1];
        // 150 m along the route (a raster route may wander a cell off the straight line).
        assert_eq!(p.time, 100.0);
        assert!(p.position.distance(v(200.0, 200.0)) < 5.0, "{id}: {:?}", p.position);
        assert!(p.route_problem.is_some(), "the disc blocks the old route");
        let r = p.replan.as_ref().unwrap();
        assert!(r.status.is_success() && !r.warm, "{id}: {r:?}");
        assert_eq!(*sim.track.points.last().unwrap(), v(950.0, 200.0));
        assert!(sim.track.points.iter().any(|q| (q.y - 200.0).abs() > 60.0), "{id}: the track goes round the disc");
        assert_continuous(&sim);
    }
}

#[test]
fn a_change_that_closes_the_way_ends_the_mission_naming_the_phase() {
    // A wall across the whole domain in front of the vehicle.
    let wall = Obstacle::fixed(Shape::Box { min: v(590.0, -10.0) - Vec3::Z, max: v(610.0, 410.0) + Vec3::Z });
    let close = Change { trigger: Trigger::AfterDistance(300.0), kind: ChangeKind::AddObstacle(wall), random: None };
    let sim = run("theta-star", &[moved_disc(None), close], &parked(), SimParams::default(), 1);
    assert!(!sim.reached && sim.complete);
    assert!(sim.reason.starts_with("phase 2: no feasible window up to the goal"), "{}", sim.reason);
    assert_eq!(sim.phases.len(), 3);
    // The route left is where the vehicle stands, 300 m along.
    assert_eq!(sim.route[0], sim.phases[2].position);
    assert!((sim.track.travelled - 300.0).abs() < 1e-6, "{}", sim.track.travelled);
}

#[test]
fn the_same_seed_gives_the_same_simulation() {
    let shift = RandomShift {
        law: Law::Gaussian,
        scale: 80.0,
        max_draws: RandomShift::LFHH2019_MAX_DRAWS,
        from_current: false,
    };
    let changes = [moved_disc(Some(shift))];
    let truth = parked();
    let params = SimParams { policy: ReplanPolicy::Always, window: 1, ..SimParams::default() };
    let strip = |mut s: Simulation| {
        s.phases.iter_mut().filter_map(|p| p.replan.as_mut()).for_each(|r| r.planning_s = 0.0);
        s
    };
    let a = strip(run("theta-star", &changes, &truth, params, 7));
    let b = strip(run("theta-star", &changes, &truth, params, 7));
    assert_eq!(a, b);
    // A randomised planner warm-started from the old route repeats too.
    let r = strip(run("rrt-star", &changes, &truth, params, 7));
    assert_eq!(r, strip(run("rrt-star", &changes, &truth, params, 7)));
    assert!(r.phases[1].replan.as_ref().unwrap().warm, "rrt-star takes warm starts");
    assert!(a.complete && a.phases.len() == 2, "{}", a.reason);
    assert!(a.phases[1].replan.is_some(), "replanned at every change");
    let c = strip(run("theta-star", &changes, &truth, params, 8));
    assert_ne!(a.phases[1].changes, c.phases[1].changes, "another seed draws another move");
}

#[test]
fn changes_with_the_same_trigger_are_one_event_with_one_replan() {
    // lfhh2019 moves every obstacle and vortex at each change: all of them are one event.
    // Two discs parked off the route move onto it at t = 100 s (listed apart, with a change
    // of another trigger between them); obstacle 0 moves back off it after 500 m.
    let world = World { obstacles: vec![disc(200.0, 330.0), disc(700.0, 330.0)], ..world_2d() };
    let change =
        |trigger, index, c| Change { trigger, kind: ChangeKind::MoveObstacle { index, center: c }, random: None };
    let changes = [
        change(Trigger::AtTime(100.0), 0, v(450.0, 200.0)),
        change(Trigger::AfterDistance(500.0), 0, v(200.0, 330.0)),
        change(Trigger::AtTime(100.0), 1, v(750.0, 200.0)),
    ];
    let params = SimParams { policy: ReplanPolicy::Always, ..SimParams::default() };
    let sim = run("theta-star", &changes, &world, params, 1);
    assert!(sim.reached && sim.complete, "{}", sim.reason);
    assert!(sim.track_violations.is_empty(), "{:?}", sim.track_violations);
    // Departure, the t = 100 s event (both moves), the 500 m event: three phases, three plans.
    assert_eq!(sim.phases.len(), 3, "{:?}", sim.phases.iter().map(|p| &p.event).collect::<Vec<_>>());
    assert_eq!(sim.phases.iter().filter(|p| p.replan.is_some()).count(), 3);
    let p = &sim.phases[1];
    assert_eq!((p.trigger, p.time), (Some(Trigger::AtTime(100.0)), 100.0));
    let moved: Vec<&ChangeKind> = p.changes.iter().map(|c| &c.resolved).collect();
    assert_eq!(moved, [&changes[0].kind, &changes[2].kind], "in the scenario's order");
    assert_eq!(p.event, "2 changes: 2 obstacles moved");
    // The one re-plan already knew both discs on the route, and went round both.
    let (known, _) = sim.known(&world, 1);
    let centres: Vec<Vec3> = known.obstacles.iter().map(|o| crate::world::changes::center(&o.shape)).collect();
    assert_eq!(centres, [v(450.0, 200.0), v(750.0, 200.0)]);
    assert!(p.route_problem.is_some());
    assert!(p.replan.as_ref().unwrap().status.is_success());
    // The track passes both discs (x = 450 and 750) off the line y = 200.
    for x in [450.0, 750.0] {
        let k = sim.track.points.iter().position(|q| q.x > x).unwrap();
        let (a, b) = (sim.track.points[k - 1], sim.track.points[k]);
        let y = a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
        assert!((y - 200.0).abs() > 60.0, "at x = {x} the track is at y = {y}");
    }
    // One epoch per event: departure, t = 100 s, the 500 m mark.
    assert_eq!(sim.epochs.len(), 3);
    assert_eq!(sim.phases[2].trigger, Some(Trigger::AfterDistance(500.0)));
    assert_eq!(sim.phases[2].changes.len(), 1);
    assert_continuous(&sim);
}
