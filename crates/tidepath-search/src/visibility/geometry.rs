//! Plane geometry for the visibility graph: tangents, and "does this segment or
//! arc enter the interior of an obstacle" tests. Boundary contact (within
//! `eps`) is allowed everywhere: paths may touch obstacles, not enter them.

use std::f64::consts::TAU;

use super::{Circle, Point, Rect};

#[inline]
pub(crate) fn sub(a: Point, b: Point) -> Point {
    [a[0] - b[0], a[1] - b[1]]
}
#[inline]
pub(crate) fn dot(a: Point, b: Point) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}
#[inline]
pub(crate) fn cross(a: Point, b: Point) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}
#[inline]
pub(crate) fn dist(a: Point, b: Point) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}
#[inline]
pub(crate) fn on_circle(c: &Circle, angle: f64) -> Point {
    [c.centre[0] + c.radius * angle.cos(), c.centre[1] + c.radius * angle.sin()]
}
#[inline]
pub(crate) fn norm_angle(a: f64) -> f64 {
    let r = a.rem_euclid(TAU);
    if r >= TAU {
        0.0
    } else {
        r
    }
}

/// Distance from `p` to the closed segment `a`–`b`.
pub(crate) fn point_segment_dist(p: Point, a: Point, b: Point) -> f64 {
    let ab = sub(b, a);
    let len2 = dot(ab, ab);
    let t = if len2 > 0.0 { (dot(sub(p, a), ab) / len2).clamp(0.0, 1.0) } else { 0.0 };
    dist(p, [a[0] + t * ab[0], a[1] + t * ab[1]])
}

/// Angles (on `c`) of the two tangent points seen from `p`, which must be
/// outside `c`: `φ ± acos(r / d)`.
pub(crate) fn point_tangent_angles(p: Point, c: &Circle) -> [f64; 2] {
    let v = sub(p, c.centre);
    let d = v[0].hypot(v[1]);
    let phi = v[1].atan2(v[0]);
    let a = (c.radius / d).clamp(-1.0, 1.0).acos();
    [norm_angle(phi + a), norm_angle(phi - a)]
}

/// Common tangents of two circles as pairs of angles (on `a`, on `b`):
/// the two outer ones when neither circle contains the other, plus the two
/// inner ones when the circles are disjoint. `eps` decides the borderline cases.
pub(crate) fn bitangent_angles(a: &Circle, b: &Circle, eps: f64) -> Vec<(f64, f64)> {
    let v = sub(b.centre, a.centre);
    let d = v[0].hypot(v[1]);
    let phi = v[1].atan2(v[0]);
    let mut out = Vec::with_capacity(4);
    if d > (a.radius - b.radius).abs() + eps {
        // Outer: both tangent points have the same outward normal φ ± β.
        let beta = ((a.radius - b.radius) / d).clamp(-1.0, 1.0).acos();
        for s in [1.0, -1.0] {
            let t = norm_angle(phi + s * beta);
            out.push((t, t));
        }
    }
    if d > a.radius + b.radius + eps {
        // Inner: opposite normals, φ ± β on `a` and φ ± β + π on `b`.
        let beta = ((a.radius + b.radius) / d).clamp(-1.0, 1.0).acos();
        for s in [1.0, -1.0] {
            let t = phi + s * beta;
            out.push((norm_angle(t), norm_angle(t + std::f64::consts::PI)));
        }
    }
    out
}

/// `true` iff `p` lies strictly inside the simple polygon (farther than `eps`
/// from its boundary).
pub(crate) fn strictly_inside_polygon(p: Point, poly: &[Point], eps: f64) -> bool {
    let n = poly.len();
    let mut inside = false;
    for k in 0..n {
        let (a, b) = (poly[k], poly[(k + 1) % n]);
        if point_segment_dist(p, a, b) <= eps {
            return false;
        }
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if x > p[0] {
                inside = !inside;
            }
        }
    }
    inside
}

/// `true` iff the segment `a`–`b` enters the interior of the polygon: it is cut
/// at every contact with the boundary and each piece's midpoint is tested.
pub(crate) fn segment_enters_polygon(a: Point, b: Point, poly: &[Point], eps: f64) -> bool {
    let d = sub(b, a);
    let len2 = dot(d, d);
    if len2 == 0.0 {
        return strictly_inside_polygon(a, poly, eps);
    }
    let mut ts = vec![0.0, 1.0];
    let n = poly.len();
    for k in 0..n {
        let (q1, q2) = (poly[k], poly[(k + 1) % n]);
        let e = sub(q2, q1);
        let den = cross(d, e);
        let w = sub(q1, a);
        if den.abs() > 1e-12 * len2.sqrt() * dot(e, e).sqrt() {
            let t = cross(w, e) / den;
            let u = cross(w, d) / den;
            if (-1e-9..=1.0 + 1e-9).contains(&u) && (0.0..=1.0).contains(&t) {
                ts.push(t);
            }
        } else {
            // Parallel: the edge's end points projected on the segment.
            for q in [q1, q2] {
                let t = dot(sub(q, a), d) / len2;
                if (0.0..=1.0).contains(&t) {
                    ts.push(t);
                }
            }
        }
    }
    ts.sort_by(f64::total_cmp);
    ts.windows(2).any(|w| {
        w[1] - w[0] > 1e-12 && {
            let t = 0.5 * (w[0] + w[1]);
            strictly_inside_polygon([a[0] + t * d[0], a[1] + t * d[1]], poly, eps)
        }
    })
}

/// `true` iff the segment passes strictly inside the circle.
pub(crate) fn segment_enters_circle(a: Point, b: Point, c: &Circle, eps: f64) -> bool {
    point_segment_dist(c.centre, a, b) < c.radius - eps
}

/// `true` iff `p` is inside the closed rectangle (with `eps` slack).
pub(crate) fn in_rect(p: Point, r: &Rect, eps: f64) -> bool {
    p[0] >= r.min[0] - eps && p[0] <= r.max[0] + eps && p[1] >= r.min[1] - eps && p[1] <= r.max[1] + eps
}

/// An arc of circle `c` from angle `start` counter-clockwise through `sweep ≥ 0`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Arc {
    pub circle: Circle,
    pub start: f64,
    pub sweep: f64,
}

impl Arc {
    /// Relative position of `angle` from the arc's start, in `[0, 2π)`.
    fn rel(&self, angle: f64) -> f64 {
        norm_angle(angle - self.start)
    }
    fn contains_angle(&self, angle: f64) -> bool {
        self.rel(angle) <= self.sweep
    }

    /// `true` iff the arc passes strictly inside circle `o`. The distance from
    /// `o`'s centre grows with the angular distance from the direction of that
    /// centre, so the closest arc point is that direction if the arc contains
    /// it, else the nearer end.
    pub fn enters_circle(&self, o: &Circle, eps: f64) -> bool {
        let v = sub(o.centre, self.circle.centre);
        let phi = v[1].atan2(v[0]);
        let closest = if self.contains_angle(phi) {
            phi
        } else {
            let rel = self.rel(phi);
            if TAU - rel < rel - self.sweep {
                self.start
            } else {
                self.start + self.sweep
            }
        };
        dist(on_circle(&self.circle, closest), o.centre) < o.radius - eps
    }

    /// `true` iff the arc enters the polygon's interior: cut at every crossing
    /// of the circle with a polygon edge, midpoints tested.
    pub fn enters_polygon(&self, poly: &[Point], eps: f64) -> bool {
        let c = &self.circle;
        let mut rels = vec![0.0, self.sweep];
        let n = poly.len();
        for k in 0..n {
            let (q1, q2) = (poly[k], poly[(k + 1) % n]);
            let e = sub(q2, q1);
            let w = sub(q1, c.centre);
            // |w + u e|² = r²
            let qa = dot(e, e);
            let qb = 2.0 * dot(w, e);
            let qc = dot(w, w) - c.radius * c.radius;
            let disc = qb * qb - 4.0 * qa * qc;
            if qa == 0.0 || disc < 0.0 {
                continue;
            }
            let s = disc.sqrt();
            for u in [(-qb - s) / (2.0 * qa), (-qb + s) / (2.0 * qa)] {
                if (-1e-9..=1.0 + 1e-9).contains(&u) {
                    let p = [w[0] + u * e[0], w[1] + u * e[1]];
                    let rel = self.rel(p[1].atan2(p[0]));
                    if rel <= self.sweep {
                        rels.push(rel);
                    }
                }
            }
        }
        rels.sort_by(f64::total_cmp);
        rels.windows(2).any(|w| {
            w[1] - w[0] > 1e-12 && strictly_inside_polygon(on_circle(c, self.start + 0.5 * (w[0] + w[1])), poly, eps)
        })
    }

    /// `true` iff the whole arc lies in the rectangle: its ends and every axis
    /// extreme (angles 0, π/2, π, 3π/2) it contains are inside.
    pub fn inside_rect(&self, r: &Rect, eps: f64) -> bool {
        let ends = [self.start, self.start + self.sweep];
        let extremes = [0.0, 0.5, 1.0, 1.5].map(|k| k * std::f64::consts::PI);
        ends.iter()
            .chain(extremes.iter().filter(|&&a| self.contains_angle(a)))
            .all(|&a| in_rect(on_circle(&self.circle, a), r, eps))
    }
}
