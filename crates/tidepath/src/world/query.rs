//! Segment queries against the seabed.
//!
//! Terrain clearance is vertical: z - h(x, y). A segment is checked by interval subdivision with
//! lower bounds of the clearance over each piece, so a stretch far above the seabed costs one
//! bound query and the test is conservative: "clear" is proven, never guessed. Three bounds
//! serve, each where it is sharp: the terrain's rectangle upper bound (far from the seabed), a
//! second-order chord bound for analytic peaks (along stretches that follow the seabed), and an
//! exact minimum for grids once a piece lies within 2 x 2 cells.

// `!(d >= margin)` is deliberate throughout: a NaN must fail every "clear" test.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::{Terrain, World};
use crate::geom::Vec3;

/// Room for the subdivision stack. Depth-first bisection holds at most one pending piece per
/// level plus one, and the resolutions below stop bisection after about 40 levels; a full stack
/// is treated like reaching the resolution (hit / settle with the lower bound), never as an
/// error.
const STACK: usize = 64;

/// Hit tests stop bisecting at this fraction of the terrain's feature length (narrowest peak
/// sigma, finer grid spacing). It only matters for peaks (grid pieces are settled exactly
/// before): a segment may pass within about 1e-3 of the peak height (the rectangle bound's
/// error at that size, the chord bound's is far smaller) above the safety envelope and still
/// be reported as a (conservative) hit.
const HIT_RESOLUTION: f64 = 1e-3;
/// The clearance search may refine further, so that even the first-order rectangle bound
/// (error about 1e-6 of the peak height at that size) meets its tolerance.
const CLEARANCE_RESOLUTION: f64 = 1e-6;
/// Absolute tolerance of the clearance, as a fraction of the terrain's vertical scale.
const CLEARANCE_TOL: f64 = 1e-6;
/// Resolution floors relative to the domain (or the segment, if longer): they bound the depth
/// of the bisection whatever the terrain.
const HIT_FLOOR: f64 = 1e-9;
const CLEARANCE_FLOOR: f64 = 1e-12;

/// A stretch [s0, s1] of the segment with its end points, their clearance g = z - h and smooth
/// clearance u = z - h_smooth (u <= g, see [`Terrain::elevation_with_smooth`]), and a lower
/// bound of g over the stretch.
#[derive(Clone, Copy)]
struct Piece {
    s0: f64,
    s1: f64,
    p0: Vec3,
    p1: Vec3,
    g0: f64,
    g1: f64,
    u0: f64,
    u1: f64,
    lower: f64,
    /// The piece's exact minimum of g, when the terrain could give it (then `lower` is it minus
    /// the rounding slack and the piece needs no splitting); NaN otherwise.
    exact: f64,
}

/// One segment against the terrain: sampling and lower bounds.
struct Probe<'a> {
    terrain: &'a Terrain,
    a: Vec3,
    b: Vec3,
    /// Upper bound of d^2 u / ds^2 = -d^2 h_smooth / ds^2 in the segment parameter s in [0, 1]
    /// (the terrain's concavity bound times the squared horizontal length), if it has one.
    concavity: Option<f64>,
    /// Allowance for rounding in the second-order bound, which works with differences of
    /// sampled values.
    slack: f64,
}

impl<'a> Probe<'a> {
    fn new(terrain: &'a Terrain, a: Vec3, b: Vec3) -> Self {
        let hlen = (b - a).truncate().length();
        let concavity = terrain.concavity_bound().map(|k| k * hlen * hlen).filter(|m| m.is_finite());
        let slack = 64.0 * f64::EPSILON * (a.z.abs().max(b.z.abs()) + terrain.vertical_scale());
        Self { terrain, a, b, concavity, slack }
    }

    /// The point at parameter s (exact at both ends), its clearance and smooth clearance.
    #[inline]
    fn sample(&self, s: f64) -> (Vec3, f64, f64) {
        let p = self.a * (1.0 - s) + self.b * s;
        let (h, h_smooth) = self.terrain.elevation_with_smooth(p.x, p.y);
        (p, p.z - h, p.z - h_smooth)
    }

    /// The piece between two samples, with a lower bound of g over it that is at least `need`
    /// if it can be shown cheaply. Grids settle pieces within 2 x 2 cells exactly
    /// ([`Terrain::exact_min_clearance`]). Otherwise two bounds. First, where the terrain has a
    /// concavity bound M (so u'' <= M), the second-order g(s) >= u(s) >= chord(s) - M/2
    /// (s - s0)(s1 - s), minimised in closed form: sharp along stretches that follow the seabed
    /// (its error shrinks with the square of the piece length) and free of exp calls. Then,
    /// only if that falls short of `need`, the rectangle bound (lowest end against the highest
    /// seabed under the piece), sharp far from the seabed.
    #[inline]
    fn piece(
        &self,
        s0: f64,
        s1: f64,
        (p0, g0, u0): (Vec3, f64, f64),
        (p1, g1, u1): (Vec3, f64, f64),
        need: f64,
    ) -> Piece {
        if let Some(m) = self.terrain.exact_min_clearance(self.a, self.b, s0, s1) {
            return Piece { s0, s1, p0, p1, g0, g1, u0, u1, lower: m - self.slack, exact: m };
        }
        let mut lower = f64::NEG_INFINITY;
        if let Some(m) = self.concavity {
            lower = chord_lower_bound(u0, u1, s1 - s0, m) - self.slack;
        }
        if !(lower >= need) {
            let lo = p0.min(p1);
            let hi = p0.max(p1);
            lower = lower.max(lo.z - self.terrain.max_elevation_in(lo.x, lo.y, hi.x, hi.y));
        }
        Piece { s0, s1, p0, p1, g0, g1, u0, u1, lower, exact: f64::NAN }
    }

    /// The two halves of `piece` (bounds computed against `need`) and the sample at its middle,
    /// or `None` when the piece is too short to split in floating point.
    #[inline]
    fn split(&self, piece: &Piece, need: f64) -> Option<(Piece, Piece, f64)> {
        let sm = 0.5 * (piece.s0 + piece.s1);
        if !(sm > piece.s0 && sm < piece.s1) {
            return None;
        }
        let mid = self.sample(sm);
        let left = self.piece(piece.s0, sm, (piece.p0, piece.g0, piece.u0), mid, need);
        let right = self.piece(sm, piece.s1, mid, (piece.p1, piece.g1, piece.u1), need);
        Some((left, right, mid.1))
    }
}

/// Minimum over t in [0, w] of g0 + (g1 - g0) t / w - m/2 t (w - t): the least value a
/// function with second derivative <= m can take between samples g0 at 0 and g1 at w (the
/// difference between the function and this curve is concave and 0 at both ends).
#[inline]
fn chord_lower_bound(g0: f64, g1: f64, w: f64, m: f64) -> f64 {
    if !(m > 0.0 && w > 0.0) {
        return g0.min(g1);
    }
    let t = (0.5 * w - (g1 - g0) / (m * w)).clamp(0.0, w);
    g0 + (g1 - g0) * (t / w) - 0.5 * m * t * (w - t)
}

impl World {
    /// Does any point of segment a -> b come within `safety` (vertically) of the seabed?
    ///
    /// Depth-first bisection: a piece is clear when a lower bound of z - h over it is at least
    /// `safety` (see `Probe::piece`: rectangle bound, and a second-order bound for peaks); a
    /// sampled point below `safety` is a hit; a piece whose horizontal length falls below the
    /// resolution without being proven clear counts as a hit. The resolution is 1e-3 of the
    /// terrain's feature length ([`Terrain::feature_length`]: min(dx, dy) for grids, the
    /// narrowest sigma for peaks), and never below 1e-9 of the domain's horizontal size (or of
    /// the segment, if longer). No allocation. Non-finite endpoints or safety count as a hit.
    pub fn segment_hits_terrain(&self, a: Vec3, b: Vec3, safety: f64) -> bool {
        let t = &self.terrain;
        if matches!(t, Terrain::None) {
            return false;
        }
        if !(a.is_finite() && b.is_finite()) || safety.is_nan() {
            return true;
        }
        // One rectangle bound over the whole segment settles the usual case of a segment well
        // above the seabed; only then is the rest worth setting up.
        let lo = a.min(b);
        let hi = a.max(b);
        // For peaks, a bound without exp first: never below the exact one, so what it proves
        // clear the exact bound would too, the same answer at a fraction of the cost (a
        // segment not proven clear here only needs the exact value's comparison below).
        if let Some(upper) = t.max_elevation_upper(lo.x, lo.y, hi.x, hi.y) {
            if lo.z - upper >= safety {
                return false;
            }
        }
        let root_rect = lo.z - t.max_elevation_in(lo.x, lo.y, hi.x, hi.y);
        if root_rect >= safety {
            return false;
        }
        let probe = Probe::new(t, a, b);
        // A short segment over a grid is settled exactly at once.
        if let Some(m) = t.exact_min_clearance(a, b, 0.0, 1.0) {
            return !(m - probe.slack >= safety);
        }
        let (sa, sb) = (probe.sample(0.0), probe.sample(1.0));
        if !(sa.1 >= safety && sb.1 >= safety) {
            return true;
        }
        let hlen = (b - a).truncate().length();
        let res = self.terrain_resolution(hlen, HIT_RESOLUTION, HIT_FLOOR);
        // The root's rectangle bound is known already; a need of -inf asks only for the rest.
        let mut root = probe.piece(0.0, 1.0, sa, sb, f64::NEG_INFINITY);
        root.lower = root.lower.max(root_rect);
        let mut stack = [root; STACK];
        let mut n = 1;
        while n > 0 {
            n -= 1;
            let piece = stack[n];
            if piece.lower >= safety {
                continue;
            }
            // An exact minimum below the safety distance (or within rounding of it) is a hit.
            if !piece.exact.is_nan() || (piece.s1 - piece.s0) * hlen <= res || n + 2 > STACK {
                return true;
            }
            let Some((left, right, g_mid)) = probe.split(&piece, safety) else { return true };
            if !(g_mid >= safety) {
                return true;
            }
            // The more suspicious half on top: a hit, if any, is found sooner.
            let (first, second) = if left.lower <= right.lower { (left, right) } else { (right, left) };
            stack[n] = second;
            stack[n + 1] = first;
            n += 2;
        }
        false
    }

    /// Minimum vertical clearance z - h(x, y) along the segment (negative below the seabed,
    /// +inf without seabed).
    ///
    /// Branch and bound over the same pieces as [`World::segment_hits_terrain`]: sampled points
    /// give upper bounds of the minimum, the piece bounds lower bounds, and a piece is dropped
    /// once its lower bound is within the tolerance (1e-6 of [`Terrain::vertical_scale`]) of
    /// the best sample. The value returned is the least lower bound of the settled pieces (or
    /// the best sample, if smaller), so it never overstates the clearance and understates it by
    /// at most the tolerance, except in pieces stopped at the resolution (1e-6 of the feature
    /// length, floor 1e-12 of the domain), whose bound is used as is. NaN for non-finite
    /// endpoints.
    pub fn segment_terrain_clearance(&self, a: Vec3, b: Vec3) -> f64 {
        let t = &self.terrain;
        if matches!(t, Terrain::None) {
            return f64::INFINITY;
        }
        if !(a.is_finite() && b.is_finite()) {
            return f64::NAN;
        }
        let probe = Probe::new(t, a, b);
        let (sa, sb) = (probe.sample(0.0), probe.sample(1.0));
        let mut upper = sa.1.min(sb.1);
        let tol = CLEARANCE_TOL * t.vertical_scale();
        let hlen = (b - a).truncate().length();
        let res = self.terrain_resolution(hlen, CLEARANCE_RESOLUTION, CLEARANCE_FLOOR);
        let mut settled = f64::INFINITY;
        let mut stack = [probe.piece(0.0, 1.0, sa, sb, upper - tol); STACK];
        let mut n = 1;
        while n > 0 {
            n -= 1;
            let piece = stack[n];
            if !piece.exact.is_nan() {
                upper = upper.min(piece.exact);
                settled = settled.min(piece.lower);
                continue;
            }
            if piece.lower >= upper - tol {
                settled = settled.min(piece.lower);
                continue;
            }
            if (piece.s1 - piece.s0) * hlen <= res || n + 2 > STACK {
                settled = settled.min(piece.lower);
                continue;
            }
            let Some((left, right, g_mid)) = probe.split(&piece, upper - tol) else {
                settled = settled.min(piece.lower);
                continue;
            };
            upper = upper.min(g_mid);
            // Explore the more promising half first: it lowers `upper` sooner and prunes more.
            let (first, second) = if left.lower <= right.lower { (left, right) } else { (right, left) };
            stack[n] = second;
            stack[n + 1] = first;
            n += 2;
        }
        upper.min(settled)
    }

    /// Horizontal length below which bisection stops: `rel` times the terrain's feature length,
    /// floored at `floor` times the domain's horizontal size (or the segment's, if longer).
    fn terrain_resolution(&self, hlen: f64, rel: f64, floor: f64) -> f64 {
        let size = self.bounds.size();
        let domain = size.x.max(size.y);
        let scale = if domain.is_finite() { domain.max(hlen) } else { hlen };
        let base = self.terrain.feature_length().map_or(0.0, |f| rel * f);
        base.max(floor * scale)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Aabb;
    use crate::world::grid::RegularGrid2;
    use crate::world::terrain::{ElevationGrid, GaussianPeaks, Peak};

    fn peak_world() -> World {
        let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(100.0, 100.0, 0.0)));
        // Base at -100, a 40 m peak at (50, 50): summit at -60.
        w.terrain = Terrain::Peaks(GaussianPeaks {
            base: -100.0,
            peaks: vec![Peak { x: 50.0, y: 50.0, height: 40.0, sigma_x: 10.0, sigma_y: 5.0 }],
            ceiling: None,
        });
        w
    }

    #[test]
    fn horizontal_segment_over_peak() {
        let w = peak_world();
        let (a, b) = (Vec3::new(0.0, 50.0, -50.0), Vec3::new(100.0, 50.0, -50.0));
        // Clearance over the summit: -50 - (-60) = 10.
        let c = w.segment_terrain_clearance(a, b);
        assert!((c - 10.0).abs() <= 1e-6 * 140.0, "{c}");
        assert!(c <= 10.0);
        assert!(!w.segment_hits_terrain(a, b, 9.9));
        assert!(w.segment_hits_terrain(a, b, 10.1));
        // Passing 1 sigma_y north of the summit: peak profile is 40 / e high there.
        let (a, b) = (Vec3::new(0.0, 55.0, -70.0), Vec3::new(100.0, 55.0, -70.0));
        let want = -70.0 - (-100.0 + 40.0 * (-1.0f64).exp());
        let c = w.segment_terrain_clearance(a, b);
        assert!((c - want).abs() <= 1e-6 * 140.0, "{c} vs {want}");
        assert!(!w.segment_hits_terrain(a, b, want - 1e-2));
        assert!(w.segment_hits_terrain(a, b, want + 1e-2));
    }

    #[test]
    fn segment_through_the_peak_hits() {
        let w = peak_world();
        let (a, b) = (Vec3::new(0.0, 50.0, -80.0), Vec3::new(100.0, 50.0, -70.0));
        assert!(w.segment_hits_terrain(a, b, 0.0));
        // At x = 50 the segment is at -75, 15 m below the summit.
        let c = w.segment_terrain_clearance(a, b);
        assert!(c <= -15.0 + 1e-9 && c > -16.0, "{c}");
    }

    #[test]
    fn endpoint_below_seabed_and_vertical_segments() {
        let w = peak_world();
        assert!(w.segment_hits_terrain(Vec3::new(50.0, 50.0, -61.0), Vec3::new(50.0, 50.0, -10.0), 0.0));
        let (a, b) = (Vec3::new(50.0, 50.0, -55.0), Vec3::new(50.0, 50.0, -10.0));
        assert!(!w.segment_hits_terrain(a, b, 4.9));
        assert!(w.segment_hits_terrain(a, b, 5.1));
        assert!((w.segment_terrain_clearance(a, b) - 5.0).abs() < 1e-9);
    }

    #[test]
    fn no_terrain_never_hits() {
        let w = World::open(Aabb::new(Vec3::splat(-1.0), Vec3::splat(1.0)));
        assert!(!w.segment_hits_terrain(Vec3::splat(-1e9), Vec3::splat(1e9), 1e9));
        assert_eq!(w.segment_terrain_clearance(Vec3::ZERO, Vec3::ONE), f64::INFINITY);
    }

    #[test]
    fn grid_clearance_over_a_ridge() {
        // A ridge along y: nodes at x = 0, 10, 20 with heights -50, -20, -50 (any y).
        let g = RegularGrid2::new(0.0, 0.0, 10.0, 10.0, 3, 2, "g").unwrap();
        let z = vec![-50.0, -20.0, -50.0, -50.0, -20.0, -50.0];
        let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -60.0), Vec3::new(20.0, 10.0, 0.0)));
        w.terrain = Terrain::Grid(ElevationGrid::new(g, z, "g").unwrap());
        // A slanted segment crossing the ridge: z = -15 at x = 0 to z = -5 at x = 20, so -10
        // at the crest: clearance 10 at x = 10 (the seabed falls 3 m per metre, faster than the
        // segment rises, so the crest is the minimum).
        let (a, b) = (Vec3::new(0.0, 3.0, -15.0), Vec3::new(20.0, 7.0, -5.0));
        let c = w.segment_terrain_clearance(a, b);
        assert!((c - 10.0).abs() < 1e-6 * 50.0 && c <= 10.0, "{c}");
        assert!(!w.segment_hits_terrain(a, b, 9.99));
        assert!(w.segment_hits_terrain(a, b, 10.01));
    }
}
