//! The invariant users trust most: a path the model calls feasible never enters the seabed or
//! an obstacle. Checked on random worlds and paths by dense sampling written independently of
//! the model (own elevation formula, own containment tests, own clock).

use proptest::prelude::*;
use tidepath::geom::{Aabb, Vec2, Vec3};
use tidepath::path::{ModelSettings, PathModel};
use tidepath::vehicle::Vehicle;
use tidepath::world::terrain::{GaussianPeaks, Peak};
use tidepath::world::{Current, Dims, Obstacle, Shape, Terrain, World};

const SIZE: f64 = 1000.0;

#[derive(Clone, Debug)]
struct Hill {
    x: f64,
    y: f64,
    h: f64,
    s: f64,
}

/// Independent seabed: the peaks formula written out again.
fn seabed(base: f64, hills: &[Hill], x: f64, y: f64) -> f64 {
    base + hills.iter().map(|p| p.h * (-((x - p.x) / p.s).powi(2) - ((y - p.y) / p.s).powi(2)).exp()).sum::<f64>()
}

/// Independent containment of a point in a shape moved to time t.
fn inside(o: &Obstacle, p: Vec3, t: f64) -> bool {
    let q = p - o.velocity * t;
    match &o.shape {
        Shape::Sphere { center, radius } => {
            let d = q - *center;
            d.x * d.x + d.y * d.y + d.z * d.z < radius * radius
        }
        Shape::Cylinder { center, radius, z_min, z_max } => {
            let (dx, dy) = (q.x - center.x, q.y - center.y);
            dx * dx + dy * dy < radius * radius && q.z > *z_min && q.z < *z_max
        }
        Shape::Box { min, max } => {
            q.x > min.x && q.x < max.x && q.y > min.y && q.y < max.y && q.z > min.z && q.z < max.z
        }
        Shape::Circle { center, radius } => {
            let (dx, dy) = (q.x - center.x, q.y - center.y);
            dx * dx + dy * dy < radius * radius
        }
    }
}

fn hill() -> impl Strategy<Value = Hill> {
    (0.0..SIZE, 0.0..SIZE, 50.0..450.0, 60.0..300.0).prop_map(|(x, y, h, s)| Hill { x, y, h, s })
}

fn obstacle() -> impl Strategy<Value = Obstacle> {
    let shape = prop_oneof![
        (0.0..SIZE, 0.0..SIZE, -480.0..-20.0, 20.0..120.0)
            .prop_map(|(x, y, z, r)| Shape::Sphere { center: Vec3::new(x, y, z), radius: r }),
        (0.0..SIZE, 0.0..SIZE, 20.0..100.0, -500.0..-250.0, -200.0..0.0).prop_map(|(x, y, r, lo, hi)| {
            Shape::Cylinder { center: Vec2::new(x, y), radius: r, z_min: lo, z_max: hi }
        }),
        (0.0..SIZE, 0.0..SIZE, -450.0..-50.0, 20.0..150.0, 20.0..150.0, 20.0..150.0)
            .prop_map(|(x, y, z, a, b, c)| Shape::Box { min: Vec3::new(x, y, z), max: Vec3::new(x + a, y + b, z + c) }),
        (0.0..SIZE, 0.0..SIZE, 10.0..60.0).prop_map(|(x, y, r)| Shape::Circle { center: Vec2::new(x, y), radius: r }),
    ];
    let velocity = prop_oneof![
        Just(Vec3::ZERO),
        (-0.5..0.5f64, -0.5..0.5f64, -0.1..0.1f64).prop_map(|(a, b, c)| Vec3::new(a, b, c)),
    ];
    (shape, velocity).prop_map(|(shape, velocity)| Obstacle { shape, velocity })
}

fn waypoint() -> impl Strategy<Value = Vec3> {
    (0.0..SIZE, 0.0..SIZE, -500.0..0.0).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn feasible_paths_never_enter_seabed_or_obstacles(
        hills in prop::collection::vec(hill(), 0..4),
        obstacles in prop::collection::vec(obstacle(), 0..14),
        points in prop::collection::vec(waypoint(), 2..7),
        safety in 0.0..15.0f64,
    ) {
        let base = -500.0;
        let terrain = Terrain::Peaks(GaussianPeaks {
            base,
            peaks: hills.iter().map(|h| Peak { x: h.x, y: h.y, height: h.h, sigma_x: h.s, sigma_y: h.s }).collect(),
            ceiling: None,
        });
        let world = World {
            bounds: Aabb::new(Vec3::new(0.0, 0.0, -500.0), Vec3::new(SIZE, SIZE, 0.0)),
            dims: Dims::Three,
            terrain,
            obstacles: obstacles.clone(),
            current: Current::None,
            waves: None,
        };
        let vehicle = Vehicle {
            safety_distance: safety,
            max_turn: std::f64::consts::PI,
            max_pitch: std::f64::consts::FRAC_PI_2,
            depth_min: 0.0,
            depth_max: 500.0,
            ..Vehicle::default()
        };
        let settings = ModelSettings::default();
        let model = PathModel::new(&world, &vehicle, 0.0, &settings);
        let violations = model.violations(&points);
        let mut times = Vec::new();
        let verdict = model.assess(&points, &mut times).feasible();
        prop_assert_eq!(verdict, violations.is_empty(), "assess and violations disagree: {:?}", violations);
        if verdict {
            // Independent clock: still water, so ground speed is the cruise speed.
            let mut t0 = 0.0;
            for w in points.windows(2) {
                let len = w[0].distance(w[1]);
                let t1 = t0 + len / vehicle.speed;
                for k in 0..=2000 {
                    let s = k as f64 / 2000.0;
                    let p = w[0] + (w[1] - w[0]) * s;
                    let t = t0 + (t1 - t0) * s;
                    let ground = seabed(base, &hills, p.x, p.y);
                    prop_assert!(p.z >= ground, "point {:?} is {} m below the seabed", p, ground - p.z);
                    for (i, o) in obstacles.iter().enumerate() {
                        prop_assert!(!inside(o, p, t), "point {:?} at t={} is inside obstacle {} {:?}", p, t, i, o);
                    }
                }
                t0 = t1;
            }
        }
    }
}
