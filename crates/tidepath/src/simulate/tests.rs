//! Hand-computed checks of the loop's parts: the window rule, splicing, flying to a trigger.

use super::*;
use crate::geom::Aabb;
use crate::vehicle::Vehicle;
use crate::world::{Current, Dims, Terrain};

pub(super) fn world_2d() -> World {
    World {
        waves: Default::default(),
        bounds: Aabb::new(Vec3::ZERO, Vec3::new(1000.0, 400.0, 0.0)),
        dims: Dims::Two,
        terrain: Terrain::None,
        obstacles: Vec::new(),
        current: Current::None,
        frame: None,
    }
}

pub(super) fn vehicle() -> Vehicle {
    Vehicle { max_turn: std::f64::consts::PI, safety_distance: 5.0, depth_max: 200.0, ..Vehicle::default() }
}

/// Flies (50, 200) -> (950, 200) on `world` (the world at departure) with `changes`, planner
/// `id`: sampling planners on 1500 samples a re-plan (so results do not depend on the
/// machine), the others on a 60 s safety net.
pub(super) fn fly(id: &str, world: &World, changes: &[Change], params: SimParams, seed: u64) -> Simulation {
    use crate::cost::{GeneralCost, GeneralWeights};
    use crate::planner::registry;
    let mission = Mission::new("m", vehicle(), v(50.0, 200.0), v(950.0, 200.0), 0.0);
    let cost = GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap());
    let make = || registry().build(id, None, None, &crate::encoding::EncodingSpec::default());
    let per_replan = match registry().find(id).is_some_and(|e| e.build.caps.randomised) {
        true => Termination { max_samples: Some(1500), ..Termination::default() },
        false => Termination::default().with_wall_time(std::time::Duration::from_secs(60)),
    };
    let setup = Setup {
        world,
        mission: &mission,
        changes,
        planner: &make,
        cost: &cost,
        settings: &ModelSettings::default(),
        params,
        per_replan: &per_replan,
        total: &Termination::default(),
    };
    simulate(&setup, &mut crate::rng::run_rng(seed, 0)).unwrap()
}

fn v(x: f64, y: f64) -> Vec3 {
    Vec3::new(x, y, 0.0)
}

#[test]
fn the_window_doubles_or_adds_and_stops_at_the_goal() {
    // 39 waypoints left (lfhh2019's 40-point path from index 0): 20 -> 39 doubling, 20 -> 21
    // adding one; a window at the goal has nothing larger to try.
    assert_eq!(next_window(20, Growth::Double, 39), Some(39));
    assert_eq!(next_window(5, Growth::Double, 39), Some(10));
    assert_eq!(next_window(20, Growth::Add(1), 39), Some(21));
    assert_eq!(next_window(38, Growth::Add(5), 39), Some(39));
    assert_eq!(next_window(39, Growth::Double, 39), None);
    assert_eq!(next_window(1, Growth::Add(0), 3), Some(2), "a growth of 0 still grows");
    // From W = 1 doubling reaches 8 remaining waypoints in 1, 2, 4, 8.
    let mut w = 1;
    let mut seen = vec![w];
    while let Some(n) = next_window(w, Growth::Double, 8) {
        w = n;
        seen.push(w);
    }
    assert_eq!(seen, [1, 2, 4, 8]);
    assert_eq!(SimParams::LFHH2019.window, 20);
    assert_eq!(SimParams::LFHH2019.growth, Growth::Add(1));
}

#[test]
fn splicing_keeps_the_route_continuous() {
    let route = [v(0.0, 0.0), v(100.0, 0.0), v(200.0, 0.0), v(300.0, 0.0), v(400.0, 0.0)];
    // A piece whose ends are off by rounding is pinned to the vehicle and the target.
    let piece = [v(1e-12, 0.0), v(50.0, 80.0), v(150.0, 80.0), v(200.0, 1e-12)];
    let s = splice(&piece, &route, 2);
    assert_eq!(s, [route[0], piece[1], piece[2], route[2], route[3], route[4]]);
    // A window to the goal replaces everything.
    let s = splice(&[route[0], v(200.0, 90.0), route[4]], &route, 4);
    assert_eq!(s, [route[0], v(200.0, 90.0), route[4]]);
}

#[test]
fn the_vehicle_stops_exactly_where_a_trigger_fires() {
    // 1.5 m/s along (0,0) -> (300,0) -> (300,300). At t = 100 it is 150 m along; after 400 m
    // it is at (300, 100), at t = 400 / 1.5.
    let (w, veh, settings) = (world_2d(), vehicle(), ModelSettings::default());
    let val = Validator::new(&w, &veh, &settings);
    let route = [v(0.0, 0.0), v(300.0, 0.0), v(300.0, 300.0)];
    let mut track = Track::new(route[0], 0.0);
    let triggers = [Event::Trigger(Trigger::AfterDistance(400.0)), Event::Trigger(Trigger::AtTime(100.0))];
    let (k, ahead) = advance(&val, &route, &triggers, &mut track).unwrap();
    assert_eq!(k, 1);
    assert_eq!(ahead, [v(150.0, 0.0), route[1], route[2]]);
    assert_eq!(track.points, [route[0], v(150.0, 0.0)]);
    assert_eq!(track.times, [0.0, 100.0]);
    let (k, ahead) = advance(&val, &ahead, &triggers[..1], &mut track).unwrap();
    assert_eq!(k, 0);
    assert_eq!(ahead, [v(300.0, 100.0), route[2]]);
    assert_eq!(track.points[2..], [route[1], v(300.0, 100.0)]);
    assert!((track.times[3] - 400.0 / 1.5).abs() < 1e-9 && (track.travelled - 400.0).abs() < 1e-9);
    // Without triggers it flies to the end: arrival 600 / 1.5 = 400 s.
    assert!(advance(&val, &ahead, &[], &mut track).is_none());
    assert_eq!(track.now().0, route[2]);
    assert!((track.now().1 - 400.0).abs() < 1e-9);
    let p = Vec3::ZERO;
    assert!(due(&Event::Trigger(Trigger::AtTime(400.0)), p, 400.0, 0.0));
    assert!(!due(&Event::Trigger(Trigger::AfterDistance(601.0)), p, 0.0, 600.0));
}

#[test]
fn warm_starts_follow_the_planner_table_and_budgets_share_the_total() {
    assert!(takes_warm_start("rrt-star") && takes_warm_start("pso"));
    assert!(!takes_warm_start("astar") && !takes_warm_start("my-own-planner"));
    let flag = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let total = Termination::default()
        .with_wall_time(std::time::Duration::from_secs(2))
        .with_stop_flag(flag.clone())
        .started_now();
    let per = Termination::iterations(5).with_wall_time(std::time::Duration::from_secs(60));
    let b = replan_budget(&per, &total);
    assert!(b.wall_time.unwrap() <= std::time::Duration::from_secs(2));
    assert_eq!(b.max_iterations, Some(5));
    assert!(b.stop.is_some() && b.started.is_none());
}

/// A disc across the far end of a 10-point route along y = 200: a window of 2 waypoints has a
/// feasible piece, but the spliced route is blocked further on. lfhh2019's acceptance takes
/// the first window; tidepath's default grows the window until the route to the goal is clear.
#[test]
fn the_window_rule_accepts_a_piece_or_the_whole_route() {
    use crate::cost::{GeneralCost, GeneralWeights};
    use crate::planner::registry;
    use crate::world::{Obstacle, Shape};
    let world = World {
        waves: Default::default(),
        obstacles: vec![Obstacle::fixed(Shape::Circle { center: crate::geom::Vec2::new(850.0, 200.0), radius: 40.0 })],
        ..world_2d()
    };
    let route: Vec<Vec3> = (0..10).map(|i| v(50.0 + 100.0 * i as f64, 200.0)).collect();
    let mission = Mission::new("m", vehicle(), route[0], route[9], 0.0);
    let cost = GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap());
    let make = || registry().build("theta-star", None, None, &crate::encoding::EncodingSpec::default());
    let per_replan = Termination::default().with_wall_time(std::time::Duration::from_secs(60));
    let settings = ModelSettings::default();
    let replan_with = |accept| {
        let params = SimParams { window: 2, growth: Growth::Add(1), accept, ..SimParams::default() };
        let setup = Setup {
            world: &world,
            mission: &mission,
            changes: &[],
            planner: &make,
            cost: &cost,
            settings: &settings,
            params,
            per_replan: &per_replan,
            total: &Termination::default(),
        };
        window::replan(&setup, &world, &route, 0.0, &mut crate::rng::run_rng(1, 0), false).unwrap()
    };
    let (record, spliced) = replan_with(Acceptance::Window);
    assert_eq!(record.windows, vec![2]);
    assert!(record.reason.contains("the route after it is not"), "{}", record.reason);
    let spliced = spliced.expect("the piece is accepted");
    assert_eq!(&spliced[spliced.len() - 7..], &route[3..]);
    // The route through the disc (850 +- 40 m) is kept.
    let (record, spliced) = replan_with(Acceptance::Route);
    assert_eq!(record.windows, vec![2, 3, 4, 5, 6, 7, 8, 9][..record.windows.len()].to_vec());
    assert!(record.windows.last().copied().unwrap() >= 9, "{:?}", record.windows);
    let spliced = spliced.expect("a route round the disc");
    let model = crate::path::PathModel::new(&world, &mission, &settings);
    assert!(model.violations(&spliced).is_empty());
}
