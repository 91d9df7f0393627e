//! Hand-computed checks of the ijs2023 terms (eqs. 15-24): U(θ) and its maximum, eq. 17's time
//! against closed forms, the safety factor for each shape and the seabed, the target window,
//! a whole Fit, the motion costs and the parameter rules.

use super::*;
use crate::cost::test_support::{assert_refused, close, flat, free_vehicle as vehicle, open_world, term};
use crate::mission::Mission;
use crate::path::{ModelSettings, TravelModel};
use crate::vehicle::Vehicle;
use crate::world::current::LambOseen;
use crate::world::terrain::{GaussianPeaks, Peak, Terrain};
use crate::world::{Obstacle, Shape, World};
use rand::Rng as _;
use std::f64::consts::{FRAC_PI_2, PI};

fn params(table: &str) -> Result<Checked<Ijs2023Params>> {
    let t: toml::Table = toml::from_str(table).unwrap();
    Ijs2023Params::from_table(&t, "cost.weights")
}

fn cost_with(table: &str) -> Ijs2023Cost {
    Ijs2023Cost::new(params(table).unwrap())
}

fn deg(d: f64) -> f64 {
    d.to_radians()
}

/// Total, terms and raw parts for a mission from the first to the last point of `p`.
fn judge(cost: &Ijs2023Cost, w: &World, v: Vehicle, p: &[Vec3]) -> (f64, Vec<(&'static str, f64)>, Ijs2023Parts) {
    let mission = Mission::new("m", v, p[0], *p.last().unwrap(), 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(w, &mission, &settings);
    let (total, terms) = cost.breakdown(&model, p);
    (total, terms, cost.parts(&model, p))
}

/// The paper's sample values (docs/papers/ijs2023.md), to three decimals.
#[test]
fn u_at_the_papers_angles() {
    for (d, want) in [(0.0, 0.0), (60.0, 0.342), (90.0, 1.625), (135.0, 0.385), (180.0, 0.650)] {
        let u = current_penalty(deg(d));
        assert!((u - want).abs() < 5e-4, "U({d}) = {u}, paper {want}");
    }
    // Exactly: 1.5 + sin(30)^3 at 90 degrees, sin(60)^3 at 180.
    close(current_penalty(FRAC_PI_2), 1.625);
    assert!((current_penalty(PI) - 0.75f64.sqrt().powi(3)).abs() < 1e-15);
}

/// U's maximum over [0, pi] by a scan and golden-section search: 1.62642 at 90.75 degrees
/// (A6), the constant the model divides by.
#[test]
fn u_max_is_found_numerically() {
    let n = 18_000;
    let k = (0..=n).max_by(|&a, &b| {
        current_penalty(PI * a as f64 / n as f64).total_cmp(&current_penalty(PI * b as f64 / n as f64))
    });
    let k = k.unwrap() as f64;
    let (mut a, mut b) = (PI * (k - 1.0) / n as f64, PI * (k + 1.0) / n as f64);
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..200 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if current_penalty(c) > current_penalty(d) {
            b = d;
        } else {
            a = c;
        }
    }
    let theta = 0.5 * (a + b);
    assert!((current_penalty(theta) - U_MAX).abs() < 1e-14, "{}", current_penalty(theta));
    assert!((theta.to_degrees() - 90.75).abs() < 0.005, "{}", theta.to_degrees());
    assert_eq!(format!("{U_MAX:.5}"), "1.62642");
}

/// A straight path along, against and across a uniform current c = 0.5 m/s, vehicle 2 m/s:
/// eq. 17 gives L / (v + c), L / (v - c) and L / sqrt(v^2 + c^2) (the vector sum, not the
/// crab model's L / sqrt(v^2 - c^2)). ϖ_tmin = |SG| / (v + c).
#[test]
fn time_in_a_uniform_current_against_the_closed_form() {
    let (v, c, l) = (2.0, 0.5, 2000.0);
    let s = Vec3::new(500.0, 500.0, -300.0);
    // Four collinear segments: the sum is the same.
    let path = |dir: Vec3| (0..=4).map(|k| s + dir * (l * k as f64 / 4.0)).collect::<Vec<_>>();
    let cost = cost_with("");
    for (current, want) in [
        (Vec3::new(c, 0.0, 0.0), l / (v + c)),
        (Vec3::new(-c, 0.0, 0.0), l / (v - c)),
        (Vec3::new(0.0, c, 0.0), l / (v * v + c * c).sqrt()),
        // A vertical component is ignored (A9).
        (Vec3::new(c, 0.0, 0.3), l / (v + c)),
    ] {
        let mut w = open_world();
        w.current = Current::Uniform(current);
        let (total, terms, x) = judge(&cost, &w, vehicle(v, 0.0), &path(Vec3::X));
        close(x.travel_time, want);
        close(x.time_min, l / (v + c));
        // F_t = (ϖ_t - ϖ_tmin) / (2 ϖ_tmin - ϖ_tmin).
        close(x.f_t, (want - l / (v + c)) / (l / (v + c)));
        close(term(&terms, "time"), x.f_t);
        close(total, x.f_t);
    }
    // Still water: L / v, and F_t = (L/v - L/v) / (L/v) = 0 on the straight path.
    let (total, _, x) = judge(&cost, &open_world(), vehicle(v, 0.0), &path(Vec3::Y));
    close(x.travel_time, l / v);
    close(total, 0.0);
    // tmax_factor 3: F_t halves.
    let mut w = open_world();
    w.current = Current::Uniform(Vec3::new(-c, 0.0, 0.0));
    let (_, _, x) = judge(&cost_with("tmax_factor = 3.0"), &w, vehicle(v, 0.0), &path(Vec3::X));
    close(x.f_t, 0.5 * (l / (v - c) - l / (v + c)) / (l / (v + c)));
}

/// In a current that varies in space, eq. 17 averages the two ends' speeds: a segment from
/// still water into a following current of 1 m/s at 2 m/s takes L/(2 * 2) + L/(2 * 3).
/// The head current is floored at 0.05 v.
#[test]
fn eq_17_averages_the_ends_and_floors_the_speed() {
    // A vortex far away would do; a uniform current cannot differ at the ends, so use a
    // Lamb-Oseen vortex and read its velocities back.
    let mut w = open_world();
    w.current = Current::Vortices(vec![LambOseen { x: 1500.0, y: 1500.0, strength: 20000.0, core_radius: 300.0 }]);
    let (a, b) = (Vec3::new(1000.0, 1500.0, -100.0), Vec3::new(1000.0, 2200.0, -100.0));
    let v = 1.5;
    let cost = cost_with("");
    let (_, _, x) = judge(&cost, &w, vehicle(v, 0.0), &[a, b]);
    let d = (b - a) / 700.0;
    let ca = w.current.velocity(a, 0.0);
    let va = (d * v + ca).length();
    let vb = (d * v + w.current.velocity(b, 0.0)).length();
    close(x.travel_time, 700.0 / (2.0 * va) + 700.0 / (2.0 * vb));
    // A head current of 1.49 m/s against 1.5: |v| = 0.01, floored at 0.075.
    let mut w = open_world();
    w.current = Current::Uniform(Vec3::new(-1.49, 0.0, 0.0));
    let (_, _, x) = judge(&cost, &w, vehicle(v, 0.0), &[a, a + Vec3::X * 150.0]);
    close(x.travel_time, 150.0 / 0.075);
}

/// Under `[model] travel = "vector-sum"` the clock is the validator's, bit for bit: the
/// travel time eval reports is ϖ_t (vortices, several segments, a speed per segment).
#[test]
fn the_clock_is_the_vector_sum_models() {
    let mut w = open_world();
    w.current = Current::Vortices(vec![
        LambOseen { x: 800.0, y: 1200.0, strength: 9000.0, core_radius: 400.0 },
        LambOseen { x: 2200.0, y: 1800.0, strength: -7000.0, core_radius: 300.0 },
    ]);
    let p = [
        Vec3::new(100.0, 100.0, -200.0),
        Vec3::new(900.0, 1500.0, -300.0),
        Vec3::new(1800.0, 1700.0, -250.0),
        Vec3::new(2900.0, 2900.0, -200.0),
    ];
    let mut veh = vehicle(1.5, 0.0);
    veh.speed_range = Some((0.5, 2.0));
    let mission = Mission::new("m", veh, p[0], p[3], 250.0);
    let settings = ModelSettings { travel: TravelModel::VectorSum, ..ModelSettings::default() };
    let base = PathModel::new(&w, &mission, &settings);
    let speeds = [1.0, 2.0, 0.7];
    let model = base.with_speeds(Some(&speeds));
    let mut times = Vec::new();
    model.arrival_times(&p, &mut times);
    let x = cost_with("").parts(&model, &p);
    assert!((x.travel_time - (times[3] - 250.0)).abs() < 1e-12 * x.travel_time);
    // ϖ_tmin divides by the top of the speed range plus the peak current.
    close(x.time_min, p[0].distance(p[3]) / (2.0 + peak_current(&model)));
}

/// max |v_c| is the world's hint at the departure time, computed once per world and thread;
/// another field is another entry, and `max_current_speed` replaces it.
#[test]
fn the_peak_current_is_cached_per_world() {
    let mut w = open_world();
    w.current = Current::Vortices(vec![LambOseen { x: 1500.0, y: 1500.0, strength: 8000.0, core_radius: 250.0 }]);
    let s = Vec3::new(100.0, 100.0, -100.0);
    let mission = Mission::new("m", vehicle(1.5, 0.0), s, Vec3::new(2900.0, 100.0, -100.0), 0.0);
    let settings = ModelSettings::default();
    let before = peak::cached();
    let peak = {
        let model = PathModel::new(&w, &mission, &settings);
        let p = peak_current(&model);
        assert_eq!(p, w.current.max_speed_hint(&w.bounds, 0.0));
        assert_eq!(peak::cached(), (before + 1).min(8));
        assert_eq!(peak_current(&model), p);
        assert_eq!(peak::cached(), (before + 1).min(8));
        p
    };
    assert!(peak > 1.0, "{peak}");
    // The same world changed in place: a new value, not the old one.
    if let Current::Vortices(v) = &mut w.current {
        v[0].strength *= 2.0;
    }
    let model = PathModel::new(&w, &mission, &settings);
    assert!((peak_current(&model) - 2.0 * peak).abs() < 1e-9 * peak);
    let cost = cost_with("max_current_speed = 0.25");
    close(cost.time_min(&model), 2800.0 / 1.75);
    // Still water and a uniform current need no cache.
    w.current = Current::Uniform(Vec3::new(0.3, 0.4, 1.0));
    let model = PathModel::new(&w, &mission, &settings);
    close(peak_current(&model), 0.5);
}

/// A gridded forecast and a jet: the peak is the hint, and a newer forecast in the same world
/// (the case of `simulate`) is a new value.
#[test]
fn the_peak_of_a_grid_and_a_jet() {
    use crate::world::current::{CurrentGrid, JetConfig, Magnitude, MeanderingJet};
    let grid_current = |u0: f64, hot: f64| {
        let g = crate::world::RegularGrid2::new(0.0, 0.0, 300.0, 300.0, 11, 11, "g").unwrap();
        let mut u = vec![u0; 121];
        u[57] = hot;
        Current::Grid(CurrentGrid::new(g, vec![0.0, 3600.0], vec![u.clone(), u], vec![vec![0.0; 121]; 2], "g").unwrap())
    };
    let mut w = open_world();
    let (s, g) = (Vec3::new(100.0, 100.0, -100.0), Vec3::new(2900.0, 100.0, -100.0));
    let mission = Mission::new("m", vehicle(1.5, 0.0), s, g, 0.0);
    let settings = ModelSettings::default();
    for (u0, hot) in [(0.1, 0.9), (0.2, 0.3), (0.1, 0.9)] {
        w.current = grid_current(u0, hot);
        let model = PathModel::new(&w, &mission, &settings);
        assert_eq!(peak_current(&model), hot);
        assert_eq!(peak_current(&model), w.current.max_speed_hint(&w.bounds, 0.0));
    }
    w.current = Current::Jet(MeanderingJet::new(JetConfig::over(&w.bounds, Magnitude::Fixed(0.75)), "jet").unwrap());
    let model = PathModel::new(&w, &mission, &settings);
    close(peak_current(&model), 0.75);
    close(cost_with("").time_min(&model), 2800.0 / (1.5 + peak_current(&model)));
}

/// F_p1 = 10 for a path through (or within the safety distance of) a sphere, a full-depth
/// cylinder (horizontal distance, at any depth) and a box; 1 when it passes clear.
#[test]
fn the_safety_factor_for_each_shape() {
    let cost = cost_with("");
    let (s, g) = (Vec3::new(0.0, 1500.0, -500.0), Vec3::new(3000.0, 1500.0, -500.0));
    let shapes = [
        Shape::Sphere { center: Vec3::new(1500.0, 1700.0, -500.0), radius: 150.0 },
        // Its axis is 200 m from the path, horizontally.
        Shape::Cylinder {
            center: crate::geom::Vec2::new(1500.0, 1700.0),
            radius: 150.0,
            z_min: f64::NEG_INFINITY,
            z_max: f64::INFINITY,
        },
        Shape::Box { min: Vec3::new(1400.0, 1650.0, -600.0), max: Vec3::new(1600.0, 1800.0, -400.0) },
    ];
    for shape in shapes {
        let mut w = open_world();
        w.obstacles.push(Obstacle::fixed(shape.clone()));
        // 200 m from the sphere's centre and the cylinder's axis (R = 150), 150 m from the
        // box: all clear with a safety distance of 40 (R + d_safe = 190 < 200); with 60 the
        // sphere and the cylinder are hit (210 > 200), the box, measured from itself, is not.
        let (total, terms, x) = judge(&cost, &w, vehicle(2.0, 40.0), &[s, g]);
        assert!(!x.obstacle && x.f_p1 == 1.0, "{shape:?}");
        close(term(&terms, "safety"), 0.0);
        close(total, 0.0);
        let (_, _, x) = judge(&cost, &w, vehicle(2.0, 60.0), &[s, g]);
        let box_clear = matches!(shape, Shape::Box { .. });
        assert_eq!(x.obstacle, !box_clear, "{shape:?}");
        // Straight through it: F_p1 = 10 with no safety distance at all.
        let through = [s, Vec3::new(1500.0, 1700.0, -500.0), g];
        let (total, terms, x) = judge(&cost, &w, vehicle(2.0, 0.0), &through);
        assert!(x.obstacle && !x.seabed, "{shape:?}");
        assert_eq!(x.f_p1, 10.0);
        let inner = term(&terms, "time") + term(&terms, "current") + term(&terms, "target");
        close(term(&terms, "safety"), 9.0 * inner);
        close(total, 10.0 * inner);
        assert!(!x.succeeded());
    }
    // The cylinder counts at any depth: the same path 400 m deeper still hits it.
    let mut w = open_world();
    w.obstacles.push(Obstacle::fixed(Shape::Cylinder {
        center: crate::geom::Vec2::new(1500.0, 1500.0),
        radius: 100.0,
        z_min: f64::NEG_INFINITY,
        z_max: f64::INFINITY,
    }));
    let deep = [Vec3::new(0.0, 1500.0, -900.0), Vec3::new(3000.0, 1500.0, -900.0)];
    assert!(judge(&cost, &w, vehicle(2.0, 0.0), &deep).2.obstacle);
}

/// A flat seabed at z = -600: a path dipping to -700 is below it, one at -580 is within a
/// 30 m safety distance (A5's sign), one at -560 is clear. Seabed and obstacle together give
/// F_p1 = 100.
#[test]
fn the_safety_factor_for_the_seabed() {
    let cost = cost_with("");
    let mut w = open_world();
    w.terrain = flat(-600.0);
    let dip = |z: f64| [Vec3::new(0.0, 0.0, -500.0), Vec3::new(1500.0, 0.0, z), Vec3::new(3000.0, 0.0, -500.0)];
    let (_, _, x) = judge(&cost, &w, vehicle(2.0, 30.0), &dip(-700.0));
    assert!(x.seabed && x.f_p1 == 10.0);
    let (_, _, x) = judge(&cost, &w, vehicle(2.0, 30.0), &dip(-580.0));
    assert!(x.seabed, "20 m above the seabed is within 30 m");
    let (_, _, x) = judge(&cost, &w, vehicle(2.0, 30.0), &dip(-560.0));
    assert!(!x.seabed && x.f_p1 == 1.0);
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(1500.0, 0.0, -700.0), radius: 50.0 }));
    let (total, terms, x) = judge(&cost, &w, vehicle(2.0, 30.0), &dip(-700.0));
    assert_eq!(x.f_p1, 100.0);
    close(total, 100.0 * term(&terms, "time"));
}

/// A moving sphere is tested where it is while the vehicle flies the segment: the same path
/// leaving 500 s later passes behind it.
#[test]
fn moving_obstacles_on_the_clock() {
    let mut w = open_world();
    // At 2 m/s the vehicle reaches x = 1500 at t = 750 s; the sphere moves north at 1 m/s and
    // is at y = 1500 at t = 750 s.
    w.obstacles
        .push(Obstacle::moving(Shape::Sphere { center: Vec3::new(1500.0, 750.0, -500.0), radius: 100.0 }, Vec3::Y));
    let p = [Vec3::new(0.0, 1500.0, -500.0), Vec3::new(3000.0, 1500.0, -500.0)];
    let cost = cost_with("");
    assert!(judge(&cost, &w, vehicle(2.0, 0.0), &p).2.obstacle);
    let mission = Mission::new("m", vehicle(2.0, 0.0), p[0], p[1], 500.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    assert!(!cost.parts(&model, &p).obstacle);
}

/// F_p3: the last leg from (2000, 1300, -300) to the goal (3000, 1000, -200) moves 300 m
/// sideways of the start-goal axis (along x) and 100 m vertically.
#[test]
fn the_target_window() {
    let w = open_world();
    let p = [Vec3::new(0.0, 1000.0, -200.0), Vec3::new(2000.0, 1300.0, -300.0), Vec3::new(3000.0, 1000.0, -200.0)];
    let v = vehicle(2.0, 0.0);
    for (table, missed) in [
        ("", false),
        ("lateral_step = 300.0", false),
        ("lateral_step = 299.0", true),
        ("lateral_step = 0.0\nvertical_step = 100.0", false),
        ("vertical_step = 99.0", true),
        ("lateral_step = 500.0\nvertical_step = 99.0", true),
        // Sideways as the x-axis planes measure it (|dy|), and as y-axis planes (|dx| = 1000).
        ("target_axis = \"x\"\nlateral_step = 300.0", false),
        ("target_axis = \"y\"\nlateral_step = 300.0", true),
    ] {
        let (total, terms, x) = judge(&cost_with(table), &w, v.clone(), &p);
        assert_eq!(x.target_missed, missed, "{table}");
        close(term(&terms, "target"), if missed { 5.0 } else { 0.0 });
        close(total, term(&terms, "time") + term(&terms, "target"));
        assert_eq!(x.succeeded(), !missed);
    }
    // A diagonal start-goal axis: sideways is across it. S = (0, 0), G = (3000, 3000); the
    // last point (2000, 2400) is 400 / sqrt 2 = 282.8 m off the axis.
    let p = [Vec3::new(0.0, 0.0, -200.0), Vec3::new(2000.0, 2400.0, -200.0), Vec3::new(3000.0, 3000.0, -200.0)];
    assert!(!judge(&cost_with("lateral_step = 283.0"), &w, v.clone(), &p).2.target_missed);
    assert!(judge(&cost_with("lateral_step = 282.5"), &w, v.clone(), &p).2.target_missed);
    // A path that stops short of the goal misses it whatever the window, at a custom penalty.
    let mission = Mission::new("m", v.clone(), p[0], p[2], 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    let c = cost_with("target_penalty = 7.0");
    assert!(c.parts(&model, &p[..2]).target_missed);
    close(c.breakdown(&model, &p[..2]).1[2].1, 7.0);
}

/// The whole Fit on a small world by hand. Vehicle 1 m/s, uniform current (0.5, 0) m/s,
/// S = (0, 0), P1 = (300, 400), G = (600, 0), all at z = -100; c1 = 0.7, c2 = 0.3.
///
/// - Both segments are 500 m along (0.6, +-0.8): |v d + c| = |(1.1, +-0.8)| = sqrt(1.85) at
///   every end, so ϖ_t = 1000 / sqrt(1.85) = 735.215 s.
/// - ϖ_tmin = 600 / (1 + 0.5) = 400 s, ϖ_tmax = 800 s: F_t = (735.215 - 400) / 400 = 0.838.
/// - θ = acos(0.6) = 53.13 degrees on both segments: U = 1.5 (0.8)^11.15 + sin(17.71 deg)^3
///   = 0.1246 + 0.0282; F_p2 = 2 U / (2 U_MAX) = U / U_MAX = 0.0939.
/// - lateral_step 300: the last leg moves 400 m across the x axis: F_p3 = 5.
/// - A sphere of radius 50 at (450, 200, -100), on the second segment: F_p1 = 10.
#[test]
fn a_whole_fit_by_hand() {
    let mut w = open_world();
    w.current = Current::Uniform(Vec3::new(0.5, 0.0, 0.0));
    let p = [Vec3::new(0.0, 0.0, -100.0), Vec3::new(300.0, 400.0, -100.0), Vec3::new(600.0, 0.0, -100.0)];
    let cost = cost_with("w_time = 0.7\nw_current = 0.3\nlateral_step = 300.0");
    let t = 1000.0 / 1.85f64.sqrt();
    let f_t = (t - 400.0) / 400.0;
    let theta = 0.6f64.acos();
    let u = 1.5 * 0.8f64.powf(11.15) + (theta / 3.0).sin().powi(3);
    let f_p2 = u / U_MAX;
    let inner = 0.7 * f_t + 0.3 * f_p2 + 5.0;
    let (total, terms, x) = judge(&cost, &w, vehicle(1.0, 0.0), &p);
    close(x.travel_time, t);
    close(x.time_min, 400.0);
    close(x.f_t, f_t);
    close(x.f_p2, f_p2);
    assert!((f_t - 0.838).abs() < 5e-4 && (f_p2 - 0.0939).abs() < 5e-5, "{f_t} {f_p2}");
    close(term(&terms, "time"), 0.7 * f_t);
    close(term(&terms, "current"), 0.3 * f_p2);
    close(term(&terms, "target"), 5.0);
    close(term(&terms, "safety"), 0.0);
    close(total, inner);
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(450.0, 200.0, -100.0), radius: 50.0 }));
    let (total, terms, x) = judge(&cost, &w, vehicle(1.0, 0.0), &p);
    assert_eq!(x.f_p1, 10.0);
    close(term(&terms, "safety"), 9.0 * inner);
    close(total, 10.0 * inner);
    // No current: U = 0 and the current term vanishes.
    w.current = Current::None;
    let (_, terms, x) = judge(&cost, &w, vehicle(1.0, 0.0), &p);
    assert_eq!(x.f_p2, 0.0);
    assert_eq!(term(&terms, "current"), 0.0);
}

/// Under the vector-sum clock, F_p1 = 1 exactly when tidepath's motion check finds no seabed
/// or obstacle on any segment: random paths over a peak, spheres, a cylinder and a box.
#[test]
fn the_safety_factor_agrees_with_the_motion_check() {
    let mut w = open_world();
    w.terrain = Terrain::Peaks(GaussianPeaks {
        base: -900.0,
        peaks: vec![Peak { x: 1500.0, y: 1500.0, height: 600.0, sigma_x: 400.0, sigma_y: 400.0 }],
        ceiling: None,
    });
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(800.0, 2200.0, -400.0), radius: 250.0 }));
    w.obstacles.push(Obstacle::fixed(Shape::Cylinder {
        center: crate::geom::Vec2::new(2200.0, 800.0),
        radius: 200.0,
        z_min: f64::NEG_INFINITY,
        z_max: f64::INFINITY,
    }));
    w.obstacles.push(Obstacle::fixed(Shape::Box {
        min: Vec3::new(2300.0, 2300.0, -700.0),
        max: Vec3::new(2600.0, 2600.0, -300.0),
    }));
    w.current = Current::Vortices(vec![LambOseen { x: 1200.0, y: 1800.0, strength: 9000.0, core_radius: 400.0 }]);
    let cost = cost_with("");
    let settings = ModelSettings { travel: TravelModel::VectorSum, ..ModelSettings::default() };
    let mut rng = crate::rng::run_rng(11, 0);
    let (mut safe, mut unsafe_) = (0, 0);
    for _ in 0..300 {
        let mut p = vec![Vec3::new(100.0, 100.0, -200.0)];
        for _ in 0..3 {
            p.push(Vec3::new(
                rng.random_range(0.0..3000.0),
                rng.random_range(0.0..3000.0),
                rng.random_range(-850.0..-50.0),
            ));
        }
        p.push(Vec3::new(2900.0, 2900.0, -200.0));
        let mission = Mission::new("m", vehicle(1.5, 10.0), p[0], p[4], 0.0);
        let model = PathModel::new(&w, &mission, &settings);
        let x = cost.parts(&model, &p);
        let (mut t, mut terrain, mut obstacle) = (0.0, false, false);
        for s in p.windows(2) {
            let m = model.validator.motion_with(s[0], s[1], t, |issue| match issue {
                crate::validity::MotionIssue::Terrain => terrain = true,
                crate::validity::MotionIssue::Obstacle(_) => obstacle = true,
                _ => {}
            });
            t = m.arrival;
        }
        assert_eq!((x.seabed, x.obstacle), (terrain, obstacle), "{p:?}");
        if x.f_p1 == 1.0 {
            safe += 1;
        } else {
            unsafe_ += 1;
        }
    }
    assert!(safe > 10 && unsafe_ > 10, "{safe} safe, {unsafe_} unsafe of 300");
}

/// Graph planners: a valid motion costs c1 Δt / (ϖ_tmax - ϖ_tmin) and arrives Δt later; along
/// a path the motion costs sum to `time` + c1 / (tmax_factor - 1). The lower bound never
/// exceeds a motion's cost at the speed bound v + |c|.
#[test]
fn motion_costs() {
    let mut w = open_world();
    w.current = Current::Uniform(Vec3::new(0.3, -0.4, 0.0));
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(1500.0, 1500.0, -500.0), radius: 200.0 }));
    let p = [
        Vec3::new(100.0, 100.0, -500.0),
        Vec3::new(1000.0, 400.0, -400.0),
        Vec3::new(2000.0, 1000.0, -450.0),
        Vec3::new(2900.0, 2900.0, -500.0),
    ];
    let mission = Mission::new("m", vehicle(2.0, 10.0), p[0], p[3], 100.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    let cost = cost_with("w_time = 0.7\nw_current = 0.3\ntmax_factor = 3.0");
    let (mut sum, mut t) = (0.0, 100.0);
    for s in p.windows(2) {
        let (c, arrival) = cost.motion_cost(&model, s[0], s[1], t).unwrap();
        sum += c;
        t = arrival;
    }
    let (_, terms) = cost.breakdown(&model, &p);
    close(sum, term(&terms, "time") + 0.7 / 2.0);
    close(t - 100.0, cost.parts(&model, &p).travel_time);
    // Through the sphere: refused.
    assert!(cost.motion_cost(&model, p[0], Vec3::new(2900.0, 2900.0, -500.0), 0.0).is_none());
    assert_eq!(cost.additive_terms(), &["time"]);
    assert_eq!(cost.cost_per_metre(&model), None);
    let mut rng = crate::rng::run_rng(3, 0);
    for _ in 0..200 {
        let a = Vec3::new(rng.random_range(0.0..3000.0), rng.random_range(0.0..1000.0), -300.0);
        let b = Vec3::new(rng.random_range(0.0..3000.0), rng.random_range(0.0..1000.0), -350.0);
        if let Some((c, _)) = cost.motion_cost(&model, a, b, 0.0) {
            assert!(cost.motion_lower_bound(&model, a.distance(b), 2.5) <= c * (1.0 + 1e-12));
        }
    }
    // Still water: c1 / (v (ϖ_tmax - ϖ_tmin)) per metre, ϖ_tmin = |SG| / v.
    w.current = Current::None;
    let model = PathModel::new(&w, &mission, &settings);
    let tmin = p[0].distance(p[3]) / 2.0;
    close(cost.cost_per_metre(&model).unwrap(), 0.7 / (2.0 * 2.0 * tmin));
    let (c, _) = cost.motion_cost(&model, p[0], p[1], 0.0).unwrap();
    close(c, cost.cost_per_metre(&model).unwrap() * p[0].distance(p[1]));
    close(cost.motion_lower_bound(&model, 100.0, 2.0), 100.0 * cost.cost_per_metre(&model).unwrap());
    assert_eq!(cost.feasible_below(), None);
}

/// A mission whose start is its goal normalises by 1 s; a single point at the goal reaches it.
#[test]
fn degenerate_paths() {
    let w = open_world();
    let s = Vec3::new(500.0, 500.0, -100.0);
    let mission = Mission::new("m", vehicle(2.0, 0.0), s, s, 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    let cost = cost_with("");
    let x = cost.parts(&model, &[s, s + Vec3::X * 100.0, s]);
    close(x.time_min, 0.0);
    close(x.f_t, 100.0);
    let x = cost.parts(&model, &[s]);
    assert!(!x.target_missed && x.f_t == 0.0 && x.f_p2 == 0.0);
    assert!(cost.parts(&model, &[]).target_missed);
}

/// Defaults, ranges and c1 + c2 = 1, refused with the prefix.
#[test]
fn bad_parameters_are_refused() {
    let d = Ijs2023Params::default();
    assert_eq!((d.w_time, d.w_current, d.safety_factor, d.target_penalty, d.tmax_factor), (1.0, 0.0, 10.0, 5.0, 2.0));
    assert_eq!((d.lateral_step, d.vertical_step, d.max_current_speed), (None, None, None));
    assert_eq!(d.target_axis, "path");
    assert_refused(
        params,
        &[
            ("w_time = 0.7", "cost.weights: w_time + w_current must be 1"),
            ("w_time = 0.5\nw_current = 0.6", "cost.weights: w_time + w_current must be 1"),
            ("w_time = 1.5\nw_current = -0.5", "cost.weights.w_time: must be in [0, 1]"),
            ("safety_factor = 0.5", "cost.weights.safety_factor: must be in [1, inf)"),
            ("tmax_factor = 1.0", "cost.weights.tmax_factor: must be in (1, inf)"),
            ("lateral_step = -1.0", "cost.weights.lateral_step"),
            ("target_axis = \"z\"", "cost.weights.target_axis"),
            ("c1 = 0.7", "cost.weights.c1: unknown parameter"),
        ],
    );
    for ok in ["w_time = 0.7\nw_current = 0.3", "w_time = 0.0\nw_current = 1.0", "lateral_step = 0.0"] {
        params(ok).unwrap();
    }
    let reg = crate::cost::registry();
    let mut t = toml::Table::new();
    t.insert("w_current".into(), toml::Value::Float(0.3));
    let e = (reg.find("ijs2023").unwrap().build)(&t).err().unwrap().to_string();
    assert!(e.starts_with("cost.weights: "), "{e}");
}
