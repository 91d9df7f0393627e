//! Hybrid-A* (issue #27) on a 2-D 1000 x 1000 m map with 40 circular obstacles placed from a
//! fixed seed, for a vehicle with a 30 m turning radius: one whole run as `plan` makes it (the
//! start and goal checks, the reachability check, the search and the evaluation of the path).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use tidepath::cost::{GeneralCost, GeneralWeights};
use tidepath::geom::{Aabb, Vec2, Vec3};
use tidepath::mission::Mission;
use tidepath::path::ModelSettings;
use tidepath::planner::hybrid_astar::{HybridAstar, HybridAstarParams};
use tidepath::planner::{solve, Problem, SolveOptions};
use tidepath::termination::Termination;
use tidepath::vehicle::Vehicle;
use tidepath::world::{Current, Dims, Obstacle, Shape, Terrain, World};

const START: Vec3 = Vec3::new(50.0, 50.0, 0.0);
const GOAL: Vec3 = Vec3::new(950.0, 950.0, 0.0);

/// 40 discs of radius 20 to 50 m, none within 60 m of the start or the goal.
fn world() -> World {
    let mut rng = ChaCha8Rng::seed_from_u64(27);
    let mut obstacles = Vec::new();
    while obstacles.len() < 40 {
        let c = Vec2::new(rng.random_range(100.0..900.0), rng.random_range(100.0..900.0));
        let radius = rng.random_range(20.0..50.0);
        if [START, GOAL].iter().all(|p| p.truncate().distance(c) > radius + 60.0) {
            obstacles.push(Obstacle::fixed(Shape::Circle { center: c, radius }));
        }
    }
    World {
        waves: Default::default(),
        bounds: Aabb::new(Vec3::ZERO, Vec3::new(1000.0, 1000.0, 0.0)),
        dims: Dims::Two,
        terrain: Terrain::None,
        obstacles,
        current: Current::None,
        frame: None,
    }
}

fn bench(c: &mut Criterion) {
    let w = world();
    let vehicle =
        Vehicle { safety_distance: 5.0, turn_radius: Some(30.0), max_turn: 180f64.to_radians(), ..Vehicle::default() };
    let missions = [Mission::new("m", vehicle, START, GOAL, 0.0)];
    let settings = ModelSettings::default();
    let cost = GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap());
    let problem =
        Problem { world: &w, settings: &settings, cost: &cost, missions: &missions, fleet: &tidepath::fleet::NO_FLEET };
    let run = || {
        let mut planner =
            HybridAstar::new(HybridAstarParams::default().checked("planner.params.hybrid-astar").unwrap());
        let mut rng = tidepath::rng::run_rng(1, 0);
        let t = Termination::default();
        solve(&mut planner, black_box(&problem), &t, &mut rng, SolveOptions::default(), &mut |_| {}).unwrap()
    };
    let plan = run();
    assert!(plan.feasible(), "{}", plan.reason);
    let m = plan.missions[0].metrics.as_ref().unwrap();
    eprintln!(
        "hybrid-astar, 40 discs: {}, length {:.1} m (straight {:.1} m), {} expansions",
        plan.status,
        m.length_m,
        START.distance(GOAL),
        plan.stats.expansions
    );
    c.bench_function("hybrid-astar, 1000 x 1000 m, 40 discs, 30 m radius", |b| b.iter(run));
}

criterion_group!(benches, bench);
criterion_main!(benches);
