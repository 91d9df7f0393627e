//! The seabed as an elevation function z = h(x, y) (negative below the sea surface).
//!
//! Besides point elevation, each terrain answers a conservative upper bound of the elevation
//! over a rectangle. The segment queries in [`super::query`] use that bound to prove whole
//! stretches of a segment clear in one step and only subdivide near the seabed. Near the seabed
//! they lean on what each terrain knows about itself: peaks bound how sharply they curve down
//! (a second-order bound between samples), grids give the exact minimum clearance along a
//! stretch spanning at most 2 x 2 cells (the surface is bilinear per cell).

use super::grid::RegularGrid2;
use crate::error::{Error, Result};
use crate::geom::Vec3;

/// One Gaussian peak: height `h` above the base at (x, y), widths `sigma_x`, `sigma_y`:
/// h exp(-((x - x_j)/sigma_x)^2 - ((y - y_j)/sigma_y)^2)  (seed 000 eq. 1 with sigma = x_j / k).
#[derive(Clone, Debug, PartialEq)]
pub struct Peak {
    pub x: f64,
    pub y: f64,
    pub height: f64,
    pub sigma_x: f64,
    pub sigma_y: f64,
}

/// Analytic seabed: base level plus a sum of Gaussian peaks, optionally capped at a ceiling
/// (seed 000 eq. 1 caps the terrain at h_max).
#[derive(Clone, Debug, PartialEq)]
pub struct GaussianPeaks {
    pub base: f64,
    pub peaks: Vec<Peak>,
    pub ceiling: Option<f64>,
}

/// A regular elevation grid, bilinear between nodes, with a max-pyramid for bound queries.
///
/// Build it with [`ElevationGrid::new`]: the pyramid is derived from `z`, so editing `z` in
/// place afterwards would leave the bounds stale.
#[derive(Clone, Debug)]
pub struct ElevationGrid {
    pub grid: RegularGrid2,
    /// Node elevations, row-major (`grid.bilinear` layout).
    pub z: Vec<f64>,
    /// Level 0 holds, per cell, the max of its 4 corner nodes; level k+1 the max of 2 x 2
    /// blocks of level k. The last level is at most 2 x 2 blocks.
    pyramid: Vec<MaxLevel>,
    /// Added to every bound: bilinear evaluation in floating point can overshoot the corner
    /// max by a few ulps of the largest |z|, and a bound must never be below a computed value.
    slack: f64,
    z_min: f64,
    z_max: f64,
}

#[derive(Clone, Debug)]
struct MaxLevel {
    nx: usize,
    ny: usize,
    max: Vec<f64>,
}

#[derive(Clone, Debug)]
pub enum Terrain {
    /// No seabed inside the domain.
    None,
    Peaks(GaussianPeaks),
    Grid(ElevationGrid),
}

impl Peak {
    /// Seed 000 eq. 1 writes the exponent as (k_x (x - x_j) / x_j)^2: the peak's own centre
    /// coordinate sets its width, sigma_x = x_j / k_x (ALGORITHMS.md 1.2). That only makes
    /// sense for centres at positive coordinates and positive k, so anything else is rejected.
    pub fn from_paper_k(x: f64, y: f64, height: f64, k_x: f64, k_y: f64, field: &str) -> Result<Self> {
        if !(x > 0.0 && y > 0.0 && x.is_finite() && y.is_finite()) {
            return Err(Error::input(
                format!("{field}.center"),
                format!("seed 000 peak widths are x_j / k, so the centre must be positive and finite, got [{x}, {y}]"),
            ));
        }
        if !(k_x > 0.0 && k_y > 0.0 && k_x.is_finite() && k_y.is_finite()) {
            return Err(Error::input(format!("{field}.k"), format!("must be positive and finite, got [{k_x}, {k_y}]")));
        }
        if !height.is_finite() {
            return Err(Error::input(format!("{field}.height"), format!("must be finite, got {height}")));
        }
        Ok(Self { x, y, height, sigma_x: x / k_x, sigma_y: y / k_y })
    }

    /// Seed 001 eq. 11, Z = h exp(-((Y - y0)^2 a^2 + (X - x0)^2 b^2) / (2 sigma^2)), is the
    /// same Gaussian with sigma_x = sqrt(2) sigma / b and sigma_y = sqrt(2) sigma / a.
    pub fn from_seabed_eq11(x0: f64, y0: f64, h: f64, a: f64, b: f64, sigma: f64, field: &str) -> Result<Self> {
        if !(x0.is_finite() && y0.is_finite() && h.is_finite()) {
            return Err(Error::input(
                field.to_string(),
                format!("centre and height must be finite, got [{x0}, {y0}], {h}"),
            ));
        }
        if !(a > 0.0 && b > 0.0 && sigma > 0.0 && a.is_finite() && b.is_finite() && sigma.is_finite()) {
            return Err(Error::input(
                field.to_string(),
                format!("a, b and sigma must be positive and finite, got a = {a}, b = {b}, sigma = {sigma}"),
            ));
        }
        let s = std::f64::consts::SQRT_2 * sigma;
        Ok(Self { x: x0, y: y0, height: h, sigma_x: s / b, sigma_y: s / a })
    }

    /// h exp(-(dx/sx)^2 - (dy/sy)^2). Both the point elevation and the rectangle bound go through
    /// this one expression so that, at a point, the bound rounds exactly like the value.
    #[inline]
    fn term(&self, dx: f64, dy: f64) -> f64 {
        let u = dx / self.sigma_x;
        let v = dy / self.sigma_y;
        self.height * (-(u * u) - v * v).exp()
    }
}

impl GaussianPeaks {
    /// The terrain of seed 000 eq. 1 from its own parameters: base h0, peaks given as
    /// `[x_j, y_j, h_j, k_x, k_y]`, and the cap h_max (see [`Peak::from_paper_k`]).
    pub fn from_paper_k(h0: f64, peaks: &[[f64; 5]], h_max: Option<f64>, field: &str) -> Result<Self> {
        if !h0.is_finite() {
            return Err(Error::input(format!("{field}.base"), format!("must be finite, got {h0}")));
        }
        if let Some(c) = h_max {
            if c.is_nan() {
                return Err(Error::input(format!("{field}.ceiling"), "must be a number, got NaN"));
            }
        }
        let peaks = peaks
            .iter()
            .enumerate()
            .map(|(j, &[x, y, h, kx, ky])| Peak::from_paper_k(x, y, h, kx, ky, &format!("{field}.peaks[{j}]")))
            .collect::<Result<Vec<_>>>()?;
        Ok(Self { base: h0, peaks, ceiling: h_max })
    }

    #[inline]
    fn elevation(&self, x: f64, y: f64) -> f64 {
        let z = self.uncapped(x, y);
        match self.ceiling {
            Some(c) => z.min(c),
            None => z,
        }
    }

    #[inline]
    fn uncapped(&self, x: f64, y: f64) -> f64 {
        let mut z = self.base;
        for p in &self.peaks {
            z += p.term(x - p.x, y - p.y);
        }
        z
    }

    /// How sharply the uncapped sum can curve downward: an upper bound of minus its second
    /// derivative along any horizontal unit direction. For one peak, with alpha = w_x / sigma_x
    /// and beta = w_y / sigma_y, the second derivative of exp(-u^2 - v^2) is
    /// [4 (u alpha + v beta)^2 - 2 (alpha^2 + beta^2)] exp(-u^2 - v^2), which lies in
    /// [-2, 4/e] (alpha^2 + beta^2). So a bump (h > 0) curves down by at most 2 h m (over its
    /// summit) and a dip by at most 4/e |h| m (on its flanks), with m = max(1/sigma_x^2,
    /// 1/sigma_y^2).
    fn max_concavity(&self) -> f64 {
        self.peaks
            .iter()
            .map(|p| {
                let m = (1.0 / (p.sigma_x * p.sigma_x)).max(1.0 / (p.sigma_y * p.sigma_y));
                let k = if p.height >= 0.0 { 2.0 } else { 4.0 / std::f64::consts::E };
                k * p.height.abs() * m
            })
            .sum()
    }

    /// Each term is bounded on its own: a bump is highest at the rectangle point nearest its
    /// centre, a dip (h < 0) is shallowest at the farthest corner. Summing per-term bounds loses
    /// a little where peaks overlap but needs one exp per peak, and collapses to the exact value
    /// (bit for bit) when the rectangle is a point.
    #[inline]
    fn max_in(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        let mut z = self.base;
        for p in &self.peaks {
            let (dx, dy) = if p.height >= 0.0 {
                ((x0 - p.x).max(p.x - x1).max(0.0), (y0 - p.y).max(p.y - y1).max(0.0))
            } else {
                ((x0 - p.x).abs().max((x1 - p.x).abs()), (y0 - p.y).abs().max((y1 - p.y).abs()))
            };
            z += p.term(dx, dy);
        }
        match self.ceiling {
            Some(c) => z.min(c),
            None => z,
        }
    }

    fn min_sigma(&self) -> Option<f64> {
        self.peaks.iter().map(|p| p.sigma_x.min(p.sigma_y)).filter(|s| *s > 0.0).reduce(f64::min)
    }
}

impl ElevationGrid {
    /// Validates the node count and values (finite) and builds the acceleration structures.
    pub fn new(grid: RegularGrid2, z: Vec<f64>, field: &str) -> Result<Self> {
        if z.len() != grid.len() {
            return Err(Error::input(
                format!("{field}.elevations"),
                format!("expected {} x {} = {} values, got {}", grid.nx, grid.ny, grid.len(), z.len()),
            ));
        }
        if let Some((k, v)) = z.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(Error::input(
                format!("{field}.elevations"),
                format!("value {k} (node [{}, {}]) must be finite, got {v}", k % grid.nx, k / grid.nx),
            ));
        }
        let (nx, ny) = (grid.nx, grid.ny);
        let (cx, cy) = (nx - 1, ny - 1);
        let mut level0 = Vec::with_capacity(cx * cy);
        for j in 0..cy {
            for i in 0..cx {
                let k = j * nx + i;
                level0.push(z[k].max(z[k + 1]).max(z[k + nx]).max(z[k + nx + 1]));
            }
        }
        let mut pyramid = vec![MaxLevel { nx: cx, ny: cy, max: level0 }];
        while let Some(last) = pyramid.last().filter(|l| l.nx > 2 || l.ny > 2) {
            let (px, py) = (last.nx.div_ceil(2), last.ny.div_ceil(2));
            let mut max = vec![f64::NEG_INFINITY; px * py];
            for j in 0..last.ny {
                for i in 0..last.nx {
                    let m = &mut max[(j / 2) * px + i / 2];
                    *m = m.max(last.max[j * last.nx + i]);
                }
            }
            pyramid.push(MaxLevel { nx: px, ny: py, max });
        }
        let z_min = z.iter().copied().fold(f64::INFINITY, f64::min);
        let z_max = z.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let slack = 16.0 * f64::EPSILON * z_min.abs().max(z_max.abs());
        Ok(Self { grid, z, pyramid, slack, z_min, z_max })
    }

    /// Lowest and highest node elevation.
    pub fn z_range(&self) -> (f64, f64) {
        (self.z_min, self.z_max)
    }

    /// The bilinear surface of cell (i, j) at local coordinates (u, v), written exactly like
    /// `RegularGrid2::bilinear` so the bound and the value round alike at shared points.
    #[inline]
    fn cell_value(&self, i: usize, j: usize, u: f64, v: f64) -> f64 {
        let nx = self.grid.nx;
        let k = j * nx + i;
        let (a, b) = (self.z[k], self.z[k + 1]);
        let (c, d) = (self.z[k + nx], self.z[k + nx + 1]);
        let lo = a + (b - a) * u;
        let hi = c + (d - c) * u;
        lo + (hi - lo) * v
    }

    /// Small rectangles (at most 2 x 2 cells) get the exact maximum: inside a cell the surface is
    /// bilinear, hence linear along each axis, so its max over a sub-rectangle sits at a corner.
    /// That is what makes the bound tight as the rectangle shrinks, which the branch and bound
    /// in the clearance query needs to converge. Larger rectangles read the pyramid.
    fn max_in(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        let g = &self.grid;
        let (cx, cy) = ((g.nx - 1) as f64, (g.ny - 1) as f64);
        // Same mapping and clamping as `RegularGrid2::locate`, so outside points see edge cells.
        let fx0 = ((x0 - g.x0) / g.dx).clamp(0.0, cx);
        let fx1 = ((x1 - g.x0) / g.dx).clamp(0.0, cx);
        let fy0 = ((y0 - g.y0) / g.dy).clamp(0.0, cy);
        let fy1 = ((y1 - g.y0) / g.dy).clamp(0.0, cy);
        let (fx0, fx1) = (fx0.min(fx1), fx0.max(fx1));
        let (fy0, fy1) = (fy0.min(fy1), fy0.max(fy1));
        let i0 = (fx0 as usize).min(g.nx - 2);
        let i1 = (fx1 as usize).min(g.nx - 2);
        let j0 = (fy0 as usize).min(g.ny - 2);
        let j1 = (fy1 as usize).min(g.ny - 2);
        let mut m = f64::NEG_INFINITY;
        if i1 - i0 <= 1 && j1 - j0 <= 1 {
            for j in j0..=j1 {
                let vl = (fy0 - j as f64).max(0.0);
                let vh = (fy1 - j as f64).min(1.0);
                for i in i0..=i1 {
                    let ul = (fx0 - i as f64).max(0.0);
                    let uh = (fx1 - i as f64).min(1.0);
                    m = m
                        .max(self.cell_value(i, j, ul, vl))
                        .max(self.cell_value(i, j, uh, vl))
                        .max(self.cell_value(i, j, ul, vh))
                        .max(self.cell_value(i, j, uh, vh));
                }
            }
        } else {
            let mut l = 0;
            while (i1 >> l) - (i0 >> l) > 1 || (j1 >> l) - (j0 >> l) > 1 {
                l += 1;
            }
            let level = &self.pyramid[l];
            for j in (j0 >> l)..=(j1 >> l) {
                for i in (i0 >> l)..=(i1 >> l) {
                    m = m.max(level.max[j * level.nx + i]);
                }
            }
        }
        m + self.slack
    }
}

impl ElevationGrid {
    /// The exact minimum of z - h along p(s) = a + (b - a) s, s in [s0, s1], when that stretch
    /// stays within 2 x 2 cells (after clamping to the grid); `None` otherwise.
    ///
    /// Inside one cell the surface is bilinear and the stretch's local coordinates are linear
    /// in s, so the clearance is a quadratic in s. Cut the stretch where it crosses cell edges
    /// (or the grid's border, beyond which the field is constant) and take, per cut, the least
    /// of its ends and the quadratic's vertex, each evaluated as a real point of the segment.
    /// That settles pieces near the seabed exactly instead of subdividing them to a resolution.
    fn min_clearance_on(&self, a: Vec3, b: Vec3, s0: f64, s1: f64) -> Option<f64> {
        let g = &self.grid;
        let d = b - a;
        let (cx, cy) = ((g.nx - 1) as f64, (g.ny - 1) as f64);
        // Raw grid coordinates are fa + fd s along the segment.
        let (fxa, fxd) = ((a.x - g.x0) / g.dx, d.x / g.dx);
        let (fya, fyd) = ((a.y - g.y0) / g.dy, d.y / g.dy);
        let cell_range = |fa: f64, fd: f64, c: f64, n: usize| {
            let f0 = (fa + fd * s0).clamp(0.0, c);
            let f1 = (fa + fd * s1).clamp(0.0, c);
            ((f0.min(f1) as usize).min(n - 2), (f0.max(f1) as usize).min(n - 2))
        };
        let (i_lo, i_hi) = cell_range(fxa, fxd, cx, g.nx);
        let (j_lo, j_hi) = cell_range(fya, fyd, cy, g.ny);
        if !(i_hi - i_lo <= 1 && j_hi - j_lo <= 1) {
            return None;
        }
        let mut cuts = [0.0f64; 8];
        cuts[0] = s0;
        let mut n = 1;
        for (fa, fd, lines) in [(fxa, fxd, [0.0, cx, (i_lo + 1) as f64]), (fya, fyd, [0.0, cy, (j_lo + 1) as f64])] {
            if fd != 0.0 {
                for k in lines {
                    let s = (k - fa) / fd;
                    if s > s0 && s < s1 {
                        cuts[n] = s;
                        n += 1;
                    }
                }
            }
        }
        cuts[n] = s1;
        n += 1;
        cuts[1..n - 1].sort_unstable_by(f64::total_cmp);
        let clearance = |s: f64| {
            let p = a * (1.0 - s) + b * s;
            p.z - g.bilinear(&self.z, p.x, p.y)
        };
        // Cell index and local coordinate w0 + w1 s along one axis, on a cut holding `mid`.
        let local = |fa: f64, fd: f64, c: f64, n: usize, mid: f64| {
            let f = fa + fd * mid;
            if f <= 0.0 {
                (0, 0.0, 0.0)
            } else if f >= c {
                (n - 2, 1.0, 0.0)
            } else {
                let i = (f as usize).min(n - 2);
                (i, fa - i as f64, fd)
            }
        };
        let mut best = f64::INFINITY;
        for k in 0..n - 1 {
            let (lo, hi) = (cuts[k], cuts[k + 1]);
            best = best.min(clearance(lo)).min(clearance(hi));
            let mid = 0.5 * (lo + hi);
            let (i, u0, u1) = local(fxa, fxd, cx, g.nx, mid);
            let (j, v0, v1) = local(fya, fyd, cy, g.ny, mid);
            let q = j * g.nx + i;
            let (z00, z10, z01, z11) = (self.z[q], self.z[q + 1], self.z[q + g.nx], self.z[q + g.nx + 1]);
            let (bx, cy_, dxy) = (z10 - z00, z01 - z00, z11 - z10 - z01 + z00);
            // h = z00 + bx u + cy v + dxy u v, so g = z - h has these s and s^2 coefficients.
            let g1 = d.z - (bx * u1 + cy_ * v1 + dxy * (u0 * v1 + u1 * v0));
            let g2 = -dxy * u1 * v1;
            if g2 > 0.0 {
                best = best.min(clearance((-g1 / (2.0 * g2)).clamp(lo, hi)));
            }
        }
        Some(best)
    }
}

impl Terrain {
    /// The exact minimum of z - h along p(s) = a + (b - a) s for s in [s0, s1], where the
    /// terrain can give it cheaply (grids, over stretches within 2 x 2 cells); `None` otherwise.
    pub fn exact_min_clearance(&self, a: Vec3, b: Vec3, s0: f64, s1: f64) -> Option<f64> {
        match self {
            Terrain::Grid(g) => g.min_clearance_on(a, b, s0, s1),
            _ => None,
        }
    }

    /// Seabed elevation at (x, y); `-inf` when there is no seabed.
    #[inline]
    pub fn elevation(&self, x: f64, y: f64) -> f64 {
        match self {
            Terrain::None => f64::NEG_INFINITY,
            Terrain::Peaks(p) => p.elevation(x, y),
            Terrain::Grid(g) => g.grid.bilinear(&g.z, x, y),
        }
    }

    /// An upper bound of the elevation over the rectangle [x0, x1] x [y0, y1] (x0 <= x1,
    /// y0 <= y1). Never below the true maximum; tight as the rectangle shrinks to a point.
    #[inline]
    pub fn max_elevation_in(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        match self {
            Terrain::None => f64::NEG_INFINITY,
            Terrain::Peaks(p) => p.max_in(x0, y0, x1, y1),
            Terrain::Grid(g) => g.max_in(x0, y0, x1, y1),
        }
    }

    /// The horizontal length over which the seabed shape changes appreciably (the narrowest
    /// peak width or the finer grid spacing); `None` for a flat or absent seabed. Segment
    /// queries scale their subdivision resolution by it.
    pub fn feature_length(&self) -> Option<f64> {
        match self {
            Terrain::None => None,
            Terrain::Peaks(p) => p.min_sigma(),
            Terrain::Grid(g) => Some(g.grid.dx.min(g.grid.dy)),
        }
    }

    /// The elevation at (x, y) and the smooth surface that [`Terrain::concavity_bound`]
    /// applies to, which is never below the elevation: for peaks the sum without the ceiling
    /// (the cap only lowers the seabed), otherwise the elevation itself.
    #[inline]
    pub fn elevation_with_smooth(&self, x: f64, y: f64) -> (f64, f64) {
        match self {
            Terrain::Peaks(p) => {
                let u = p.uncapped(x, y);
                (p.ceiling.map_or(u, |c| u.min(c)), u)
            }
            _ => {
                let h = self.elevation(x, y);
                (h, h)
            }
        }
    }

    /// An upper bound of minus the second derivative (per metre squared), along any
    /// horizontal line, of the smooth surface of [`Terrain::elevation_with_smooth`]: how
    /// sharply it can curve downward. `None` where there is no such bound (grids have creases
    /// at cell edges).
    ///
    /// Over a stretch of segment the clearance to a surface that curves down by at most K can
    /// sag below the chord between two samples by at most K/8 times the squared length, so
    /// segment queries get a second-order lower bound that converges far faster than the
    /// rectangle bound along stretches that follow the seabed closely.
    pub fn concavity_bound(&self) -> Option<f64> {
        match self {
            Terrain::Peaks(p) => Some(p.max_concavity()),
            _ => None,
        }
    }

    /// A magnitude of the elevations (largest |z| or relief, whichever is bigger), used to turn
    /// relative tolerances into absolute ones; 0 without a seabed.
    pub fn vertical_scale(&self) -> f64 {
        match self {
            Terrain::None => 0.0,
            Terrain::Peaks(p) => {
                let relief: f64 = p.peaks.iter().map(|q| q.height.abs()).sum();
                let s = p.base.abs() + relief;
                if s.is_finite() {
                    s
                } else {
                    0.0
                }
            }
            Terrain::Grid(g) => g.z_min.abs().max(g.z_max.abs()).max(g.z_max - g.z_min),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn one_peak(ceiling: Option<f64>) -> Terrain {
        Terrain::Peaks(GaussianPeaks {
            base: -100.0,
            peaks: vec![Peak { x: 10.0, y: 20.0, height: 40.0, sigma_x: 2.0, sigma_y: 5.0 }],
            ceiling,
        })
    }

    #[test]
    fn peak_elevation_at_centre_and_one_sigma() {
        let t = one_peak(None);
        assert_eq!(t.elevation(10.0, 20.0), -60.0);
        // One sigma east: -100 + 40 / e.
        let e1 = -100.0 + 40.0 * (-1.0f64).exp();
        assert!((t.elevation(12.0, 20.0) - e1).abs() < 1e-12);
        // One sigma in both directions: -100 + 40 / e^2.
        let e2 = -100.0 + 40.0 * (-2.0f64).exp();
        assert!((t.elevation(8.0, 25.0) - e2).abs() < 1e-12);
        // Far away: the base.
        assert!((t.elevation(1e4, 20.0) + 100.0).abs() < 1e-12);
    }

    #[test]
    fn ceiling_caps_elevation_and_bound() {
        let t = one_peak(Some(-70.0));
        assert_eq!(t.elevation(10.0, 20.0), -70.0);
        assert_eq!(t.max_elevation_in(0.0, 0.0, 50.0, 50.0), -70.0);
        // Below the cap the peak is untouched: at 2 sigma_x, -100 + 40 e^-4 < -70.
        let v = -100.0 + 40.0 * (-4.0f64).exp();
        assert!((t.elevation(14.0, 20.0) - v).abs() < 1e-12);
    }

    #[test]
    fn paper_k_parametrisation_sets_width_from_centre() {
        // x_j = 10, k_x = 5 -> sigma_x = 2; y_j = 20, k_y = 4 -> sigma_y = 5.
        let p = Peak::from_paper_k(10.0, 20.0, 40.0, 5.0, 4.0, "t").unwrap();
        assert_eq!((p.sigma_x, p.sigma_y), (2.0, 5.0));
        let g = GaussianPeaks::from_paper_k(1.0, &[[10.0, 20.0, 40.0, 5.0, 4.0]], Some(30.0), "t").unwrap();
        assert_eq!(g.peaks[0], p);
        assert_eq!(g.ceiling, Some(30.0));
        assert!(Peak::from_paper_k(-1.0, 20.0, 1.0, 1.0, 1.0, "t").is_err());
        assert!(Peak::from_paper_k(1.0, 20.0, 1.0, 0.0, 1.0, "t").is_err());
        let err = GaussianPeaks::from_paper_k(0.0, &[[1.0, 1.0, 1.0, 1.0, 1.0], [0.0, 1.0, 1.0, 1.0, 1.0]], None, "t")
            .unwrap_err()
            .to_string();
        assert!(err.contains("t.peaks[1]"), "{err}");
    }

    #[test]
    fn seabed_eq11_matches_paper_formula() {
        let (x0, y0, h, a, b, s) = (3.0, 4.0, 7.0, 0.8, 1.3, 2.0);
        let p = Peak::from_seabed_eq11(x0, y0, h, a, b, s, "t").unwrap();
        let t = Terrain::Peaks(GaussianPeaks { base: 0.0, peaks: vec![p], ceiling: None });
        let (x, y): (f64, f64) = (4.1, 2.5);
        let want = h * (-((y - y0).powi(2) * a * a + (x - x0).powi(2) * b * b) / (2.0 * s * s)).exp();
        assert!((t.elevation(x, y) - want).abs() < 1e-12);
    }

    fn small_grid() -> Terrain {
        // Nodes: (10,20)=1 (12,20)=3 (14,20)=5 ; (10,24)=2 (12,24)=6 (14,24)=4
        let g = RegularGrid2::new(10.0, 20.0, 2.0, 4.0, 3, 2, "g").unwrap();
        Terrain::Grid(ElevationGrid::new(g, vec![1.0, 3.0, 5.0, 2.0, 6.0, 4.0], "g").unwrap())
    }

    #[test]
    fn grid_elevation_is_bilinear() {
        let t = small_grid();
        assert_eq!(t.elevation(12.0, 24.0), 6.0);
        assert!((t.elevation(11.0, 22.0) - 3.0).abs() < 1e-12);
        assert!((t.elevation(13.0, 21.0) - 4.25).abs() < 1e-12);
        // Outside: clamped to the edge.
        assert_eq!(t.elevation(-5.0, 100.0), 2.0);
    }

    #[test]
    fn grid_bound_is_exact_on_small_rectangles_and_clamps_outside() {
        let t = small_grid();
        let tol = 1e-12;
        // Whole grid: the highest node.
        assert!((t.max_elevation_in(0.0, 0.0, 100.0, 100.0) - 6.0).abs() < tol);
        // First cell, lower half (v in [0, 0.5]): corners 1, 3, 1.5, 4.5 -> 4.5.
        assert!((t.max_elevation_in(10.0, 20.0, 12.0, 22.0) - 4.5).abs() < tol);
        // A point: its own value.
        assert!((t.max_elevation_in(13.0, 21.0, 13.0, 21.0) - 4.25).abs() < tol);
        // Entirely west of the grid: the west edge, nodes 1 and 2.
        assert!((t.max_elevation_in(-50.0, 0.0, -40.0, 100.0) - 2.0).abs() < tol);
    }

    #[test]
    fn grid_rejects_bad_values() {
        let g = RegularGrid2::new(0.0, 0.0, 1.0, 1.0, 2, 2, "g").unwrap();
        let err = ElevationGrid::new(g.clone(), vec![0.0; 3], "terrain").unwrap_err().to_string();
        assert!(err.contains("terrain.elevations") && err.contains('3'), "{err}");
        let err = ElevationGrid::new(g, vec![0.0, 1.0, f64::NAN, 2.0], "terrain").unwrap_err().to_string();
        assert!(err.contains("terrain.elevations") && err.contains("value 2") && err.contains("NaN"), "{err}");
    }

    /// Dense sampling of the rectangle (including its corners and edges) must never find a point
    /// above the bound.
    fn check_bound_against_samples(t: &Terrain, rng: &mut ChaCha8Rng, lo: (f64, f64), hi: (f64, f64)) {
        for _ in 0..300 {
            let (xa, xb) = (rng.random_range(lo.0..hi.0), rng.random_range(lo.0..hi.0));
            let (ya, yb) = (rng.random_range(lo.1..hi.1), rng.random_range(lo.1..hi.1));
            // Mix large and tiny rectangles.
            let shrink = if rng.random_bool(0.3) { 1e-3 } else { 1.0 };
            let (x0, x1) = (xa.min(xb), xa.min(xb) + (xa - xb).abs() * shrink);
            let (y0, y1) = (ya.min(yb), ya.min(yb) + (ya - yb).abs() * shrink);
            let bound = t.max_elevation_in(x0, y0, x1, y1);
            let n = 40;
            let mut sampled = f64::NEG_INFINITY;
            for i in 0..=n {
                for j in 0..=n {
                    let x = x0 + (x1 - x0) * i as f64 / n as f64;
                    let y = y0 + (y1 - y0) * j as f64 / n as f64;
                    sampled = sampled.max(t.elevation(x.min(x1), y.min(y1)));
                }
            }
            assert!(bound >= sampled, "bound {bound} < sampled {sampled} on [{x0}, {x1}] x [{y0}, {y1}]");
        }
    }

    #[test]
    fn peak_bound_never_below_dense_samples() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        for _ in 0..20 {
            let peaks = (0..rng.random_range(1..6))
                .map(|_| Peak {
                    x: rng.random_range(0.0..100.0),
                    y: rng.random_range(0.0..100.0),
                    height: rng.random_range(-40.0..40.0),
                    sigma_x: rng.random_range(2.0..20.0),
                    sigma_y: rng.random_range(2.0..20.0),
                })
                .collect();
            let ceiling = rng.random_bool(0.3).then(|| rng.random_range(-60.0..-20.0));
            let t = Terrain::Peaks(GaussianPeaks { base: -50.0, peaks, ceiling });
            check_bound_against_samples(&t, &mut rng, (-20.0, -20.0), (120.0, 120.0));
        }
    }

    #[test]
    fn grid_bound_never_below_dense_samples() {
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        for _ in 0..20 {
            let (nx, ny) = (rng.random_range(2..40), rng.random_range(2..40));
            let g = RegularGrid2::new(-5.0, 3.0, rng.random_range(0.5..5.0), rng.random_range(0.5..5.0), nx, ny, "g")
                .unwrap();
            let z = (0..nx * ny).map(|_| rng.random_range(-100.0..-10.0)).collect();
            let (xm, ym) = (g.x_max(), g.y_max());
            let t = Terrain::Grid(ElevationGrid::new(g, z, "g").unwrap());
            check_bound_against_samples(&t, &mut rng, (-20.0, -10.0), (xm + 10.0, ym + 10.0));
        }
    }

    #[test]
    fn grid_exact_min_clearance_matches_dense_sampling() {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        let g = RegularGrid2::new(0.0, 0.0, 2.0, 3.0, 6, 5, "g").unwrap();
        let z: Vec<f64> = (0..30).map(|_| rng.random_range(-50.0..-10.0)).collect();
        let t = Terrain::Grid(ElevationGrid::new(g, z, "g").unwrap());
        let mut settled = 0;
        for _ in 0..500 {
            // Short segments (some leaving the grid) so that many fit in 2 x 2 cells.
            let a = Vec3::new(rng.random_range(-2.0..12.0), rng.random_range(-2.0..14.0), rng.random_range(-40.0..0.0));
            let b =
                a + Vec3::new(rng.random_range(-3.0..3.0), rng.random_range(-4.0..4.0), rng.random_range(-5.0..5.0));
            let Some(m) = t.exact_min_clearance(a, b, 0.0, 1.0) else { continue };
            settled += 1;
            let n = 4000;
            let sampled = (0..=n)
                .map(|k| {
                    let p = a + (b - a) * (k as f64 / n as f64);
                    p.z - t.elevation(p.x, p.y)
                })
                .fold(f64::INFINITY, f64::min);
            // Exact minimum: never above a sample, and samples 1/4000 apart come within the
            // clearance's change over half a step.
            let step = (b - a).length() * (1.0 + 20.0) / n as f64;
            assert!(m <= sampled + 1e-12 && m >= sampled - step, "exact {m} vs sampled {sampled}");
        }
        assert!(settled > 100, "only {settled} segments settled exactly");
    }

    #[test]
    fn bounds_shrink_to_the_point_value() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let t = one_peak(None);
        let g = RegularGrid2::new(0.0, 0.0, 1.0, 1.0, 5, 5, "g").unwrap();
        let grid = Terrain::Grid(ElevationGrid::new(g, (0..25).map(|k| (k * 7 % 11) as f64).collect(), "g").unwrap());
        for t in [&t, &grid] {
            for _ in 0..100 {
                let (x, y) = (rng.random_range(0.0..4.0), rng.random_range(0.0..4.0));
                let h = 1e-7;
                let gap = t.max_elevation_in(x, y, x + h, y + h) - t.elevation(x, y);
                assert!((0.0..1e-5).contains(&gap), "gap {gap} at ({x}, {y})");
            }
        }
    }

    #[test]
    fn no_terrain_is_minus_infinity() {
        assert_eq!(Terrain::None.elevation(1.0, 2.0), f64::NEG_INFINITY);
        assert_eq!(Terrain::None.max_elevation_in(0.0, 0.0, 1.0, 1.0), f64::NEG_INFINITY);
    }
}
