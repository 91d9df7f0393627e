//! Hand-computed checks of the sampling planners' parts (radius, joints, informed set,
//! neighbours, tree re-timing) and of the planners on small worlds with known answers.

use std::f64::consts::PI;

use rand::SeedableRng;

use super::informed::Informed;
use super::neighbours::Neighbours;
use super::tree::Tree;
use super::*;
use crate::cost::{GeneralCost, GeneralWeights};
use crate::geom::{Aabb, Vec3};
use crate::mission::Mission;
use crate::path::ModelSettings;
use crate::planner::{solve, Plan, Planner, RunOptions, SolveOptions, Status};
use crate::rng::Rng;
use crate::termination::{StopReason, Termination};
use crate::vehicle::Vehicle;
use crate::world::{Current, Dims, Obstacle, Shape, Terrain, World};

fn world_2d(w: f64, h: f64) -> World {
    World {
        waves: Default::default(),
        bounds: Aabb::new(Vec3::ZERO, Vec3::new(w, h, 0.0)),
        dims: Dims::Two,
        terrain: Terrain::None,
        obstacles: Vec::new(),
        current: Current::None,
        frame: None,
    }
}

fn vehicle() -> Vehicle {
    Vehicle {
        propulsion: Default::default(),
        speed: 1.5,
        max_turn: PI,
        max_pitch: 30f64.to_radians(),
        depth_min: 0.0,
        depth_max: 200.0,
        safety_distance: 5.0,
        turn_radius: None,
        speed_range: None,
    }
}

fn cost() -> GeneralCost {
    GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap())
}

fn rrt(table: &str, informed: bool) -> RrtStar {
    RrtStar::new(RrtStarParams::from_table(&toml::from_str(table).unwrap(), "p").unwrap(), informed)
}

fn prm(table: &str) -> PrmStar {
    PrmStar::new(PrmStarParams::from_table(&toml::from_str(table).unwrap(), "p").unwrap())
}

fn run(planner: &mut dyn Planner, w: &World, m: &Mission, termination: Termination, seed: u64) -> Plan {
    let settings = ModelSettings::default();
    let cost = cost();
    let missions = [m.clone()];
    let problem =
        Problem { world: w, settings: &settings, cost: &cost, missions: &missions, fleet: &crate::fleet::NO_FLEET };
    let mut rng = crate::rng::run_rng(seed, 0);
    solve(planner, &problem, &termination, &mut rng, SolveOptions::default(), &mut |_| {}).unwrap()
}

fn samples(n: u64) -> Termination {
    Termination { max_samples: Some(n), ..Termination::default() }
}

/// gamma_RRT* = (2 (1 + 1/d))^(1/d) (mu / zeta_d)^(1/d) and gamma_PRM* = 2 (1 + 1/d)^(1/d)
/// (mu / zeta_d)^(1/d), times (log n / n)^(1/d), written out by hand.
#[test]
fn rewire_radius_is_karaman_and_frazzoli() {
    let flat = SampleSpace { lo: Vec3::ZERO, hi: Vec3::new(1000.0, 1000.0, 0.0), dims: 2 };
    // d = 2, mu = 1e6: gamma_RRT* = sqrt(3) sqrt(1e6 / pi) = 977.205; at n = 100, times
    // sqrt(ln 100 / 100) = 0.214597.
    let r = rewire_radius(Variant::Rrt, &flat, flat.measure(), 100, 1.0);
    assert!((r - 977.205_023 * 0.214_596_7).abs() < 1e-3, "{r}");
    // gamma_PRM* = 2 sqrt(1.5) sqrt(1e6 / pi) = 1381.977.
    let r = rewire_radius(Variant::Prm, &flat, flat.measure(), 100, 1.0);
    assert!((r - 1_381.976_597 * 0.214_596_7).abs() < 1e-3, "{r}");
    // d = 3, mu = 1e9: (mu / (4 pi / 3))^(1/3) = 620.350; gamma_RRT* = (8/3)^(1/3) * that =
    // 860.272; at n = 1000, (ln 1000 / 1000)^(1/3) = 0.190455; the factor scales it.
    let cube = SampleSpace { lo: Vec3::ZERO, hi: Vec3::splat(1000.0), dims: 3 };
    let r = rewire_radius(Variant::Rrt, &cube, cube.measure(), 1000, 1.1);
    assert!((r - 1.1 * 860.272_4 * 0.190_455_4).abs() < 1e-2, "{r}");
    assert!((unit_ball_measure(3) - 4.188_790_2).abs() < 1e-6);
}

#[test]
fn joints_keep_the_turn_pitch_and_fillet_limits() {
    let mut v = vehicle();
    v.max_turn = 60f64.to_radians();
    let k = Kinematics::of(&v, true);
    let o = Vec3::ZERO;
    let east = Vec3::new(100.0, 0.0, 0.0);
    // From the west heading east: 45 degrees left passes, 90 does not, at the start anything.
    assert!(k.joint_ok(Some(Vec3::new(-100.0, 0.0, 0.0)), o, Vec3::new(100.0, 100.0, 0.0)));
    assert!(!k.joint_ok(Some(Vec3::new(-100.0, 0.0, 0.0)), o, Vec3::new(0.0, 100.0, 0.0)));
    assert!(k.joint_ok(None, o, Vec3::new(-100.0, 0.0, 0.0)));
    // Pitch 30 degrees: tan = 0.577; a rise of 50 on 100 passes, 60 does not; vertical never.
    assert!(k.edge_ok(o, Vec3::new(100.0, 0.0, 50.0)));
    assert!(!k.edge_ok(o, Vec3::new(100.0, 0.0, 60.0)));
    assert!(!k.edge_ok(o, Vec3::new(0.0, 0.0, 10.0)));
    // A 90-degree turn at radius 10 needs 10 m of each leg: legs of 21 m give 10.5, 19 m 9.5.
    v.max_turn = PI;
    v.turn_radius = Some(10.0);
    let k = Kinematics::of(&v, false);
    assert!(k.joint_ok(Some(Vec3::new(-21.0, 0.0, 0.0)), o, Vec3::new(0.0, 21.0, 0.0)));
    assert!(!k.joint_ok(Some(Vec3::new(-19.0, 0.0, 0.0)), o, Vec3::new(0.0, 21.0, 0.0)));
    // Straight on needs nothing; a reversal never fits a radius.
    assert!(k.joint_ok(Some(Vec3::new(-1.0, 0.0, 0.0)), o, east));
    assert!(!k.joint_ok(Some(east), o, east * 0.5));
}

/// Every informed sample is in the hyperspheroid and the box, and they fill it: the extreme
/// samples along and across the axis come near the semi-axes c_best / 2 and
/// sqrt(c_best^2 - c_min^2) / 2.
#[test]
fn informed_samples_fill_the_prolate_hyperspheroid() {
    let (s, g) = (Vec3::new(100.0, 100.0, -50.0), Vec3::new(900.0, 700.0, -150.0));
    let c_min = s.distance(g);
    let c_best = 1.2 * c_min;
    let set = Informed::new(s, g, c_best).unwrap();
    let space = SampleSpace { lo: Vec3::new(0.0, 0.0, -200.0), hi: Vec3::new(1000.0, 1000.0, 0.0), dims: 3 };
    let mut rng = Rng::seed_from_u64(3);
    let axis = (g - s) / c_min;
    let centre = (s + g) * 0.5;
    let (mut along, mut across) = (0.0f64, 0.0f64);
    for _ in 0..20_000 {
        let p = set.sample(&space, &mut rng);
        assert!(set.contains(p) || p.distance(s) + p.distance(g) <= c_best * (1.0 + 1e-12), "{p}");
        assert!(space.contains(p), "{p}");
        let d = p - centre;
        along = along.max(d.dot(axis).abs());
        across = across.max((d - axis * d.dot(axis)).length());
    }
    let conjugate = 0.5 * (c_best * c_best - c_min * c_min).sqrt();
    assert!(along > 0.97 * 0.5 * c_best && along <= 0.5 * c_best + 1e-9, "{along}");
    // The box clips the depth (200 m) across: the largest sample across is capped there.
    assert!(across > 0.5 * conjugate && across <= conjugate + 1e-9, "{across} of {conjugate}");
    // In 2-D the samples stay at the plane's height.
    let plane = SampleSpace { lo: Vec3::ZERO, hi: Vec3::new(1000.0, 1000.0, 0.0), dims: 2 };
    let set = Informed::new(Vec3::new(100.0, 100.0, 0.0), Vec3::new(900.0, 700.0, 0.0), 1100.0).unwrap();
    for _ in 0..1000 {
        let p = set.sample(&plane, &mut rng);
        assert!(p.z == 0.0 && set.contains(p) && plane.contains(p), "{p}");
    }
}

/// The index answers as a brute-force scan does, also when every point shares z (2-D sampling
/// in 3-D) and when many points share x.
#[test]
fn neighbours_agree_with_a_brute_force_scan() {
    let mut rng = Rng::seed_from_u64(9);
    for (flat, shared_x) in [(true, false), (false, false), (false, true)] {
        let space =
            SampleSpace { lo: Vec3::ZERO, hi: Vec3::new(1000.0, 500.0, if flat { 0.0 } else { 100.0 }), dims: 3 };
        let mut index = Neighbours::new(flat);
        let mut pts = Vec::new();
        for i in 0..3000u32 {
            let mut p = space.sample(&mut rng);
            if shared_x && i % 2 == 0 {
                p.x = 250.0;
            }
            index.insert(p, i);
            pts.push(p);
        }
        let mut near = Vec::new();
        for _ in 0..200 {
            let q = space.sample(&mut rng);
            let best = pts.iter().map(|p| p.distance(q)).fold(f64::INFINITY, f64::min);
            let n = index.nearest(q).unwrap();
            assert_eq!(pts[n as usize].distance(q), best);
            index.within(q, 60.0, &mut near);
            let brute: Vec<u32> = (0..pts.len() as u32).filter(|&i| pts[i as usize].distance(q) <= 60.0).collect();
            assert_eq!(near, brute);
        }
    }
}

/// Rewiring in a world that changes in time re-prices the subtree at its new times, and is
/// refused when an edge below would meet a moving obstacle then.
#[test]
fn rewiring_retimes_the_subtree_and_refuses_what_the_clock_makes_invalid() {
    let mut w = world_2d(2000.0, 1000.0);
    // A disc moving north at 1 m/s, at (1000, 0) at t = 0: at y = 500 when t = 500 s.
    w.obstacles.push(Obstacle {
        shape: Shape::Circle { center: crate::geom::Vec2::new(1000.0, 0.0), radius: 20.0 },
        velocity: Vec3::new(0.0, 1.0, 0.0),
        window: None,
    });
    let m = Mission::new("m", vehicle(), Vec3::new(0.0, 500.0, 0.0), Vec3::new(1900.0, 500.0, 0.0), 0.0);
    let settings = ModelSettings::default();
    let cost = cost();
    let missions = [m];
    let problem =
        Problem { world: &w, settings: &settings, cost: &cost, missions: &missions, fleet: &crate::fleet::NO_FLEET };
    let mut edges = Edges::new(&problem, 0, 1.0, &|| false).unwrap();
    assert!(edges.time_varying);
    let t = Termination::default();
    // Root at x = 0; a at x = 300 reached at 200 s; b at x = 1500 below a, leaving a at 200 s
    // and crossing x = 1000 at 200 + 700 / 1.5 = 667 s, long after the disc passed y = 500.
    let mut tree = Tree::new(missions[0].start, 0.0);
    let p_a = Vec3::new(300.0, 500.0, 0.0);
    let (c_a, t_a) = edges.price(missions[0].start, p_a, 0.0).unwrap();
    let a = tree.add(p_a, 0, c_a, t_a);
    let p_b = Vec3::new(1500.0, 500.0, 0.0);
    let (c_b, t_b) = edges.price(p_a, p_b, t_a).unwrap();
    let b = tree.add(p_b, a, c_a + c_b, t_b);
    // Re-timing a to arrive at 33.3 s makes a -> b cross x = 1000 at 33.3 + 700 / 1.5 = 500 s,
    // when the disc is there: refused, nothing changed.
    let other = Vec3::new(300.0, 499.0, 0.0);
    let other_parent = tree.add(other, 0, 0.0, 0.0);
    let early = 500.0 - 700.0 / 1.5;
    assert!(!tree.reparent(a, other_parent, c_a, early, &mut edges, None, &t));
    assert_eq!((tree.parent[a as usize], tree.time[b as usize]), (0, t_b));
    // Arriving at 150 s instead, it crosses at 617 s, the disc 117 m away: the rewire is
    // taken and b is re-timed by the edge's own travel time.
    assert!(tree.reparent(a, other_parent, c_a, 150.0, &mut edges, None, &t));
    let (c_ab, t_ab) = edges.price(p_a, p_b, 150.0).unwrap();
    assert!((t_ab - (150.0 + 1200.0 / 1.5)).abs() < 1e-9);
    assert_eq!(tree.time[b as usize], t_ab);
    assert_eq!(tree.cost[b as usize], c_a + c_ab);
    assert_eq!(tree.parent[a as usize], other_parent);
}

/// In open water a first sample at the goal joins start and goal straight (the exact answer);
/// with the usual goal bias the path converges towards it; each sample leaves one history
/// entry, the last one the plan's cost.
#[test]
fn open_water_gives_the_straight_line() {
    let w = world_2d(1000.0, 1000.0);
    let m = Mission::new("m", vehicle(), Vec3::new(100.0, 100.0, 0.0), Vec3::new(900.0, 800.0, 0.0), 0.0);
    let straight = m.start.distance(m.goal);
    for informed in [false, true] {
        let plan = run(&mut rrt("range = 2000.0\ngoal_bias = 1.0", informed), &w, &m, samples(5), 4);
        assert_eq!(plan.missions[0].waypoints, vec![m.start, m.goal]);
        let plan = run(&mut rrt("range = 2000.0", informed), &w, &m, samples(300), 4);
        assert_eq!(plan.status, Status::Feasible, "{}", plan.reason);
        let len = plan.missions[0].metrics.unwrap().length_m;
        assert!(len >= straight && len < 1.05 * straight, "{len} vs {straight}");
        assert_eq!(plan.stats.samples, 300);
        assert_eq!(plan.stats.history.len(), 300);
        assert_eq!(plan.stats.stop_reason, StopReason::MaxSamples);
        let last = *plan.stats.history.last().unwrap();
        assert!((last - plan.cost).abs() < 1e-12, "{last} vs {}", plan.cost);
    }
    // PRM* joins only vertices within its radius (895 m with two vertices, less later), so
    // its path is a roadmap path: feasible and near the straight line.
    let plan = run(&mut prm(""), &w, &m, samples(300), 4);
    assert_eq!(plan.status, Status::Feasible, "{}", plan.reason);
    let len = plan.missions[0].metrics.unwrap().length_m;
    assert!(len >= straight && len < 1.1 * straight, "{len} vs {straight}");
}

fn wall_world() -> (World, Mission) {
    let mut w = world_2d(2000.0, 1000.0);
    // A wall across the middle with a gap at its north end.
    w.obstacles.push(Obstacle::fixed(Shape::Box {
        min: Vec3::new(950.0, -10.0, -100.0),
        max: Vec3::new(1050.0, 800.0, 100.0),
    }));
    let m = Mission::new("m", vehicle(), Vec3::new(200.0, 200.0, 0.0), Vec3::new(1800.0, 200.0, 0.0), 0.0);
    (w, m)
}

/// Around a wall the three planners find feasible paths no shorter than the shortest (over
/// the wall's padded corners, hand-computed), and not far above it; seeds reproduce runs.
#[test]
fn around_a_wall_the_paths_are_near_the_shortest() {
    let (w, m) = wall_world();
    // Shortest: start -> (945, 805) -> (1055, 805) -> goal, the corners padded by the 5 m
    // safety distance.
    let (c1, c2) = (Vec3::new(945.0, 805.0, 0.0), Vec3::new(1055.0, 805.0, 0.0));
    let shortest = m.start.distance(c1) + c1.distance(c2) + c2.distance(m.goal);
    let planners: Vec<Box<dyn Fn() -> Box<dyn Planner>>> = vec![
        Box::new(|| Box::new(rrt("", false))),
        Box::new(|| Box::new(rrt("", true))),
        Box::new(|| Box::new(prm(""))),
    ];
    for make in &planners {
        let a = run(make().as_mut(), &w, &m, samples(4000), 7);
        assert_eq!(a.status, Status::Feasible, "{}", a.reason);
        let len = a.missions[0].metrics.unwrap().length_m;
        assert!(len >= shortest - 1e-6 && len < 1.05 * shortest, "{len} vs {shortest}");
        let b = run(make().as_mut(), &w, &m, samples(4000), 7);
        assert_eq!(a.missions[0].waypoints, b.missions[0].waypoints);
        let c = run(make().as_mut(), &w, &m, samples(4000), 8);
        assert_ne!(a.missions[0].waypoints, c.missions[0].waypoints);
    }
}

/// Too few samples to get round the wall: the path stops short, the distance left is
/// reported, and the status is never `feasible`.
#[test]
fn too_few_samples_report_the_distance_left() {
    let (w, m) = wall_world();
    for mut planner in [Box::new(rrt("range = 100.0", false)) as Box<dyn Planner>, Box::new(prm(""))] {
        let plan = run(planner.as_mut(), &w, &m, samples(20), 1);
        assert_eq!(plan.status, Status::Infeasible, "{}", plan.reason);
        let mp = &plan.missions[0];
        if mp.waypoints.len() >= 2 {
            let left = mp.goal_distance_m.unwrap();
            assert!((left - mp.waypoints.last().unwrap().distance(m.goal)).abs() < 1e-9);
            assert!(plan.reason.contains("short of the goal"), "{}", plan.reason);
        }
    }
    // RRT* with 20 samples of 100 m gets somewhere: its path stops short.
    let plan = run(&mut rrt("range = 100.0", false), &w, &m, samples(20), 1);
    assert!(plan.missions[0].waypoints.len() >= 2);
}

/// The warm start's states join the tree: with a valid initial path round the wall and very
/// few samples, RRT* returns a feasible path.
#[test]
fn a_warm_start_seeds_the_tree_and_the_roadmap() {
    let (w, m) = wall_world();
    let init = vec![vec![m.start, Vec3::new(900.0, 900.0, 0.0), Vec3::new(1100.0, 900.0, 0.0), m.goal]];
    let settings = ModelSettings::default();
    let cost = cost();
    let missions = [m.clone()];
    let problem =
        Problem { world: &w, settings: &settings, cost: &cost, missions: &missions, fleet: &crate::fleet::NO_FLEET };
    let mut planners: Vec<Box<dyn Planner>> = vec![Box::new(rrt("", false)), Box::new(prm(""))];
    for p in planners.iter_mut() {
        let mut rng = crate::rng::run_rng(1, 0);
        let options =
            SolveOptions { run: RunOptions { init: Some(&init), ..RunOptions::default() }, ..SolveOptions::default() };
        let plan = solve(p.as_mut(), &problem, &samples(5), &mut rng, options, &mut |_| {}).unwrap();
        assert_eq!(plan.status, Status::Feasible, "{}: {}", p.id(), plan.reason);
    }
}

/// The budget: a stop flag raised before the run stops it at once; a sample limit is met.
#[test]
fn termination_is_polled_every_sample() {
    let (w, m) = wall_world();
    let flag = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(true));
    let t = samples(1_000_000).with_stop_flag(flag);
    for mut planner in [Box::new(rrt("", false)) as Box<dyn Planner>, Box::new(prm(""))] {
        let plan = run(planner.as_mut(), &w, &m, t.clone(), 1);
        assert_eq!(plan.stats.stop_reason, StopReason::Cancelled);
        assert!(plan.stats.samples <= 1, "{}", plan.stats.samples);
    }
}
