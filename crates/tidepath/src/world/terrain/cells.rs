//! Seabed given cell by cell (scenario terrain `kind = "cells"`): one elevation per square
//! cell, constant inside it, as in occupancy grids and the grid worlds of acopf2016.
//!
//! Cells are open squares and the elevation on an edge or corner is the lowest of the cells
//! that meet there: touching a land cell's edge is not entering it, so a route may run along a
//! coast of cells, and the water cells of a map are usable up to their edges (a raster at the
//! map's own resolution sees exactly the map). Every query is exact: the elevation is
//! piecewise constant, so along a segment the clearance is least at the ends of the stretch
//! inside each cell, and a walk over the cells the segment crosses (at most nx + ny) finds it.

use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::world::grid::{walk_cells, EDGE_TOL};

/// Above this many cells a rectangle's upper bound is the grid's highest cell (still an upper
/// bound); the segment walk settles what it leaves open.
const SCAN_LIMIT: usize = 4096;

#[derive(Clone, Debug)]
pub struct CellGrid {
    /// South-west corner of cell (0, 0).
    pub x0: f64,
    pub y0: f64,
    /// Cell sides (m).
    pub dx: f64,
    pub dy: f64,
    pub nx: usize,
    pub ny: usize,
    /// Cell elevations, row-major from the south-west: cell (i, j) is `z[j * nx + i]`.
    pub z: Vec<f64>,
    pub(super) z_min: f64,
    pub(super) z_max: f64,
}

impl CellGrid {
    /// Checks sizes and values; `field` names the scenario field for error messages.
    pub fn new(origin: [f64; 2], size: [f64; 2], shape: [usize; 2], z: Vec<f64>, field: &str) -> Result<Self> {
        let [nx, ny] = shape;
        if nx == 0 || ny == 0 {
            return Err(Error::input(field, format!("needs at least one cell, got {nx} x {ny}")));
        }
        if nx.checked_mul(ny) != Some(z.len()) {
            return Err(Error::input(field, format!("{nx} x {ny} cells need {} values, got {}", nx * ny, z.len())));
        }
        for (name, v) in [("cell_size", size[0]), ("cell_size", size[1])] {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::input(format!("{field}.{name}"), format!("must be positive and finite, got {v}")));
            }
        }
        if let Some((k, v)) = z.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(Error::input(
                field,
                format!("cell {k} (column {}, row {} from the south) must be finite, got {v}", k % nx, k / nx),
            ));
        }
        let z_min = z.iter().copied().fold(f64::INFINITY, f64::min);
        let z_max = z.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Ok(Self { x0: origin[0], y0: origin[1], dx: size[0], dy: size[1], nx, ny, z, z_min, z_max })
    }

    /// Position in cell units along x and y, clamped to the grid (edge cells hold beyond it).
    #[inline]
    fn units(&self, x: f64, y: f64) -> (f64, f64) {
        (((x - self.x0) / self.dx).clamp(0.0, self.nx as f64), ((y - self.y0) / self.dy).clamp(0.0, self.ny as f64))
    }

    /// The cells along one axis whose closure holds coordinate f (cell units): two on an
    /// inner edge, else one.
    #[inline]
    fn holding(f: f64, n: usize) -> (usize, usize) {
        let k = f.round();
        if (f - k).abs() <= EDGE_TOL {
            let k = k as usize;
            (k.saturating_sub(1), k.min(n - 1))
        } else {
            let i = (f.floor() as usize).min(n - 1);
            (i, i)
        }
    }

    /// The cells along one axis whose interior meets [f0, f1] (f0 < f1), or that hold the
    /// point when f0 = f1.
    #[inline]
    fn meeting_interior(f0: f64, f1: f64, n: usize) -> (usize, usize) {
        if f1 - f0 <= EDGE_TOL {
            return Self::holding(f0, n);
        }
        let lo = ((f0 + EDGE_TOL).floor().max(0.0) as usize).min(n - 1);
        let hi = (((f1 - EDGE_TOL).ceil() - 1.0).max(0.0) as usize).min(n - 1);
        (lo, hi.max(lo))
    }

    /// The cells along one axis whose closure meets [f0, f1].
    #[inline]
    fn meeting_closure(f0: f64, f1: f64, n: usize) -> (usize, usize) {
        (Self::holding(f0, n).0, Self::holding(f1, n).1)
    }

    fn fold(&self, (i0, i1): (usize, usize), (j0, j1): (usize, usize), init: f64, f: fn(f64, f64) -> f64) -> f64 {
        // NaN coordinates (a hostile input) must not reverse a range.
        let (i0, i1) = (i0.min(i1), i0.max(i1));
        let (j0, j1) = (j0.min(j1), j0.max(j1));
        let mut m = init;
        for j in j0..=j1 {
            for &v in &self.z[j * self.nx + i0..=j * self.nx + i1] {
                m = f(m, v);
            }
        }
        m
    }

    /// Elevation at (x, y): the cell's, or on an edge or corner the lowest of the cells there.
    pub fn elevation(&self, x: f64, y: f64) -> f64 {
        let (fx, fy) = self.units(x, y);
        self.fold(Self::holding(fx, self.nx), Self::holding(fy, self.ny), f64::INFINITY, f64::min)
    }

    /// The exact maximum over the closed rectangle (x0 <= x1, y0 <= y1) where it spans at most
    /// a few thousand cells, else the grid's highest cell.
    pub fn max_in(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        let (fx0, fy0) = self.units(x0.min(x1), y0.min(y1));
        let (fx1, fy1) = self.units(x0.max(x1), y0.max(y1));
        let (ci, cj) = (Self::meeting_interior(fx0, fx1, self.nx), Self::meeting_interior(fy0, fy1, self.ny));
        // A point or a line: an upper bound from every cell holding it.
        let (ci, cj) = if fx1 - fx0 <= EDGE_TOL || fy1 - fy0 <= EDGE_TOL {
            (Self::meeting_closure(fx0, fx1, self.nx), Self::meeting_closure(fy0, fy1, self.ny))
        } else {
            (ci, cj)
        };
        if (ci.1 - ci.0 + 1) * (cj.1 - cj.0 + 1) > SCAN_LIMIT {
            return self.z_max;
        }
        self.fold(ci, cj, f64::NEG_INFINITY, f64::max)
    }

    /// The exact minimum over the closed rectangle: every cell whose closure meets it counts,
    /// since its edges take the lowest neighbouring value.
    pub fn min_in(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        let (fx0, fy0) = self.units(x0.min(x1), y0.min(y1));
        let (fx1, fy1) = self.units(x0.max(x1), y0.max(y1));
        let (ci, cj) = (Self::meeting_closure(fx0, fx1, self.nx), Self::meeting_closure(fy0, fy1, self.ny));
        if (ci.1 - ci.0 + 1) * (cj.1 - cj.0 + 1) > SCAN_LIMIT {
            return self.z_min;
        }
        self.fold(ci, cj, f64::INFINITY, f64::min)
    }

    /// The minimum of z - h along p(s) = a + (b - a) s for s in [s0, s1]: the stretch is cut
    /// where it crosses cell edges, and on each cut z is linear and h constant, so the least
    /// clearance is at a cut's end against the cut's elevation (taken at its midpoint, which
    /// is on an edge only when the segment runs along one). The infimum where a cut meets a
    /// lower edge is counted, so the answer never overstates the clearance.
    pub fn min_clearance_on(&self, a: Vec3, b: Vec3, s0: f64, s1: f64) -> f64 {
        let point = |s: f64| a + (b - a) * s;
        let (ua, va) = ((a.x - self.x0) / self.dx, (a.y - self.y0) / self.dy);
        let (du, dv) = ((b.x - a.x) / self.dx, (b.y - a.y) / self.dy);
        let mut best = f64::INFINITY;
        let mut reached = s0;
        let walked = walk_cells((ua, du), (va, dv), (self.nx - 1, self.ny - 1), (s0, s1), |s, e| {
            let (pa, pe) = (point(s), point(e));
            let mid = point(0.5 * (s + e));
            best = best.min(pa.z.min(pe.z) - self.elevation(mid.x, mid.y));
            reached = e;
            false
        });
        if walked.is_some() {
            return best;
        }
        let s = reached;
        // Only rounding could stall the walk: bound the rest by the highest cell.
        best.min(point(s).z.min(point(s1).z) - self.z_max)
    }
}
