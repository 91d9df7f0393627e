//! Property test of the world's segment queries against brute-force sampling.
//!
//! Random worlds (Gaussian peaks or a small elevation grid, up to six obstacles of every shape,
//! some moving) and random timed segments. Whenever the world calls a segment clear, 2000
//! samples along it, each at its interpolated time, must keep the safety distance from the
//! seabed and from every obstacle. The geometry the samples are checked with (elevation,
//! signed distances to the shapes, obstacle motion) is written here from scratch, so a shared
//! mistake in the model cannot make both sides agree.

use proptest::prelude::*;
use tidepath::geom::{Aabb, Vec2, Vec3};
use tidepath::world::terrain::{ElevationGrid, GaussianPeaks, Peak};
use tidepath::world::{Obstacle, RegularGrid2, Shape, Terrain, World};

const SAMPLES: usize = 2000;

// ---------------------------------------------------------------------------------------------
// Specifications drawn by proptest, and the independent geometry.

#[derive(Clone, Debug)]
enum TerrainSpec {
    Peaks { base: f64, peaks: Vec<[f64; 5]>, ceiling: Option<f64> },
    Grid { x0: f64, y0: f64, dx: f64, dy: f64, nx: usize, ny: usize, z: Vec<f64> },
}

impl TerrainSpec {
    fn build(&self) -> Terrain {
        match self {
            TerrainSpec::Peaks { base, peaks, ceiling } => Terrain::Peaks(GaussianPeaks {
                base: *base,
                peaks: peaks
                    .iter()
                    .map(|&[x, y, height, sigma_x, sigma_y]| Peak { x, y, height, sigma_x, sigma_y })
                    .collect(),
                ceiling: *ceiling,
            }),
            TerrainSpec::Grid { x0, y0, dx, dy, nx, ny, z } => {
                let g = RegularGrid2::new(*x0, *y0, *dx, *dy, *nx, *ny, "grid").unwrap();
                Terrain::Grid(ElevationGrid::new(g, z.clone(), "grid").unwrap())
            }
        }
    }

    /// Seabed height, computed directly from the specification.
    fn height(&self, x: f64, y: f64) -> f64 {
        match self {
            TerrainSpec::Peaks { base, peaks, ceiling } => {
                let mut h = *base;
                for &[px, py, ph, sx, sy] in peaks {
                    let r2 = ((x - px) / sx).powi(2) + ((y - py) / sy).powi(2);
                    h += ph * (-r2).exp();
                }
                ceiling.map_or(h, |c| h.min(c))
            }
            TerrainSpec::Grid { x0, y0, dx, dy, nx, ny, z } => {
                // Clamp to the grid, then interpolate in the cell holding the point.
                let gx = ((x - x0) / dx).max(0.0).min((nx - 1) as f64);
                let gy = ((y - y0) / dy).max(0.0).min((ny - 1) as f64);
                let i = (gx.floor() as usize).min(nx - 2);
                let j = (gy.floor() as usize).min(ny - 2);
                let (u, v) = (gx - i as f64, gy - j as f64);
                let at = |i: usize, j: usize| z[j * nx + i];
                (1.0 - u) * (1.0 - v) * at(i, j)
                    + u * (1.0 - v) * at(i + 1, j)
                    + (1.0 - u) * v * at(i, j + 1)
                    + u * v * at(i + 1, j + 1)
            }
        }
    }

    /// Bound on how much the conservative hit test may overstate a near pass: the terrain's
    /// slope times the subdivision resolution (1e-3 of the feature length), generously.
    fn hit_allowance(&self) -> f64 {
        match self {
            TerrainSpec::Peaks { peaks, .. } => 3e-3 * peaks.iter().map(|p| p[2].abs()).sum::<f64>() + 1e-9,
            TerrainSpec::Grid { z, .. } => {
                let lo = z.iter().copied().fold(f64::INFINITY, f64::min);
                let hi = z.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                3e-3 * (hi - lo) + 1e-9
            }
        }
    }
}

#[derive(Clone, Debug)]
enum ShapeSpec {
    Sphere { c: [f64; 3], r: f64 },
    Cylinder { c: [f64; 2], r: f64, z_min: f64, z_max: f64 },
    Box { min: [f64; 3], max: [f64; 3] },
    Circle { c: [f64; 2], r: f64 },
}

#[derive(Clone, Debug)]
struct ObstacleSpec {
    shape: ShapeSpec,
    velocity: [f64; 3],
}

impl ObstacleSpec {
    fn build(&self) -> Obstacle {
        let v3 = |a: [f64; 3]| Vec3::new(a[0], a[1], a[2]);
        let shape = match self.shape {
            ShapeSpec::Sphere { c, r } => Shape::Sphere { center: v3(c), radius: r },
            ShapeSpec::Cylinder { c, r, z_min, z_max } => {
                Shape::Cylinder { center: Vec2::new(c[0], c[1]), radius: r, z_min, z_max }
            }
            ShapeSpec::Box { min, max } => Shape::Box { min: v3(min), max: v3(max) },
            ShapeSpec::Circle { c, r } => Shape::Circle { center: Vec2::new(c[0], c[1]), radius: r },
        };
        Obstacle { shape, velocity: v3(self.velocity), window: None }
    }

    /// Signed distance from point `p` at time `t` to the obstacle: negative inside (minus the
    /// depth below the nearest surface), positive outside.
    fn signed_distance(&self, p: [f64; 3], t: f64) -> f64 {
        // Move the point back into the frame where the shape sits at its time-0 position.
        let q = [p[0] - self.velocity[0] * t, p[1] - self.velocity[1] * t, p[2] - self.velocity[2] * t];
        let horizontal = |c: [f64; 2]| ((q[0] - c[0]).powi(2) + (q[1] - c[1]).powi(2)).sqrt();
        match self.shape {
            ShapeSpec::Sphere { c, r } => {
                ((q[0] - c[0]).powi(2) + (q[1] - c[1]).powi(2) + (q[2] - c[2]).powi(2)).sqrt() - r
            }
            ShapeSpec::Circle { c, r } => horizontal(c) - r,
            ShapeSpec::Cylinder { c, r, z_min, z_max } => {
                let radial = horizontal(c) - r; // > 0 outside the infinite cylinder
                let vertical = (z_min - q[2]).max(q[2] - z_max); // > 0 outside the slab
                if radial <= 0.0 && vertical <= 0.0 {
                    radial.max(vertical)
                } else {
                    (radial.max(0.0).powi(2) + vertical.max(0.0).powi(2)).sqrt()
                }
            }
            ShapeSpec::Box { min, max } => {
                let e: Vec<f64> = (0..3).map(|i| (min[i] - q[i]).max(q[i] - max[i])).collect();
                if e.iter().all(|&x| x <= 0.0) {
                    e.iter().copied().fold(f64::NEG_INFINITY, f64::max)
                } else {
                    e.iter().map(|x| x.max(0.0).powi(2)).sum::<f64>().sqrt()
                }
            }
        }
    }
}

/// A concrete timed segment and the safety distance it is checked with.
#[derive(Clone, Debug)]
struct SegmentSpec {
    a: [f64; 3],
    b: [f64; 3],
    ta: f64,
    tb: f64,
    safety: f64,
}

/// How a segment is placed. Uniformly random segments rarely pass within a safety distance of
/// a surface without crossing it, which is where mistakes hide, so most segments are laid
/// along a tangent plane of the seabed or of an obstacle, near the safety distance off the
/// surface.
#[derive(Clone, Debug)]
enum Placement {
    Free {
        a: [f64; 3],
        b: [f64; 3],
    },
    Degenerate {
        a: [f64; 3],
    },
    Horizontal {
        a: [f64; 3],
        b: [f64; 2],
    },
    Vertical {
        a: [f64; 3],
        z: f64,
    },
    /// Along the seabed at (x, y), the safety distance plus `delta` above it, tangent to it
    /// but for a small `slope`.
    SkimSeabed {
        x: f64,
        y: f64,
        delta: f64,
        heading: f64,
        slope: f64,
        len: f64,
        lambda: f64,
    },
    /// Tangent to obstacle `pick` (modulo the count) at the surface point chosen by `surf`,
    /// the safety distance plus `delta` outside it, at the time the segment passes there.
    SkimObstacle {
        pick: usize,
        surf: [f64; 3],
        dir: [f64; 3],
        delta: f64,
        len: f64,
        lambda: f64,
    },
}

#[derive(Clone, Debug)]
struct SegmentDraw {
    placement: Placement,
    ta: f64,
    dt: f64,
    safety: f64,
}

impl SegmentDraw {
    fn resolve(&self, terrain: &TerrainSpec, obstacles: &[ObstacleSpec]) -> SegmentSpec {
        let (ta, tb) = (self.ta, self.ta + self.dt);
        let seg = |a: [f64; 3], b: [f64; 3]| SegmentSpec { a, b, ta, tb, safety: self.safety };
        // A segment of length `len` through `p` along unit `w`, with p at parameter `lambda`.
        let through = |p: [f64; 3], w: [f64; 3], len: f64, lambda: f64| {
            let a = [p[0] - w[0] * len * lambda, p[1] - w[1] * len * lambda, p[2] - w[2] * len * lambda];
            let b = [a[0] + w[0] * len, a[1] + w[1] * len, a[2] + w[2] * len];
            (a, b)
        };
        match self.placement {
            Placement::Free { a, b } => seg(a, b),
            Placement::Degenerate { a } => seg(a, a),
            Placement::Horizontal { a, b } => seg(a, [b[0], b[1], a[2]]),
            Placement::Vertical { a, z } => seg(a, [a[0], a[1], z]),
            Placement::SkimSeabed { x, y, delta, heading, slope, len, lambda } => {
                let p = [x, y, terrain.height(x, y) + self.safety + delta];
                // Tangent to the seabed (numerical slope along the heading), plus a little tilt.
                let (hx, hy) = (heading.cos(), heading.sin());
                let e = 1e-5;
                let rise =
                    (terrain.height(x + hx * e, y + hy * e) - terrain.height(x - hx * e, y - hy * e)) / (2.0 * e);
                let w = unit([hx, hy, rise + slope]);
                let (a, b) = through(p, w, len, lambda);
                seg(a, b)
            }
            Placement::SkimObstacle { pick, surf, dir, delta, len, lambda } => {
                if obstacles.is_empty() {
                    return seg([50.0, 50.0, -50.0], [60.0, 40.0, -45.0]);
                }
                let o = &obstacles[pick % obstacles.len()];
                let (point, normal) = o.surface_point(surf);
                // Where the obstacle is when the segment passes the tangent point.
                let t = ta + (tb - ta) * lambda;
                let off = self.safety + delta;
                let p: Vec<f64> = (0..3).map(|i| point[i] + o.velocity[i] * t + normal[i] * off).collect();
                // Direction: `dir` with its normal component removed.
                let dn = dot(dir, normal);
                let w = [dir[0] - dn * normal[0], dir[1] - dn * normal[1], dir[2] - dn * normal[2]];
                let w = if dot(w, w) < 1e-6 { perpendicular(normal) } else { unit(w) };
                let (a, b) = through([p[0], p[1], p[2]], w, len, lambda);
                seg(a, b)
            }
        }
    }
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn unit(a: [f64; 3]) -> [f64; 3] {
    let n = dot(a, a).sqrt();
    [a[0] / n, a[1] / n, a[2] / n]
}

fn perpendicular(n: [f64; 3]) -> [f64; 3] {
    if n[0].abs() < 0.9 {
        unit([0.0, -n[2], n[1]])
    } else {
        unit([-n[2], 0.0, n[0]])
    }
}

impl ObstacleSpec {
    /// A point on the surface at time 0 and the outward unit normal there, chosen by three
    /// numbers in [0, 1).
    fn surface_point(&self, u: [f64; 3]) -> ([f64; 3], [f64; 3]) {
        use std::f64::consts::PI;
        let side = |c: [f64; 2], r: f64, z: f64| {
            let th = 2.0 * PI * u[0];
            ([c[0] + r * th.cos(), c[1] + r * th.sin(), z], [th.cos(), th.sin(), 0.0])
        };
        match self.shape {
            ShapeSpec::Sphere { c, r } => {
                let (th, zc) = (2.0 * PI * u[0], 2.0 * u[1] - 1.0);
                let rh = (1.0 - zc * zc).sqrt();
                let n = [rh * th.cos(), rh * th.sin(), zc];
                ([c[0] + r * n[0], c[1] + r * n[1], c[2] + r * n[2]], n)
            }
            ShapeSpec::Circle { c, r } => side(c, r, -100.0 * u[1]),
            ShapeSpec::Cylinder { c, r, z_min, z_max } => {
                let lo = if z_min.is_finite() { z_min } else { z_max - 30.0 };
                let hi = if z_max.is_finite() { z_max } else { z_min + 30.0 };
                if u[2] < 0.6 {
                    side(c, r, lo + (hi - lo) * u[1])
                } else {
                    // A cap, if it has one (else the side again).
                    let (z, nz) = if u[2] < 0.8 { (z_max, 1.0) } else { (z_min, -1.0) };
                    if !z.is_finite() {
                        return side(c, r, lo + (hi - lo) * u[1]);
                    }
                    let (th, rr) = (2.0 * PI * u[0], r * u[1].sqrt());
                    ([c[0] + rr * th.cos(), c[1] + rr * th.sin(), z], [0.0, 0.0, nz])
                }
            }
            ShapeSpec::Box { min, max } => {
                let axis = ((u[2] * 6.0) as usize).min(5);
                let (i, upper) = (axis % 3, axis >= 3);
                let (j, k) = ((i + 1) % 3, (i + 2) % 3);
                let mut p = [0.0; 3];
                p[i] = if upper { max[i] } else { min[i] };
                p[j] = min[j] + (max[j] - min[j]) * u[0];
                p[k] = min[k] + (max[k] - min[k]) * u[1];
                let mut n = [0.0; 3];
                n[i] = if upper { 1.0 } else { -1.0 };
                (p, n)
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Strategies. The domain is [0, 100] x [0, 100] x [-100, 0]; segments may stray a little out.

fn peaks_strategy() -> impl Strategy<Value = TerrainSpec> {
    let peak =
        (0.0..100.0, 0.0..100.0, -30.0..50.0, 3.0..30.0, 3.0..30.0).prop_map(|(x, y, h, sx, sy)| [x, y, h, sx, sy]);
    (-100.0..-60.0, prop::collection::vec(peak, 1..5), prop::option::weighted(0.3, -70.0..-30.0))
        .prop_map(|(base, peaks, ceiling)| TerrainSpec::Peaks { base, peaks, ceiling })
}

fn grid_strategy() -> impl Strategy<Value = TerrainSpec> {
    (2usize..7, 2usize..7).prop_flat_map(|(nx, ny)| {
        (-10.0..10.0, -10.0..10.0, 8.0..40.0, 8.0..40.0, prop::collection::vec(-95.0..-20.0, nx * ny))
            .prop_map(move |(x0, y0, dx, dy, z)| TerrainSpec::Grid { x0, y0, dx, dy, nx, ny, z })
    })
}

fn obstacle_strategy() -> impl Strategy<Value = ObstacleSpec> {
    let shape = (0u8..6, (0.0..100.0, 0.0..100.0, -100.0..0.0), (1.0..20.0, 1.0..20.0, 1.0..20.0), 1.0..15.0).prop_map(
        |(kind, (x, y, z), (sx, sy, sz), r)| match kind {
            0 => ShapeSpec::Sphere { c: [x, y, z], r },
            1 => ShapeSpec::Cylinder { c: [x, y], r, z_min: z - sz, z_max: z + sz },
            2 => ShapeSpec::Cylinder { c: [x, y], r, z_min: f64::NEG_INFINITY, z_max: z },
            3 => ShapeSpec::Cylinder { c: [x, y], r, z_min: z, z_max: f64::INFINITY },
            4 => ShapeSpec::Box { min: [x - sx, y - sy, z - sz], max: [x + sx, y + sy, z + sz] },
            _ => ShapeSpec::Circle { c: [x, y], r },
        },
    );
    let velocity = prop_oneof![Just([0.0; 3]), (-3.0..3.0, -3.0..3.0, -1.0..1.0).prop_map(|(x, y, z)| [x, y, z]),];
    (shape, velocity).prop_map(|(shape, velocity)| ObstacleSpec { shape, velocity })
}

fn segment_strategy() -> impl Strategy<Value = SegmentDraw> {
    let point = || (-10.0..110.0, -10.0..110.0, -110.0..10.0).prop_map(|(x, y, z)| [x, y, z]);
    let unit3 = || (0.0..1.0, 0.0..1.0, 0.0..1.0).prop_map(|(x, y, z)| [x, y, z]);
    let dir = || (-1.0..1.0, -1.0..1.0, -1.0..1.0).prop_map(|(x, y, z)| [x, y, z]);
    // Mostly within a hair of the safety distance, sometimes well inside or outside it.
    let offset = || prop_oneof![3 => -0.05..0.05, 1 => -1.0..6.0];
    let placement = prop_oneof![
        2 => (point(), point()).prop_map(|(a, b)| Placement::Free { a, b }),
        1 => point().prop_map(|a| Placement::Degenerate { a }),
        1 => (point(), point()).prop_map(|(a, b)| Placement::Horizontal { a, b: [b[0], b[1]] }),
        1 => (point(), -110.0..10.0).prop_map(|(a, z)| Placement::Vertical { a, z }),
        4 => (0.0..100.0, 0.0..100.0, offset(), 0.0..6.3, prop_oneof![Just(0.0), -0.3..0.3], 0.5..20.0, 0.0..1.0).prop_map(
            |(x, y, delta, heading, slope, len, lambda)| Placement::SkimSeabed { x, y, delta, heading, slope, len, lambda }
        ),
        6 => (0usize..6, unit3(), dir(), offset(), 0.5..40.0, 0.0..1.0).prop_map(
            |(pick, surf, dir, delta, len, lambda)| Placement::SkimObstacle { pick, surf, dir, delta, len, lambda }
        ),
    ];
    (placement, 0.0..20.0, 0.0..20.0, prop_oneof![Just(0.0), 0.0..5.0])
        .prop_map(|(placement, ta, dt, safety)| SegmentDraw { placement, ta, dt, safety })
}

fn world_strategy() -> impl Strategy<Value = (TerrainSpec, Vec<ObstacleSpec>, Vec<SegmentDraw>)> {
    (
        prop_oneof![peaks_strategy(), grid_strategy()],
        prop::collection::vec(obstacle_strategy(), 0..=6),
        prop::collection::vec(segment_strategy(), 1..=8),
    )
}

// ---------------------------------------------------------------------------------------------
// The checks.

fn lerp(a: [f64; 3], b: [f64; 3], s: f64) -> [f64; 3] {
    [a[0] + (b[0] - a[0]) * s, a[1] + (b[1] - a[1]) * s, a[2] + (b[2] - a[2]) * s]
}

fn check_terrain(spec: &TerrainSpec, world: &World, seg: &SegmentSpec) -> Result<(), TestCaseError> {
    let (a, b) = (Vec3::from(seg.a), Vec3::from(seg.b));
    let hits = world.segment_hits_terrain(a, b, seg.safety);
    let clearance = world.segment_terrain_clearance(a, b);
    let tol = 1e-8;
    let mut sampled_min = f64::INFINITY;
    for k in 0..=SAMPLES {
        let p = lerp(seg.a, seg.b, k as f64 / SAMPLES as f64);
        let g = p[2] - spec.height(p[0], p[1]);
        sampled_min = sampled_min.min(g);
        if !hits {
            prop_assert!(
                g >= seg.safety - tol,
                "terrain called clear with safety {} but sample {k} has vertical clearance {g}",
                seg.safety
            );
        }
        prop_assert!(clearance <= g + tol, "terrain clearance {clearance} above sample {k}'s {g}");
    }
    if clearance > seg.safety + spec.hit_allowance() {
        prop_assert!(!hits, "clearance {clearance} but a hit at safety {} (sampled min {sampled_min})", seg.safety);
    }
    Ok(())
}

fn check_obstacle(spec: &ObstacleSpec, obstacle: &Obstacle, seg: &SegmentSpec) -> Result<(), TestCaseError> {
    let (a, b) = (Vec3::from(seg.a), Vec3::from(seg.b));
    let hits = obstacle.segment_hits(a, b, seg.ta, seg.tb, seg.safety);
    let clearance = obstacle.segment_clearance(a, b, seg.ta, seg.tb);
    // Length of the segment in the obstacle's frame: the distance changes at most this much per
    // unit of the segment parameter.
    let v = Vec3::from(spec.velocity);
    let rel_len = ((b - v * seg.tb) - (a - v * seg.ta)).length();
    let tol = 1e-7 * (1.0 + rel_len);
    prop_assert!(clearance >= 0.0, "negative clearance {clearance}");
    let mut sampled_min = f64::INFINITY;
    for k in 0..=SAMPLES {
        let s = k as f64 / SAMPLES as f64;
        let p = lerp(seg.a, seg.b, s);
        let t = seg.ta + (seg.tb - seg.ta) * s;
        let d = spec.signed_distance(p, t);
        sampled_min = sampled_min.min(d.max(0.0));
        if !hits {
            prop_assert!(
                d >= seg.safety - tol,
                "obstacle called clear at safety {} but sample {k} is at {d}",
                seg.safety
            );
        }
        prop_assert!(clearance <= d.max(0.0) + tol, "clearance {clearance} above sample {k}'s distance {d}");
    }
    // Between samples the distance cannot dip by more than half a sample spacing.
    let gap = rel_len / (2.0 * SAMPLES as f64);
    prop_assert!(clearance >= sampled_min - gap - tol, "clearance {clearance} far below sampled min {sampled_min}");
    // The hit test and the clearance must agree away from the boundary.
    if clearance > seg.safety + tol {
        prop_assert!(!hits, "clearance {clearance} > safety {} yet a hit", seg.safety);
    }
    if clearance < seg.safety - tol || clearance == 0.0 {
        prop_assert!(hits, "clearance {clearance} < safety {} yet clear", seg.safety);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn segments_called_clear_are_clear((terrain, obstacles, segments) in world_strategy()) {
        let mut world = World::open(Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(100.0, 100.0, 0.0)));
        world.terrain = terrain.build();
        world.obstacles = obstacles.iter().map(ObstacleSpec::build).collect();
        for draw in &segments {
            let seg = &draw.resolve(&terrain, &obstacles);
            check_terrain(&terrain, &world, seg)?;
            for (spec, obstacle) in obstacles.iter().zip(&world.obstacles) {
                check_obstacle(spec, obstacle, seg)?;
            }
        }
    }
}
