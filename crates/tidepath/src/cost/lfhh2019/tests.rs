//! Hand-computed checks of every lfhh2019 term, the readings, and F < 2 implying feasibility.

use super::*;
use crate::geom::{Aabb, Vec2};
use crate::mission::Mission;
use crate::path::ModelSettings;
use crate::vehicle::Vehicle;
use crate::world::terrain::{GaussianPeaks, Peak, Terrain};
use crate::world::{Current, Obstacle, Shape, World};
use rand::Rng as _;

/// A 3000 x 3000 m box, 1000 m deep, still water.
fn world_3d() -> World {
    World::open(Aabb::new(Vec3::new(0.0, 0.0, -1000.0), Vec3::new(3000.0, 3000.0, 0.0)))
}

/// The same box as a 2-D (sea surface) world.
fn world_2d() -> World {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, 0.0), Vec3::new(3000.0, 3000.0, 0.0)));
    w.dims = Dims::Two;
    w
}

/// A vehicle whose own limits never bind: any turn, any pitch.
fn free_vehicle() -> Vehicle {
    Vehicle {
        speed: 2.0,
        max_turn: PI,
        max_pitch: FRAC_PI_2,
        depth_max: 1000.0,
        safety_distance: 5.0,
        ..Vehicle::default()
    }
}

fn cost() -> Lfhh2019Cost {
    Lfhh2019Cost::new(Lfhh2019Params::default().checked("cost.weights").unwrap())
}

fn term(terms: &[(&str, f64)], name: &str) -> f64 {
    terms.iter().find(|t| t.0 == name).unwrap().1
}

fn close(a: f64, b: f64) {
    assert!((a - b).abs() <= 1e-12 * (1.0 + b.abs()), "{a} != {b}");
}

/// Evaluates `p` for a mission from its first to its last point.
fn breakdown(w: &World, v: Vehicle, p: &[Vec3]) -> (f64, Vec<(&'static str, f64)>, bool) {
    let mission = Mission::new("m", v, p[0], *p.last().unwrap(), 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(w, &mission, &settings);
    let (total, terms) = cost().breakdown(&model, p);
    let feasible = model.assess(p, &mut Vec::new()).feasible();
    (total, terms, feasible)
}

/// Collinear waypoints in still water: no length excess, no joint, no block; the current
/// term is neutral (1/2).
#[test]
fn a_straight_path_in_still_water_costs_one_half() {
    for (w, z) in [(world_2d(), 0.0), (world_3d(), -50.0)] {
        let p = [Vec3::new(100.0, 100.0, z), Vec3::new(1100.0, 600.0, z), Vec3::new(2100.0, 1100.0, z)];
        let (total, terms, feasible) = breakdown(&w, free_vehicle(), &p);
        for name in ["length", "curvature", "block"] {
            close(term(&terms, name), 0.0);
        }
        close(term(&terms, "current"), 0.5);
        close(total, 0.5);
        assert!(feasible);
    }
}

/// S = (0, 0), W = (300, 400), G = (600, 0): L_straight = 600, L_path = 1000.
#[test]
fn the_length_term_by_hand() {
    let p = [Vec3::new(0.0, 0.0, 0.0), Vec3::new(300.0, 400.0, 0.0), Vec3::new(600.0, 0.0, 0.0)];
    let (_, terms, _) = breakdown(&world_2d(), free_vehicle(), &p);
    close(term(&terms, "length"), 1.0 - 600.0 / 1000.0);
    // The same in 3-D, with a dive: L_straight = |(600, 0, -100)|, L_path = 2 |(300, 400, -50)|.
    let p = [Vec3::new(0.0, 0.0, -100.0), Vec3::new(300.0, 400.0, -150.0), Vec3::new(600.0, 0.0, -200.0)];
    let (_, terms, _) = breakdown(&world_3d(), free_vehicle(), &p);
    let straight = (600.0f64 * 600.0 + 100.0 * 100.0).sqrt();
    let path = 2.0 * (300.0f64 * 300.0 + 400.0 * 400.0 + 50.0 * 50.0).sqrt();
    close(term(&terms, "length"), 1.0 - straight / path);
    // A path of zero length (a mission whose start is its goal) has no length excess.
    let q = [Vec3::new(500.0, 500.0, -100.0), Vec3::new(500.0, 500.0, -100.0)];
    let (total, terms, _) = breakdown(&world_3d(), free_vehicle(), &q);
    close(term(&terms, "length"), 0.0);
    close(total, 0.5);
}

/// A joint whose interior angle is 20 degrees is unable: 1 of 2 segments, so 1/2 + 2.
/// The vehicle allows any turn, so tidepath calls the path feasible: the paper's rule is
/// stricter there.
#[test]
fn a_sharp_joint_costs_one_over_n_all_plus_two() {
    let wp = Vec3::new(1500.0, 1000.0, -50.0);
    let back = 160f64.to_radians();
    let g = wp + Vec3::new(back.cos(), back.sin(), 0.0) * 1000.0;
    let p = [Vec3::new(500.0, 1000.0, -50.0), wp, g];
    let (total, terms, feasible) = breakdown(&world_3d(), free_vehicle(), &p);
    close(term(&terms, "curvature"), 0.5 + 2.0);
    assert!(total >= FEASIBLE_BELOW && feasible);
    // At 40 degrees the joint is able.
    let back = 140f64.to_radians();
    let p = [p[0], wp, wp + Vec3::new(back.cos(), back.sin(), 0.0) * 1000.0];
    let (_, terms, _) = breakdown(&world_3d(), free_vehicle(), &p);
    close(term(&terms, "curvature"), 0.0);
    // T_theta is a parameter: at 150 degrees this joint is unable; with a 2-D path of
    // three unable joints out of four segments the term is 3/4 + 2.
    let c =
        Lfhh2019Cost::new(Lfhh2019Params { min_interior_angle_deg: 150.0, ..Default::default() }.checked("w").unwrap());
    let mission = Mission::new("m", free_vehicle(), p[0], p[2], 0.0);
    let settings = ModelSettings::default();
    let w = world_3d();
    let model = PathModel::new(&w, &mission, &settings);
    close(term(&c.breakdown(&model, &p).1, "curvature"), 0.5 + 2.0);
    let zig = [
        Vec3::new(0.0, 0.0, 0.0),
        Vec3::new(1000.0, 0.0, 0.0),
        Vec3::new(1000.0, 1000.0, 0.0),
        Vec3::new(2000.0, 1000.0, 0.0),
        Vec3::new(2000.0, 2000.0, 0.0),
    ];
    let w = world_2d();
    let mission = Mission::new("m", free_vehicle(), zig[0], zig[4], 0.0);
    let model = PathModel::new(&w, &mission, &settings);
    close(term(&c.breakdown(&model, &zig).1, "curvature"), 0.75 + 2.0);
    close(term(&cost().breakdown(&model, &zig).1, "curvature"), 0.0);
}

/// The interior angle is measured in 3-D: two steep dives whose horizontal directions
/// are opposite turn by about 11 degrees in 3-D (interior angle about 169): able.
#[test]
fn the_interior_angle_is_measured_in_3d() {
    let p = [Vec3::new(1000.0, 1000.0, -10.0), Vec3::new(1100.0, 1000.0, -510.0), Vec3::new(1000.0, 1000.0, -1000.0)];
    let (_, terms, feasible) = breakdown(&world_3d(), free_vehicle(), &p);
    close(term(&terms, "curvature"), 0.0);
    assert!(feasible);
    // Flattened to the plane it would be a 0 degree interior angle.
    let flat: Vec<Vec3> = p.iter().map(|q| Vec3::new(q.x, q.y, -10.0)).collect();
    let (_, terms, _) = breakdown(&world_3d(), free_vehicle(), &flat);
    close(term(&terms, "curvature"), 0.5 + 2.0);
}

/// The middle one of three segments crosses a circle: 1/3 + 2; its motion has no cost.
#[test]
fn a_segment_through_a_circle_is_blocked() {
    let mut w = world_2d();
    w.obstacles.push(Obstacle::fixed(Shape::Circle { center: Vec2::new(1500.0, 1000.0), radius: 100.0 }));
    let p = [
        Vec3::new(100.0, 1000.0, 0.0),
        Vec3::new(1000.0, 1000.0, 0.0),
        Vec3::new(2000.0, 1000.0, 0.0),
        Vec3::new(2900.0, 1000.0, 0.0),
    ];
    let (total, terms, feasible) = breakdown(&w, free_vehicle(), &p);
    close(term(&terms, "block"), 1.0 / 3.0 + 2.0);
    close(total, 1.0 / 3.0 + 2.0 + 0.5);
    assert!(!feasible);
    let mission = Mission::new("m", free_vehicle(), p[0], p[3], 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    assert!(cost().motion_cost(&model, p[1], p[2], 0.0).is_none());
    assert!(cost().motion_cost(&model, p[0], p[1], 0.0).is_some());
    // Passing within the safety distance (5 m) blocks too: 3 m from the circle.
    let q = [Vec3::new(100.0, 1103.0, 0.0), Vec3::new(2900.0, 1103.0, 0.0)];
    let (_, terms, _) = breakdown(&w, free_vehicle(), &q);
    close(term(&terms, "block"), 1.0 + 2.0);
}

/// A sphere in 3-D, the seabed and a waypoint out of the domain block their segments.
#[test]
fn spheres_the_seabed_and_the_domain_block() {
    let mut w = world_3d();
    w.terrain = Terrain::Peaks(GaussianPeaks { base: -500.0, peaks: vec![], ceiling: None });
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(1500.0, 1000.0, -200.0), radius: 100.0 }));
    let p = [
        Vec3::new(100.0, 1000.0, -200.0),
        Vec3::new(1000.0, 1000.0, -200.0),
        Vec3::new(2000.0, 1000.0, -200.0), // through the sphere
        Vec3::new(2200.0, 1000.0, -497.0), // within 5 m of the seabed
        Vec3::new(2400.0, 1000.0, -200.0),
        Vec3::new(2600.0, 3200.0, -200.0), // outside the box
        Vec3::new(2800.0, 1000.0, -200.0),
    ];
    let (_, terms, feasible) = breakdown(&w, free_vehicle(), &p);
    // Segments 1, 2, 3, 4 and 5 of 6.
    close(term(&terms, "block"), 5.0 / 6.0 + 2.0);
    assert!(!feasible);
}

/// A uniform current at 60 degrees from east: an eastward segment is 60 degrees from it
/// (1/3), a northward one 30 (1/6), a westward one 120 (2/3), a vertical one neutral.
#[test]
fn the_current_term_by_hand() {
    let mut w = world_3d();
    let a = 60f64.to_radians();
    w.current = Current::Uniform(Vec3::new(0.5 * a.cos(), 0.5 * a.sin(), 0.0));
    let p = [
        Vec3::new(1000.0, 1000.0, -100.0),
        Vec3::new(2000.0, 1000.0, -100.0),
        Vec3::new(2000.0, 2000.0, -100.0),
        Vec3::new(1500.0, 2000.0, -100.0),
        Vec3::new(1500.0, 2000.0, -300.0),
    ];
    let (_, terms, feasible) = breakdown(&w, free_vehicle(), &p);
    close(term(&terms, "current"), (1.0 / 3.0 + 1.0 / 6.0 + 2.0 / 3.0 + 0.5) / 4.0);
    // A vertical segment is steeper than any pitch limit, for tidepath and for the model.
    close(term(&terms, "curvature"), 0.25 + 2.0);
    assert!(!feasible);
    // Straight with the current: 0; straight against it: 1.
    let along =
        [Vec3::new(1000.0, 1000.0, -100.0), Vec3::new(1000.0 + 500.0 * a.cos(), 1000.0 + 500.0 * a.sin(), -100.0)];
    close(term(&breakdown(&w, free_vehicle(), &along).1, "current"), 0.0);
    let against = [along[1], along[0]];
    close(term(&breakdown(&w, free_vehicle(), &against).1, "current"), 1.0);
}

/// The current is read at the segment's midpoint: below a counter-clockwise vortex's
/// centre the flow runs east, along an eastward segment (alpha = 0), though at the
/// segment's ends it turns north and south. Through the centre, where the flow is zero,
/// the angle is neutral.
#[test]
fn the_current_is_read_at_the_midpoint() {
    let mut w = world_2d();
    let vortex = crate::world::current::LambOseen { x: 1500.0, y: 1000.0, strength: 50.0, core_radius: 50.0 };
    w.current = Current::Vortices(vec![vortex]);
    let p = [Vec3::new(1000.0, 900.0, 0.0), Vec3::new(2000.0, 900.0, 0.0)];
    let ends = w.current.velocity(p[0], 0.0).truncate();
    assert!(ends.y.abs() > 0.1 * ends.length(), "the flow at the ends is not along the segment");
    let (_, terms, _) = breakdown(&w, free_vehicle(), &p);
    close(term(&terms, "current"), 0.0);
    let through = [Vec3::new(1000.0, 1000.0, 0.0), Vec3::new(2000.0, 1000.0, 0.0)];
    let (_, terms, _) = breakdown(&w, free_vehicle(), &through);
    close(term(&terms, "current"), 0.5);
}

/// Flow below the threshold counts as none: the angle is neutral whatever the direction.
/// With a threshold of 0 the same weak flow is measured.
#[test]
fn practically_zero_flow_is_neutral() {
    let mut w = world_2d();
    w.current = Current::Uniform(Vec3::new(-1e-12, 0.0, 0.0));
    let p = [Vec3::new(100.0, 100.0, 0.0), Vec3::new(1100.0, 100.0, 0.0)];
    let (_, terms, _) = breakdown(&w, free_vehicle(), &p);
    close(term(&terms, "current"), 0.5);
    let c = Lfhh2019Cost::new(Lfhh2019Params { still_current: 0.0, ..Default::default() }.checked("w").unwrap());
    let mission = Mission::new("m", free_vehicle(), p[0], p[1], 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    close(term(&c.breakdown(&model, &p).1, "current"), 1.0);
    close(c.current_angle_ratio(Vec2::new(1.0, 0.0), Vec2::ZERO), 0.5);
}

/// The vehicle's own limits make joints unable: a 90 degree turn (interior angle 90, fine
/// for the paper) against a 60 degree limit, a 45 degree dive against a 30 degree limit,
/// and with a turning radius a turn whose fillet does not fit.
#[test]
fn a_joint_over_the_vehicles_limits_is_unable() {
    let w = world_3d();
    let limited = Vehicle { max_turn: 60f64.to_radians(), max_pitch: 30f64.to_radians(), ..free_vehicle() };
    let turn = [Vec3::new(500.0, 500.0, -100.0), Vec3::new(1500.0, 500.0, -100.0), Vec3::new(1500.0, 1500.0, -100.0)];
    let (_, terms, _) = breakdown(&w, free_vehicle(), &turn);
    close(term(&terms, "curvature"), 0.0);
    let (total, terms, feasible) = breakdown(&w, limited.clone(), &turn);
    close(term(&terms, "curvature"), 0.5 + 2.0);
    assert!(total >= FEASIBLE_BELOW && !feasible);
    // Level, then a 45 degree dive, then level: one steep segment of three.
    let dive = [
        Vec3::new(500.0, 500.0, -100.0),
        Vec3::new(1000.0, 500.0, -100.0),
        Vec3::new(1200.0, 500.0, -300.0),
        Vec3::new(2000.0, 500.0, -300.0),
    ];
    let (_, terms, _) = breakdown(&w, free_vehicle(), &dive);
    close(term(&terms, "curvature"), 0.0);
    let (_, terms, feasible) = breakdown(&w, limited.clone(), &dive);
    close(term(&terms, "curvature"), 1.0 / 3.0 + 2.0);
    assert!(!feasible);
    // 2-D has no pitch.
    let (_, terms, _) = breakdown(&world_2d(), limited, &[Vec3::new(0.0, 0.0, 0.0), Vec3::new(10.0, 0.0, 0.0)]);
    close(term(&terms, "curvature"), 0.0);
    // A 90 degree turn needs r of each leg: 100 m legs allow r = 100, not 200.
    let short = [Vec3::new(500.0, 500.0, -100.0), Vec3::new(600.0, 500.0, -100.0), Vec3::new(600.0, 600.0, -100.0)];
    let fits = Vehicle { turn_radius: Some(100.0), ..free_vehicle() };
    let (_, terms, feasible) = breakdown(&w, fits, &short);
    close(term(&terms, "curvature"), 0.0);
    assert!(feasible);
    let wide = Vehicle { turn_radius: Some(200.0), ..free_vehicle() };
    let (_, terms, feasible) = breakdown(&w, wide, &short);
    close(term(&terms, "curvature"), 0.5 + 2.0);
    assert!(!feasible);
}

/// A path that stops short of the goal blocks its last segment.
#[test]
fn a_path_off_its_mission_is_blocked() {
    let w = world_2d();
    let (s, g) = (Vec3::new(100.0, 100.0, 0.0), Vec3::new(2000.0, 100.0, 0.0));
    let mission = Mission::new("m", free_vehicle(), s, g, 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    let p = [s, Vec3::new(1000.0, 100.0, 0.0), Vec3::new(1500.0, 100.0, 0.0)];
    close(term(&cost().breakdown(&model, &p).1, "block"), 0.5 + 2.0);
    assert!(!model.assess(&p, &mut Vec::new()).feasible());
    // No segment at all: 3.
    close(cost().breakdown(&model, &[s]).0, 3.0);
    close(cost().breakdown(&model, &[]).0, 3.0);
}

/// The motion costs of a path add up to L_path / L_straight = 1 / (1 - C_length), and
/// the lower bound is below each.
#[test]
fn motion_costs_add_up_to_the_length_ratio() {
    let mut w = world_3d();
    w.current = Current::Uniform(Vec3::new(0.3, -0.2, 0.0));
    let p = [
        Vec3::new(100.0, 100.0, -50.0),
        Vec3::new(900.0, 700.0, -250.0),
        Vec3::new(1500.0, 800.0, -300.0),
        Vec3::new(2500.0, 2000.0, -100.0),
    ];
    let mission = Mission::new("m", free_vehicle(), p[0], p[3], 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    let c = cost();
    let (_, terms) = c.breakdown(&model, &p);
    let (mut t, mut sum) = (model.departure_time, 0.0);
    for s in p.windows(2) {
        let (cost, arrival) = c.motion_cost(&model, s[0], s[1], t).unwrap();
        assert!(cost >= c.motion_lower_bound(&model, s[0].distance(s[1]), 10.0) - 1e-15);
        close(cost, s[0].distance(s[1]) * c.cost_per_metre(&model).unwrap());
        sum += cost;
        t = arrival;
    }
    close(1.0 - 1.0 / sum, term(&terms, "length"));
    assert_eq!(c.additive_terms(), ["length"]);
    assert_eq!(c.feasible_below(), Some(2.0));
}

/// The paper's rule implies tidepath's: on random paths in a small world with a seabed,
/// spheres, a current and (sometimes) a turning radius, F < 2 never comes with a
/// violation. Both verdicts occur, so the check is not empty.
#[test]
fn f_below_two_implies_feasible_on_random_paths() {
    let mut rng = crate::rng::run_rng(7, 0);
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -400.0), Vec3::new(2000.0, 2000.0, 0.0)));
    w.terrain = Terrain::Peaks(GaussianPeaks {
        base: -380.0,
        peaks: vec![Peak { x: 1000.0, y: 1000.0, height: 200.0, sigma_x: 300.0, sigma_y: 300.0 }],
        ceiling: None,
    });
    for (x, y) in [(500.0, 1500.0), (1500.0, 500.0), (1400.0, 1500.0)] {
        w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(x, y, -150.0), radius: 150.0 }));
    }
    let c = cost();
    let settings = ModelSettings::default();
    let (mut below, mut above) = (0, 0);
    for k in 0..600 {
        w.current = match k % 3 {
            0 => Current::None,
            1 => Current::Uniform(Vec3::new(0.4, 0.1, 0.0)),
            _ => Current::Uniform(Vec3::new(-2.0, 1.5, 0.0)),
        };
        let v = Vehicle {
            max_turn: rng.random_range(30.0f64..180.0).to_radians(),
            max_pitch: rng.random_range(10.0f64..60.0).to_radians(),
            depth_max: 390.0,
            turn_radius: (k % 4 == 0).then_some(40.0),
            ..free_vehicle()
        };
        let point = |rng: &mut crate::rng::Rng| {
            Vec3::new(rng.random_range(0.0..2000.0), rng.random_range(0.0..2000.0), rng.random_range(-300.0..-20.0))
        };
        let (s, g) = (point(&mut rng), point(&mut rng));
        let n = rng.random_range(0..4usize);
        let mut p = vec![s];
        for _ in 0..n {
            // Mostly near the straight line, so some paths are feasible.
            let u = rng.random_range(0.0..1.0);
            let q = s.lerp(g, u) + (point(&mut rng) - Vec3::new(1000.0, 1000.0, -160.0)) * 0.1;
            p.push(q);
        }
        p.sort_by(|a, b| a.distance(s).total_cmp(&b.distance(s)));
        p.push(g);
        let mission = Mission::new("m", v, s, g, 0.0);
        let model = PathModel::new(&w, &mission, &settings);
        let f = c.cost(&model, &p, &mut Scratch::default());
        let feasible = model.assess(&p, &mut Vec::new()).feasible();
        if f < FEASIBLE_BELOW {
            assert!(feasible, "F = {f} < 2 but infeasible: {:?}", model.violations(&p));
            below += 1;
        } else {
            above += 1;
        }
    }
    assert!(below > 30 && above > 30, "F < 2 on {below} paths, F >= 2 on {above}");
}

/// Once the scratch has grown, evaluating again reuses it and gives the same terms.
#[test]
fn evaluation_reuses_the_scratch() {
    let w = world_3d();
    let p = [Vec3::new(100.0, 100.0, -50.0), Vec3::new(900.0, 700.0, -250.0), Vec3::new(2500.0, 2000.0, -100.0)];
    let mission = Mission::new("m", Vehicle { turn_radius: Some(50.0), ..free_vehicle() }, p[0], p[2], 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    let mut scratch = Scratch::default();
    let first = cost().cost(&model, &p, &mut scratch);
    let (cap_v, cap_t) = (scratch.values.capacity(), scratch.times.capacity());
    assert_eq!(cost().cost(&model, &p, &mut scratch), first);
    assert_eq!((scratch.values.capacity(), scratch.times.capacity()), (cap_v, cap_t));
}

#[test]
fn the_registry_builds_it_and_refuses_unknown_weights() {
    let reg = crate::cost::registry();
    let build = reg.get("lfhh2019").unwrap().build;
    let m = build(&toml::Table::new()).unwrap();
    assert_eq!((m.id(), m.feasible_below()), ("lfhh2019", Some(2.0)));
    assert_eq!(m.term_names(), ["length", "curvature", "block", "current"]);
    let t: toml::Table = toml::from_str("min_interior_angle_deg = 45.0\nstill_current = 1e-6").unwrap();
    build(&t).unwrap();
    let t: toml::Table = toml::from_str("length = 2.0").unwrap();
    let e = build(&t).err().unwrap().to_string();
    assert!(e.starts_with("cost.weights.length"), "{e}");
    let t: toml::Table = toml::from_str("min_interior_angle_deg = 200.0").unwrap();
    let e = build(&t).err().unwrap().to_string();
    assert!(e.starts_with("cost.weights.min_interior_angle_deg"), "{e}");
    // The other models keep no rule of their own.
    assert_eq!((reg.get("general").unwrap().build)(&toml::Table::new()).unwrap().feasible_below(), None);
}
