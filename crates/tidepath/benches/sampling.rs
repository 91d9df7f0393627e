//! The sampling planners at 10,000 samples on the world of the OMPL comparison
//! (`scripts/ompl_bench`): 2-D, 20 x 40 km, 40 random discs, start and goal at opposite ends,
//! range 1000 m, resolution 25 m, cost proportional to length. Also RRT* in 3-D (a depth band
//! of 400 m over the same discs as columns) and PRM*.

use criterion::{criterion_group, criterion_main, Criterion};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use tidepath::cost::{GeneralCost, GeneralWeights};
use tidepath::geom::{Aabb, Vec2, Vec3};
use tidepath::mission::Mission;
use tidepath::path::ModelSettings;
use tidepath::planner::sampling::{PrmStar, PrmStarParams, RrtStar, RrtStarParams};
use tidepath::planner::{solve, Planner, Problem, SolveOptions};
use tidepath::termination::Termination;
use tidepath::vehicle::Vehicle;
use tidepath::world::{Current, Dims, Obstacle, Shape, Terrain, World};

fn world(dims: Dims) -> World {
    let mut rng = ChaCha8Rng::seed_from_u64(20240601);
    let mut obstacles = Vec::new();
    while obstacles.len() < 40 {
        let c = Vec2::new(rng.random_range(0.0..20000.0), rng.random_range(0.0..40000.0));
        let r = rng.random_range(400.0..1500.0);
        let clear = |p: Vec2| p.distance(c) > r + 100.0;
        if clear(Vec2::new(10000.0, 1000.0)) && clear(Vec2::new(10000.0, 39000.0)) {
            obstacles.push(Obstacle::fixed(Shape::Circle { center: c, radius: r }));
        }
    }
    let z = if dims == Dims::Three { -400.0 } else { 0.0 };
    World {
        waves: Default::default(),
        bounds: Aabb::new(Vec3::new(0.0, 0.0, z), Vec3::new(20000.0, 40000.0, 0.0)),
        dims,
        terrain: Terrain::None,
        obstacles,
        current: Current::None,
        frame: None,
    }
}

fn bench(c: &mut Criterion) {
    let weights: toml::Table = toml::from_str("length = 1.0\ntime = 0.0\nturn = 0.0\npitch = 0.0").unwrap();
    let cost = GeneralCost::new(GeneralWeights::from_table(&weights, "w").unwrap());
    let settings = ModelSettings::default();
    let vehicle = Vehicle {
        propulsion: Default::default(),
        speed: 1.5,
        max_turn: std::f64::consts::PI,
        max_pitch: 30f64.to_radians(),
        depth_min: 0.0,
        depth_max: 400.0,
        safety_distance: 0.0,
        turn_radius: None,
        speed_range: None,
    };
    let params: toml::Table = toml::from_str("range = 1000.0\nresolution = 25.0").unwrap();
    let mut group = c.benchmark_group("sampling_10000");
    group.sample_size(20);
    for (name, dims) in [("2d", Dims::Two), ("3d", Dims::Three)] {
        let w = world(dims);
        let z = if dims == Dims::Three { -200.0 } else { 0.0 };
        let missions =
            [Mission::new("m", vehicle.clone(), Vec3::new(10000.0, 1000.0, z), Vec3::new(10000.0, 39000.0, z), 0.0)];
        let problem = Problem {
            world: &w,
            settings: &settings,
            cost: &cost,
            missions: &missions,
            fleet: &tidepath::fleet::NO_FLEET,
        };
        let t = Termination { max_samples: Some(10_000), ..Termination::default() };
        let run = |planner: &mut dyn Planner, seed| {
            let mut rng = tidepath::rng::run_rng(seed, 0);
            solve(planner, &problem, &t, &mut rng, SolveOptions::default(), &mut |_| {}).unwrap()
        };
        let mut seed = 0;
        group.bench_function(format!("rrt-star_{name}"), |b| {
            b.iter(|| {
                seed += 1;
                let mut p = RrtStar::new(RrtStarParams::from_table(&params, "p").unwrap(), false);
                run(&mut p, seed)
            })
        });
        if dims == Dims::Two {
            group.bench_function("prm-star_2d", |b| {
                b.iter(|| {
                    seed += 1;
                    let mut p = PrmStar::new(PrmStarParams::from_table(&toml::Table::new(), "p").unwrap());
                    run(&mut p, seed)
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
