//! Distance math between straight segments (or points) and the obstacle shapes: bounding-box
//! rejection, point-segment distances, the cylinder search and the box slab and distance tests.

// `!(d >= margin)` is deliberate throughout: a NaN must fail every "clear" test.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::geom::{Vec2, Vec3};

/// Golden-section searches stop when the bracket is this fraction of the segment parameter
/// range: the distance along a segment is |b - a|-Lipschitz in the parameter, so the minimum
/// found is within 1e-9 |b - a| of the true one.
const GOLDEN_TOL: f64 = 1e-9;

/// Is the segment a -> b entirely beyond one face of the box [bmin, bmax]? Non-short-circuit
/// operators keep it one branch; NaN compares false, so it never rejects.
#[inline(always)]
pub(super) fn aabb_apart(a: Vec3, b: Vec3, bmin: Vec3, bmax: Vec3) -> bool {
    ((a.x < bmin.x) & (b.x < bmin.x))
        | ((a.y < bmin.y) & (b.y < bmin.y))
        | ((a.z < bmin.z) & (b.z < bmin.z))
        | ((a.x > bmax.x) & (b.x > bmax.x))
        | ((a.y > bmax.y) & (b.y > bmax.y))
        | ((a.z > bmax.z) & (b.z > bmax.z))
}

/// Squared distance from `p` to the segment a + s d, s in [0, 1].
#[inline(always)]
pub(super) fn segment_point_dist2(a: Vec3, d: Vec3, p: Vec3) -> f64 {
    let w = p - a;
    let dd = d.length_squared();
    let s = if dd > 0.0 { (w.dot(d) / dd).clamp(0.0, 1.0) } else { 0.0 };
    (w - d * s).length_squared()
}

/// Squared distance from `p` to the 2-D segment a + s d restricted to s in [s0, s1], and the
/// closest parameter.
#[inline(always)]
pub(super) fn segment_point_dist2_2d(a: Vec2, d: Vec2, p: Vec2, s0: f64, s1: f64) -> (f64, f64) {
    let w = p - a;
    let dd = d.length_squared();
    let s = if dd > 0.0 { (w.dot(d) / dd).clamp(s0, s1) } else { s0 };
    ((w - d * s).length_squared(), s)
}

pub(super) fn circle_segment_distance(center: Vec2, radius: f64, a: Vec3, b: Vec3) -> f64 {
    let (d2, _) = segment_point_dist2_2d(a.truncate(), (b - a).truncate(), center, 0.0, 1.0);
    (d2.sqrt() - radius).max(0.0)
}

#[inline]
pub(super) fn cylinder_point_distance(center: Vec2, radius: f64, z_min: f64, z_max: f64, p: Vec3) -> f64 {
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
pub(super) fn cylinder_segment_distance(
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
pub(super) fn box_excess(min: Vec3, max: Vec3, p: Vec3) -> Vec3 {
    (min - p).max(p - max).max(Vec3::ZERO)
}

/// Slab test: does the closed segment a -> b meet the closed box?
#[inline]
pub(super) fn segment_intersects_box(min: Vec3, max: Vec3, a: Vec3, b: Vec3) -> bool {
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
pub(super) fn box_segment_dist2(min: Vec3, max: Vec3, a: Vec3, b: Vec3) -> f64 {
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
