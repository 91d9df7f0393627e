//! Hand-computed checks of the amfa2015 terms (eqs. 6-8), the point counts, the clock and the
//! parameter rules.

use super::*;
use crate::cost::test_support::{assert_refused, close, flat, free_vehicle, open_world, term};
use crate::mission::Mission;
use crate::path::ModelSettings;
use crate::vehicle::Vehicle;
use crate::world::terrain::{GaussianPeaks, Peak, Terrain};
use crate::world::{Obstacle, Shape, World};
use rand::Rng as _;

/// A vehicle whose own limits never bind, at 2 m/s, with the given safety distance.
fn vehicle(safety: f64) -> Vehicle {
    free_vehicle(2.0, safety)
}

fn params(table: &str) -> Result<Checked<Amfa2015Params>> {
    let t: toml::Table = toml::from_str(table).unwrap();
    Amfa2015Params::from_table(&t, "cost.weights")
}

fn cost_with(table: &str) -> Amfa2015Cost {
    Amfa2015Cost::new(params(table).unwrap())
}

/// Total, terms, (k1, k2) and tidepath's verdict for a mission from the first to the last
/// point of `p`.
struct Judged {
    total: f64,
    terms: Vec<(&'static str, f64)>,
    counts: (usize, usize),
    feasible: bool,
}

fn judge(cost: &Amfa2015Cost, w: &World, v: Vehicle, p: &[Vec3]) -> Judged {
    let mission = Mission::new("m", v, p[0], *p.last().unwrap(), 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(w, &mission, &settings);
    let (total, terms) = cost.breakdown(&model, p);
    let counts = cost.counts(&model, p);
    let feasible = model.assess(p, &mut Vec::new()).feasible();
    Judged { total, terms, counts, feasible }
}

/// S = (0, 0, -100), P1 = (300, 400, -100), P2 = (300, 400, -220), G = (600, 800, -220):
/// E_L = 500 + 120 + 500 = 1120 m, all in open water, so E = 0.5 * 1120.
#[test]
fn the_length_of_a_three_segment_path_by_hand() {
    let p = [
        Vec3::new(0.0, 0.0, -100.0),
        Vec3::new(300.0, 400.0, -100.0),
        Vec3::new(300.0, 400.0, -220.0),
        Vec3::new(600.0, 800.0, -220.0),
    ];
    let j = judge(&cost_with(""), &open_world(), vehicle(5.0), &p);
    close(term(&j.terms, "length"), 0.5 * 1120.0);
    assert_eq!(j.counts, (0, 0));
    close(term(&j.terms, "risk_k1"), 0.0);
    close(term(&j.terms, "risk_k2"), 0.0);
    close(j.total, 560.0);
    // (tidepath's verdict is not asked: the vertical segment breaks any pitch limit.)
}

/// A sphere of radius 200 at (1000, 1000, -500); S = (0, 1000, -500), P1 at the sphere's
/// centre, G = (2000, 1000, -500). Two segments of 1000 m, m = 10 evaluation points each at
/// 1000 i / 11 = 90.9 i m from the segment's start. k1 = 1 (P1). Segment 1: inside when
/// x >= 800, i >= 8.8: i = 9, 10. Segment 2: inside when 90.9 i <= 200: i = 1, 2. k2 = 4.
/// C = |SG| = 2000, E_D = 2000 (1 + 4) = 10 000, E = 0.5 * 2000 + 0.5 * 10 000 = 6000.
#[test]
fn points_inside_a_sphere_by_hand() {
    let mut w = open_world();
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(1000.0, 1000.0, -500.0), radius: 200.0 }));
    let p = [Vec3::new(0.0, 1000.0, -500.0), Vec3::new(1000.0, 1000.0, -500.0), Vec3::new(2000.0, 1000.0, -500.0)];
    let j = judge(&cost_with(""), &w, vehicle(0.0), &p);
    assert_eq!(j.counts, (1, 4));
    close(term(&j.terms, "length"), 1000.0);
    close(term(&j.terms, "risk_k1"), 0.5 * 2000.0);
    close(term(&j.terms, "risk_k2"), 0.5 * 2000.0 * 4.0);
    close(j.total, 6000.0);
    assert!(!j.feasible);

    // "Inside" includes the safety distance, as the validator's point check does: with 100 m
    // the sphere reaches x >= 700 on segment 1 (i >= 7.7: i = 8, 9, 10) and 300 m into
    // segment 2 (i = 1, 2, 3). k2 = 6.
    let j = judge(&cost_with(""), &w, vehicle(100.0), &p);
    assert_eq!(j.counts, (1, 6));

    // m = 3: points at 250, 500, 750 m of each segment; only 750 m of segment 1 (x = 750,
    // 250 m from the centre) and 250 m of segment 2 are within 200 + 100 m. k2 = 2.
    let j = judge(&cost_with("eval_points = 3"), &w, vehicle(100.0), &p);
    assert_eq!(j.counts, (1, 2));
}

/// A flat seabed at z = -600 under S = (0, 0, -500), P1 = (1100, 0, -700), G = (2200, 0, -500),
/// no safety distance. P1 is under the seabed (k1 = 1). Segment 1 dives from -500 to -700:
/// its point i is at z = -500 - 200 i / 11, under the seabed when i / 11 > 1/2: i = 6 ... 10.
/// Segment 2 mirrors it: i = 1 ... 5. k2 = 10.
#[test]
fn points_under_the_seabed_by_hand() {
    let mut w = open_world();
    w.terrain = flat(-600.0);
    let p = [Vec3::new(0.0, 0.0, -500.0), Vec3::new(1100.0, 0.0, -700.0), Vec3::new(2200.0, 0.0, -500.0)];
    let j = judge(&cost_with(""), &w, vehicle(0.0), &p);
    assert_eq!(j.counts, (1, 10));
    let c = 2200.0;
    close(term(&j.terms, "risk_k1"), 0.5 * c);
    close(term(&j.terms, "risk_k2"), 0.5 * c * 10.0);
    assert!(!j.feasible);
    // 60 m of safety distance: z <= -540 counts, i / 11 >= 0.2: i = 3 ... 10 on segment 1 and
    // i = 1 ... 8 on segment 2. k2 = 16.
    let j = judge(&cost_with(""), &w, vehicle(60.0), &p);
    assert_eq!(j.counts, (1, 16));
}

/// C defaults to |SG| and a number replaces it; the weights scale the terms.
#[test]
fn the_risk_coefficient_and_the_weights() {
    let mut w = open_world();
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(1000.0, 1000.0, -500.0), radius: 200.0 }));
    // |SG| = |(1200, 1600, 0)| = 2000 although the path is longer.
    let p = [Vec3::new(400.0, 200.0, -500.0), Vec3::new(1000.0, 1000.0, -500.0), Vec3::new(1600.0, 1800.0, -500.0)];
    let mission = Mission::new("m", vehicle(0.0), p[0], p[2], 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    close(cost_with("").risk_coefficient(&model), 2000.0);
    close(cost_with("risk_coefficient = 7.5").risk_coefficient(&model), 7.5);

    // Segments of 1000 m along the diagonal through the centre: as in the sphere test, k1 = 1,
    // k2 = 4.
    let j = judge(&cost_with("w_length = 0.25\nw_risk = 0.75\nrisk_coefficient = 7.5"), &w, vehicle(0.0), &p);
    assert_eq!(j.counts, (1, 4));
    close(term(&j.terms, "length"), 0.25 * 2000.0);
    close(term(&j.terms, "risk_k1"), 0.75 * 7.5);
    close(term(&j.terms, "risk_k2"), 0.75 * 7.5 * 4.0);
    close(j.total, 500.0 + 0.75 * 7.5 * 5.0);

    // Start = goal: the default C is 1, not 0.
    let same = Mission::new("m", vehicle(0.0), p[1], p[1], 0.0);
    let model = PathModel::new(&w, &same, &settings);
    close(cost_with("").risk_coefficient(&model), 1.0);
}

/// A moving sphere (radius 100, 2 m/s north) whose centre is at (1000, -909.09, -500) at
/// t = 0. The vehicle flies S = (0, 0, -500) -> G = (2000, 0, -500) at 2 m/s; m = 10 points at
/// 181.8 i m, reached at 90.9 i s. Point 5 (x = 909.09, t = 454.5 s) meets the centre at
/// y = 0, 90.9 m away: inside. Points 4 and 6 find it 181.8 m south or north, more than
/// 200 m away: outside. Tested at t = 0 no point would be inside. k2 = 1.
#[test]
fn moving_obstacles_are_tested_at_the_arrival_time() {
    let mut w = open_world();
    let x5 = 2000.0 * 5.0 / 11.0;
    w.obstacles.push(Obstacle::moving(
        Shape::Sphere { center: Vec3::new(1000.0, -x5, -500.0), radius: 100.0 },
        Vec3::new(0.0, 2.0, 0.0),
    ));
    let p = [Vec3::new(0.0, 0.0, -500.0), Vec3::new(2000.0, 0.0, -500.0)];
    let j = judge(&cost_with(""), &w, vehicle(0.0), &p);
    assert_eq!(j.counts, (0, 1));
    close(term(&j.terms, "risk_k2"), 0.5 * 2000.0);
    assert!(!j.feasible);
    // Departing 100 s later the sphere has passed: no point inside, and the path is feasible.
    let mission = Mission::new("m", vehicle(0.0), p[0], p[1], 100.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    assert_eq!(cost_with("").counts(&model, &p), (0, 0));
    assert!(model.assess(&p, &mut Vec::new()).feasible());
}

/// A path entirely in the water, clear of the seabed and the obstacles: E_D = 0 and E =
/// w1 E_L; tidepath's verdict agrees.
#[test]
fn a_path_in_the_water_has_no_risk() {
    let mut w = open_world();
    w.terrain = flat(-800.0);
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(1500.0, 1500.0, -400.0), radius: 300.0 }));
    let p = [
        Vec3::new(100.0, 100.0, -300.0),
        Vec3::new(1500.0, 600.0, -500.0),
        Vec3::new(2600.0, 1500.0, -700.0),
        Vec3::new(2800.0, 2800.0, -300.0),
    ];
    let j = judge(&cost_with(""), &w, vehicle(20.0), &p);
    assert_eq!(j.counts, (0, 0));
    close(j.total, 0.5 * PathModel::length(&p));
    assert!(j.feasible);
}

/// Feasible under tidepath's checks implies E_D = 0 (the converse fails only between
/// evaluation points): random paths over peaks and spheres.
#[test]
fn feasible_paths_have_zero_risk() {
    let mut w = open_world();
    w.terrain = Terrain::Peaks(GaussianPeaks {
        base: -900.0,
        peaks: vec![Peak { x: 1500.0, y: 1500.0, height: 600.0, sigma_x: 400.0, sigma_y: 400.0 }],
        ceiling: None,
    });
    for (x, y) in [(800.0, 2200.0), (2200.0, 800.0)] {
        w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(x, y, -400.0), radius: 250.0 }));
    }
    let cost = cost_with("");
    let mut rng = crate::rng::run_rng(7, 0);
    let (mut feasible, mut risky) = (0, 0);
    for _ in 0..400 {
        let mut p = vec![Vec3::new(100.0, 100.0, -200.0)];
        for _ in 0..3 {
            p.push(Vec3::new(
                rng.random_range(0.0..3000.0),
                rng.random_range(0.0..3000.0),
                rng.random_range(-850.0..-50.0),
            ));
        }
        p.push(Vec3::new(2900.0, 2900.0, -200.0));
        let j = judge(&cost, &w, vehicle(10.0), &p);
        if j.feasible {
            feasible += 1;
            assert_eq!(j.counts, (0, 0), "{p:?}");
        }
        if j.counts != (0, 0) {
            risky += 1;
            assert!(!j.feasible);
        }
    }
    assert!(feasible > 10 && risky > 10, "{feasible} feasible, {risky} risky of 400");
}

/// Graph planners see w1 per metre of a valid motion; an invalid one is refused.
#[test]
fn motion_costs() {
    let mut w = open_world();
    w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(1000.0, 1000.0, -500.0), radius: 200.0 }));
    let (s, g) = (Vec3::new(0.0, 1000.0, -500.0), Vec3::new(2000.0, 1000.0, -500.0));
    let mission = Mission::new("m", vehicle(0.0), s, g, 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    let cost = cost_with("w_length = 0.3\nw_risk = 0.7");
    let (c, arrival) = cost.motion_cost(&model, s, Vec3::new(0.0, 0.0, -500.0), 0.0).unwrap();
    close(c, 0.3 * 1000.0);
    close(arrival, 500.0);
    assert!(cost.motion_cost(&model, s, g, 0.0).is_none());
    assert!(cost.motion_cost(&model, s, Vec3::new(0.0, 1000.0, -1500.0), 0.0).is_none());
    assert_eq!(cost.cost_per_metre(&model), Some(0.3));
    close(cost.motion_lower_bound(&model, 100.0, 2.0), 30.0);
    assert_eq!(cost.additive_terms(), &["length"]);
}

/// Out-of-range values and weights that do not sum to 1 are refused with the prefix.
#[test]
fn bad_parameters_are_refused() {
    let d = Amfa2015Params::default();
    assert_eq!((d.w_length, d.w_risk, d.eval_points, d.risk_coefficient), (0.5, 0.5, 10, None));
    assert_refused(
        params,
        &[
            ("w_length = 0.7", "cost.weights: w_length + w_risk must be 1"),
            ("w_length = 0.2\nw_risk = 0.2", "cost.weights: w_length + w_risk must be 1"),
            ("w_length = 1.5\nw_risk = -0.5", "cost.weights.w_length: must be in [0, 1]"),
            ("eval_points = 0", "cost.weights.eval_points: must be an integer in [1, 1000]"),
            ("risk_coefficient = 0.0", "cost.weights.risk_coefficient: must be in (0, inf)"),
            ("risk_coefficient = -3.0", "cost.weights.risk_coefficient"),
            ("m = 10", "cost.weights.m: unknown parameter"),
        ],
    );
    // Decimal weights that round are accepted; so is either extreme.
    for ok in ["w_length = 0.3\nw_risk = 0.7", "w_length = 0.1\nw_risk = 0.9", "w_length = 1.0\nw_risk = 0.0"] {
        params(ok).unwrap();
    }
    // The registry builds it by name, under the same prefix.
    let reg = crate::cost::registry();
    let mut t = toml::Table::new();
    t.insert("w_risk".into(), toml::Value::Float(0.9));
    let e = (reg.find("amfa2015").unwrap().build)(&t).err().unwrap().to_string();
    assert!(e.starts_with("cost.weights: "), "{e}");
}
