//! Hybrid-A* on small worlds, judged by the shared evaluation and by an independent dense
//! sampler of the flown curve.

use std::f64::consts::{PI, TAU};

use super::*;
use crate::cost::{GeneralCost, GeneralWeights};
use crate::geom::{Aabb, Vec2, Vec3};
use crate::kinematics::dubins::Dubins;
use crate::kinematics::fillet::{self, FlownPiece};
use crate::kinematics::Pose;
use crate::mission::Mission;
use crate::path::{ModelSettings, PathModel};
use crate::planner::{solve, Plan, SolveOptions, Status};
use crate::vehicle::Vehicle;
use crate::world::terrain::{GaussianPeaks, Peak};
use crate::world::{Current, Obstacle, Shape, Terrain, World};

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

fn vehicle(radius: Option<f64>) -> Vehicle {
    Vehicle {
        propulsion: Default::default(),
        speed: 1.5,
        max_turn: PI,
        max_pitch: 20f64.to_radians(),
        depth_min: 0.0,
        depth_max: 200.0,
        safety_distance: 5.0,
        turn_radius: radius,
        speed_range: None,
    }
}

fn params(table: &str) -> Checked<HybridAstarParams> {
    HybridAstarParams::from_table(&toml::from_str(table).unwrap(), "planner.params.hybrid-astar").unwrap()
}

fn plan(w: &World, m: &Mission, table: &str, termination: Termination) -> Plan {
    let settings = ModelSettings::default();
    let cost = GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap());
    let missions = [m.clone()];
    let problem =
        Problem { world: w, settings: &settings, cost: &cost, missions: &missions, fleet: &crate::fleet::NO_FLEET };
    let mut planner = HybridAstar::new(params(table));
    let mut rng = crate::rng::run_rng(1, 0);
    solve(&mut planner, &problem, &termination, &mut rng, SolveOptions::default(), &mut |_| {}).unwrap()
}

/// Length of the curve flown along `points` with radius `r`.
fn flown_length(points: &[Vec3], r: f64) -> f64 {
    let mut len = 0.0;
    fillet::for_each_piece(points, r, |p| match p {
        FlownPiece::Line { a, b, .. } => len += a.distance(b),
        FlownPiece::Arc(arc) => len += arc.horizontal_length().hypot(arc.b.z - arc.a.z),
    });
    len
}

/// The independent check: every turn of the flown curve at radius r or wider and fitting its
/// legs; the curve sampled every 0.5 m inside the domain and depth band, the safety distance
/// above the seabed and from every (fixed) obstacle; pitch within the limit.
fn dense_check(w: &World, v: &Vehicle, points: &[Vec3], r: f64) -> std::result::Result<(), String> {
    for (i, c) in fillet::corners(points, r).iter().enumerate() {
        if c.turn > 0.0 && !(c.fits && c.radius >= r * (1.0 - 1e-9)) {
            return Err(format!("waypoint {i}: radius {} < {r} or does not fit", c.radius));
        }
    }
    let safety = v.safety_distance * (1.0 - 1e-9);
    let three_d = w.dims == Dims::Three;
    let check = |p: Vec3| -> std::result::Result<(), String> {
        if !w.bounds.inflate(1e-6).contains(p) {
            return Err(format!("{p:?} outside the domain"));
        }
        if three_d {
            if p.z > v.z_max() + 1e-6 || p.z < v.z_min() - 1e-6 {
                return Err(format!("{p:?} outside the depth band"));
            }
            if !matches!(w.terrain, Terrain::None) && p.z - w.terrain.elevation(p.x, p.y) < safety {
                return Err(format!("{p:?} within the safety distance of the seabed"));
            }
        }
        if let Some(k) = w.obstacles.iter().position(|o| o.contains(p, 0.0, safety)) {
            return Err(format!("{p:?} within the safety distance of obstacle {k}"));
        }
        Ok(())
    };
    let tan_pitch = v.max_pitch.tan() * (1.0 + 1e-9);
    let mut result = Ok(());
    fillet::for_each_piece(points, r, |piece| {
        if result.is_err() {
            return;
        }
        let (len, at): (f64, Box<dyn Fn(f64) -> Vec3>) = match piece {
            FlownPiece::Line { a, b, .. } => {
                let d = b - a;
                let h = d.truncate().length();
                if three_d && h > 1e-6 && d.z.abs() > tan_pitch * h {
                    result = Err(format!("straight {a:?} -> {b:?} too steep"));
                }
                (a.distance(b), Box::new(move |f| a + d * f))
            }
            FlownPiece::Arc(arc) => {
                if three_d && arc.a != arc.b && arc.slope() > tan_pitch {
                    result = Err(format!("turn at {} too steep", arc.waypoint));
                }
                (arc.horizontal_length(), Box::new(move |f| arc.point(f)))
            }
        };
        let n = (len / 0.5).ceil().max(1.0) as usize;
        for k in 0..=n {
            if let Err(e) = check(at(k as f64 / n as f64)) {
                result = Err(e);
                return;
            }
        }
    });
    result
}

#[test]
fn the_free_heading_length_is_the_shortest_dubins_length_over_goal_headings() {
    let r = 10.0;
    let from = Pose::new(Vec3::new(3.0, -4.0, 0.0), 0.6);
    let mut outside = 0;
    for i in -12..=12 {
        for j in -12..=12 {
            if (i, j) == (0, 0) {
                continue; // the pose itself: length 0, where sampled headings loop round
            }
            let goal = from.p.truncate() + Vec2::new(i as f64, j as f64) * 4.3;
            let sampled = (0..720)
                .filter_map(|k| Dubins::shortest(from, Pose::new(goal.extend(0.0), TAU * k as f64 / 720.0), r))
                .map(|d| d.length())
                .fold(f64::INFINITY, f64::min);
            let bound = free_heading_length(from, goal, r);
            // A lower bound everywhere ...
            assert!(bound <= sampled + 1e-9, "{goal:?}: {bound} > {sampled}");
            // ... and the minimum itself outside both turning circles (the sampled minimum
            // approaches it from above as the headings get finer).
            let both = [1, -1].iter().all(|&s| turn_then_straight(from, goal, r, s).is_some());
            if both {
                outside += 1;
                assert!(sampled - bound < 0.01 * r, "{goal:?}: {bound} vs {sampled}");
            }
        }
    }
    assert!(outside > 500, "{outside}");
    // By hand: straight ahead, and a half circle to the point 2r to the left.
    let o = Pose::new(Vec3::ZERO, 0.0);
    assert!((free_heading_length(o, Vec2::new(50.0, 0.0), r) - 50.0).abs() < 1e-12);
    assert!((free_heading_length(o, Vec2::new(0.0, 2.0 * r), r) - PI * r).abs() < 1e-9);
}

#[test]
fn in_open_water_the_path_is_the_straight_line_flown_exactly() {
    let w = world_2d(1000.0, 1000.0);
    let m = Mission::new("m", vehicle(Some(30.0)), Vec3::new(100.0, 200.0, 0.0), Vec3::new(900.0, 700.0, 0.0), 0.0);
    let p = plan(&w, &m, "", Termination::default());
    assert_eq!(p.status, Status::Feasible, "{}", p.reason);
    let path = p.missions[0].path();
    assert_eq!((path[0], *path.last().unwrap()), (m.start, m.goal));
    let straight = m.start.distance(m.goal);
    assert!((flown_length(path, 30.0) - straight).abs() < 1e-6 * straight);
    dense_check(&w, &m.vehicle, path, 30.0).unwrap();
}

#[test]
fn round_a_disc_the_path_is_flyable_and_near_the_shortest() {
    let mut w = world_2d(1000.0, 400.0);
    w.obstacles.push(Obstacle::fixed(Shape::Circle { center: Vec2::new(500.0, 200.0), radius: 100.0 }));
    let r = 30.0;
    let m = Mission::new("m", vehicle(Some(r)), Vec3::new(100.0, 200.0, 0.0), Vec3::new(900.0, 200.0, 0.0), 0.0);
    let p = plan(&w, &m, "", Termination::default());
    assert_eq!(p.status, Status::Feasible, "{}", p.reason);
    let path = p.missions[0].path();
    dense_check(&w, &m.vehicle, path, r).unwrap();
    // The shortest path round the disc grown by the safety distance (R = 105) is tangent, arc,
    // tangent; its turn is wider than r, so it is also the shortest flyable path.
    let (d, big) = (400.0f64, 105.0f64);
    let shortest = 2.0 * (d * d - big * big).sqrt() + big * (PI - 2.0 * (big / d).acos());
    let len = flown_length(path, r);
    assert!(len >= shortest - 1e-6 && len <= 1.03 * shortest, "{len} vs {shortest}");
    assert!((p.missions[0].metrics.as_ref().unwrap().length_m - len).abs() < 1e-6 * len);
}

#[test]
fn a_corner_too_tight_for_the_radius_is_no_route_on_the_lattice() {
    // An L-shaped corridor 20 m wide (15 m of water either side of the safety distance): a
    // vehicle with a 100 m radius cannot take its corner; the optimistic check connects start
    // and goal, so the reason is the lattice's.
    let mut w = world_2d(400.0, 400.0);
    let wall = |x0: f64, y0: f64, x1: f64, y1: f64| {
        Obstacle::fixed(Shape::Box { min: Vec3::new(x0, y0, -10.0), max: Vec3::new(x1, y1, 10.0) })
    };
    w.obstacles.push(wall(0.0, 0.0, 400.0, 150.0));
    w.obstacles.push(wall(0.0, 180.0, 220.0, 400.0));
    w.obstacles.push(wall(250.0, 180.0, 400.0, 400.0));
    let m = Mission::new("m", vehicle(Some(100.0)), Vec3::new(20.0, 165.0, 0.0), Vec3::new(235.0, 380.0, 0.0), 0.0);
    let p = plan(&w, &m, "cells = 80", Termination::default());
    assert_eq!(p.status, Status::Infeasible, "{}", p.reason);
    assert!(
        p.reason.starts_with("no route on the 72-heading lattice of 80 x 80 cells for the vehicle's 100.0 m turning radius (searched completely)"),
        "{}",
        p.reason
    );
    // The same corridor for a vehicle with a 5 m radius: flyable.
    let m = Mission { vehicle: vehicle(Some(5.0)), ..m };
    let p = plan(&w, &m, "cells = 80", Termination::default());
    assert_eq!(p.status, Status::Feasible, "{}", p.reason);
    dense_check(&w, &m.vehicle, p.missions[0].path(), 5.0).unwrap();
}

#[test]
fn a_depth_change_over_a_seamount_keeps_the_pitch_and_the_seabed() {
    let mut w = World::open(Aabb::new(Vec3::ZERO, Vec3::new(2000.0, 1000.0, -0.0)));
    w.bounds.min.z = -300.0;
    w.terrain = Terrain::Peaks(GaussianPeaks {
        base: -280.0,
        peaks: vec![Peak { x: 1000.0, y: 500.0, height: 240.0, sigma_x: 250.0, sigma_y: 250.0 }],
        ceiling: None,
    });
    let r = 40.0;
    let v = vehicle(Some(r));
    let m = Mission::new("m", v.clone(), Vec3::new(100.0, 500.0, -200.0), Vec3::new(1900.0, 450.0, -60.0), 0.0);
    let p = plan(&w, &m, "", Termination::default());
    assert_eq!(p.status, Status::Feasible, "{}", p.reason);
    let path = p.missions[0].path();
    assert_eq!((path[0], *path.last().unwrap()), (m.start, m.goal));
    dense_check(&w, &v, path, r).unwrap();
    // It does change depth, and goes round or over the peak (the straight line hits it).
    assert!(PathModel::new(&w, &m, &ModelSettings::default()).validator.motion(m.start, m.goal, 0.0).first.is_some());
    let zs: Vec<f64> = path.iter().map(|p| p.z).collect();
    assert!(zs.iter().any(|&z| z != -200.0 && z != -60.0), "{zs:?}");
}

#[test]
fn an_expansion_budget_stops_early_with_a_path_toward_the_goal() {
    let mut w = world_2d(1000.0, 400.0);
    w.obstacles.push(Obstacle::fixed(Shape::Circle { center: Vec2::new(500.0, 200.0), radius: 100.0 }));
    let m = Mission::new("m", vehicle(Some(30.0)), Vec3::new(100.0, 200.0, 0.0), Vec3::new(900.0, 200.0, 0.0), 0.0);
    let t = Termination { max_expansions: Some(10), ..Termination::default() };
    let p = plan(&w, &m, "", t);
    assert_eq!(p.stats.expansions, 10);
    assert_eq!(p.stats.stop_reason, StopReason::MaxExpansions);
    assert_eq!(p.status, Status::Infeasible, "{}", p.reason);
    let mp = &p.missions[0];
    assert_eq!(mp.waypoints[0], m.start);
    let left = mp.goal_distance_m.expect("stops short of the goal");
    assert!(left < m.start.distance(m.goal), "{left}");
    assert!(p.reason.contains("short of the goal"), "{}", p.reason);
}

#[test]
fn a_vehicle_without_a_radius_gets_the_default_and_the_reason_names_it() {
    let mut w = world_2d(1000.0, 400.0);
    w.obstacles.push(Obstacle::fixed(Shape::Circle { center: Vec2::new(500.0, 200.0), radius: 100.0 }));
    let m = Mission::new("m", vehicle(None), Vec3::new(100.0, 200.0, 0.0), Vec3::new(900.0, 200.0, 0.0), 0.0);
    // Two cells of 5 m: a 10 m radius; the vehicle flies the polygon itself.
    let p = plan(&w, &m, "", Termination::default());
    assert_eq!(p.status, Status::Feasible, "{}", p.reason);
    dense_check(&w, &m.vehicle, p.missions[0].path(), 10.0).unwrap();
    let t = Termination { max_expansions: Some(5), ..Termination::default() };
    let p = plan(&w, &m, "radius = 25.0", t);
    assert!(
        p.reason.contains("on the 72-heading lattice of 200 x 80 cells for the planner's 25.0 m turning radius"),
        "{}",
        p.reason
    );
}

#[test]
fn a_dive_too_steep_for_the_straight_line_spirals_within_the_pitch_limit() {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -300.0), Vec3::new(1000.0, 1000.0, 0.0)));
    w.terrain = Terrain::Peaks(GaussianPeaks { base: -290.0, peaks: vec![], ceiling: None });
    let r = 40.0;
    let v = vehicle(Some(r));
    // 160 m down over 150 m: at 20 degrees at most, at least 440 m of horizontal flight.
    let m = Mission::new("m", v.clone(), Vec3::new(500.0, 500.0, -20.0), Vec3::new(650.0, 500.0, -180.0), 0.0);
    let p = plan(&w, &m, "", Termination::default());
    assert_eq!(p.status, Status::Feasible, "{}", p.reason);
    let path = p.missions[0].path();
    dense_check(&w, &v, path, r).unwrap();
    let mut horizontal = 0.0;
    fillet::for_each_piece(path, r, |pc| match pc {
        FlownPiece::Line { a, b, .. } => horizontal += (b - a).truncate().length(),
        FlownPiece::Arc(arc) => horizontal += arc.horizontal_length(),
    });
    assert!(horizontal >= 160.0 / 20f64.to_radians().tan() - 1e-6, "{horizontal}");
    let pitch = p.missions[0].metrics.as_ref().unwrap().max_pitch_deg;
    assert!(pitch <= 20.0 + 1e-9, "{pitch}");
}
