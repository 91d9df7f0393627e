//! Segment queries against the seabed.
//!
//! Terrain clearance is vertical: z - h(x, y). A segment is checked by interval subdivision with
//! the terrain's rectangle upper bound, so a stretch far above the seabed costs one bound query
//! and the test is conservative: "clear" is proven, never guessed.

use super::{Terrain, World};
use crate::geom::Vec3;

/// Room for the subdivision stack. Depth-first bisection holds at most one pending piece per
/// level plus one, and the resolutions below stop bisection after about 40 levels; a full stack
/// is treated like reaching the resolution (hit / settle with the lower bound), never as an
/// error.
const STACK: usize = 64;

/// Hit tests stop bisecting at this fraction of the terrain's feature length (narrowest peak
/// sigma, finer grid spacing). Near a peak the rectangle bound then overestimates by about
/// 1e-3 of the peak height, which is how close to the safety envelope a segment may pass and
/// still be reported as a (conservative) hit.
const HIT_RESOLUTION: f64 = 1e-3;
/// The clearance search refines further, so its first-order bound error (about 1e-6 of the
/// peak height) matches its tolerance.
const CLEARANCE_RESOLUTION: f64 = 1e-6;
/// Absolute tolerance of the clearance, as a fraction of the terrain's vertical scale.
const CLEARANCE_TOL: f64 = 1e-6;
/// Resolution floors relative to the domain (or the segment, if longer): they bound the depth
/// of the bisection whatever the terrain.
const HIT_FLOOR: f64 = 1e-9;
const CLEARANCE_FLOOR: f64 = 1e-12;

#[derive(Clone, Copy)]
struct Piece {
    s0: f64,
    s1: f64,
    p0: Vec3,
    p1: Vec3,
    /// Lower bound of the vertical clearance on the piece (clearance search only).
    lower: f64,
}

impl World {
    /// Does any point of segment a -> b come within `safety` (vertically) of the seabed?
    ///
    /// Depth-first bisection: a piece is clear when min z over it minus the terrain bound over
    /// its horizontal box is at least `safety`; a sampled point below `safety` is a hit; a piece
    /// whose horizontal length falls below the resolution without being proven clear counts as
    /// a hit. The resolution is 1e-3 of the terrain's feature length
    /// ([`Terrain::feature_length`]: min(dx, dy) for grids, the narrowest sigma for peaks), and
    /// never below 1e-9 of the domain's horizontal size (or of the segment, if longer).
    /// No allocation. Non-finite endpoints or safety count as a hit.
    pub fn segment_hits_terrain(&self, a: Vec3, b: Vec3, safety: f64) -> bool {
        let t = &self.terrain;
        if matches!(t, Terrain::None) {
            return false;
        }
        if !(a.is_finite() && b.is_finite()) || safety.is_nan() {
            return true;
        }
        let g = |p: Vec3| p.z - t.elevation(p.x, p.y);
        if !(g(a) >= safety && g(b) >= safety) {
            return true;
        }
        let hlen = (b - a).truncate().length();
        let res = self.terrain_resolution(hlen, HIT_RESOLUTION, HIT_FLOOR);
        let mut stack = [Piece { s0: 0.0, s1: 1.0, p0: a, p1: b, lower: 0.0 }; STACK];
        let mut n = 1;
        while n > 0 {
            n -= 1;
            let Piece { s0, s1, p0, p1, .. } = stack[n];
            if piece_lower_bound(t, p0, p1) >= safety {
                continue;
            }
            let sm = 0.5 * (s0 + s1);
            if (s1 - s0) * hlen <= res || !(sm > s0 && sm < s1) || n + 2 > STACK {
                return true;
            }
            let pm = point_at(a, b, sm);
            if !(g(pm) >= safety) {
                return true;
            }
            stack[n] = Piece { s0: sm, s1, p0: pm, p1, lower: 0.0 };
            stack[n + 1] = Piece { s0, s1: sm, p0, p1: pm, lower: 0.0 };
            n += 2;
        }
        false
    }

    /// Minimum vertical clearance z - h(x, y) along the segment (negative below the seabed,
    /// +inf without seabed).
    ///
    /// Branch and bound over the same pieces as [`World::segment_hits_terrain`]: sampled points
    /// give upper bounds of the minimum, `min z - max_elevation_in` lower bounds, and a piece is
    /// dropped once its lower bound is within the tolerance (1e-6 of
    /// [`Terrain::vertical_scale`]) of the best sample. The value returned is the least lower
    /// bound of the settled pieces (or the best sample, if smaller), so it never overstates the
    /// clearance and understates it by at most the tolerance, except in pieces stopped at the
    /// resolution (1e-6 of the feature length, floor 1e-12 of the domain), whose bound is used
    /// as is. NaN for non-finite endpoints.
    pub fn segment_terrain_clearance(&self, a: Vec3, b: Vec3) -> f64 {
        let t = &self.terrain;
        if matches!(t, Terrain::None) {
            return f64::INFINITY;
        }
        if !(a.is_finite() && b.is_finite()) {
            return f64::NAN;
        }
        let g = |p: Vec3| p.z - t.elevation(p.x, p.y);
        let mut upper = g(a).min(g(b));
        let tol = CLEARANCE_TOL * t.vertical_scale();
        let hlen = (b - a).truncate().length();
        let res = self.terrain_resolution(hlen, CLEARANCE_RESOLUTION, CLEARANCE_FLOOR);
        let mut settled = f64::INFINITY;
        let first = Piece { s0: 0.0, s1: 1.0, p0: a, p1: b, lower: piece_lower_bound(t, a, b) };
        let mut stack = [first; STACK];
        let mut n = 1;
        while n > 0 {
            n -= 1;
            let Piece { s0, s1, p0, p1, lower } = stack[n];
            if lower >= upper - tol {
                settled = settled.min(lower);
                continue;
            }
            let sm = 0.5 * (s0 + s1);
            if (s1 - s0) * hlen <= res || !(sm > s0 && sm < s1) || n + 2 > STACK {
                settled = settled.min(lower);
                continue;
            }
            let pm = point_at(a, b, sm);
            upper = upper.min(g(pm));
            let left = Piece { s0, s1: sm, p0, p1: pm, lower: piece_lower_bound(t, p0, pm) };
            let right = Piece { s0: sm, s1, p0: pm, p1, lower: piece_lower_bound(t, pm, p1) };
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

/// The segment point at parameter s, exact at both ends.
#[inline]
fn point_at(a: Vec3, b: Vec3, s: f64) -> Vec3 {
    a * (1.0 - s) + b * s
}

/// Lower bound of z - h over the piece p0 -> p1: its lowest end against the highest seabed in
/// its horizontal bounding box.
#[inline]
fn piece_lower_bound(t: &Terrain, p0: Vec3, p1: Vec3) -> f64 {
    let lo = p0.min(p1);
    let hi = p0.max(p1);
    lo.z - t.max_elevation_in(lo.x, lo.y, hi.x, hi.y)
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
