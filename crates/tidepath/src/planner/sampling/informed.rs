//! Informed sampling (Gammell, Srinivasa & Barfoot 2014): once a path of length c_best joins
//! start and goal, only states x with |x - start| + |x - goal| <= c_best can lie on a shorter
//! one. They fill a prolate hyperspheroid with foci at start and goal, transverse diameter
//! c_best and conjugate diameters sqrt(c_best^2 - c_min^2), c_min = |goal - start| (their
//! eqs. 5-7); a uniform sample of it is x = C L x_ball + (start + goal) / 2, with x_ball
//! uniform in the unit ball, L = diag(c_best / 2, r, r) and C a rotation taking the first axis
//! to the start-goal direction (their Alg. 2).
//!
//! The bound is a bound on length: it holds for a cost that is a fixed multiple of length
//! ([`crate::cost::CostModel::cost_per_metre`], still water); in a current it does not (a
//! longer path can be cheaper), and Informed RRT* then samples the whole space like RRT*.
//!
//! The hyperspheroid is clipped to the sampled box: when it is the smaller of the two, it is
//! sampled and samples outside the box are drawn again; otherwise the box is sampled and
//! samples outside the hyperspheroid are drawn again; after [`MAX_DRAWS`] misses the last
//! box sample is used (it is uniform in the box, so RRT*'s guarantees are kept).

use rand::Rng as _;

use super::SampleSpace;
use crate::geom::Vec3;
use crate::rng::Rng;

/// Draws per sample before falling back to the box.
pub const MAX_DRAWS: usize = 100;

/// The informed set of one start-goal pair and a best length.
#[derive(Clone, Copy, Debug)]
pub struct Informed {
    centre: Vec3,
    /// Unit vector from start to goal, and two unit vectors completing an orthonormal basis.
    axes: [Vec3; 3],
    start: Vec3,
    goal: Vec3,
    c_best: f64,
    /// Semi-axes: c_best / 2 along the first axis, the conjugate radius across.
    semi: [f64; 2],
}

impl Informed {
    /// The informed set for paths shorter than `c_best` between `start` and `goal`; `None`
    /// when start and goal coincide (no direction).
    pub fn new(start: Vec3, goal: Vec3, c_best: f64) -> Option<Self> {
        let c_min = start.distance(goal);
        if c_min.is_nan() || c_min <= 0.0 || !c_best.is_finite() {
            return None;
        }
        let c_best = c_best.max(c_min);
        let a1 = (goal - start) / c_min;
        let (a2, a3) = a1.any_orthonormal_pair();
        let conjugate = 0.5 * (c_best * c_best - c_min * c_min).max(0.0).sqrt();
        Some(Self {
            centre: (start + goal) * 0.5,
            axes: [a1, a2, a3],
            start,
            goal,
            c_best,
            semi: [0.5 * c_best, conjugate],
        })
    }

    /// Whether `p` can lie on a path shorter than c_best.
    #[inline]
    pub fn contains(&self, p: Vec3) -> bool {
        p.distance(self.start) + p.distance(self.goal) <= self.c_best
    }

    /// Measure of the informed set in `dims` dimensions (the ellipse's area in the plane of
    /// start and goal for a 2-D space).
    pub fn measure(&self, dims: usize) -> f64 {
        let [a, b] = self.semi;
        if dims == 3 {
            4.0 / 3.0 * std::f64::consts::PI * a * b * b
        } else {
            std::f64::consts::PI * a * b
        }
    }

    /// A uniform sample of the hyperspheroid: in 2-D the ellipse in the horizontal plane
    /// through the foci (a 2-D space has start and goal at one height).
    fn draw(&self, space: &SampleSpace, rng: &mut Rng) -> Vec3 {
        let [a, b] = self.semi;
        // A uniform point of the unit ball by rejection from the cube (in 2-D, the disc).
        let u = loop {
            let x = 2.0 * rng.random::<f64>() - 1.0;
            let y = 2.0 * rng.random::<f64>() - 1.0;
            let z = if space.dims == 3 { 2.0 * rng.random::<f64>() - 1.0 } else { 0.0 };
            if x * x + y * y + z * z <= 1.0 {
                break Vec3::new(x, y, z);
            }
        };
        if space.dims == 3 {
            self.centre + self.axes[0] * (a * u.x) + self.axes[1] * (b * u.y) + self.axes[2] * (b * u.z)
        } else {
            // The planar basis: the start-goal direction and its horizontal normal.
            let d = self.axes[0];
            let n = Vec3::new(-d.y, d.x, 0.0);
            let mut p = self.centre + d * (a * u.x) + n * (b * u.y);
            p.z = space.lo.z;
            p
        }
    }

    /// A uniform sample of the informed set within `space`.
    pub fn sample(&self, space: &SampleSpace, rng: &mut Rng) -> Vec3 {
        let mut last = space.lo;
        if self.measure(space.dims) < space.measure() {
            for _ in 0..MAX_DRAWS {
                let p = self.draw(space, rng);
                if space.contains(p) {
                    return p;
                }
            }
        }
        for _ in 0..MAX_DRAWS {
            last = space.sample(rng);
            if self.contains(last) {
                return last;
            }
        }
        last
    }
}
