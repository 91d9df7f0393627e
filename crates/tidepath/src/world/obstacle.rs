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
}

/// Golden-section searches stop when the bracket is this fraction of the segment parameter
/// range: the distance along a segment is |b - a|-Lipschitz in the parameter, so the minimum
/// found is within 1e-9 |b - a| of the true one.
const GOLDEN_TOL: f64 = 1e-9;

impl Obstacle {
    pub fn fixed(shape: Shape) -> Self {
        Self { shape, velocity: Vec3::ZERO }
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

    /// Does the segment a -> b, traversed from time `ta` to `tb`, come closer than `margin`
    /// to the obstacle? Exact (up to floating point).
    ///
    /// With a non-finite `ta` or `tb` a moving obstacle's position is undefined and the answer
    /// is `true` (conservative); a fixed obstacle ignores the times. A NaN coordinate never
    /// makes a segment clear: it is a hit unless the other coordinates alone keep it away
    /// (checking for NaN up front would cost every call in the hot loop).
    #[inline]
    pub fn segment_hits(&self, a: Vec3, b: Vec3, ta: f64, tb: f64, margin: f64) -> bool {
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

/// Is the segment a -> b entirely beyond one face of the box [bmin, bmax]? Non-short-circuit
/// operators keep it one branch; NaN compares false, so it never rejects.
#[inline(always)]
fn aabb_apart(a: Vec3, b: Vec3, bmin: Vec3, bmax: Vec3) -> bool {
    ((a.x < bmin.x) & (b.x < bmin.x))
        | ((a.y < bmin.y) & (b.y < bmin.y))
        | ((a.z < bmin.z) & (b.z < bmin.z))
        | ((a.x > bmax.x) & (b.x > bmax.x))
        | ((a.y > bmax.y) & (b.y > bmax.y))
        | ((a.z > bmax.z) & (b.z > bmax.z))
}

/// Squared distance from `p` to the segment a + s d, s in [0, 1].
#[inline(always)]
fn segment_point_dist2(a: Vec3, d: Vec3, p: Vec3) -> f64 {
    let w = p - a;
    let dd = d.length_squared();
    let s = if dd > 0.0 { (w.dot(d) / dd).clamp(0.0, 1.0) } else { 0.0 };
    (w - d * s).length_squared()
}

/// Squared distance from `p` to the 2-D segment a + s d restricted to s in [s0, s1], and the
/// closest parameter.
#[inline(always)]
fn segment_point_dist2_2d(a: Vec2, d: Vec2, p: Vec2, s0: f64, s1: f64) -> (f64, f64) {
    let w = p - a;
    let dd = d.length_squared();
    let s = if dd > 0.0 { (w.dot(d) / dd).clamp(s0, s1) } else { s0 };
    ((w - d * s).length_squared(), s)
}

fn circle_segment_distance(center: Vec2, radius: f64, a: Vec3, b: Vec3) -> f64 {
    let (d2, _) = segment_point_dist2_2d(a.truncate(), (b - a).truncate(), center, 0.0, 1.0);
    (d2.sqrt() - radius).max(0.0)
}

#[inline]
fn cylinder_point_distance(center: Vec2, radius: f64, z_min: f64, z_max: f64, p: Vec3) -> f64 {
    let dr = ((p.truncate() - center).length() - radius).max(0.0);
    let dz = (z_min - p.z).max(p.z - z_max).max(0.0);
    (dr * dr + dz * dz).sqrt()
}

/// Distance from a segment to a vertical cylinder. Hit tests only need the answer relative to
/// their margin, so the search returns any value below `stop_below` as soon as it finds one and
/// skips stretches whose lower bound is already at least `irrelevant_above` (the value returned
/// is then only known to be at least that); the clearance query passes -inf and +inf.
///
/// Split the parameter range where the segment crosses z_min and z_max. Where z is inside the
/// slab the distance is the horizontal distance to the circle, in closed form. Above or below
/// the slab the distance (to the rim or the caps) is a convex function of the parameter
/// without a convenient closed form, so it is minimised by golden section, after cheap lower
/// bounds (horizontal and vertical distance taken separately) have had a chance to skip it.
#[allow(clippy::too_many_arguments)]
fn cylinder_segment_distance(
    center: Vec2,
    radius: f64,
    z_min: f64,
    z_max: f64,
    a: Vec3,
    b: Vec3,
    stop_below: f64,
    irrelevant_above: f64,
) -> f64 {
    let d = b - a;
    let (a2, d2) = (a.truncate(), d.truncate());
    // Parameter range inside the slab z_min <= z <= z_max (empty when s_in0 > s_in1).
    let (s_in0, s_in1) = if d.z == 0.0 {
        if a.z >= z_min && a.z <= z_max {
            (0.0, 1.0)
        } else {
            (1.0, 0.0)
        }
    } else {
        let t0 = (z_min - a.z) / d.z;
        let t1 = (z_max - a.z) / d.z;
        (t0.min(t1).max(0.0), t0.max(t1).min(1.0))
    };
    let mut best = f64::INFINITY;
    if s_in0 <= s_in1 {
        let (r2, _) = segment_point_dist2_2d(a2, d2, center, s_in0, s_in1);
        best = (r2.sqrt() - radius).max(0.0);
        if best <= 0.0 || best < stop_below {
            return best;
        }
    }
    let parts: [(f64, f64); 2] = if s_in0 <= s_in1 { [(0.0, s_in0), (s_in1, 1.0)] } else { [(0.0, 1.0), (1.0, 0.0)] };
    let f = |s: f64| cylinder_point_distance(center, radius, z_min, z_max, a + d * s);
    let lipschitz = d.length();
    for (lo, hi) in parts {
        if !(lo < hi) {
            continue;
        }
        // Lower bound on the part: the distance is at least the horizontal distance to the
        // circle and at least the vertical distance to the slab, each at its own minimum.
        let (r2, s_r) = segment_point_dist2_2d(a2, d2, center, lo, hi);
        let dr = (r2.sqrt() - radius).max(0.0);
        let z_lo = a.z + d.z * lo;
        let z_hi = a.z + d.z * hi;
        let dz = (z_min - z_lo.max(z_hi)).max(z_lo.min(z_hi) - z_max).max(0.0);
        let bound = dr.max(dz);
        if bound >= best || bound >= irrelevant_above {
            continue;
        }
        // Cheap upper bounds: the part ends and the horizontally closest point.
        let (f_lo, f_hi) = (f(lo), f(hi));
        best = best.min(f_lo).min(f_hi).min(f(s_r));
        if best < stop_below {
            return best;
        }
        if bound >= best {
            continue;
        }
        let enough = best.min(irrelevant_above);
        best = best.min(golden_min(&f, lo, hi, f_lo.min(f_hi), lipschitz, stop_below, enough));
        if best < stop_below {
            return best;
        }
    }
    best
}

/// Minimum of a convex, `lipschitz`-Lipschitz function on [lo, hi] by golden section, to a
/// bracket of GOLDEN_TOL; `known` is the least value already evaluated in [lo, hi] (the ends).
///
/// Hit tests rarely need the minimum itself: the search returns as soon as a value is below
/// `stop_below`, or as soon as the minimum is proven at least `enough_above`. The proof: every
/// point of the bracket is within 0.191 of its width of an evaluated point (the largest gap is
/// 0.382 of the width), and convexity keeps the discarded ends above the evaluated values.
#[allow(clippy::too_many_arguments)]
fn golden_min(
    f: &impl Fn(f64) -> f64,
    mut lo: f64,
    mut hi: f64,
    known: f64,
    lipschitz: f64,
    stop_below: f64,
    enough_above: f64,
) -> f64 {
    const INV_PHI: f64 = 0.618_033_988_749_894_8;
    let mut x1 = hi - INV_PHI * (hi - lo);
    let mut x2 = lo + INV_PHI * (hi - lo);
    let (mut f1, mut f2) = (f(x1), f(x2));
    let mut best = known.min(f1).min(f2);
    while hi - lo > GOLDEN_TOL && best >= stop_below && best - 0.191 * lipschitz * (hi - lo) < enough_above {
        if f1 <= f2 {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - INV_PHI * (hi - lo);
            f1 = f(x1);
            best = best.min(f1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + INV_PHI * (hi - lo);
            f2 = f(x2);
            best = best.min(f2);
        }
    }
    best
}

/// Per-axis distance from `p` to the box (0 along axes where p is within the box's extent).
#[inline(always)]
fn box_excess(min: Vec3, max: Vec3, p: Vec3) -> Vec3 {
    (min - p).max(p - max).max(Vec3::ZERO)
}

/// Slab test: does the closed segment a -> b meet the closed box?
#[inline]
fn segment_intersects_box(min: Vec3, max: Vec3, a: Vec3, b: Vec3) -> bool {
    let d = b - a;
    let (mut s0, mut s1) = (0.0f64, 1.0f64);
    for i in 0..3 {
        if d[i] == 0.0 {
            if a[i] < min[i] || a[i] > max[i] {
                return false;
            }
        } else {
            let t0 = (min[i] - a[i]) / d[i];
            let t1 = (max[i] - a[i]) / d[i];
            s0 = s0.max(t0.min(t1));
            s1 = s1.min(t0.max(t1));
            if s0 > s1 {
                return false;
            }
        }
    }
    s0 <= s1
}

/// Exact squared distance from the segment a -> b to the box.
///
/// Along the segment each axis's excess over the box is piecewise linear, changing form only
/// where the segment crosses one of the six face planes. Between consecutive crossings the
/// squared distance is therefore one convex quadratic, minimised in closed form; the answer is
/// the least of at most seven such minima.
fn box_segment_dist2(min: Vec3, max: Vec3, a: Vec3, b: Vec3) -> f64 {
    let d = b - a;
    let mut cuts = [0.0f64; 8];
    let mut n = 1;
    for i in 0..3 {
        if d[i] != 0.0 {
            for bound in [min[i], max[i]] {
                let s = (bound - a[i]) / d[i];
                if s > 0.0 && s < 1.0 {
                    cuts[n] = s;
                    n += 1;
                }
            }
        }
    }
    cuts[n] = 1.0;
    n += 1;
    cuts[1..n - 1].sort_unstable_by(f64::total_cmp);
    let mut best = f64::INFINITY;
    for k in 0..n - 1 {
        let (s0, s1) = (cuts[k], cuts[k + 1]);
        let mid = a + d * (0.5 * (s0 + s1));
        // d^2(s) = sum over axes outside the box of (alpha + beta s)^2 = A s^2 + B s + const.
        let (mut qa, mut qb) = (0.0, 0.0);
        for i in 0..3 {
            let (alpha, beta) = if mid[i] < min[i] {
                (min[i] - a[i], -d[i])
            } else if mid[i] > max[i] {
                (a[i] - max[i], d[i])
            } else {
                continue;
            };
            qa += beta * beta;
            qb += 2.0 * alpha * beta;
        }
        let s = if qa > 0.0 { (-qb / (2.0 * qa)).clamp(s0, s1) } else { s0 };
        best = best.min(box_excess(min, max, a + d * s).length_squared());
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    const TOL: f64 = 1e-9;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= TOL * (1.0 + b.abs())
    }

    fn v(x: f64, y: f64, z: f64) -> Vec3 {
        Vec3::new(x, y, z)
    }

    fn sphere() -> Obstacle {
        Obstacle::fixed(Shape::Sphere { center: v(0.0, 0.0, -10.0), radius: 2.0 })
    }

    #[test]
    fn sphere_segment_distance_hand_cases() {
        let o = sphere();
        // Passing 5 m above the centre: clearance 3.
        let (a, b) = (v(-10.0, 0.0, -5.0), v(10.0, 0.0, -5.0));
        assert!(close(o.segment_clearance(a, b, 0.0, 1.0), 3.0));
        assert!(o.segment_hits(a, b, 0.0, 1.0, 3.5));
        assert!(!o.segment_hits(a, b, 0.0, 1.0, 2.5));
        // Touching the top tangentially: distance 0, a hit even with zero margin.
        let (a, b) = (v(-10.0, 0.0, -8.0), v(10.0, 0.0, -8.0));
        assert_eq!(o.segment_clearance(a, b, 0.0, 1.0), 0.0);
        assert!(o.segment_hits(a, b, 0.0, 1.0, 0.0));
        // Piercing through the centre.
        let (a, b) = (v(0.0, -10.0, -10.0), v(0.0, 10.0, -10.0));
        assert_eq!(o.segment_clearance(a, b, 0.0, 1.0), 0.0);
        assert!(o.segment_hits(a, b, 0.0, 1.0, 0.0));
        // Segment ending short of the sphere: closest point is the end, 3 - 2 = 1 away.
        let (a, b) = (v(-10.0, 0.0, -10.0), v(-3.0, 0.0, -10.0));
        assert!(close(o.segment_clearance(a, b, 0.0, 1.0), 1.0));
        // Degenerate zero-length segment: point distance sqrt(3^2 + 4^2) - 2 = 3.
        let p = v(3.0, 4.0, -10.0);
        assert!(close(o.segment_clearance(p, p, 0.0, 1.0), 3.0));
        assert!(o.contains(p, 0.0, 3.1) && !o.contains(p, 0.0, 2.9));
    }

    #[test]
    fn circle_ignores_depth() {
        let o = Obstacle::fixed(Shape::Circle { center: Vec2::new(5.0, 5.0), radius: 1.0 });
        // Horizontal distance from (5,5) to the line y = 8 is 3: clearance 2, whatever the depth.
        let (a, b) = (v(0.0, 8.0, -1000.0), v(10.0, 8.0, 50.0));
        assert!(close(o.segment_clearance(a, b, 0.0, 1.0), 2.0));
        assert!(!o.segment_hits(a, b, 0.0, 1.0, 1.9));
        assert!(o.segment_hits(a, b, 0.0, 1.0, 2.1));
        // A vertical segment through the circle.
        assert!(o.segment_hits(v(5.5, 5.0, -1e6), v(5.5, 5.0, 1e6), 0.0, 1.0, 0.0));
        // Zero-length segment on the rim.
        let p = v(6.0, 5.0, 3.0);
        assert!(o.segment_hits(p, p, 0.0, 0.0, 0.0));
        assert_eq!(o.segment_clearance(p, p, 0.0, 0.0), 0.0);
    }

    #[test]
    fn infinite_cylinder_equals_circle() {
        let cyl = Obstacle::fixed(Shape::Cylinder {
            center: Vec2::new(5.0, 5.0),
            radius: 1.0,
            z_min: f64::NEG_INFINITY,
            z_max: f64::INFINITY,
        });
        let (a, b) = (v(0.0, 8.0, -1000.0), v(10.0, 8.0, 50.0));
        assert!(close(cyl.segment_clearance(a, b, 0.0, 1.0), 2.0));
        assert!(cyl.segment_hits(v(5.0, 0.0, -3.0), v(5.0, 10.0, -3.0), 0.0, 1.0, 0.0));
    }

    fn finite_cylinder() -> Obstacle {
        Obstacle::fixed(Shape::Cylinder { center: Vec2::ZERO, radius: 2.0, z_min: -20.0, z_max: -10.0 })
    }

    #[test]
    fn finite_cylinder_hand_cases() {
        let o = finite_cylinder();
        // Horizontal pass beside the side wall, inside the slab: 5 - 2 = 3.
        assert!(close(o.segment_clearance(v(-10.0, 5.0, -15.0), v(10.0, 5.0, -15.0), 0.0, 1.0), 3.0));
        // Horizontal pass over the top cap, 4 above it: 4.
        assert!(close(o.segment_clearance(v(-10.0, 0.0, -6.0), v(10.0, 0.0, -6.0), 0.0, 1.0), 4.0));
        // Pass above and beside: nearest point is the rim; 3 out and 4 up -> 5.
        let (a, b) = (v(-10.0, 5.0, -6.0), v(10.0, 5.0, -6.0));
        assert!(close(o.segment_clearance(a, b, 0.0, 1.0), 5.0));
        assert!(o.segment_hits(a, b, 0.0, 1.0, 5.01));
        assert!(!o.segment_hits(a, b, 0.0, 1.0, 4.99));
        // Slanted segment above the cap, moving away from the rim point (2, 0, -10) along the
        // 45-degree line through it: closest at its start, sqrt(1 + 1) from the rim.
        let (a, b) = (v(3.0, 0.0, -9.0), v(7.0, 0.0, -5.0));
        assert!(close(o.segment_clearance(a, b, 0.0, 1.0), 2f64.sqrt()));
        // Piercing the cap vertically.
        assert!(o.segment_hits(v(0.5, 0.5, 0.0), v(0.5, 0.5, -12.0), 0.0, 1.0, 0.0));
        assert_eq!(o.segment_clearance(v(0.5, 0.5, 0.0), v(0.5, 0.5, -12.0), 0.0, 1.0), 0.0);
        // Vertical segment beside the cylinder, spanning its height: 3 away.
        assert!(close(o.segment_clearance(v(5.0, 0.0, 0.0), v(5.0, 0.0, -30.0), 0.0, 1.0), 3.0));
        // Degenerate segment below the bottom cap: 1 below and 1 out -> sqrt(2).
        let p = v(3.0, 0.0, -21.0);
        assert!(close(o.segment_clearance(p, p, 0.0, 1.0), 2f64.sqrt()));
        assert!(o.contains(p, 0.0, 1.5) && !o.contains(p, 0.0, 1.4));
    }

    #[test]
    fn box_hand_cases() {
        let o = Obstacle::fixed(Shape::Box { min: v(0.0, 0.0, -10.0), max: v(4.0, 2.0, -5.0) });
        // Parallel to x, 3 north of the box, inside its depth range: 3.
        assert!(close(o.segment_clearance(v(-5.0, 5.0, -7.0), v(10.0, 5.0, -7.0), 0.0, 1.0), 3.0));
        // Parallel to x, 3 north and 4 above: 5 (edge distance).
        let (a, b) = (v(-5.0, 5.0, -1.0), v(10.0, 5.0, -1.0));
        assert!(close(o.segment_clearance(a, b, 0.0, 1.0), 5.0));
        assert!(o.segment_hits(a, b, 0.0, 1.0, 5.1) && !o.segment_hits(a, b, 0.0, 1.0, 4.9));
        // Towards a corner, stopping short: from (8, 6, 0) to (5, 3, -4): nearest corner
        // (4, 2, -5) at distance sqrt(1 + 1 + 1).
        assert!(close(o.segment_clearance(v(8.0, 6.0, 0.0), v(5.0, 3.0, -4.0), 0.0, 1.0), 3f64.sqrt()));
        // Passing a vertical edge diagonally: the line x + y = 8 at z = -7 is |4 + 2 - 8| / sqrt 2
        // from the edge x = 4, y = 2.
        assert!(close(o.segment_clearance(v(8.0, 0.0, -7.0), v(0.0, 8.0, -7.0), 0.0, 1.0), 2f64.sqrt()));
        // Touching a face.
        assert_eq!(o.segment_clearance(v(-1.0, 2.0, -7.0), v(5.0, 2.0, -7.0), 0.0, 1.0), 0.0);
        assert!(o.segment_hits(v(-1.0, 2.0, -7.0), v(5.0, 2.0, -7.0), 0.0, 1.0, 0.0));
        // Piercing.
        assert!(o.segment_hits(v(2.0, -3.0, -7.0), v(2.0, 5.0, -7.0), 0.0, 1.0, 0.0));
        // Degenerate point inside and outside.
        assert_eq!(o.segment_clearance(v(1.0, 1.0, -6.0), v(1.0, 1.0, -6.0), 0.0, 1.0), 0.0);
        assert!(close(o.segment_clearance(v(1.0, 1.0, 0.0), v(1.0, 1.0, 0.0), 0.0, 1.0), 5.0));
    }

    #[test]
    fn moving_sphere_changes_the_answer() {
        // A fixed sphere at the origin blocks the segment along x at y = 0.
        let shape = Shape::Sphere { center: v(0.0, 0.0, -10.0), radius: 1.0 };
        let (a, b) = (v(-10.0, 0.0, -10.0), v(10.0, 0.0, -10.0));
        assert!(Obstacle::fixed(shape.clone()).segment_hits(a, b, 0.0, 10.0, 0.0));
        // Moving north at 1 m/s: at t = 5 (when we pass x = 0) it is at y = 5, 4 m clear.
        let moving = Obstacle { shape: shape.clone(), velocity: v(0.0, 1.0, 0.0) };
        assert!(!moving.segment_hits(a, b, 0.0, 10.0, 0.0));
        // In the sphere's frame the segment runs from (-10, 0) to (10, -10).
        let c = moving.segment_clearance(a, b, 0.0, 10.0);
        // Relative positions p(s) = (-10 + 20 s, -10 s): distance^2 = (20 s - 10)^2 + 100 s^2,
        // minimised at s = 0.4: 4 + 16 = 20 -> sqrt(20) = 4.4721.
        assert!(close(c, 20f64.sqrt() - 1.0), "{c}");
        // And vice versa: a sphere starting 5 m south and moving north crosses our path just
        // as we get there.
        let incoming =
            Obstacle { shape: Shape::Sphere { center: v(0.0, -5.0, -10.0), radius: 1.0 }, velocity: v(0.0, 1.0, 0.0) };
        assert!(!Obstacle::fixed(incoming.shape.clone()).segment_hits(a, b, 0.0, 10.0, 0.0));
        assert!(incoming.segment_hits(a, b, 0.0, 10.0, 0.0));
        assert_eq!(incoming.segment_clearance(a, b, 0.0, 10.0), 0.0);
        assert!(incoming.contains(v(0.0, 0.0, -10.0), 5.0, 0.0));
        assert!(!incoming.contains(v(0.0, 0.0, -10.0), 0.0, 0.0));
        assert_eq!(incoming.shape_at(5.0), Shape::Sphere { center: v(0.0, 0.0, -10.0), radius: 1.0 });
    }

    #[test]
    fn non_finite_times_are_conservative_for_moving_obstacles_only() {
        let shape = Shape::Sphere { center: v(100.0, 100.0, 100.0), radius: 1.0 };
        let (a, b) = (v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0));
        let fixed = Obstacle::fixed(shape.clone());
        assert!(!fixed.segment_hits(a, b, 0.0, f64::INFINITY, 0.0));
        let moving = Obstacle { shape, velocity: v(0.0, 0.0, 1.0) };
        assert!(moving.segment_hits(a, b, 0.0, f64::INFINITY, 0.0));
        assert_eq!(moving.segment_clearance(a, b, f64::NAN, 1.0), 0.0);
        assert!(moving.contains(a, f64::INFINITY, 0.0));
        // NaN points are hits, unless their finite coordinates alone keep them away.
        assert!(fixed.segment_hits(Vec3::NAN, b, 0.0, 1.0, 0.0));
        assert!(fixed.segment_hits(v(f64::NAN, 100.0, 100.0), v(0.0, 100.0, 100.0), 0.0, 1.0, 0.0));
        assert!(!fixed.segment_hits(v(f64::NAN, 0.0, 0.0), b, 0.0, 1.0, 0.0));
    }

    #[test]
    fn translated_cylinder_and_circle() {
        let o = Obstacle {
            shape: Shape::Cylinder { center: Vec2::ZERO, radius: 1.0, z_min: -5.0, z_max: f64::INFINITY },
            velocity: v(1.0, 0.0, -1.0),
        };
        assert_eq!(
            o.shape_at(2.0),
            Shape::Cylinder { center: Vec2::new(2.0, 0.0), radius: 1.0, z_min: -7.0, z_max: f64::INFINITY }
        );
        let c = Obstacle { shape: Shape::Circle { center: Vec2::ZERO, radius: 1.0 }, velocity: v(0.0, 2.0, 5.0) };
        assert_eq!(c.shape_at(1.0), Shape::Circle { center: Vec2::new(0.0, 2.0), radius: 1.0 });
    }
}
