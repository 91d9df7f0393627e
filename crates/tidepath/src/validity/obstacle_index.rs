//! A uniform grid over the domain's horizontal extent listing which fixed obstacles may come
//! near each cell, so a segment is tested only against obstacles around it.
//!
//! The index is conservative: an obstacle is skipped for a segment only when their horizontal
//! boxes (the obstacle's inflated by the safety margin) are apart, in which case the exact test
//! rejects the pair anyway. Moving obstacles are not indexed: the validator tests them piece by
//! piece at the vehicle's clock (see [`super::Validator::motion`]).

use crate::geom::Vec3;
use crate::world::World;

/// Below this many fixed obstacles a plain loop is as fast as the index.
const MIN_INDEXED: usize = 8;
/// Obstacles a candidate bitset can hold; more fall back to the plain loop.
const MAX_INDEXED: usize = 256;

#[derive(Clone, Debug, Default)]
pub(crate) struct ObstacleIndex {
    /// Fixed obstacles tested against every segment when the world is too sparse to index.
    always: Vec<u32>,
    /// Moving obstacles, in increasing index.
    moving: Vec<u32>,
    /// Per moving obstacle (same order): its box at time 0 and its velocity, for the box test
    /// over a whole motion without going through the shape.
    moving_boxes: Vec<(Vec3, Vec3, Vec3)>,
    x0: f64,
    y0: f64,
    inv_w: f64,
    inv_h: f64,
    nx: usize,
    ny: usize,
    /// Cell c lists items[offsets[c]..offsets[c + 1]].
    offsets: Vec<u32>,
    items: Vec<u32>,
    indexed: bool,
}

impl ObstacleIndex {
    pub(crate) fn new(world: &World, margin: f64) -> Self {
        let n = world.obstacles.len();
        let fixed: Vec<usize> = (0..n).filter(|&k| world.obstacles[k].is_fixed()).collect();
        let moving: Vec<u32> = (0..n as u32).filter(|&k| !world.obstacles[k as usize].is_fixed()).collect();
        let moving_boxes = moving
            .iter()
            .map(|&k| {
                let o = &world.obstacles[k as usize];
                let b = o.shape.aabb();
                (b.min, b.max, o.velocity)
            })
            .collect();
        if fixed.len() < MIN_INDEXED || n > MAX_INDEXED {
            return Self { always: fixed.iter().map(|&k| k as u32).collect(), moving, moving_boxes, ..Self::default() };
        }
        let b = world.bounds;
        let side = ((fixed.len() as f64).sqrt() * 2.0).ceil().clamp(2.0, 32.0) as usize;
        let (w, h) = ((b.max.x - b.min.x).max(1e-9), (b.max.y - b.min.y).max(1e-9));
        let (nx, ny) = if w >= h {
            (side, ((side as f64 * h / w).ceil() as usize).max(1))
        } else {
            (((side as f64 * w / h).ceil() as usize).max(1), side)
        };
        let mut index = Self {
            always: Vec::new(),
            moving,
            moving_boxes,
            x0: b.min.x,
            y0: b.min.y,
            inv_w: nx as f64 / w,
            inv_h: ny as f64 / h,
            nx,
            ny,
            offsets: Vec::new(),
            items: Vec::new(),
            indexed: true,
        };
        // Inflate by the margin plus a hair so rounding never makes the index stricter than the
        // exact test's own box rejection.
        let grow = margin.max(0.0) * (1.0 + 1e-9) + 1e-9 * (w + h);
        let mut cells: Vec<Vec<u32>> = vec![Vec::new(); nx * ny];
        for &k in &fixed {
            let bb = world.obstacles[k].shape.aabb();
            let (i0, j0) = index.cell(bb.min.x - grow, bb.min.y - grow);
            let (i1, j1) = index.cell(bb.max.x + grow, bb.max.y + grow);
            for j in j0..=j1 {
                for i in i0..=i1 {
                    cells[j * nx + i].push(k as u32);
                }
            }
        }
        index.offsets.push(0);
        for c in cells {
            index.items.extend_from_slice(&c);
            index.offsets.push(index.items.len() as u32);
        }
        index
    }

    /// The cell of (x, y), clamped to the grid. Clamping is monotone, so two overlapping
    /// intervals still share a cell after it.
    #[inline]
    fn cell(&self, x: f64, y: f64) -> (usize, usize) {
        let fx = ((x - self.x0) * self.inv_w).floor();
        let fy = ((y - self.y0) * self.inv_h).floor();
        // NaN maps to 0 and is then covered by the full-range fallback in `for_each_candidate`.
        let i = if fx.is_nan() { 0.0 } else { fx.clamp(0.0, (self.nx - 1) as f64) };
        let j = if fy.is_nan() { 0.0 } else { fy.clamp(0.0, (self.ny - 1) as f64) };
        (i as usize, j as usize)
    }

    /// The moving obstacles, in increasing index.
    #[inline]
    pub(crate) fn moving(&self) -> &[u32] {
        &self.moving
    }

    /// Whether the `j`-th moving obstacle, swept over [t0, t1], may meet the box `lo`..`hi`
    /// ([`crate::world::obstacle::swept_box_meets`] on the stored box).
    #[inline]
    pub(crate) fn moving_may_come_within(&self, j: usize, lo: Vec3, hi: Vec3, t0: f64, t1: f64) -> bool {
        let (min, max, v) = self.moving_boxes[j];
        crate::world::obstacle::swept_box_meets(min, max, v, lo, hi, t0, t1)
    }

    /// Calls `f(k)` once for every fixed obstacle k that may come near segment a-b: all of them
    /// in a sparse world, else the indexed ones whose cells the segment's horizontal box
    /// touches, in increasing k.
    #[inline]
    pub(crate) fn for_each_candidate(&self, a: Vec3, b: Vec3, mut f: impl FnMut(usize)) {
        for &k in &self.always {
            f(k as usize);
        }
        if !self.indexed {
            return;
        }
        let (lo, hi) = (a.min(b), a.max(b));
        let ((i0, j0), (i1, j1)) = if lo.is_finite() && hi.is_finite() {
            (self.cell(lo.x, lo.y), self.cell(hi.x, hi.y))
        } else {
            ((0, 0), (self.nx - 1, self.ny - 1))
        };
        let mut seen = [0u64; MAX_INDEXED / 64];
        for j in j0..=j1 {
            for i in i0..=i1 {
                let c = j * self.nx + i;
                for &k in &self.items[self.offsets[c] as usize..self.offsets[c + 1] as usize] {
                    seen[k as usize / 64] |= 1 << (k % 64);
                }
            }
        }
        for (w, mut bits) in seen.into_iter().enumerate() {
            while bits != 0 {
                let t = bits.trailing_zeros() as usize;
                f(w * 64 + t);
                bits &= bits - 1;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::{Aabb, Vec2};
    use crate::world::{Obstacle, Shape};
    use rand::{Rng, SeedableRng};

    /// The index may only skip pairs the exact test rejects: compare with the plain loop on
    /// random worlds dense enough to be indexed.
    #[test]
    fn index_never_skips_a_hit() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(11);
        for _ in 0..200 {
            let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(1000.0, 600.0, 0.0)));
            let n = rng.random_range(10..40);
            for k in 0..n {
                let c = Vec3::new(rng.random_range(-50.0..1050.0), rng.random_range(-50.0..650.0), -50.0);
                let r = rng.random_range(1.0..60.0);
                let shape = match k % 4 {
                    0 => Shape::Sphere { center: c, radius: r },
                    1 => Shape::Circle { center: Vec2::new(c.x, c.y), radius: r },
                    2 => Shape::Box { min: c - Vec3::splat(r), max: c + Vec3::new(r, 2.0 * r, r) },
                    _ => Shape::Cylinder { center: Vec2::new(c.x, c.y), radius: r, z_min: -80.0, z_max: -20.0 },
                };
                let velocity = if k % 7 == 3 { Vec3::new(0.5, -0.2, 0.0) } else { Vec3::ZERO };
                w.obstacles.push(Obstacle { shape, velocity, window: None });
            }
            let margin = rng.random_range(0.0..20.0);
            let index = ObstacleIndex::new(&w, margin);
            assert!(index.indexed);
            for _ in 0..200 {
                let p = |rng: &mut rand_chacha::ChaCha8Rng| {
                    Vec3::new(
                        rng.random_range(-100.0..1100.0),
                        rng.random_range(-100.0..700.0),
                        rng.random_range(-100.0..0.0),
                    )
                };
                let (a, b) = (p(&mut rng), p(&mut rng));
                let (ta, tb) = (0.0, rng.random_range(0.0..500.0));
                let mut seen = Vec::new();
                index.for_each_candidate(a, b, |k| seen.push(k));
                let mut unique = seen.clone();
                unique.sort();
                unique.dedup();
                assert_eq!(unique.len(), seen.len(), "a candidate was offered twice");
                for (k, o) in w.obstacles.iter().enumerate() {
                    if !o.is_fixed() {
                        assert!(!seen.contains(&k) && index.moving().contains(&(k as u32)));
                    } else if o.segment_hits(a, b, ta, tb, margin) {
                        assert!(seen.contains(&k), "obstacle {k} hit but skipped by the index");
                    }
                }
            }
        }
    }

    #[test]
    fn sparse_worlds_use_the_plain_loop() {
        let mut w = World::open(Aabb::new(Vec3::ZERO, Vec3::ONE));
        w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::splat(0.5), radius: 0.1 }));
        let index = ObstacleIndex::new(&w, 0.0);
        let mut seen = Vec::new();
        index.for_each_candidate(Vec3::ZERO, Vec3::ONE, |k| seen.push(k));
        assert_eq!(seen, vec![0]);
    }
}
