//! The space the sampling planners sample, and the rewiring radius of Karaman & Frazzoli.

use std::f64::consts::PI;

use rand::Rng as _;

use super::super::Problem;
use crate::geom::Vec3;
use crate::rng::Rng;

/// The domain box of one mission: x and y over the world's bounds; z over the vehicle's depth
/// band within the bounds in 3-D, fixed at the start's height in 2-D.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampleSpace {
    pub lo: Vec3,
    pub hi: Vec3,
    /// 2 or 3: the dimension of the sampled space.
    pub dims: usize,
}

impl SampleSpace {
    /// The space of mission `i`.
    pub fn of(problem: &Problem<'_>, i: usize) -> Self {
        let b = &problem.world.bounds;
        let m = &problem.missions[i];
        match problem.z_range(i) {
            Some((z0, z1)) => {
                Self { lo: Vec3::new(b.min.x, b.min.y, z0), hi: Vec3::new(b.max.x, b.max.y, z1), dims: 3 }
            }
            None => {
                Self { lo: Vec3::new(b.min.x, b.min.y, m.start.z), hi: Vec3::new(b.max.x, b.max.y, m.start.z), dims: 2 }
            }
        }
    }

    /// A uniform sample (two draws in 2-D, three in 3-D).
    #[inline]
    pub fn sample(&self, rng: &mut Rng) -> Vec3 {
        let x = self.lo.x + (self.hi.x - self.lo.x) * rng.random::<f64>();
        let y = self.lo.y + (self.hi.y - self.lo.y) * rng.random::<f64>();
        let z = if self.dims == 3 { self.lo.z + (self.hi.z - self.lo.z) * rng.random::<f64>() } else { self.lo.z };
        Vec3::new(x, y, z)
    }

    pub fn contains(&self, p: Vec3) -> bool {
        p.x >= self.lo.x
            && p.x <= self.hi.x
            && p.y >= self.lo.y
            && p.y <= self.hi.y
            && (self.dims == 2 || (p.z >= self.lo.z && p.z <= self.hi.z))
    }

    /// Lebesgue measure of the space (area in 2-D, volume in 3-D): an upper bound on the free
    /// space's measure, which the radius needs (a larger measure only adds neighbours).
    pub fn measure(&self) -> f64 {
        let d = self.hi - self.lo;
        if self.dims == 3 {
            d.x * d.y * d.z.max(f64::MIN_POSITIVE)
        } else {
            d.x * d.y
        }
    }

    /// No extent in z: a 2-D world, or a depth band of one height.
    pub fn is_flat(&self) -> bool {
        self.hi.z <= self.lo.z
    }

    /// The diagonal (m): the default steering range is a fraction of it.
    pub fn diagonal(&self) -> f64 {
        (self.hi - self.lo).length()
    }
}

/// Which of Karaman & Frazzoli's constants.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Variant {
    /// RRT*: gamma > (2 (1 + 1/d))^(1/d) (mu / zeta_d)^(1/d) (Karaman & Frazzoli 2011, Thm. 38).
    Rrt,
    /// PRM*: gamma > 2 (1 + 1/d)^(1/d) (mu / zeta_d)^(1/d) (Karaman & Frazzoli 2011, Thm. 34).
    Prm,
}

/// Volume of the unit ball in `d` dimensions (zeta_d): pi in 2-D, 4 pi / 3 in 3-D.
pub fn unit_ball_measure(d: usize) -> f64 {
    if d == 3 {
        4.0 * PI / 3.0
    } else {
        PI
    }
}

/// The connection radius after `n` vertices: gamma (log n / n)^(1/d), with gamma the
/// variant's lower bound times `factor` (OMPL's `rewire_factor`, 1.1 by default: the theorems
/// need gamma strictly above the bound), for samples spread over `measure` (the space's, or
/// the informed set's once Informed RRT* samples only that) in `space.dims` dimensions. For
/// RRT* the caller also caps it at the steering range (the eta of the paper).
pub fn rewire_radius(variant: Variant, space: &SampleSpace, measure: f64, n: usize, factor: f64) -> f64 {
    let d = space.dims as f64;
    let ratio = (measure / unit_ball_measure(space.dims)).powf(1.0 / d);
    let gamma = match variant {
        Variant::Rrt => (2.0 * (1.0 + 1.0 / d)).powf(1.0 / d) * ratio,
        Variant::Prm => 2.0 * (1.0 + 1.0 / d).powf(1.0 / d) * ratio,
    };
    let n = n.max(2) as f64;
    factor * gamma * (n.ln() / n).powf(1.0 / d)
}
