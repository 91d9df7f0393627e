//! Obstacles: spheres, vertical cylinders (finite or full depth), axis-aligned boxes and 2-D
//! circles (full-depth vertical cylinders), each optionally moving with a constant velocity.
//!
//! A segment traversed from time ta to tb at constant ground speed is a straight segment in the
//! obstacle's own frame too (subtract the obstacle's motion), so moving obstacles get the same
//! exact tests as fixed ones.
//!
//! Shapes are closed sets: touching the surface counts as a hit, and a margin of 0 means
//! "touching or inside". Seeds 001 and 003 use spheres, cylinders (radar threats that reach
//! through every depth) and cubes; 2-D worlds use circles.

// `!(d >= margin)` is deliberate throughout: a NaN must fail every "clear" test.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::geom::{Vec2, Vec3};

mod distance;

use distance::{
    aabb_apart, box_excess, box_segment_dist2, circle_segment_distance, cylinder_point_distance,
    cylinder_segment_distance, segment_intersects_box, segment_point_dist2, segment_point_dist2_2d,
};

/// A shape at time 0.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    Sphere {
        center: Vec3,
        radius: f64,
    },
    /// Vertical cylinder between z_min and z_max (use +-inf for full depth).
    Cylinder {
        center: Vec2,
        radius: f64,
        z_min: f64,
        z_max: f64,
    },
    Box {
        min: Vec3,
        max: Vec3,
    },
    /// A 2-D circle, i.e. a vertical cylinder through the whole water column.
    Circle {
        center: Vec2,
        radius: f64,
    },
}

#[derive(Clone, Debug, PartialEq)]
pub struct Obstacle {
    pub shape: Shape,
    /// Constant velocity in m/s; the shape at time t is translated by velocity * t.
    pub velocity: Vec3,
    /// The closed time interval the obstacle exists in (`None`: always). A vehicle of a fleet
    /// planned earlier is a chain of such obstacles, one per leg of its timed path.
    pub window: Option<(f64, f64)>,
}

impl Obstacle {
    pub fn fixed(shape: Shape) -> Self {
        Self { shape, velocity: Vec3::ZERO, window: None }
    }

    /// An obstacle moving at `velocity` from its place `shape` at time 0, at all times.
    pub fn moving(shape: Shape, velocity: Vec3) -> Self {
        Self { shape, velocity, window: None }
    }

    /// Whether it stays where it is for all time (what the rasters, the reachability check
    /// and the visibility graph take as terrain).
    #[inline]
    pub fn is_fixed(&self) -> bool {
        self.velocity == Vec3::ZERO && self.window.is_none()
    }

    /// The part of the motion a -> b (from `ta` to `tb`) inside the obstacle's window, or
    /// `None` when they do not overlap in time. Undefined times keep the whole motion (the
    /// exact tests treat them as hits).
    #[inline]
    fn clip(&self, a: Vec3, b: Vec3, ta: f64, tb: f64) -> Option<(Vec3, Vec3, f64, f64)> {
        let Some((w0, w1)) = self.window else { return Some((a, b, ta, tb)) };
        if !(ta.is_finite() && tb.is_finite()) {
            return Some((a, b, ta, tb));
        }
        let (lo, hi) = (ta.max(w0), tb.min(w1));
        if lo > hi {
            return None;
        }
        if tb > ta {
            let f = |t: f64| a + (b - a) * ((t - ta) / (tb - ta));
            Some((if lo > ta { f(lo) } else { a }, if hi < tb { f(hi) } else { b }, lo, hi))
        } else {
            Some((a, b, ta, tb))
        }
    }

    /// The shape translated to time `t`. A moving obstacle at a non-finite time has no place,
    /// and its coordinates come out non-finite (axes it does not move along stay put).
    pub fn shape_at(&self, t: f64) -> Shape {
        if self.velocity == Vec3::ZERO {
            return self.shape.clone();
        }
        let shift = Vec3::select(self.velocity.cmpeq(Vec3::ZERO), Vec3::ZERO, self.velocity * t);
        self.shape.translated(shift)
    }

    /// Is point `p` at time `t` closer than `margin` to the obstacle (or inside it)?
    ///
    /// A moving obstacle at a non-finite time could be anywhere, so the answer is `true`.
    #[inline]
    pub fn contains(&self, p: Vec3, t: f64, margin: f64) -> bool {
        if let Some((w0, w1)) = self.window {
            if t.is_finite() && !(w0 <= t && t <= w1) {
                return false;
            }
        }
        let p = if self.velocity == Vec3::ZERO {
            p
        } else if t.is_finite() {
            p - self.velocity * t
        } else {
            return true;
        };
        let d = self.shape.distance_to_point(p);
        !(d >= margin && d > 0.0)
    }

    /// Whether the obstacle's box can meet the box `lo`..`hi` at some time in [t0, t1]: its
    /// box at time 0 moved by every displacement it makes over the interval (a box test,
    /// conservative: `false` proves it stays clear).
    #[inline]
    pub fn may_come_within(&self, lo: Vec3, hi: Vec3, t0: f64, t1: f64) -> bool {
        let (t0, t1) = match self.window {
            Some((w0, w1)) if t0.is_finite() && t1.is_finite() => {
                if t0.max(w0) > t1.min(w1) {
                    return false;
                }
                (t0.max(w0), t1.min(w1))
            }
            _ => (t0, t1),
        };
        let (min, max) = self.shape.bounds();
        swept_box_meets(min, max, self.velocity, lo, hi, t0, t1)
    }

    /// Does the segment a -> b, traversed from time `ta` to `tb`, come closer than `margin`
    /// to the obstacle? Exact (up to floating point).
    ///
    /// With a non-finite `ta` or `tb` a moving obstacle's position is undefined and the answer
    /// is `true` (conservative); a fixed obstacle ignores the times. A NaN coordinate never
    /// makes a segment clear: it is a hit unless the other coordinates alone keep it away
    /// (checking for NaN up front would cost every call in the hot loop).
    #[inline]
    pub fn segment_hits(&self, a: Vec3, b: Vec3, ta: f64, tb: f64, margin: f64) -> bool {
        let Some((a, b, ta, tb)) = self.clip(a, b, ta, tb) else { return false };
        match self.relative_segment(a, b, ta, tb) {
            Some((a, b)) => self.shape.segment_hits(a, b, margin),
            None => true,
        }
    }

    /// Minimum Euclidean distance between the moving segment and the obstacle surface;
    /// 0 when they touch or intersect.
    ///
    /// Non-finite times for a moving obstacle, or non-finite points, give 0 (conservative).
    pub fn segment_clearance(&self, a: Vec3, b: Vec3, ta: f64, tb: f64) -> f64 {
        if !(a.is_finite() && b.is_finite()) {
            return 0.0;
        }
        let Some((a, b, ta, tb)) = self.clip(a, b, ta, tb) else { return f64::INFINITY };
        match self.relative_segment(a, b, ta, tb) {
            Some((a, b)) => self.shape.segment_distance(a, b),
            None => 0.0,
        }
    }

    /// The segment in the obstacle's frame (shape frozen at time 0). At constant ground speed
    /// the point at time t is a + (b - a)(t - ta)/(tb - ta) and the obstacle has moved by
    /// v t, so the relative motion is again a straight segment from a - v ta to b - v tb.
    #[inline]
    fn relative_segment(&self, a: Vec3, b: Vec3, ta: f64, tb: f64) -> Option<(Vec3, Vec3)> {
        // Branch-free in the common case: with zero velocity the shift is an exact 0.
        if ta.is_finite() && tb.is_finite() {
            Some((a - self.velocity * ta, b - self.velocity * tb))
        } else if self.velocity == Vec3::ZERO {
            Some((a, b))
        } else {
            None
        }
    }
}

/// Whether the box `min`..`max` moving at `velocity` (at its place at time 0) meets the box
/// `lo`..`hi` at some time in [t0, t1]. Conservative: `false` proves they stay apart.
/// Undefined times keep the caller on its exact test (which treats them as hits); so does NaN
/// anywhere, through `!(x > y)` (`min` and `max` alone would drop a NaN).
#[inline]
pub fn swept_box_meets(min: Vec3, max: Vec3, velocity: Vec3, lo: Vec3, hi: Vec3, t0: f64, t1: f64) -> bool {
    if !(t0.is_finite() && t1.is_finite()) {
        return true;
    }
    let (d0, d1) = (velocity * t0, velocity * t1);
    let (swept_lo, swept_hi) = (min + d0.min(d1), max + d0.max(d1));
    !(swept_lo.x > hi.x
        || swept_lo.y > hi.y
        || swept_lo.z > hi.z
        || lo.x > swept_hi.x
        || lo.y > swept_hi.y
        || lo.z > swept_hi.z)
}

impl Shape {
    /// The shape moved by `d` (a circle ignores d.z: it spans the whole water column).
    pub fn translated(&self, d: Vec3) -> Shape {
        match *self {
            Shape::Sphere { center, radius } => Shape::Sphere { center: center + d, radius },
            Shape::Cylinder { center, radius, z_min, z_max } => {
                Shape::Cylinder { center: center + d.truncate(), radius, z_min: z_min + d.z, z_max: z_max + d.z }
            }
            Shape::Box { min, max } => Shape::Box { min: min + d, max: max + d },
            Shape::Circle { center, radius } => Shape::Circle { center: center + d.truncate(), radius },
        }
    }

    /// Euclidean distance from `p` to the shape, 0 inside.
    #[inline]
    pub fn distance_to_point(&self, p: Vec3) -> f64 {
        match *self {
            Shape::Sphere { center, radius } => ((p - center).length() - radius).max(0.0),
            Shape::Cylinder { center, radius, z_min, z_max } => {
                cylinder_point_distance(center, radius, z_min, z_max, p)
            }
            Shape::Box { min, max } => box_excess(min, max, p).length(),
            Shape::Circle { center, radius } => ((p.truncate() - center).length() - radius).max(0.0),
        }
    }

    /// Exact distance from the static segment a -> b to the shape (0 when they touch).
    pub fn segment_distance(&self, a: Vec3, b: Vec3) -> f64 {
        match *self {
            Shape::Sphere { center, radius } => (segment_point_dist2(a, b - a, center).sqrt() - radius).max(0.0),
            Shape::Circle { center, radius } => circle_segment_distance(center, radius, a, b),
            Shape::Cylinder { center, radius, z_min, z_max } => {
                cylinder_segment_distance(center, radius, z_min, z_max, a, b, f64::NEG_INFINITY, f64::INFINITY)
            }
            Shape::Box { min, max } => box_segment_dist2(min, max, a, b).sqrt(),
        }
    }

    /// Does the static segment a -> b come closer than `margin` to the shape, or touch it?
    ///
    /// The shape's box grown by the margin rejects the usual far-away case (both endpoints
    /// beyond one face) in a dozen comparisons, inlined; only segments that get near reach the
    /// exact tests. Comparisons with NaN are false, so a NaN never rejects, and the exact tests
    /// are written as `!(clear)` so that NaN reports a hit.
    #[inline]
    pub fn segment_hits(&self, a: Vec3, b: Vec3, margin: f64) -> bool {
        let m = if margin > 0.0 { margin } else { 0.0 };
        let (lo, hi) = self.bounds();
        if aabb_apart(a, b, lo - Vec3::splat(m), hi + Vec3::splat(m)) {
            return false;
        }
        self.segment_hits_near(a, b, margin, m)
    }

    /// The bounding box corners (z infinite for circles), for the rejection test.
    #[inline(always)]
    fn bounds(&self) -> (Vec3, Vec3) {
        match *self {
            Shape::Sphere { center, radius } => (center - Vec3::splat(radius), center + Vec3::splat(radius)),
            Shape::Cylinder { center, radius, z_min, z_max } => (
                Vec3::new(center.x - radius, center.y - radius, z_min),
                Vec3::new(center.x + radius, center.y + radius, z_max),
            ),
            Shape::Box { min, max } => (min, max),
            Shape::Circle { center, radius } => (
                Vec3::new(center.x - radius, center.y - radius, f64::NEG_INFINITY),
                Vec3::new(center.x + radius, center.y + radius, f64::INFINITY),
            ),
        }
    }

    /// The exact part of [`Shape::segment_hits`], kept out of line so the rejection inlines.
    #[inline(never)]
    fn segment_hits_near(&self, a: Vec3, b: Vec3, margin: f64, m: f64) -> bool {
        match *self {
            Shape::Sphere { center, radius } => {
                let d2 = segment_point_dist2(a, b - a, center);
                if margin > 0.0 {
                    let reach = radius + m;
                    !(d2 >= reach * reach)
                } else {
                    !(d2 > radius * radius)
                }
            }
            Shape::Circle { center, radius } => {
                let (d2, _) = segment_point_dist2_2d(a.truncate(), (b - a).truncate(), center, 0.0, 1.0);
                if margin > 0.0 {
                    let reach = radius + m;
                    !(d2 >= reach * reach)
                } else {
                    !(d2 > radius * radius)
                }
            }
            Shape::Cylinder { center, radius, z_min, z_max } => {
                let d = cylinder_segment_distance(center, radius, z_min, z_max, a, b, margin, m);
                !(d >= margin && d > 0.0)
            }
            Shape::Box { min, max } => {
                if segment_intersects_box(min, max, a, b) {
                    return true;
                }
                if !(margin > 0.0) {
                    // Not intersecting the closed box and no margin to honour: clear, unless
                    // NaN made the slab test fail.
                    return (a + b).is_nan();
                }
                // The margin-rounded box lies inside the box grown by the margin: missing that
                // one settles most near passes without the exact distance.
                if !segment_intersects_box(min - Vec3::splat(m), max + Vec3::splat(m), a, b) {
                    return (a + b).is_nan();
                }
                let d2 = box_segment_dist2(min, max, a, b);
                !(d2 >= margin * margin)
            }
        }
    }

    /// The shape's bounding box (infinite along z for circles and full-depth cylinders).
    pub fn aabb(&self) -> crate::geom::Aabb {
        let (min, max) = self.bounds();
        crate::geom::Aabb::new(min, max)
    }
}

#[cfg(test)]
mod tests;
