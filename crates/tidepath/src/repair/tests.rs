//! Hand-computed cases of the excluding and contracting operators, and the registry.

use super::*;
use crate::geom::{Aabb, Vec2};
use crate::mission::Mission;
use crate::path::ModelSettings;
use crate::vehicle::Vehicle;
use crate::world::grid::RegularGrid2;
use crate::world::terrain::{ElevationGrid, GaussianPeaks};
use crate::world::{Obstacle, Shape, Terrain, World};

/// Safety distance 1 m, margin 2 m: points land 3 m from the surfaces (plus 1e-9 of the
/// 100 m domain).
const SAFETY: f64 = 1.0;
const MARGIN: f64 = 2.0;
const REACH: f64 = SAFETY + MARGIN;
const TOL: f64 = 1e-6;

fn world3() -> World {
    World::open(Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(100.0, 100.0, 0.0)))
}

fn vehicle() -> Vehicle {
    Vehicle { safety_distance: SAFETY, depth_max: 100.0, max_turn: std::f64::consts::PI, ..Vehicle::default() }
}

/// Applies `repair` to start, `p`, goal in `world`; returns the moved path.
fn run(world: &World, repair: &dyn Repair, path: &[Vec3]) -> Vec<Vec3> {
    let mission = Mission::new("m", vehicle(), path[0], *path.last().unwrap(), 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(world, &mission, &settings);
    let mut out = path.to_vec();
    repair.apply(&model, &mut out);
    out
}

fn exclude() -> Exclude {
    // The point pass alone: the hand-computed pushes below are of single points.
    Exclude::with_margin(Some(MARGIN), false)
}

fn assert_close(a: Vec3, b: Vec3) {
    assert!(a.distance(b) < TOL, "{a} vs {b}");
}

/// One interior point excluded from `shape`, between two far-away endpoints.
fn excluded_from(world: &mut World, shape: Shape, p: Vec3) -> Vec3 {
    world.obstacles.push(Obstacle::fixed(shape));
    let path = [Vec3::new(5.0, 5.0, -50.0), p, Vec3::new(95.0, 5.0, -50.0)];
    let out = run(world, &exclude(), &path);
    assert_eq!((out[0], out[2]), (path[0], path[2]));
    out[1]
}

#[test]
fn sphere_pushes_radially() {
    let mut w = world3();
    let c = Vec3::new(50.0, 50.0, -50.0);
    // 2 m east of the centre: to 10 + 3 m east.
    let q = excluded_from(&mut w, Shape::Sphere { center: c, radius: 10.0 }, Vec3::new(52.0, 50.0, -50.0));
    assert_close(q, Vec3::new(50.0 + 10.0 + REACH, 50.0, -50.0));
    // Outside the sphere but within the safety distance (10.5 m from the centre, along (3,4,0)/5).
    let p = c + Vec3::new(3.0, 4.0, 0.0) * (10.5 / 5.0);
    let q = run(&w, &exclude(), &[Vec3::new(5.0, 5.0, -50.0), p, Vec3::new(95.0, 5.0, -50.0)])[1];
    assert_close(q, c + Vec3::new(3.0, 4.0, 0.0) * (13.0 / 5.0));
}

#[test]
fn box_pushes_through_the_nearest_face() {
    let mut w = world3();
    let shape = Shape::Box { min: Vec3::new(40.0, 40.0, -60.0), max: Vec3::new(60.0, 70.0, -40.0) };
    // Depths to the faces: x 5 / 15, y 15 / 15, z 10 / 10: out through x = 40.
    let q = excluded_from(&mut w, shape.clone(), Vec3::new(45.0, 55.0, -50.0));
    assert_close(q, Vec3::new(40.0 - REACH, 55.0, -50.0));
    // Nearest face the top (z = -40, 2 m away).
    let q =
        run(&w, &exclude(), &[Vec3::new(5.0, 5.0, -50.0), Vec3::new(50.0, 55.0, -42.0), Vec3::new(95.0, 5.0, -50.0)])
            [1];
    assert_close(q, Vec3::new(50.0, 55.0, -40.0 + REACH));
    // Half a metre outside the x = 60 face (within the safety distance): to 3 m from it.
    let q =
        run(&w, &exclude(), &[Vec3::new(5.0, 5.0, -50.0), Vec3::new(60.5, 55.0, -50.0), Vec3::new(95.0, 5.0, -50.0)])
            [1];
    assert_close(q, Vec3::new(60.0 + REACH, 55.0, -50.0));
}

#[test]
fn cylinder_pushes_through_the_side_or_a_cap() {
    let mut w = world3();
    let shape = Shape::Cylinder { center: Vec2::new(50.0, 50.0), radius: 10.0, z_min: -80.0, z_max: -20.0 };
    // Side: 8 m to the side, 30 m to either cap.
    let q = excluded_from(&mut w, shape, Vec3::new(52.0, 50.0, -50.0));
    assert_close(q, Vec3::new(50.0 + 10.0 + REACH, 50.0, -50.0));
    // Top cap: 9 m to the side, 1 m to the top.
    let q =
        run(&w, &exclude(), &[Vec3::new(5.0, 5.0, -50.0), Vec3::new(50.0, 51.0, -21.0), Vec3::new(95.0, 5.0, -50.0)])
            [1];
    assert_close(q, Vec3::new(50.0, 51.0, -20.0 + REACH));
    // Bottom cap: 1 m above z_min.
    let q =
        run(&w, &exclude(), &[Vec3::new(5.0, 5.0, -50.0), Vec3::new(51.0, 50.0, -79.0), Vec3::new(95.0, 5.0, -50.0)])
            [1];
    assert_close(q, Vec3::new(51.0, 50.0, -80.0 - REACH));
}

#[test]
fn full_depth_cylinder_never_uses_its_infinite_caps() {
    let mut w = world3();
    let shape =
        Shape::Cylinder { center: Vec2::new(50.0, 50.0), radius: 10.0, z_min: f64::NEG_INFINITY, z_max: f64::INFINITY };
    let q = excluded_from(&mut w, shape, Vec3::new(50.0, 41.0, -1.0));
    assert_close(q, Vec3::new(50.0, 50.0 - 10.0 - REACH, -1.0));
}

#[test]
fn circle_in_a_2d_world_pushes_in_the_plane() {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -10.0), Vec3::new(100.0, 100.0, -10.0)));
    w.dims = crate::world::Dims::Two;
    w.obstacles.push(Obstacle::fixed(Shape::Circle { center: Vec2::new(50.0, 50.0), radius: 10.0 }));
    let path = [Vec3::new(5.0, 5.0, -10.0), Vec3::new(50.0, 45.0, -10.0), Vec3::new(95.0, 5.0, -10.0)];
    let out = run(&w, &exclude(), &path);
    assert_close(out[1], Vec3::new(50.0, 50.0 - 10.0 - REACH, -10.0));
    // A sphere met in the plane z = -10 from its centre at z = -14: a disc of radius
    // sqrt(13^2 - 4^2) once grown by the safety distance and the margin.
    let mut w2 = w.clone();
    w2.obstacles = vec![Obstacle::fixed(Shape::Sphere { center: Vec3::new(50.0, 50.0, -14.0), radius: 10.0 })];
    let out = run(&w2, &exclude(), &path);
    assert_close(out[1], Vec3::new(50.0, 50.0 - (13.0f64 * 13.0 - 16.0).sqrt(), -10.0));
}

#[test]
fn flat_seabed_raises_the_point() {
    let mut w = world3();
    w.terrain = Terrain::Peaks(GaussianPeaks { base: -90.0, peaks: vec![], ceiling: None });
    let path = [Vec3::new(5.0, 5.0, -50.0), Vec3::new(50.0, 50.0, -90.5), Vec3::new(95.0, 5.0, -50.0)];
    let out = run(&w, &exclude(), &path);
    assert_close(out[1], Vec3::new(50.0, 50.0, -90.0 + REACH));
}

#[test]
fn sloped_seabed_pushes_along_its_normal() {
    // A plane seabed h = -90 + x / 2 (bilinear grid, exact): at x = 40, h = -70.
    let g = RegularGrid2::new(0.0, 0.0, 50.0, 50.0, 3, 3, "g").unwrap();
    let row = [-90.0, -65.0, -40.0];
    let z: Vec<f64> = (0..3).flat_map(|_| row).collect();
    let mut w = world3();
    w.terrain = Terrain::Grid(ElevationGrid::new(g, z, "g").unwrap());
    // 1 m below the seabed: the deficit is 3 - (-1) = 4 m; with h_x = 1/2 the move is
    // 4 / 1.25 (-1/2, 0, 1) = (-1.6, 0, 3.2).
    let path = [Vec3::new(5.0, 5.0, -50.0), Vec3::new(40.0, 50.0, -71.0), Vec3::new(95.0, 5.0, -10.0)];
    let out = run(&w, &exclude(), &path);
    assert_close(out[1], Vec3::new(38.4, 50.0, -67.8));
    // The vertical clearance there is exactly the safety distance plus the margin.
    let h = w.terrain.elevation(out[1].x, out[1].y);
    assert!((out[1].z - h - REACH).abs() < TOL);
}

/// Every segment of `path` clear of the seabed and obstacles in `w` (start at t = 0).
fn all_segments_valid(w: &World, path: &[Vec3]) -> bool {
    let mission = Mission::new("m", vehicle(), path[0], *path.last().unwrap(), 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(w, &mission, &settings);
    // Motions only (the seabed and obstacles): pitch and turn limits are not the operator's.
    let mut t = 0.0;
    path.windows(2).all(|w| {
        let m = model.validator.motion(w[0], w[1], t);
        t = m.arrival;
        m.valid()
    })
}

/// Two clear route points whose chord cuts a sphere, a cylinder or a ridge of the seabed: the
/// segment pass moves the chord out, so every segment ends valid; the start and goal stay.
#[test]
fn chords_through_an_envelope_are_pushed_out() {
    let shapes = [
        Shape::Sphere { center: Vec3::new(50.0, 50.0, -50.0), radius: 10.0 },
        Shape::Cylinder { center: Vec2::new(50.0, 50.0), radius: 10.0, z_min: f64::NEG_INFINITY, z_max: f64::INFINITY },
        Shape::Box { min: Vec3::new(45.0, 45.0, -60.0), max: Vec3::new(55.0, 55.0, -40.0) },
    ];
    let path = [
        Vec3::new(5.0, 40.0, -50.0),
        Vec3::new(30.0, 40.0, -50.0),
        Vec3::new(70.0, 40.0, -50.0),
        Vec3::new(95.0, 40.0, -50.0),
    ];
    for shape in shapes {
        let mut w = world3();
        // At y = 48 the chord from x = 30 to 70 crosses all three shapes; its ends are clear.
        let p: Vec<Vec3> = path.iter().map(|q| Vec3::new(q.x, 48.0, q.z)).collect();
        w.obstacles.push(Obstacle::fixed(shape.clone()));
        assert!(!all_segments_valid(&w, &p), "{shape:?}: the set-up must cut the shape");
        let out = run(&w, &Exclude::with_margin(Some(MARGIN), true), &p);
        assert_eq!((out[0], out[3]), (p[0], p[3]), "{shape:?}");
        assert!(all_segments_valid(&w, &out), "{shape:?}: {out:?}");
    }
    // A seabed ridge h = -40 at x = 50 falling to -90 at x = 25 and 75 (a tent of two planes
    // on a grid): the chord at z = -50 from x = 30 to 70 cuts it, both ends clear.
    let g = RegularGrid2::new(0.0, 0.0, 25.0, 50.0, 5, 3, "g").unwrap();
    let row = [-90.0, -90.0, -40.0, -90.0, -90.0];
    let z: Vec<f64> = (0..3).flat_map(|_| row).collect();
    let mut w = world3();
    w.terrain = Terrain::Grid(ElevationGrid::new(g, z, "g").unwrap());
    let p = [
        Vec3::new(5.0, 50.0, -70.0),
        Vec3::new(30.0, 50.0, -50.0),
        Vec3::new(70.0, 50.0, -50.0),
        Vec3::new(95.0, 50.0, -70.0),
    ];
    assert!(!all_segments_valid(&w, &p));
    let out = run(&w, &Exclude::with_margin(Some(MARGIN), true), &p);
    assert!(all_segments_valid(&w, &out), "{out:?}");
    assert_eq!((out[0], out[3]), (p[0], p[3]));
}

#[test]
fn outside_points_and_endpoints_are_untouched() {
    let mut w = world3();
    // The start and the goal inside spheres: they still never move.
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(5.0, 5.0, -50.0), radius: 3.0 }));
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(50.0, 50.0, -50.0), radius: 10.0 }));
    let path = [
        Vec3::new(5.0, 5.0, -50.0),
        Vec3::new(50.0, 64.0, -50.0),
        Vec3::new(30.0, 30.0, -30.0),
        Vec3::new(95.0, 95.0, -50.0),
    ];
    for r in [&exclude() as &dyn Repair, &Contract::default(), &ExcludeContract::default()] {
        let out = run(&w, r, &path);
        assert_eq!((out[0], out[3]), (path[0], path[3]), "{}", r.id());
    }
    assert_eq!(run(&w, &exclude(), &path), path);
}

#[test]
fn moving_sphere_is_met_where_it_is_on_arrival() {
    let mut w = world3();
    // Centre (50, 50, -50) at t = 0 moving +x at 1 m/s; the vehicle (1.5 m/s) reaches the
    // point (60, 50, -50) from (15, 50, -50) after 30 s, when the centre is at (80, 50, -50).
    w.obstacles.push(Obstacle::moving(
        Shape::Sphere { center: Vec3::new(50.0, 50.0, -50.0), radius: 10.0 },
        Vec3::new(1.0, 0.0, 0.0),
    ));
    let path = [Vec3::new(15.0, 50.0, -50.0), Vec3::new(60.0, 50.0, -50.0), Vec3::new(15.0, 90.0, -50.0)];
    assert_eq!(run(&w, &exclude(), &path), path, "the sphere has moved on by then");
    // At (75, 50, -50) it arrives after 40 s, the centre at (90, 50, -50): pushed west to 13 m.
    let path = [Vec3::new(15.0, 50.0, -50.0), Vec3::new(75.0, 50.0, -50.0), Vec3::new(15.0, 90.0, -50.0)];
    let q = run(&w, &exclude(), &path)[1];
    assert!(q.x < 90.0 - 10.0 - SAFETY, "{q}");
}

#[test]
fn default_margin_is_one_percent_of_the_depth_range() {
    let mut w = world3();
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(50.0, 50.0, -50.0), radius: 10.0 }));
    let path = [Vec3::new(5.0, 5.0, -50.0), Vec3::new(52.0, 50.0, -50.0), Vec3::new(95.0, 5.0, -50.0)];
    let out = run(&w, &Exclude::with_margin(None, false), &path);
    // Depth range 100 m: margin 1 m.
    assert_close(out[1], Vec3::new(50.0 + 10.0 + SAFETY + 1.0, 50.0, -50.0));
}

#[test]
fn pushed_into_a_second_obstacle_the_point_is_pushed_again() {
    let mut w = world3();
    // Out of the sphere eastward lands in the box east of it; the box then pushes it out
    // through its nearest face.
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(50.0, 50.0, -50.0), radius: 10.0 }));
    w.obstacles
        .push(Obstacle::fixed(Shape::Box { min: Vec3::new(58.0, 48.0, -52.0), max: Vec3::new(70.0, 52.0, -48.0) }));
    let path = [Vec3::new(5.0, 5.0, -50.0), Vec3::new(52.0, 50.0, -50.0), Vec3::new(95.0, 5.0, -50.0)];
    let out = run(&w, &exclude(), &path);
    let mission = Mission::new("m", vehicle(), path[0], path[2], 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    assert!(model.validator.state(out[1], 0.0).is_ok(), "{}", out[1]);
}

#[test]
fn contracting_one_point_moves_it_k_of_the_way() {
    let w = world3();
    let path = [Vec3::new(0.0, 0.0, -50.0), Vec3::new(50.0, 10.0, -50.0), Vec3::new(100.0, 0.0, -50.0)];
    let out = run(&w, &Contract::default(), &path);
    assert_close(out[1], Vec3::new(50.0, 10.0 * (1.0 - RESISTANCE), -50.0));
}

#[test]
fn contracting_shortens_a_zigzag_and_keeps_the_endpoints() {
    let w = world3();
    let path: Vec<Vec3> =
        (0..=10).map(|i| Vec3::new(5.0 + 9.0 * i as f64, if i % 2 == 1 { 70.0 } else { 30.0 }, -50.0)).collect();
    let mut prev = PathModel::length(&path);
    let mut cur = path.clone();
    for _ in 0..3 {
        cur = run(&w, &Contract::default(), &cur);
        let len = PathModel::length(&cur);
        assert!(len < prev, "{len} >= {prev}");
        prev = len;
        assert_eq!((cur[0], cur[10]), (path[0], path[10]));
    }
    // Sequential: point 1 moves toward (start + old point 2) / 2 = (14, 30): y = 70 - k 40.
    let once = run(&w, &Contract::default(), &path);
    assert_close(once[1], Vec3::new(14.0, 70.0 - RESISTANCE * 40.0, -50.0));
    // Point 2 then moves toward (new point 1 + old point 3) / 2.
    let mid = (once[1] + path[3]) * 0.5;
    assert_close(once[2], path[2] + (mid - path[2]) * RESISTANCE);
}

#[test]
fn contracting_never_moves_a_point_into_an_obstacle() {
    let mut w = world3();
    // The neighbours' midpoint (50, 0, -50) is the sphere's centre: the pull would end at
    // y = 20 (1 - k) = 0.894, inside; the point stays.
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(50.0, 2.0, -50.0), radius: 5.0 }));
    let path = [Vec3::new(0.0, 0.0, -50.0), Vec3::new(50.0, 20.0, -50.0), Vec3::new(100.0, 0.0, -50.0)];
    assert_eq!(run(&w, &Contract::default(), &path), path);
    // Nor below the seabed: the midpoint lies under it.
    let mut w = world3();
    w.terrain = Terrain::Peaks(GaussianPeaks { base: -60.0, peaks: vec![], ceiling: None });
    let path = [Vec3::new(0.0, 0.0, -58.0), Vec3::new(50.0, 0.0, -40.0), Vec3::new(100.0, 0.0, -100.0)];
    assert_eq!(run(&w, &Contract::default(), &path)[1], path[1]);
}

/// The pulled point's new place (50, 1.79) is free, but the chord from the first neighbour to
/// it passes (25, 0.89), 2.1 m from a sphere's centre at (25, 3), inside its radius 1.5 plus the
/// 1 m safety distance; the old chords pass 13 m and more from it. The pull is undone; without
/// the sphere it is made.
#[test]
fn contracting_never_makes_a_valid_segment_cut_an_obstacle() {
    let path = [Vec3::new(0.0, 0.0, -50.0), Vec3::new(50.0, 40.0, -50.0), Vec3::new(100.0, 0.0, -50.0)];
    let target = Vec3::new(50.0, 40.0 * (1.0 - RESISTANCE), -50.0);
    let mut w = world3();
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(25.0, 3.0, -50.0), radius: 1.5 }));
    let mission = Mission::new("m", vehicle(), path[0], path[2], 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    // The set-up: every point valid, the old segments valid, the new first segment not.
    assert!(model.validator.state(target, 0.0).is_ok());
    assert!(model.validator.motion(path[0], path[1], 0.0).valid());
    assert!(model.validator.motion(path[1], path[2], 0.0).valid());
    assert!(!model.validator.motion(path[0], target, 0.0).valid());
    assert_eq!(run(&w, &Contract::default(), &path), path);
    assert_close(run(&world3(), &Contract::default(), &path)[1], target);
}

#[test]
fn every_repair_builds_with_defaults_and_rejects_bad_parameters() {
    for e in REPAIRS {
        let r = build_repair(e.id, None).unwrap();
        assert_eq!(r.id(), e.id);
        let r = build_repair(e.id, Some(&e.defaults())).unwrap();
        assert_eq!(r.id(), e.id);
        let prefix = format!("encoding.repair_params.{}", e.id);
        let mut t = toml::Table::new();
        t.insert("bogus".into(), toml::Value::Float(1.0));
        let err = build_repair(e.id, Some(&t)).err().unwrap().to_string();
        assert!(err.starts_with(&prefix), "{err}");
        for spec in e.params {
            let mut t = toml::Table::new();
            t.insert(spec.name.into(), toml::Value::Float(-1.0));
            let err = build_repair(e.id, Some(&t)).err().unwrap().to_string();
            assert!(err.starts_with(&format!("{prefix}.{}", spec.name)), "{err}");
            assert!(!err.contains('\n'), "{err}");
        }
    }
    let err = build_repair("x", None).err().unwrap().to_string();
    assert!(
        err.starts_with("encoding.repair: unknown repair 'x' (known: exclude, contract, exclude-contract"),
        "{err}"
    );
}
