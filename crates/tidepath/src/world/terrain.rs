//! The seabed as an elevation function z = h(x, y) (negative below the sea surface).
//!
//! Besides point elevation, each terrain answers a conservative upper bound of the elevation
//! over a rectangle. The segment queries in [`super::query`] use that bound to prove whole
//! stretches of a segment clear in one step and only subdivide near the seabed.

use super::grid::RegularGrid2;
use crate::error::Result;

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
#[derive(Clone, Debug)]
pub struct ElevationGrid {
    pub grid: RegularGrid2,
    /// Node elevations, row-major (`grid.bilinear` layout).
    pub z: Vec<f64>,
    // Helpers may add private acceleration structures here (e.g. the max pyramid).
}

#[derive(Clone, Debug)]
pub enum Terrain {
    /// No seabed inside the domain.
    None,
    Peaks(GaussianPeaks),
    Grid(ElevationGrid),
}

impl ElevationGrid {
    /// Validates the node count and values (finite) and builds the acceleration structures.
    pub fn new(grid: RegularGrid2, z: Vec<f64>, field: &str) -> Result<Self> {
        let _ = (grid, z, field);
        todo!("geometry helper")
    }
}

impl Terrain {
    /// Seabed elevation at (x, y); `-inf` when there is no seabed.
    pub fn elevation(&self, x: f64, y: f64) -> f64 {
        let _ = (x, y);
        todo!("geometry helper")
    }

    /// An upper bound of the elevation over the rectangle [x0, x1] x [y0, y1] (x0 <= x1,
    /// y0 <= y1). Never below the true maximum; tight as the rectangle shrinks to a point.
    pub fn max_elevation_in(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        let _ = (x0, y0, x1, y1);
        todo!("geometry helper")
    }
}
