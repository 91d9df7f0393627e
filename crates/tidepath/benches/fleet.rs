//! What a fleet's separation check costs: the exact closest approach of three vehicles'
//! 20-waypoint timed paths through two Lamb-Oseen vortices (legs of constant ground speed on
//! each clock, three pairs), beside the cost evaluation of the same three paths, so the
//! overhead a joint optimizer pays for the separation is read off directly.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use tidepath::cost::{CostModel, GeneralCost, GeneralWeights};
use tidepath::fleet::{check, Arrival, FleetRules, Presence};
use tidepath::geom::{Aabb, Vec3};
use tidepath::mission::Mission;
use tidepath::optim::Scratch;
use tidepath::path::{ModelSettings, PathModel};
use tidepath::vehicle::Vehicle;
use tidepath::world::current::LambOseen;
use tidepath::world::{Current, Dims, Terrain, World};

fn bench(c: &mut Criterion) {
    let world = World {
        waves: Default::default(),
        bounds: Aabb::new(Vec3::ZERO, Vec3::new(10_000.0, 10_000.0, 0.0)),
        dims: Dims::Two,
        terrain: Terrain::None,
        obstacles: Vec::new(),
        current: Current::Vortices(vec![
            LambOseen { x: 3000.0, y: 4000.0, strength: 4000.0, core_radius: 900.0 },
            LambOseen { x: 7000.0, y: 6000.0, strength: -3500.0, core_radius: 800.0 },
        ]),
        frame: None,
    };
    let settings = ModelSettings::default();
    let vehicle = Vehicle { speed: 2.0, max_turn: std::f64::consts::PI, ..Vehicle::default() };
    // Three vehicles from the west, south and north to goals near the centre, wavy paths.
    let paths: Vec<Vec<Vec3>> = (0..3)
        .map(|k| {
            let (a, b) = match k {
                0 => (Vec3::new(500.0, 5000.0, 0.0), Vec3::new(5000.0, 5200.0, 0.0)),
                1 => (Vec3::new(5000.0, 500.0, 0.0), Vec3::new(5200.0, 4800.0, 0.0)),
                _ => (Vec3::new(5000.0, 9500.0, 0.0), Vec3::new(4800.0, 5400.0, 0.0)),
            };
            (0..20)
                .map(|i| {
                    let t = i as f64 / 19.0;
                    let wave = if i == 0 || i == 19 { 0.0 } else { 300.0 * (t * 9.0).sin() };
                    a.lerp(b, t) + Vec3::new(wave, -wave, 0.0)
                })
                .collect()
        })
        .collect();
    let missions: Vec<Mission> =
        paths.iter().map(|p| Mission::new("m", vehicle.clone(), p[0], *p.last().unwrap(), 0.0)).collect();
    let models: Vec<PathModel<'_>> = missions.iter().map(|m| PathModel::new(&world, m, &settings)).collect();
    let rules = FleetRules {
        separation_m: 100.0,
        pairs: Vec::new(),
        presence: Presence::Stays,
        arrival: Arrival::Together { tolerance_s: 60.0 },
    };
    let cost = GeneralCost::new(GeneralWeights::default().checked("bench").unwrap());
    let mut scratch = Scratch::default();
    let mut legs = Vec::new();
    c.bench_function("fleet/3 vehicles x 20 waypoints, vortices: cost of the three paths", |b| {
        b.iter(|| paths.iter().zip(&models).map(|(p, m)| cost.cost(m, black_box(p), &mut scratch)).sum::<f64>())
    });
    // The same paths flown at per-segment speeds, each evaluation making its model copy as the
    // joint objective does: the price of speeds as decisions.
    let speeds: Vec<f64> = (0..19).map(|i| 1.5 + 0.05 * i as f64).collect();
    c.bench_function("fleet/3 vehicles x 20 waypoints, vortices: cost at per-segment speeds", |b| {
        b.iter(|| {
            paths
                .iter()
                .zip(&models)
                .map(|(p, m)| cost.cost(&m.with_speeds(Some(black_box(&speeds))), black_box(p), &mut scratch))
                .sum::<f64>()
        })
    });
    c.bench_function("fleet/3 vehicles x 20 waypoints, vortices: separation and arrival check", |b| {
        b.iter(|| check(&models, black_box(&paths), &rules, &mut legs).penalty())
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
