//! A regular 2-D grid of nodes and bilinear interpolation on it, shared by the elevation,
//! current and wave fields so they all sample space the same way.

use crate::error::{Error, Result};

/// Most nodes a grid may have: 2^28 (2 GiB of f64 values), far beyond any scenario file and
/// any sensible in-memory subset of a bathymetry file.
pub const MAX_NODES: usize = 1 << 28;

/// Node (i, j) sits at (x0 + i dx, y0 + j dy); values are stored row-major by y then x:
/// `values[j * nx + i]`.
#[derive(Clone, Debug, PartialEq)]
pub struct RegularGrid2 {
    pub x0: f64,
    pub y0: f64,
    pub dx: f64,
    pub dy: f64,
    pub nx: usize,
    pub ny: usize,
}

impl RegularGrid2 {
    /// Checks the geometry; `field` names the scenario field for error messages.
    pub fn new(x0: f64, y0: f64, dx: f64, dy: f64, nx: usize, ny: usize, field: &str) -> Result<Self> {
        if !(dx > 0.0 && dx.is_finite() && dy > 0.0 && dy.is_finite()) {
            return Err(Error::input(
                format!("{field}.spacing"),
                format!("must be positive and finite, got [{dx}, {dy}]"),
            ));
        }
        if nx < 2 || ny < 2 {
            return Err(Error::input(
                format!("{field}.shape"),
                format!("needs at least 2 x 2 nodes, got [{nx}, {ny}]"),
            ));
        }
        match nx.checked_mul(ny) {
            Some(n) if n <= MAX_NODES => {}
            _ => {
                return Err(Error::input(
                    format!("{field}.shape"),
                    format!("[{nx}, {ny}] has more than {MAX_NODES} nodes"),
                ));
            }
        }
        if !x0.is_finite() || !y0.is_finite() {
            return Err(Error::input(format!("{field}.origin"), format!("must be finite, got [{x0}, {y0}]")));
        }
        Ok(Self { x0, y0, dx, dy, nx, ny })
    }

    pub fn len(&self) -> usize {
        self.nx * self.ny
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    pub fn x_max(&self) -> f64 {
        self.x0 + self.dx * (self.nx - 1) as f64
    }

    pub fn y_max(&self) -> f64 {
        self.y0 + self.dy * (self.ny - 1) as f64
    }

    pub fn node(&self, i: usize, j: usize) -> (f64, f64) {
        (self.x0 + self.dx * i as f64, self.y0 + self.dy * j as f64)
    }

    /// The cell holding (x, y) and the local coordinates (u, v) in [0, 1] inside it.
    /// Points outside the grid are clamped to its edge (the field is extended as constant).
    #[inline]
    pub fn locate(&self, x: f64, y: f64) -> (usize, usize, f64, f64) {
        let fx = ((x - self.x0) / self.dx).clamp(0.0, (self.nx - 1) as f64);
        let fy = ((y - self.y0) / self.dy).clamp(0.0, (self.ny - 1) as f64);
        let i = (fx as usize).min(self.nx - 2);
        let j = (fy as usize).min(self.ny - 2);
        (i, j, fx - i as f64, fy - j as f64)
    }

    /// Bilinear interpolation of `values` (row-major, `len()` long) at (x, y).
    #[inline]
    pub fn bilinear(&self, values: &[f64], x: f64, y: f64) -> f64 {
        let (i, j, u, v) = self.locate(x, y);
        let k = j * self.nx + i;
        let (a, b) = (values[k], values[k + 1]);
        let (c, d) = (values[k + self.nx], values[k + self.nx + 1]);
        let lo = a + (b - a) * u;
        let hi = c + (d - c) * u;
        lo + (hi - lo) * v
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid() -> RegularGrid2 {
        RegularGrid2::new(10.0, 20.0, 2.0, 4.0, 3, 2, "g").unwrap()
    }

    #[test]
    fn bilinear_matches_hand_computation() {
        // Nodes: (10,20)=1 (12,20)=3 (14,20)=5 ; (10,24)=2 (12,24)=6 (14,24)=4
        let v = [1.0, 3.0, 5.0, 2.0, 6.0, 4.0];
        let g = grid();
        // Corner values are reproduced exactly.
        assert_eq!(g.bilinear(&v, 12.0, 24.0), 6.0);
        // Centre of the first cell: mean of 1, 3, 2, 6 = 3.
        assert!((g.bilinear(&v, 11.0, 22.0) - 3.0).abs() < 1e-12);
        // (13, 21): u = 0.5, v = 0.25 in cell (1, 0): lo = 4, hi = 5, value 4.25.
        assert!((g.bilinear(&v, 13.0, 21.0) - 4.25).abs() < 1e-12);
    }

    #[test]
    fn outside_points_clamp_to_edge() {
        let v = [1.0, 3.0, 5.0, 2.0, 6.0, 4.0];
        let g = grid();
        assert_eq!(g.bilinear(&v, -100.0, 0.0), 1.0);
        assert_eq!(g.bilinear(&v, 100.0, 100.0), 4.0);
    }

    #[test]
    fn rejects_bad_geometry() {
        assert!(RegularGrid2::new(0.0, 0.0, 0.0, 1.0, 3, 3, "g").is_err());
        assert!(RegularGrid2::new(0.0, 0.0, 1.0, 1.0, 1, 3, "g").is_err());
        assert!(RegularGrid2::new(f64::NAN, 0.0, 1.0, 1.0, 3, 3, "g").is_err());
    }
}
