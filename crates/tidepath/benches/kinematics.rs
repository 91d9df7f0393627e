//! Kinematics speed (issue #27): the `dubins` smoother on a 40-waypoint path (a 2-D world
//! 2000 x 1000 m, a wave of five periods weaving round ten discs; its corners do not fit at
//! the vehicle's radius of 30 m), and one planar Dubins shortest-path call (and one 3-D
//! Dubins-airplane call) between random poses.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use tidepath::cost::{GeneralCost, GeneralWeights};
use tidepath::geom::{Aabb, Vec2, Vec3};
use tidepath::kinematics::dubins::Dubins;
use tidepath::kinematics::dubins3::Dubins3;
use tidepath::kinematics::Pose;
use tidepath::mission::Mission;
use tidepath::path::{ModelSettings, PathModel};
use tidepath::smoothing::dubins::DubinsSmoother;
use tidepath::smoothing::Smoother;
use tidepath::termination::Termination;
use tidepath::vehicle::Vehicle;
use tidepath::world::{Dims, Obstacle, Shape, World};

const RADIUS: f64 = 30.0;

const PERIODS: f64 = 5.0;

/// Ten discs of radius 75 m on the centre line, one inside each crest of the path's wave
/// (the wave keeps 91 m from their centres): the straight line and wide shortcuts hit them.
fn world() -> World {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -50.0), Vec3::new(2000.0, 1000.0, -50.0)));
    w.dims = Dims::Two;
    let crests = (2.0 * PERIODS) as usize;
    for k in 0..crests {
        let x = 50.0 + 1900.0 * (0.5 + k as f64) / crests as f64;
        w.obstacles.push(Obstacle::fixed(Shape::Circle { center: Vec2::new(x, 500.0), radius: 75.0 }));
    }
    w
}

/// 40 waypoints on a wave of amplitude 250 m from x = 50 to 1950.
fn path() -> Vec<Vec3> {
    (0..40)
        .map(|i| {
            let t = i as f64 / 39.0;
            Vec3::new(50.0 + 1900.0 * t, 500.0 + 250.0 * (t * PERIODS * std::f64::consts::TAU).sin(), -50.0)
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let w = world();
    let points = path();
    let vehicle = Vehicle { turn_radius: Some(RADIUS), safety_distance: 5.0, ..Vehicle::default() };
    let mission = Mission::new("bench", vehicle, points[0], points[39], 0.0);
    let settings = ModelSettings::default();
    let model = PathModel::new(&w, &mission, &settings);
    let cost = GeneralCost::new(GeneralWeights::default().checked("cost.weights").unwrap());
    let smoother = DubinsSmoother::default();
    let out = smoother.smooth(&model, &cost, &points, &Termination::default());
    let (a_in, a_out) = (model.assess(&points, &mut Vec::new()), model.assess(&out, &mut Vec::new()));
    let free =
        Mission::new("bench", Vehicle { turn_radius: None, ..mission.vehicle.clone() }, points[0], points[39], 0.0);
    let polyline = PathModel::new(&w, &free, &settings).assess(&points, &mut Vec::new());
    assert_eq!(polyline.collisions, 0, "the wave should clear the discs");
    eprintln!(
        "dubins smoother: 40 waypoints (length {:.1} m; {} violations at r = {RADIUS} m: {} turns beyond max_turn, {} fillets that do not fit) -> {} polygon points, feasible {}, length {:.1} m",
        a_in.length,
        a_in.violation_count(),
        a_in.turn_violations,
        a_in.radius_violations,
        out.len(),
        a_out.feasible(),
        a_out.length,
    );
    assert!(a_out.feasible(), "the bench's smoothed path should be feasible: {:?}", model.violations(&out));
    c.bench_function("dubins smoother, 40 waypoints, 2-D, 10 discs, r = 30 m", |b| {
        b.iter(|| smoother.smooth(black_box(&model), &cost, black_box(&points), &Termination::default()))
    });

    let mut rng = ChaCha8Rng::seed_from_u64(27);
    let mut pose = |z: f64| {
        Pose::new(
            Vec3::new(rng.random_range(-200.0..200.0), rng.random_range(-200.0..200.0), z),
            rng.random_range(-std::f64::consts::PI..std::f64::consts::PI),
        )
    };
    let pairs: Vec<(Pose, Pose)> = (0..256).map(|_| (pose(0.0), pose(0.0))).collect();
    let mut k = 0;
    c.bench_function("planar Dubins shortest (6 words)", |b| {
        b.iter(|| {
            k = (k + 1) % pairs.len();
            Dubins::shortest(black_box(pairs[k].0), black_box(pairs[k].1), RADIUS)
        })
    });
    // 3-D: height changes up to 300 m at a 20 degree limit, so many pairs need a pre-turn.
    let pairs3: Vec<(Pose, Pose)> = (0..256).map(|i| (pose(0.0), pose(-300.0 * (i % 4) as f64 / 3.0))).collect();
    let pitch = 20f64.to_radians();
    c.bench_function("3-D Dubins airplane (low, medium and high altitude)", |b| {
        b.iter(|| {
            k = (k + 1) % pairs3.len();
            Dubins3::shortest(black_box(pairs3[k].0), black_box(pairs3[k].1), RADIUS, pitch)
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
