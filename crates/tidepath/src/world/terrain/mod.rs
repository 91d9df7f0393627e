//! The seabed as an elevation function z = h(x, y) (negative below the sea surface).
//!
//! Besides point elevation, each terrain answers a conservative upper bound of the elevation
//! over a rectangle. The segment queries in [`super::query`] use that bound to prove whole
//! stretches of a segment clear in one step and only subdivide near the seabed. Near the seabed
//! they lean on what each terrain knows about itself: peaks bound how sharply they curve down
//! (a second-order bound between samples), grids give the exact minimum clearance along a
//! stretch spanning at most 2 x 2 cells (the surface is bilinear per cell).

mod cells;
mod grid;
mod peaks;

pub use cells::CellGrid;
pub use grid::ElevationGrid;
pub use peaks::{GaussianPeaks, Peak};

use crate::geom::Vec3;

#[derive(Clone, Debug)]
pub enum Terrain {
    /// No seabed inside the domain.
    None,
    Peaks(GaussianPeaks),
    Grid(ElevationGrid),
    /// One elevation per cell, constant inside it (occupancy grids).
    Cells(CellGrid),
}

impl Terrain {
    /// The exact minimum of z - h along p(s) = a + (b - a) s for s in [s0, s1], where the
    /// terrain can give it cheaply (grids, over stretches within 2 x 2 cells); `None` otherwise.
    pub fn exact_min_clearance(&self, a: Vec3, b: Vec3, s0: f64, s1: f64) -> Option<f64> {
        match self {
            Terrain::Grid(g) => g.min_clearance_on(a, b, s0, s1),
            Terrain::Cells(c) => Some(c.min_clearance_on(a, b, s0, s1)),
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
            Terrain::Cells(c) => c.elevation(x, y),
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
            Terrain::Cells(c) => c.max_in(x0, y0, x1, y1),
        }
    }

    /// A cheaper upper bound of [`Terrain::max_elevation_in`]'s value: never below it as
    /// computed (or NaN), so a segment clear of it is clear of the exact bound too. Analytic
    /// peaks have one without exp (above it by at most 1.15 % of a peak's height); `None` for the
    /// others, whose bound is cheap already.
    #[inline]
    pub fn max_elevation_upper(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> Option<f64> {
        match self {
            Terrain::Peaks(p) => Some(p.max_in_upper(x0, y0, x1, y1)),
            _ => None,
        }
    }

    /// A lower bound of the elevation over the closed rectangle [x0, x1] x [y0, y1]: never
    /// above the true minimum. Optimistic rasterisations use it to prove a cell blocked
    /// everywhere.
    pub fn min_elevation_in(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        match self {
            Terrain::None => f64::NEG_INFINITY,
            Terrain::Peaks(p) => p.min_in(x0, y0, x1, y1),
            Terrain::Grid(g) => g.min_in(x0, y0, x1, y1),
            Terrain::Cells(c) => c.min_in(x0, y0, x1, y1),
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
            Terrain::Cells(c) => Some(c.dx.min(c.dy)),
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
            Terrain::Cells(c) => c.z_min.abs().max(c.z_max.abs()).max(c.z_max - c.z_min),
        }
    }
}

#[cfg(test)]
mod tests;
