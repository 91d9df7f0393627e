//! Cost of evaluating one 40-waypoint path in a world with 20 obstacles and a 200 x 200
//! terrain grid (issue #2 target: at most 5 microseconds on one core), with still water and
//! with three Lamb-Oseen vortices.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use tidepath::cost::{CostModel, GeneralCost, GeneralWeights};
use tidepath::geom::{Aabb, Vec2, Vec3};
use tidepath::optim::Scratch;
use tidepath::path::{ModelSettings, PathModel};
use tidepath::vehicle::Vehicle;
use tidepath::world::current::LambOseen;
use tidepath::world::terrain::ElevationGrid;
use tidepath::world::{Current, Obstacle, RegularGrid2, Shape, Terrain, World};

fn world(current: Current) -> World {
    let mut rng = ChaCha8Rng::seed_from_u64(42);
    let n = 200;
    let grid = RegularGrid2::new(0.0, 0.0, 100.0, 60.0, n, n, "bench").unwrap();
    let mut z = Vec::with_capacity(n * n);
    for j in 0..n {
        for i in 0..n {
            let (x, y) = grid.node(i, j);
            let hill = 600.0 * (-((x - 8000.0) / 2500.0).powi(2) - ((y - 6000.0) / 2000.0).powi(2)).exp();
            z.push(-950.0 + hill + 20.0 * (x / 700.0).sin() * (y / 900.0).cos());
        }
    }
    let terrain = Terrain::Grid(ElevationGrid::new(grid, z, "bench").unwrap());
    let mut obstacles = Vec::new();
    for k in 0..20 {
        let c = Vec3::new(rng.random_range(2000.0..18000.0), rng.random_range(1000.0..11000.0), -500.0);
        let shape = match k % 4 {
            0 => Shape::Sphere { center: c, radius: 300.0 },
            1 => Shape::Cylinder { center: c.truncate(), radius: 250.0, z_min: -800.0, z_max: -200.0 },
            2 => Shape::Box { min: c - Vec3::splat(200.0), max: c + Vec3::splat(200.0) },
            _ => Shape::Circle { center: Vec2::new(c.x, c.y), radius: 150.0 },
        };
        let velocity = if k % 5 == 0 { Vec3::new(0.05, -0.05, 0.0) } else { Vec3::ZERO };
        obstacles.push(Obstacle { shape, velocity, window: None });
    }
    let bounds = Aabb::new(Vec3::new(0.0, 0.0, -1000.0), Vec3::new(19900.0, 11940.0, 0.0));
    World {
        waves: Default::default(),
        bounds,
        dims: tidepath::world::Dims::Three,
        terrain,
        obstacles,
        current,
        frame: None,
    }
}

fn path() -> Vec<Vec3> {
    (0..40)
        .map(|i| {
            let t = i as f64 / 39.0;
            Vec3::new(500.0 + 19000.0 * t, 6000.0 + 3000.0 * (t * 6.0).sin(), -300.0 - 100.0 * (t * 9.0).cos())
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let vehicle = Vehicle { safety_distance: 25.0, ..Vehicle::default() };
    let points = path();
    let vortices = Current::Vortices(vec![
        LambOseen { x: 8000.0, y: 3500.0, strength: 6000.0, core_radius: 1500.0 },
        LambOseen { x: 15000.0, y: 8500.0, strength: -7000.0, core_radius: 1800.0 },
        LambOseen { x: 4000.0, y: 9500.0, strength: 5000.0, core_radius: 1200.0 },
    ]);
    for (name, current) in [("still water", Current::None), ("3 vortices", vortices)] {
        let w = world(current);
        let settings = ModelSettings { current_step: 250.0, ..ModelSettings::default() };
        let mission = tidepath::mission::Mission::new("m", vehicle.clone(), points[0], points[points.len() - 1], 0.0);
        let model = PathModel::new(&w, &mission, &settings);
        let cost = GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap());
        let mut scratch = Scratch::default();
        c.bench_function(&format!("cost of 40-waypoint path, 20 obstacles, 200x200 grid, {name}"), |b| {
            b.iter(|| cost.cost(&model, black_box(&points), &mut scratch))
        });
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
