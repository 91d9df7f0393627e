//! Hand-computed approaches, the rules, and a property test against dense sampling of two
//! timed paths through a vortex current.

use super::*;
use crate::geom::Aabb;
use crate::mission::Mission;
use crate::path::ModelSettings;
use crate::rng::run_rng;
use crate::vehicle::Vehicle;
use crate::world::current::LambOseen;
use crate::world::{Current, Dims, Terrain, World};
use rand::Rng as _;

fn v(x: f64, y: f64) -> Vec3 {
    Vec3::new(x, y, 0.0)
}

#[test]
fn crossing_vehicles_meet_where_the_closed_form_says() {
    // A: (0, 0) -> (100, 0) over [0, 100]; B: (50, -50) -> (50, 50) over [10, 110].
    // Offset (t - 50, 60 - t): least at t = 55, distance sqrt(50).
    let a = [(v(0.0, 0.0), v(100.0, 0.0), 0.0, 100.0)];
    let b = [(v(50.0, -50.0), v(50.0, 50.0), 10.0, 110.0)];
    let x = closest_approach(&a, &b, Presence::Leaves).unwrap();
    assert!((x.time - 55.0).abs() < 1e-12 && (x.distance - 50f64.sqrt()).abs() < 1e-12, "{x:?}");
    assert_eq!(x.at_a, v(55.0, 0.0));
    // Same start time: they meet at (50, 0) at t = 50.
    let b0 = [(v(50.0, -50.0), v(50.0, 50.0), 0.0, 100.0)];
    let y = closest_approach(&a, &b0, Presence::Stays).unwrap();
    assert_eq!((y.distance, y.time), (0.0, 50.0));
}

#[test]
fn presence_decides_what_happens_outside_the_missions() {
    // B crosses A's goal (100, 0) long after A arrived: staying there, A is hit; having left,
    // it is not, and B alone in the water meets nobody.
    let a = [(v(0.0, 0.0), v(100.0, 0.0), 0.0, 100.0)];
    let b = [(v(100.0, -50.0), v(100.0, 50.0), 200.0, 300.0)];
    let stays = closest_approach(&a, &b, Presence::Stays).unwrap();
    assert_eq!((stays.distance, stays.time), (0.0, 250.0));
    assert!(closest_approach(&a, &b, Presence::Leaves).is_none());
    // Before departure a waiting vehicle is at its start.
    let c = [(v(0.0, -30.0), v(0.0, 30.0), 0.0, 60.0)];
    let late = [(v(0.0, 0.0), v(100.0, 0.0), 100.0, 200.0)];
    let w = closest_approach(&late, &c, Presence::Stays).unwrap();
    assert_eq!((w.distance, w.time), (0.0, 30.0));
}

#[test]
fn pair_overrides_and_the_penalty() {
    let rules = FleetRules {
        separation_m: 100.0,
        pairs: vec![(2, 0, 50.0)],
        presence: Presence::Stays,
        arrival: Arrival::Free,
    };
    assert_eq!(rules.separation(0, 2), 50.0);
    assert_eq!(rules.separation(1, 2), 100.0);
    assert!(rules.active(2) && !rules.active(1) && !NO_FLEET.active(5));
    assert!(rules.check(3).is_ok());
    assert!(rules.check(2).unwrap_err().to_string().contains("fleet.pairs[0]"));
    let bad = FleetRules { separation_m: f64::NAN, ..rules.clone() };
    assert!(bad.check(3).unwrap_err().to_string().contains("fleet.separation_m"));
    let approach = Approach { distance: 25.0, time: 0.0, at_a: Vec3::ZERO, at_b: Vec3::ZERO };
    let c =
        FleetCheck { closest: None, conflicts: vec![Conflict { a: 0, b: 2, approach, required: 50.0 }], arrival: None };
    assert_eq!(c.penalty(), SEPARATION_PENALTY * 1.5);
}

/// A 2-D world with two vortices, so ground speeds vary along every segment.
fn swirling() -> World {
    let vortex = |x, y, s| LambOseen { x, y, strength: s, core_radius: 200.0 };
    World {
        waves: Default::default(),
        bounds: Aabb::new(Vec3::ZERO, Vec3::new(1000.0, 1000.0, 0.0)),
        dims: Dims::Two,
        terrain: Terrain::None,
        obstacles: Vec::new(),
        current: Current::Vortices(vec![vortex(300.0, 400.0, 900.0), vortex(700.0, 600.0, -700.0)]),
        frame: None,
    }
}

/// Where a vehicle flying `legs` is at `t` (waiting at its ends outside them).
fn position(legs: &[Leg], t: f64) -> Vec3 {
    if t <= legs[0].2 {
        return legs[0].0;
    }
    for &(p0, p1, t0, t1) in legs {
        if t <= t1 {
            return if t1 > t0 { p0.lerp(p1, (t - t0) / (t1 - t0)) } else { p1 };
        }
    }
    legs[legs.len() - 1].1
}

#[test]
fn the_closest_approach_agrees_with_dense_sampling_in_currents() {
    let world = swirling();
    let settings = ModelSettings { current_step: 25.0, ..ModelSettings::default() };
    let veh = Vehicle { speed: 2.0, max_turn: std::f64::consts::PI, ..Vehicle::default() };
    let mut rng = run_rng(42, 0);
    let pt = |rng: &mut crate::rng::Rng| v(rng.random_range(50.0..950.0), rng.random_range(50.0..950.0));
    for case in 0..60 {
        let paths: Vec<Vec<Vec3>> = (0..2).map(|_| (0..4).map(|_| pt(&mut rng)).collect()).collect();
        let departs = [0.0, rng.random_range(0.0..200.0)];
        let missions: Vec<Mission> =
            (0..2).map(|k| Mission::new("m", veh.clone(), paths[k][0], paths[k][3], departs[k])).collect();
        let bases: Vec<PathModel<'_>> = missions.iter().map(|m| PathModel::new(&world, m, &settings)).collect();
        // Every other case, each segment at its own speed (a plan over a speed range).
        let speeds: Vec<Vec<f64>> = (0..2).map(|_| (0..3).map(|_| rng.random_range(1.0..2.5)).collect()).collect();
        let models: Vec<PathModel<'_>> =
            (0..2).map(|k| bases[k].with_speeds((case % 2 == 1).then_some(&speeds[k][..]))).collect();
        let mut legs = [Vec::new(), Vec::new()];
        for k in 0..2 {
            timed_legs(&models[k], &paths[k], &mut legs[k]);
        }
        let exact = closest_approach(&legs[0], &legs[1], Presence::Stays).unwrap();
        // Sample both from the earlier departure to the later arrival, every 0.05 s.
        let (t0, t1) = (departs[0].min(departs[1]), legs[0].last().unwrap().3.max(legs[1].last().unwrap().3));
        let steps = ((t1 - t0) / 0.05).ceil() as usize;
        let mut sampled = f64::INFINITY;
        for s in 0..=steps {
            let t = t0 + (t1 - t0) * s as f64 / steps as f64;
            sampled = sampled.min(position(&legs[0], t).distance(position(&legs[1], t)));
        }
        // Never above what sampling finds, and within the relative motion of half a step
        // (ground speeds stay below 6 m/s here) of it.
        assert!(exact.distance <= sampled + 1e-9, "case {case}: {exact:?} vs {sampled}");
        assert!(sampled - exact.distance <= 12.0 * 0.05, "case {case}: {exact:?} vs {sampled}");
        let (pa, pb) = (position(&legs[0], exact.time), position(&legs[1], exact.time));
        assert!((pa.distance(pb) - exact.distance).abs() < 1e-6, "case {case}");
        // The legs follow the evaluation's clock.
        let mut times = Vec::new();
        models[0].arrival_times(&paths[0], &mut times);
        assert!((legs[0].last().unwrap().3 - times[3]).abs() < 1e-6 * times[3].max(1.0), "case {case}");
    }
}

#[test]
fn arrivals_together_and_in_order() {
    let arrivals = [(0, 1000.0), (1, 1090.0), (2, 1030.0)];
    let together = check_arrivals(&Arrival::Together { tolerance_s: 60.0 }, &arrivals).unwrap();
    assert_eq!((together.spread_s, together.first, together.last), (90.0, (0, 1000.0), (1, 1090.0)));
    assert_eq!(together.excess_s, 30.0);
    assert_eq!(together.broken, Some(Broken::Spread { tolerance_s: 60.0 }));
    // 30 s over: the penalty plus 30 / 600 of it.
    assert_eq!(arrival_penalty(&together), SEPARATION_PENALTY * (1.0 + 30.0 / 600.0));
    let loose = check_arrivals(&Arrival::Together { tolerance_s: 90.0 }, &arrivals).unwrap();
    assert!(loose.broken.is_none() && arrival_penalty(&loose) == 0.0);
    // Order 0, 1, 2: 2 arrives 60 s before 1.
    let order = check_arrivals(&Arrival::Order(vec![0, 1, 2]), &arrivals).unwrap();
    assert_eq!(order.broken, Some(Broken::Order { earlier: 1, later: 2, by_s: 60.0 }));
    assert!(check_arrivals(&Arrival::Order(vec![0, 2, 1]), &arrivals).unwrap().broken.is_none());
    assert!(check_arrivals(&Arrival::Free, &arrivals[..1]).is_none());
    let bad = FleetRules { arrival: Arrival::Order(vec![0, 0]), ..FleetRules::default() };
    assert!(bad.check(2).unwrap_err().to_string().contains("fleet.arrival_order"));
}
