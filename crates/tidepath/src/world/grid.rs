//! A regular 2-D grid of nodes and bilinear interpolation on it, shared by the elevation,
//! current and wave fields so they all sample space the same way.

use crate::error::{Error, Result};

/// Most nodes a grid may have: 2^28 (2 GiB of f64 values), far beyond any scenario file and
/// any sensible in-memory subset of a bathymetry file.
pub const MAX_NODES: usize = 1 << 28;

/// Within this distance (in cells) of a cell edge a coordinate counts as on it, so that a walk
/// over cells never gets stuck on an edge it computed in floating point.
pub const EDGE_TOL: f64 = 1e-9;

/// Walks the line (u0 + du s, v0 + dv s), in cell units, over s in [s0, s1] cell by cell:
/// `stretch(s, e)` is called for each stretch between two crossings of the cell edges
/// u = 1..=edges_u and v = 1..=edges_v (beyond the outer edges the edge cells extend), in
/// order, until it returns `true`. Returns `Some(true)` if it did, `Some(false)` at the end,
/// and `None` with the walk stalled by rounding (at most edges_u + edges_v + 4 steps), in which
/// case the caller must judge the rest conservatively.
pub(crate) fn walk_cells(
    (u0, du): (f64, f64),
    (v0, dv): (f64, f64),
    (edges_u, edges_v): (usize, usize),
    (s0, s1): (f64, f64),
    mut stretch: impl FnMut(f64, f64) -> bool,
) -> Option<bool> {
    // The next parameter past s where the line crosses an edge along one axis.
    let next = |p: f64, d: f64, s: f64, last: usize| {
        let c = p + d * s;
        let line = if d > 0.0 {
            ((c + EDGE_TOL).floor() + 1.0).max(1.0)
        } else if d < 0.0 {
            ((c - EDGE_TOL).ceil() - 1.0).min(last as f64)
        } else {
            return f64::INFINITY;
        };
        if line < 1.0 || line > last as f64 {
            return f64::INFINITY;
        }
        (line - p) / d
    };
    let mut s = s0;
    for _ in 0..(edges_u + edges_v + 4) {
        let e = next(u0, du, s, edges_u).min(next(v0, dv, s, edges_v)).min(s1).max(s);
        if stretch(s, e) {
            return Some(true);
        }
        if e >= s1 {
            return Some(false);
        }
        s = e;
    }
    None
}

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
