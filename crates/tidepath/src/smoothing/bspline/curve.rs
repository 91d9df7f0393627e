//! The curve of the `bspline` smoother: clamped uniform knots on [0, 1], the Cox–de Boor
//! basis of ijs2023 eq. 26 (with the numerator of A11), de Boor's algorithm for evaluation,
//! midpoint insertion into the control polygon, and the sampling into a polyline.
//!
//! Indices are 0-based: control points φ₀ .. φ_{m−1}, knots t₀ .. t_{m+p}, and knot span s
//! (counted from 0) is [t_{p+s}, t_{p+s+1}], on which only φ_s .. φ_{s+p} act.

use crate::geom::Vec3;

/// The largest degree the smoother takes (de Boor's working points live on the stack).
pub const MAX_DEGREE: usize = 7;

/// Writes the clamped uniform knot vector on [0, 1] of `m` control points of degree `p`
/// (p < m) into `out`: p + 1 zeros, the interior knots j / (m − p), p + 1 ones. The curve then
/// starts at φ₀ and ends at φ_{m−1}.
pub fn clamped_knots(m: usize, p: usize, out: &mut Vec<f64>) {
    debug_assert!(p < m);
    let spans = m - p;
    out.clear();
    out.extend(std::iter::repeat_n(0.0, p + 1));
    out.extend((1..spans).map(|j| j as f64 / spans as f64));
    out.extend(std::iter::repeat_n(1.0, p + 1));
}

/// The basis function B_{i,k}(u) by the Cox–de Boor recursion (eq. 26 as read in A11):
///
/// ```text
/// B_{i,0}(u) = 1 if t_i ≤ u < t_{i+1} (the last non-empty span also at u = t_{i+1}), else 0
/// B_{i,k}(u) = (u − t_i)/(t_{i+k} − t_i) B_{i,k−1}(u) + (t_{i+k+1} − u)/(t_{i+k+1} − t_{i+1}) B_{i+1,k−1}(u)
/// ```
///
/// with a term whose denominator is 0 (repeated knots) read as 0. Exponential in k: this is
/// the definition, for tests and hand checks; the smoother evaluates with [`de_boor`].
pub fn basis(knots: &[f64], i: usize, k: usize, u: f64) -> f64 {
    if k == 0 {
        let (a, b) = (knots[i], knots[i + 1]);
        let end = knots[knots.len() - 1];
        // The paper prints the open interval t_i < u < t_{i+1}; at a knot every basis function
        // would then vanish. Half-open, and the last span closed so the curve reaches u = 1.
        let inside = (a <= u && u < b) || (a < b && b == end && u == end);
        return if inside { 1.0 } else { 0.0 };
    }
    let mut out = 0.0;
    let d = knots[i + k] - knots[i];
    if d > 0.0 {
        out += (u - knots[i]) / d * basis(knots, i, k - 1, u);
    }
    let d = knots[i + k + 1] - knots[i + 1];
    if d > 0.0 {
        out += (knots[i + k + 1] - u) / d * basis(knots, i + 1, k - 1, u);
    }
    out
}

/// The knot span (counted from 0) that holds `u` for `m` control points of degree `p`: the s
/// with t_{p+s} ≤ u < t_{p+s+1}, the last span at u = 1.
pub fn span_of(knots: &[f64], m: usize, p: usize, u: f64) -> usize {
    let k = knots.partition_point(|&t| t <= u).saturating_sub(1);
    k.clamp(p, m - 1) - p
}

/// The curve point Σ φ_i B_{i,p}(u) of span `s` by de Boor's algorithm: p(p + 1)/2 blends,
/// no allocation.
pub fn de_boor(ctrl: &[Vec3], knots: &[f64], p: usize, s: usize, u: f64) -> Vec3 {
    debug_assert!(p <= MAX_DEGREE);
    let mut d = [Vec3::ZERO; MAX_DEGREE + 1];
    d[..=p].copy_from_slice(&ctrl[s..=s + p]);
    // Knot index of the span's start: t_{p+s}.
    let k = p + s;
    for r in 1..=p {
        for j in (r..=p).rev() {
            let i = j + k - p;
            let den = knots[i + p + 1 - r] - knots[i];
            let a = if den > 0.0 { (u - knots[i]) / den } else { 0.0 };
            d[j] = d[j - 1] * (1.0 - a) + d[j] * a;
        }
    }
    d[p]
}

/// The control polygon of the input `points` with every leg i cut into 2^levels[i] equal
/// pieces (level 1: its midpoint inserted, ijs2023 Fig. 8; each further level inserts the
/// midpoints of the pieces), written into `ctrl`. `legs` receives, per control point, the
/// first and last input leg it belongs to (a waypoint belongs to the legs either side).
pub fn control_polygon(points: &[Vec3], levels: &[u8], ctrl: &mut Vec<Vec3>, legs: &mut Vec<(u32, u32)>) {
    let n = points.len();
    debug_assert!(n >= 2 && levels.len() == n - 1);
    ctrl.clear();
    legs.clear();
    for (i, w) in points.windows(2).enumerate() {
        let leg = i as u32;
        ctrl.push(w[0]);
        legs.push((leg.saturating_sub(1), leg));
        let pieces = 1u32 << levels[i];
        for k in 1..pieces {
            ctrl.push(w[0].lerp(w[1], f64::from(k) / f64::from(pieces)));
            legs.push((leg, leg));
        }
    }
    ctrl.push(points[n - 1]);
    let last = (n - 2) as u32;
    legs.push((last, last));
}

/// A sampled curve: the polyline, and the knot span of each of its points.
#[derive(Clone, Debug, Default)]
pub struct Samples {
    pub points: Vec<Vec3>,
    pub spans: Vec<u32>,
}

impl Samples {
    /// Appends `q` (of span `s`); the previous point is dropped when it lies on the segment
    /// from the point before it to `q`, within `tol` (a straight stretch of the curve needs
    /// only its ends).
    fn push(&mut self, q: Vec3, s: u32, tol: f64) {
        let n = self.points.len();
        if n >= 2 && on_segment(self.points[n - 2], self.points[n - 1], q, tol) {
            self.points[n - 1] = q;
            self.spans[n - 1] = s;
        } else {
            self.points.push(q);
            self.spans.push(s);
        }
    }
}

/// Whether `b` lies strictly between `a` and `q` along their segment, within `tol` of it.
fn on_segment(a: Vec3, b: Vec3, q: Vec3, tol: f64) -> bool {
    let d = q - a;
    let l2 = d.length_squared();
    if l2 == 0.0 {
        return false;
    }
    let t = (b - a).dot(d) / l2;
    t > 0.0 && t < 1.0 && (a + d * t).distance_squared(b) <= tol * tol
}

/// Samples the B-spline of `ctrl` (degree `p`, at most m − 1, knots from [`clamped_knots`])
/// with `per_span` equal parameter steps in each knot span into `out` (cleared first). The
/// first and last points are φ₀ and φ_{m−1} exactly; points within `tol` of the segment
/// between their neighbours are left out.
pub fn sample(ctrl: &[Vec3], knots: &[f64], p: usize, per_span: usize, tol: f64, out: &mut Samples) {
    let m = ctrl.len();
    debug_assert!(p < m && per_span >= 1);
    out.points.clear();
    out.spans.clear();
    out.points.push(ctrl[0]);
    out.spans.push(0);
    for s in 0..m - p {
        let (a, b) = (knots[p + s], knots[p + s + 1]);
        let first = if s == 0 { 1 } else { 0 };
        for j in first..per_span {
            let u = a + (b - a) * (j as f64 / per_span as f64);
            out.push(de_boor(ctrl, knots, p, s, u), s as u32, tol);
        }
    }
    out.push(ctrl[m - 1], (m - p - 1) as u32, tol);
}
