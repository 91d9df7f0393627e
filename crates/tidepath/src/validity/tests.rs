//! Hand-computed checks of the state and motion validators.

use super::*;
use crate::geom::{Aabb, Vec2};
use crate::world::current::{CurrentGrid, LambOseen};
use crate::world::terrain::{GaussianPeaks, Peak};
use crate::world::{Obstacle, RegularGrid2, Shape, Terrain};

fn world() -> World {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(1000.0, 1000.0, 0.0)));
    w.terrain = Terrain::Peaks(GaussianPeaks {
        base: -90.0,
        peaks: vec![Peak { x: 500.0, y: 500.0, height: 60.0, sigma_x: 50.0, sigma_y: 50.0 }],
        ceiling: None,
    });
    w
}

fn vehicle() -> Vehicle {
    Vehicle { speed: 2.0, safety_distance: 5.0, depth_min: 0.0, depth_max: 100.0, ..Vehicle::default() }
}

#[test]
fn state_issues_name_what_is_wrong() {
    let mut w = world();
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(100.0, 100.0, -50.0), radius: 10.0 }));
    w.obstacles.push(Obstacle {
        shape: Shape::Sphere { center: Vec3::new(0.0, 300.0, -50.0), radius: 10.0 },
        velocity: Vec3::new(1.0, 0.0, 0.0),
        window: None,
    });
    let (v, s) = (vehicle(), ModelSettings::default());
    let val = Validator::new(&w, &v, &s);
    assert_eq!(val.state(Vec3::new(200.0, 200.0, -50.0), 0.0), Ok(()));
    assert_eq!(val.state(Vec3::new(-1.0, 200.0, -50.0), 0.0), Err(StateIssue::OutsideDomain));
    // Seabed at -90 + 60 = -30 on the peak: -33 is 3 m below it.
    match val.state(Vec3::new(500.0, 500.0, -33.0), 0.0) {
        Err(StateIssue::Seabed { clearance }) => assert!((clearance + 3.0).abs() < 1e-9),
        other => panic!("{other:?}"),
    }
    assert_eq!(val.state(Vec3::new(100.0, 100.0, -50.0), 0.0), Err(StateIssue::Obstacle { index: 0, inside: true }));
    assert_eq!(val.state(Vec3::new(100.0, 113.0, -50.0), 0.0), Err(StateIssue::Obstacle { index: 0, inside: false }));
    // The moving sphere is at x = 100 at t = 100 s, and gone at t = 0.
    assert_eq!(val.state(Vec3::new(100.0, 300.0, -50.0), 0.0), Ok(()));
    assert!(val.state(Vec3::new(100.0, 300.0, -50.0), 100.0).is_err());
    assert_eq!(val.fixed_state(Vec3::new(100.0, 300.0, -50.0)), Ok(()));
    let msg = val.describe(Vec3::new(500.0, 500.0, -33.0), StateIssue::Seabed { clearance: -3.0 });
    assert!(msg.contains("below the seabed"), "{msg}");
}

#[test]
fn pieces_tile_the_segment_and_sum_to_the_travel_time() {
    let mut w = world();
    w.current = Current::Vortices(vec![LambOseen { x: 300.0, y: 200.0, strength: 400.0, core_radius: 80.0 }]);
    let v = vehicle();
    let s = ModelSettings { current_step: 30.0, ..ModelSettings::default() };
    let val = Validator::new(&w, &v, &s);
    let (a, b) = (Vec3::new(100.0, 150.0, -60.0), Vec3::new(600.0, 260.0, -60.0));
    let mut pieces = Vec::new();
    let (t1, blocked) = val.for_each_piece(a, b, 10.0, |p| pieces.push(p));
    assert_eq!(blocked, 0);
    assert_eq!(pieces.len(), (a.distance(b) / 30.0).ceil() as usize);
    assert_eq!(pieces[0].p0, a);
    assert_eq!(pieces.last().unwrap().p1, b);
    assert_eq!(pieces[0].t0, 10.0);
    for w in pieces.windows(2) {
        assert_eq!(w[0].p1, w[1].p0);
        assert_eq!(w[0].t1, w[1].t0);
    }
    assert_eq!(pieces.last().unwrap().t1, t1);
    assert!((val.travel_time(a, b, 10.0).0 - (t1 - 10.0)).abs() < 1e-12);
}

#[test]
fn uniform_current_time_is_the_crab_closed_form() {
    let mut w = world();
    w.terrain = Terrain::None;
    // Cross-current 1.2 with v = 2: ground speed 1.6; 800 m take 500 s.
    w.current = Current::Uniform(Vec3::new(0.0, 1.2, 0.0));
    let (v, s) = (vehicle(), ModelSettings::default());
    let val = Validator::new(&w, &v, &s);
    let m = val.motion(Vec3::new(100.0, 100.0, -50.0), Vec3::new(900.0, 100.0, -50.0), 0.0);
    assert!(m.valid());
    assert!((m.arrival - 500.0).abs() < 1e-9);
    // A cross-current of 2.5 > v stops the vehicle: one blocked piece, reported as an issue.
    w.current = Current::Uniform(Vec3::new(0.0, 2.5, 0.0));
    let val = Validator::new(&w, &v, &s);
    let m = val.motion(Vec3::new(100.0, 100.0, -50.0), Vec3::new(900.0, 100.0, -50.0), 0.0);
    assert_eq!((m.blocked, m.first), (1, Some(MotionIssue::Current { pieces: 1 })));
}

/// The clock matters: a current that is fast on the first half of a segment and still on the
/// second brings the vehicle to the far half early. A sphere moving across the track is met
/// there at the piecewise clock; a constant-speed clock over the whole segment would put the
/// vehicle elsewhere at that time and call the motion clear.
///
/// Motions of up to 32 pieces keep their pieces and test each obstacle after a box test over
/// the whole motion; longer ones are walked twice. Both are checked (20 and 100 pieces).
#[test]
fn moving_obstacles_are_tested_at_the_vehicle_clock() {
    for step in [50.0, 10.0] {
        moving_obstacle_met_at_the_vehicle_clock(step);
    }
}

fn moving_obstacle_met_at_the_vehicle_clock(step: f64) {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, -500.0, -100.0), Vec3::new(1000.0, 500.0, 0.0)));
    // u = 2 m/s (following) for x < 500, 0 beyond, constant in time; v = 2 m/s.
    let grid = RegularGrid2::new(0.0, -500.0, 500.0, 1000.0, 3, 2, "g").unwrap();
    let u = vec![vec![2.0, 2.0, 0.0, 2.0, 2.0, 0.0]];
    let vv = vec![vec![0.0; 6]];
    w.current = Current::Grid(CurrentGrid::new(grid, vec![0.0], u, vv, "g").unwrap());
    let (a, b) = (Vec3::new(0.0, 0.0, -50.0), Vec3::new(1000.0, 0.0, -50.0));
    let v = Vehicle { speed: 2.0, safety_distance: 1.0, ..Vehicle::default() };
    let s = ModelSettings { current_step: step, ..ModelSettings::default() };
    let clear = Validator::new(&w, &v, &s);
    let at = |t: f64| {
        let mut p = a;
        clear.for_each_piece(a, b, 0.0, |pc| {
            if pc.t0 <= t && t <= pc.t1 && pc.t1 > pc.t0 {
                p = pc.p0 + (pc.p1 - pc.p0) * ((t - pc.t0) / (pc.t1 - pc.t0));
            }
        });
        p
    };
    let (t_total, _) = clear.travel_time(a, b, 0.0);
    let t_meet = 0.6 * t_total;
    let where_it_is = at(t_meet);
    let constant_speed_guess = a + (b - a) * 0.6;
    assert!(where_it_is.distance(constant_speed_guess) > 50.0, "the test needs a clock that differs");
    // A small sphere crossing the track (moving in y) so that it is at the vehicle at t_meet.
    let speed = 5.0;
    let centre0 = Vec3::new(where_it_is.x, -speed * t_meet, -50.0);
    w.obstacles.push(Obstacle {
        shape: Shape::Sphere { center: centre0, radius: 3.0 },
        velocity: Vec3::new(0.0, speed, 0.0),
        window: None,
    });
    let val = Validator::new(&w, &v, &s);
    let m = val.motion(a, b, 0.0);
    assert_eq!((m.first, m.collisions), (Some(MotionIssue::Obstacle(0)), 1), "step {step}");
    assert!(val.motion_clearance(a, b, 0.0) < 1e-6);
    // Moved 100 m further along its way, it crosses the track long after the vehicle passed.
    let mut late = w.clone();
    late.obstacles[0].shape = Shape::Sphere { center: centre0 - Vec3::new(0.0, 100.0, 0.0), radius: 3.0 };
    assert!(Validator::new(&late, &v, &s).motion(a, b, 0.0).valid(), "step {step}");
    // The constant-speed reading of the whole segment misses it.
    assert!(!w.obstacles[0].segment_hits(a, b, 0.0, t_total, 1.0));
}

/// A forecast node without data makes the cells around it unusable: states there are invalid
/// and motions through them are refused, once per motion, while motions elsewhere pass.
/// The swept box of a moving obstacle, by hand: a unit cube at the origin moving at 1 m/s in
/// x covers x in [-1 + t0, 1 + t1] over [t0, t1].
#[test]
fn moving_obstacle_box_test_covers_its_sweep() {
    let o = Obstacle {
        shape: Shape::Box { min: Vec3::splat(-1.0), max: Vec3::splat(1.0) },
        velocity: Vec3::X,
        window: None,
    };
    let probe = |x: f64| (Vec3::new(x, -0.5, -0.5), Vec3::new(x + 0.1, 0.5, 0.5));
    let (lo, hi) = probe(5.5);
    assert!(o.may_come_within(lo, hi, 0.0, 5.0)); // reaches x = 6
    assert!(!o.may_come_within(lo, hi, 0.0, 4.0)); // reaches x = 5 only
    assert!(!o.may_come_within(lo, hi, 7.0, 9.0)); // already past: x in [6, 10]
    let (lo, hi) = probe(-3.0);
    assert!(!o.may_come_within(lo, hi, 0.0, 10.0)); // behind it
    assert!(o.may_come_within(lo, hi, -3.0, 0.0)); // it came from there
    assert!(o.may_come_within(lo, hi, f64::NAN, 1.0)); // undefined times keep the exact test
    assert!(o.may_come_within(lo, hi, 0.0, f64::INFINITY));
}

#[test]
fn current_gaps_refuse_states_and_motions_that_need_them() {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(400.0, 400.0, 0.0)));
    // 5 x 5 nodes 100 m apart; node (2, 2) at (200, 200) has no data.
    let grid = RegularGrid2::new(0.0, 0.0, 100.0, 100.0, 5, 5, "g").unwrap();
    let layer = vec![0.1; 25];
    let g = CurrentGrid::new(grid, vec![0.0], vec![layer.clone()], vec![layer], "g").unwrap();
    assert!(g.clone().with_gaps(vec![25], "world.current").unwrap_err().to_string().contains("world.current.no_data"));
    w.current = Current::Grid(g.with_gaps(vec![12], "g").unwrap());
    let v = Vehicle { speed: 2.0, safety_distance: 1.0, ..Vehicle::default() };
    let s = ModelSettings { current_step: 10.0, ..ModelSettings::default() };
    let val = Validator::new(&w, &v, &s);
    // Cells (1..3) x (1..3) touch the gap node; the node's own row and column at the cell edge too.
    assert_eq!(val.state(Vec3::new(150.0, 250.0, -50.0), 0.0), Err(StateIssue::NoCurrentData));
    assert_eq!(val.fixed_state(Vec3::new(250.0, 150.0, -50.0)), Err(StateIssue::NoCurrentData));
    assert_eq!(val.state(Vec3::new(50.0, 50.0, -50.0), 0.0), Ok(()));
    // On the line x = 100 the weight of column 2 is zero: data only.
    assert_eq!(val.state(Vec3::new(100.0, 250.0, -50.0), 0.0), Ok(()));
    assert!(val.describe(Vec3::new(150.0, 250.0, -50.0), StateIssue::NoCurrentData).contains("no current data"));
    // Along y = 50 (clear); along y = 150 from x = 0 to 400 it enters cell (1, 1) at x = 100,
    // reported at the middle of its stretch there.
    assert!(val.motion(Vec3::new(0.0, 50.0, -50.0), Vec3::new(400.0, 50.0, -50.0), 0.0).valid());
    let m = val.motion(Vec3::new(0.0, 150.0, -50.0), Vec3::new(400.0, 150.0, -50.0), 0.0);
    assert_eq!((m.gaps, m.first), (1, Some(MotionIssue::NoCurrentData)));
    assert_eq!(
        w.current.first_gap_on(Vec3::new(0.0, 150.0, 0.0), Vec3::new(400.0, 150.0, 0.0)),
        Some(Vec2::new(150.0, 150.0))
    );
    // A diagonal that clips the corner of cell (1, 1) by 1 m: far shorter than any sampling step.
    let clip = (Vec3::new(0.0, 201.0, -50.0), Vec3::new(201.0, 0.0, -50.0));
    assert!(!val.motion(clip.0, clip.1, 0.0).valid());
    let miss = (Vec3::new(0.0, 199.0, -50.0), Vec3::new(199.0, 0.0, -50.0));
    assert!(val.motion(miss.0, miss.1, 0.0).valid());
    // Backwards, vertical, and a point.
    assert!(!val.motion(Vec3::new(400.0, 150.0, -50.0), Vec3::new(0.0, 150.0, -50.0), 0.0).valid());
    assert!(!val.motion(Vec3::new(250.0, 0.0, -50.0), Vec3::new(250.0, 400.0, -50.0), 0.0).valid());
    assert!(val.motion(Vec3::new(50.0, 0.0, -50.0), Vec3::new(50.0, 400.0, -50.0), 0.0).valid());
    assert!(!val.motion(Vec3::new(250.0, 250.0, -50.0), Vec3::new(250.0, 250.0, -50.0), 0.0).valid());
}

/// A blocked motion is cut at its last valid point, to within the resolution, and the cut
/// motion is itself valid: a sphere of radius 10 at x = 300 with a 5 m safety distance blocks
/// the line y = 100 from x = 285 on (hand-computed).
#[test]
fn a_blocked_motion_is_cut_at_its_last_valid_point() {
    let mut w = world();
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(300.0, 100.0, -50.0), radius: 10.0 }));
    let (v, s) = (vehicle(), ModelSettings::default());
    let val = Validator::new(&w, &v, &s);
    let (a, b) = (Vec3::new(100.0, 100.0, -50.0), Vec3::new(400.0, 100.0, -50.0));
    for res in [25.0, 1.0, 0.01] {
        let (p, checks) = val.last_valid(a, b, 0.0, res);
        let p = p.unwrap();
        assert!(p.x <= 285.0 && p.x > 285.0 - res, "resolution {res}: cut at {p}");
        assert!(val.motion(a, p, 0.0).valid());
        // About log2(300 / res) bisections, plus the first check.
        assert!(checks as f64 <= (300.0_f64 / res).log2().ceil() + 2.0, "{checks} checks at {res}");
    }
    // A valid motion is not cut; a motion blocked within the resolution of its start has no cut.
    assert_eq!(val.last_valid(a, Vec3::new(200.0, 100.0, -50.0), 0.0, 1.0).0, None);
    assert_eq!(val.last_valid(Vec3::new(284.5, 100.0, -50.0), b, 0.0, 1.0).0, None);
}

fn glider() -> Vehicle {
    let g = crate::vehicle::GliderSpeed::default();
    Vehicle { safety_distance: 1.0, propulsion: crate::vehicle::Propulsion::WaveGlider(g), ..Vehicle::default() }
}

#[test]
fn a_glider_flies_at_the_regression_speed_whatever_the_travel_model() {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, 0.0), Vec3::new(4000.0, 4000.0, 0.0)));
    w.dims = Dims::Two;
    w.waves = crate::world::Waves::Uniform(2.0);
    w.current = Current::Uniform(Vec3::new(0.5, 0.3, 0.0));
    let v = glider();
    for travel in [TravelModel::Crab, TravelModel::VectorSum] {
        let s = ModelSettings { travel, ..ModelSettings::default() };
        let val = Validator::new(&w, &v, &s);
        // East: 0.1623 * 2 + 0.266 * 0.5 = 0.4576 m/s (the cross-current plays no part).
        let (t, blocked) = val.travel_time(Vec3::ZERO, Vec3::new(1000.0, 0.0, 0.0), 0.0);
        assert!((t - 1000.0 / 0.4576).abs() < 1e-9 && blocked == 0, "{t}");
        // West: 0.3246 - 0.133 = 0.1916 m/s.
        let (t, _) = val.travel_time(Vec3::new(1000.0, 0.0, 0.0), Vec3::ZERO, 0.0);
        assert!((t - 1000.0 / 0.1916).abs() < 1e-9, "{t}");
    }
    // Calm water and a head current that drives it back: blocked, flown at the floor.
    w.waves = crate::world::Waves::Uniform(0.5);
    w.current = Current::Uniform(Vec3::new(-0.4, 0.0, 0.0));
    let s = ModelSettings::default();
    let val = Validator::new(&w, &v, &s);
    let m = val.motion(Vec3::ZERO, Vec3::new(100.0, 0.0, 0.0), 0.0);
    assert_eq!(m.first, Some(MotionIssue::Current { pieces: 1 }));
    assert!((m.arrival - 100.0 / 0.05).abs() < 1e-9);
}

#[test]
fn a_glider_follows_gridded_waves_piece_by_piece_and_refuses_their_gaps() {
    let mut w = World::open(Aabb::new(Vec3::ZERO, Vec3::new(400.0, 400.0, 0.0)));
    w.dims = Dims::Two;
    // Waves of 1 m at x = 0 rising to 3 m at x = 400, steady.
    let grid = RegularGrid2::new(0.0, 0.0, 200.0, 200.0, 3, 3, "g").unwrap();
    let layer = vec![1.0, 2.0, 3.0, 1.0, 2.0, 3.0, 1.0, 2.0, 3.0];
    let waves = crate::world::waves::WaveGrid::new(grid, vec![0.0], vec![layer], "g").unwrap();
    w.waves = crate::world::Waves::Grid(waves.clone());
    let v = glider();
    let s = ModelSettings { current_step: 100.0, ..ModelSettings::default() };
    let val = Validator::new(&w, &v, &s);
    // Four pieces of 100 m at midpoints x = 50, 150, 250, 350: heights 1.25, 1.75, 2.25, 2.75.
    let expected: f64 = [1.25, 1.75, 2.25, 2.75].iter().map(|h| 100.0 / (0.1623 * h)).sum();
    let (t, _) = val.travel_time(Vec3::new(0.0, 200.0, 0.0), Vec3::new(400.0, 200.0, 0.0), 0.0);
    assert!((t - expected).abs() < 1e-9, "{t} vs {expected}");
    // A thruster vehicle ignores the waves: one piece at its speed.
    let auv = Vehicle { speed: 2.0, ..Vehicle::default() };
    let (t, _) = Validator::new(&w, &auv, &s).travel_time(Vec3::ZERO, Vec3::new(400.0, 0.0, 0.0), 0.0);
    assert_eq!(t, 200.0);
    // Node 8 (400, 400) without data: the glider may not enter the cell touching it, the AUV may.
    w.waves = crate::world::Waves::Grid(waves.with_gaps(vec![8], "g").unwrap());
    let val = Validator::new(&w, &v, &s);
    assert_eq!(val.state(Vec3::new(300.0, 300.0, 0.0), 0.0), Err(StateIssue::NoWaveData));
    assert!(val.describe(Vec3::new(300.0, 300.0, 0.0), StateIssue::NoWaveData).contains("no wave data"));
    let m = val.motion(Vec3::new(0.0, 100.0, 0.0), Vec3::new(400.0, 100.0, 0.0), 0.0);
    assert_eq!((m.gaps, m.first), (0, None));
    let m = val.motion(Vec3::new(0.0, 300.0, 0.0), Vec3::new(400.0, 300.0, 0.0), 0.0);
    assert_eq!((m.gaps, m.first), (1, Some(MotionIssue::NoWaveData)));
    assert_eq!(Validator::new(&w, &auv, &s).state(Vec3::new(300.0, 300.0, 0.0), 0.0), Ok(()));
}
