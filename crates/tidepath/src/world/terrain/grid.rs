//! Gridded seabed: bilinear elevations with a max-pyramid for bound queries and the exact
//! minimum clearance over short stretches.

use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::world::grid::RegularGrid2;

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
    pub(super) z_min: f64,
    pub(super) z_max: f64,
}

#[derive(Clone, Debug)]
struct MaxLevel {
    nx: usize,
    ny: usize,
    max: Vec<f64>,
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

    /// The minimum over a rectangle, exactly: inside each grid cell the surface is bilinear,
    /// so its minimum over the part of the rectangle in that cell sits at a corner of that part.
    /// Points outside the grid see the edge cells, as in `locate`. Cost: one evaluation per
    /// corner of each grid cell the rectangle overlaps.
    pub(super) fn min_in(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        let g = &self.grid;
        let (cx, cy) = ((g.nx - 1) as f64, (g.ny - 1) as f64);
        let fx0 = ((x0.min(x1) - g.x0) / g.dx).clamp(0.0, cx);
        let fx1 = ((x0.max(x1) - g.x0) / g.dx).clamp(0.0, cx);
        let fy0 = ((y0.min(y1) - g.y0) / g.dy).clamp(0.0, cy);
        let fy1 = ((y0.max(y1) - g.y0) / g.dy).clamp(0.0, cy);
        let (i0, i1) = ((fx0 as usize).min(g.nx - 2), (fx1 as usize).min(g.nx - 2));
        let (j0, j1) = ((fy0 as usize).min(g.ny - 2), (fy1 as usize).min(g.ny - 2));
        let mut m = f64::INFINITY;
        for j in j0..=j1 {
            let vl = (fy0 - j as f64).clamp(0.0, 1.0);
            let vh = (fy1 - j as f64).clamp(0.0, 1.0);
            for i in i0..=i1 {
                let ul = (fx0 - i as f64).clamp(0.0, 1.0);
                let uh = (fx1 - i as f64).clamp(0.0, 1.0);
                m = m
                    .min(self.cell_value(i, j, ul, vl))
                    .min(self.cell_value(i, j, uh, vl))
                    .min(self.cell_value(i, j, ul, vh))
                    .min(self.cell_value(i, j, uh, vh));
            }
        }
        // The same rounding allowance as the upper bound, on the safe side.
        m - self.slack
    }

    /// Small rectangles (at most 2 x 2 cells) get the exact maximum: inside a cell the surface is
    /// bilinear, hence linear along each axis, so its max over a sub-rectangle sits at a corner.
    /// That is what makes the bound tight as the rectangle shrinks, which the branch and bound
    /// in the clearance query needs to converge. Larger rectangles read the pyramid.
    pub(super) fn max_in(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
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
    pub(super) fn min_clearance_on(&self, a: Vec3, b: Vec3, s0: f64, s1: f64) -> Option<f64> {
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
