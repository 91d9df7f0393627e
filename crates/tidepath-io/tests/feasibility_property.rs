//! The invariant users trust most: a path the model calls feasible never enters the seabed or
//! an obstacle. Checked on random worlds (moving obstacles, vortex currents) and paths by dense
//! sampling written independently of the validity module (own elevation formula, own
//! containment tests, own clock: the crab travel model integrated piece by piece as documented,
//! sampled densely inside every piece at the time the vehicle is there).

use crate::common;

use proptest::prelude::*;
use tidepath::geom::{Aabb, Vec2, Vec3};
use tidepath::mission::Mission;
use tidepath::path::{ModelSettings, PathModel};
use tidepath::vehicle::Vehicle;
use tidepath::world::current::LambOseen;
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
    (shape, velocity).prop_map(|(shape, velocity)| Obstacle { shape, velocity, window: None })
}

fn vortex() -> impl Strategy<Value = LambOseen> {
    (0.0..SIZE, 0.0..SIZE, -3000.0..3000.0, 50.0..300.0).prop_map(|(x, y, strength, core_radius)| LambOseen {
        x,
        y,
        strength,
        core_radius,
    })
}

/// The re-checker's own clock (`common/`), with the model's current step.
fn own_clock(world: &World, a: Vec3, b: Vec3, t0: f64, v: f64, step: f64) -> Option<Vec<(Vec3, Vec3, f64, f64)>> {
    let settings = ModelSettings { current_step: step, ..ModelSettings::default() };
    common::clock(world, &settings, v, a, b, t0)
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
        vortices in prop::collection::vec(vortex(), 0..3),
    ) {
        let base = -500.0;
        let terrain = Terrain::Peaks(GaussianPeaks {
            base,
            peaks: hills.iter().map(|h| Peak { x: h.x, y: h.y, height: h.h, sigma_x: h.s, sigma_y: h.s }).collect(),
            ceiling: None,
        });
        let world = World { waves: Default::default(),
            bounds: Aabb::new(Vec3::new(0.0, 0.0, -500.0), Vec3::new(SIZE, SIZE, 0.0)),
            dims: Dims::Three,
            terrain,
            obstacles: obstacles.clone(),
            current: if vortices.is_empty() { Current::None } else { Current::Vortices(vortices) }, frame: None,
        };
        let vehicle = Vehicle {
            safety_distance: safety,
            max_turn: std::f64::consts::PI,
            max_pitch: std::f64::consts::FRAC_PI_2,
            depth_min: 0.0,
            depth_max: 500.0,
            ..Vehicle::default()
        };
        let settings = ModelSettings { current_step: 50.0, ..ModelSettings::default() };
        let mission = Mission::new("m", vehicle.clone(), points[0], *points.last().unwrap(), 0.0);
        let model = PathModel::new(&world, &mission, &settings);
        let violations = model.violations(&points);
        let mut times = Vec::new();
        let verdict = model.assess(&points, &mut times).feasible();
        prop_assert_eq!(verdict, violations.is_empty(), "assess and violations disagree: {:?}", violations);
        if verdict {
            let mut t0 = 0.0;
            for (i, w) in points.windows(2).enumerate() {
                let pieces = own_clock(&world, w[0], w[1], t0, vehicle.speed, settings.current_step);
                prop_assert!(pieces.is_some(), "segment {} cannot be flown against the current", i);
                let pieces = pieces.unwrap();
                let samples = (2000 / pieces.len()).max(20);
                for &(p0, p1, ta, tb) in &pieces {
                    for k in 0..=samples {
                        let s = k as f64 / samples as f64;
                        let p = p0 + (p1 - p0) * s;
                        let t = ta + (tb - ta) * s;
                        let ground = seabed(base, &hills, p.x, p.y);
                        prop_assert!(p.z >= ground, "point {:?} is {} m below the seabed", p, ground - p.z);
                        for (k, o) in obstacles.iter().enumerate() {
                            prop_assert!(!inside(o, p, t), "point {:?} at t={} is inside obstacle {} {:?}", p, t, k, o);
                        }
                    }
                }
                let t1 = pieces.last().unwrap().3;
                prop_assert!((t1 - times[i + 1]).abs() <= 1e-9 * t1.abs().max(1.0), "clock differs: {} vs {}", t1, times[i + 1]);
                t0 = t1;
            }
        }
    }
}

/// The same dense re-check over many random worlds built to give feasible paths often: fast
/// moving obstacles (up to the vehicle's speed) and strong vortices, so the clock matters. The
/// count of feasible paths is asserted, so the check can never pass by checking nothing.
#[test]
fn dense_recheck_agrees_on_thousands_of_feasible_paths_in_moving_worlds() {
    use rand::{Rng, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(2026);
    let mut feasible = 0;
    let mut moving_near = 0;
    for case in 0..4000 {
        let base = -500.0;
        let hills: Vec<Hill> = (0..rng.random_range(0..3))
            .map(|_| Hill {
                x: rng.random_range(0.0..SIZE),
                y: rng.random_range(0.0..SIZE),
                h: rng.random_range(50.0..300.0),
                s: rng.random_range(60.0..250.0),
            })
            .collect();
        let obstacles: Vec<Obstacle> = (0..rng.random_range(0..6))
            .map(|_| {
                let c = Vec3::new(
                    rng.random_range(0.0..SIZE),
                    rng.random_range(0.0..SIZE),
                    rng.random_range(-300.0..-100.0),
                );
                let v = Vec3::new(rng.random_range(-1.5..1.5), rng.random_range(-1.5..1.5), 0.0);
                Obstacle {
                    shape: Shape::Sphere { center: c, radius: rng.random_range(10.0..60.0) },
                    velocity: v,
                    window: None,
                }
            })
            .collect();
        let vortices: Vec<LambOseen> = (0..rng.random_range(0..3))
            .map(|_| LambOseen {
                x: rng.random_range(0.0..SIZE),
                y: rng.random_range(0.0..SIZE),
                strength: rng.random_range(-1500.0..1500.0),
                core_radius: rng.random_range(80.0..300.0),
            })
            .collect();
        let world = World {
            waves: Default::default(),
            bounds: Aabb::new(Vec3::new(0.0, 0.0, -500.0), Vec3::new(SIZE, SIZE, 0.0)),
            dims: Dims::Three,
            terrain: Terrain::Peaks(GaussianPeaks {
                base,
                peaks: hills.iter().map(|h| Peak { x: h.x, y: h.y, height: h.h, sigma_x: h.s, sigma_y: h.s }).collect(),
                ceiling: None,
            }),
            obstacles: obstacles.clone(),
            current: if vortices.is_empty() { Current::None } else { Current::Vortices(vortices) },
            frame: None,
        };
        let vehicle = Vehicle {
            propulsion: Default::default(),
            speed: 1.5,
            safety_distance: rng.random_range(0.0..10.0),
            max_turn: std::f64::consts::PI,
            max_pitch: std::f64::consts::FRAC_PI_2,
            depth_min: 0.0,
            depth_max: 500.0,
            turn_radius: None,
            speed_range: Some((0.5, 3.0)),
        };
        let n = rng.random_range(2..5);
        let points: Vec<Vec3> = (0..n)
            .map(|_| {
                Vec3::new(rng.random_range(0.0..SIZE), rng.random_range(0.0..SIZE), rng.random_range(-300.0..-100.0))
            })
            .collect();
        let settings = ModelSettings { current_step: 40.0, ..ModelSettings::default() };
        let mission = Mission::new("m", vehicle.clone(), points[0], points[n - 1], 0.0);
        let base_model = PathModel::new(&world, &mission, &settings);
        // Every other case flies each segment at its own speed (a plan over a speed range).
        let speeds: Vec<f64> = (1..n).map(|_| rng.random_range(0.5..3.0)).collect();
        let speeds: Option<&[f64]> = (case % 2 == 1).then_some(&speeds);
        let model = base_model.with_speeds(speeds);
        let mut times = Vec::new();
        if !model.assess(&points, &mut times).feasible() {
            continue;
        }
        feasible += 1;
        let mut t0 = 0.0;
        let mut closest = f64::INFINITY;
        for (i, w) in points.windows(2).enumerate() {
            let v = speeds.map_or(vehicle.speed, |s| s[i]);
            let pieces = own_clock(&world, w[0], w[1], t0, v, settings.current_step)
                .unwrap_or_else(|| panic!("case {case}: segment {i} judged flyable but the current blocks it"));
            for &(p0, p1, ta, tb) in &pieces {
                for k in 0..=40 {
                    let s = k as f64 / 40.0;
                    let (p, t) = (p0 + (p1 - p0) * s, ta + (tb - ta) * s);
                    assert!(p.z >= seabed(base, &hills, p.x, p.y), "case {case}: {p:?} below the seabed");
                    for (j, o) in obstacles.iter().enumerate() {
                        assert!(!inside(o, p, t), "case {case}: {p:?} at t={t} inside obstacle {j}");
                        if let Shape::Sphere { center, radius } = o.shape {
                            closest = closest.min((p - (center + o.velocity * t)).length() - radius);
                        }
                    }
                }
            }
            t0 = pieces.last().unwrap().3;
            assert!((t0 - times[i + 1]).abs() <= 1e-9 * t0.max(1.0), "case {case}: clocks differ");
        }
        if closest < 100.0 {
            moving_near += 1;
        }
    }
    assert!(feasible >= 1000, "only {feasible} feasible paths: the check would be too thin");
    assert!(moving_near >= 100, "only {moving_near} feasible paths passed near a moving obstacle");
}
