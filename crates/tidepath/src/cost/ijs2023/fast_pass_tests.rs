//! The evaluation's fast passes (the clock alone, then the seabed and fixed obstacles with
//! early exits) against the plain single loop they replaced, bit for bit.

use super::*;
use crate::cost::test_support::{free_vehicle as vehicle, open_world};
use crate::mission::Mission;
use crate::path::{ModelSettings, TravelModel};
use crate::world::current::LambOseen;
use crate::world::terrain::{GaussianPeaks, Peak, Terrain};
use crate::world::Shape;
use rand::Rng as _;

/// The evaluation as one plain loop (the clock, U and every obstacle's own test on it, the
/// seabed), to check the faster passes against: the same travel time, U sum and tests, bit
/// for bit.
fn plain_walk(model: &PathModel<'_>, points: &[Vec3]) -> (f64, f64, bool, bool) {
    let world = model.world;
    let safety = model.vehicle.safety_distance;
    let mut t = model.departure_time;
    let (mut travel, mut u_sum) = (0.0, 0.0);
    let (mut seabed, mut obstacle) = (false, false);
    for (i, w) in points.windows(2).enumerate() {
        let (a, b) = (w[0], w[1]);
        let ca = horizontal_current(&world.current, a, t);
        let (dt, _) = Ijs2023Cost::segment_time(world, a, b, t, model.segment_speed(i), ca);
        u_sum += segment_penalty((b - a).truncate(), ca.truncate());
        let t1 = t + dt;
        seabed |= world.segment_hits_terrain(a, b, safety);
        obstacle |= world.obstacles.iter().any(|o| o.segment_hits(a, b, t, t1, safety));
        travel += dt;
        t = t1;
    }
    (travel, u_sum, seabed, obstacle)
}

/// The still-water clock, the boxes of fixed obstacles (up to 16, and the fallback beyond),
/// moving obstacles on the clock and the early stop give what the plain loop gives, bit for
/// bit, on random paths in still water, a uniform current, vortices and a jet.
#[test]
fn the_fast_passes_match_the_plain_loop() {
    use crate::world::current::{JetConfig, Magnitude, MeanderingJet};
    let mut rng = crate::rng::run_rng(5, 0);
    let base = {
        let mut w = open_world();
        w.terrain = Terrain::Peaks(GaussianPeaks {
            base: -900.0,
            peaks: vec![Peak { x: 1500.0, y: 1500.0, height: 600.0, sigma_x: 400.0, sigma_y: 400.0 }],
            ceiling: None,
        });
        w
    };
    let obstacles = |n: usize, moving: bool, rng: &mut crate::rng::Rng| {
        (0..n)
            .map(|k| {
                let c = Vec3::new(rng.random_range(0.0..3000.0), rng.random_range(0.0..3000.0), -400.0);
                let r = rng.random_range(50.0..200.0);
                let shape = match k % 3 {
                    0 => Shape::Sphere { center: c, radius: r },
                    1 => Shape::Cylinder {
                        center: c.truncate(),
                        radius: r,
                        z_min: f64::NEG_INFINITY,
                        z_max: f64::INFINITY,
                    },
                    _ => Shape::Box { min: c - Vec3::splat(r), max: c + Vec3::splat(r) },
                };
                if moving && k == 0 {
                    Obstacle::moving(shape, Vec3::new(0.5, -0.3, 0.0))
                } else {
                    Obstacle::fixed(shape)
                }
            })
            .collect::<Vec<_>>()
    };
    let currents = [
        Current::None,
        Current::Uniform(Vec3::new(0.4, -0.2, 0.1)),
        Current::Vortices(vec![LambOseen { x: 1200.0, y: 1800.0, strength: 9000.0, core_radius: 400.0 }]),
        Current::Jet(MeanderingJet::new(JetConfig::over(&base.bounds, Magnitude::Fixed(0.75)), "jet").unwrap()),
    ];
    let table: toml::Table = toml::from_str("w_time = 0.7\nw_current = 0.3").unwrap();
    let cost = Ijs2023Cost::new(Ijs2023Params::from_table(&table, "cost.weights").unwrap());
    let settings = ModelSettings { travel: TravelModel::VectorSum, ..ModelSettings::default() };
    let mut checked = [0usize; 2];
    for current in &currents {
        for (n, moving) in [(0, false), (5, false), (16, false), (20, false), (5, true)] {
            let mut w = base.clone();
            w.current = current.clone();
            w.obstacles = obstacles(n, moving, &mut rng);
            for _ in 0..40 {
                let mut p = vec![Vec3::new(100.0, 100.0, -200.0)];
                for _ in 0..6 {
                    p.push(Vec3::new(
                        rng.random_range(0.0..3000.0),
                        rng.random_range(0.0..3000.0),
                        rng.random_range(-850.0..-50.0),
                    ));
                }
                // A repeated point: a segment of zero length.
                p.push(p[6]);
                p.push(Vec3::new(2900.0, 2900.0, -200.0));
                let mission = Mission::new("m", vehicle(1.5, 10.0), p[0], *p.last().unwrap(), 100.0);
                let model = PathModel::new(&w, &mission, &settings);
                let x = cost.parts(&model, &p);
                let (travel, u_sum, seabed, obstacle) = plain_walk(&model, &p);
                assert_eq!(x.travel_time.to_bits(), travel.to_bits());
                let segments = (p.len() - 1) as f64;
                assert_eq!(x.f_p2.to_bits(), (u_sum / (segments * U_MAX)).to_bits());
                assert_eq!((x.seabed, x.obstacle), (seabed, obstacle), "{p:?}");
                checked[usize::from(obstacle)] += 1;
            }
        }
    }
    assert!(checked[0] > 50 && checked[1] > 50, "{checked:?}");
}
