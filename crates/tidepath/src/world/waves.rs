//! Significant wave height on a regular grid (the wave glider's propulsion, seed 004).
//!
//! A wave glider turns wave motion into thrust, so the height field is its "fuel map". The
//! field is steady: seed 004's environments are, and layers in time (as `CurrentGrid` has)
//! are a later extension that will not change `height`'s signature, which already takes t.

use super::grid::RegularGrid2;
use crate::error::{Error, Result};

#[derive(Clone, Debug, PartialEq)]
pub struct WaveField {
    pub grid: RegularGrid2,
    /// Significant wave height (m) at the nodes, row-major.
    pub heights: Vec<f64>,
}

impl WaveField {
    /// Checks that there is one finite, non-negative height per node; `field` names the
    /// scenario field for error messages, which give the offending node and value.
    pub fn new(grid: RegularGrid2, heights: Vec<f64>, field: &str) -> Result<Self> {
        let name = format!("{field}.heights");
        if heights.len() != grid.len() {
            return Err(Error::input(
                name,
                format!("has {} values; the grid has {} x {} = {} nodes", heights.len(), grid.nx, grid.ny, grid.len()),
            ));
        }
        if let Some(k) = heights.iter().position(|h| !(h.is_finite() && *h >= 0.0)) {
            return Err(Error::input(
                name,
                format!(
                    "value {k} (node i = {}, j = {}) is {}; must be finite and non-negative",
                    k % grid.nx,
                    k / grid.nx,
                    heights[k]
                ),
            ));
        }
        Ok(Self { grid, heights })
    }

    /// A height that is `h_flat` up to `x_flat_end`, changes linearly to `h_end` at `x_end` and
    /// stays there: seed 004's environments 2 and 3 (ALGORITHMS.md 5.5, Chosen 2.0 m up to
    /// x = 10 falling to 0.5 m at x = 20, in the scenario's length unit).
    ///
    /// The profile is sampled at the nodes, so it is reproduced exactly only when both break
    /// points fall on node columns; otherwise each kink is smoothed across one cell.
    pub fn ramp_in_x(
        grid: RegularGrid2,
        x_flat_end: f64,
        h_flat: f64,
        x_end: f64,
        h_end: f64,
        field: &str,
    ) -> Result<Self> {
        if !(x_flat_end.is_finite() && x_end.is_finite() && x_end > x_flat_end) {
            return Err(Error::input(
                format!("{field}.ramp"),
                format!("needs finite x_flat_end < x_end, got {x_flat_end} and {x_end}"),
            ));
        }
        let mut heights = Vec::with_capacity(grid.len());
        for j in 0..grid.ny {
            for i in 0..grid.nx {
                let (x, _) = grid.node(i, j);
                let s = ((x - x_flat_end) / (x_end - x_flat_end)).clamp(0.0, 1.0);
                heights.push(h_flat + (h_end - h_flat) * s);
            }
        }
        Self::new(grid, heights, field)
    }

    /// Significant wave height (m) at (x, y) and time t (s); bilinear between nodes and the
    /// edge value outside the grid. `t` is unused until the field gets layers in time.
    #[inline]
    pub fn height(&self, x: f64, y: f64, t: f64) -> f64 {
        let _ = t;
        self.grid.bilinear(&self.heights, x, y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid() -> RegularGrid2 {
        // Nodes x = 10, 12, 14; y = 20, 24.
        RegularGrid2::new(10.0, 20.0, 2.0, 4.0, 3, 2, "g").unwrap()
    }

    #[test]
    fn height_is_bilinear() {
        let w = WaveField::new(grid(), vec![1.0, 3.0, 5.0, 2.0, 6.0, 4.0], "waves").unwrap();
        // Nodes are reproduced.
        assert_eq!(w.height(12.0, 24.0, 0.0), 6.0);
        // (13, 21): u = 0.5, v = 0.25 in cell (1, 0): lo = (3 + 5) / 2 = 4, hi = (6 + 4) / 2 = 5,
        // height 4 + 0.25 (5 - 4) = 4.25.
        assert!((w.height(13.0, 21.0, 0.0) - 4.25).abs() < 1e-12);
        // Centre of the first cell: mean of 1, 3, 2, 6.
        assert!((w.height(11.0, 22.0, 0.0) - 3.0).abs() < 1e-12);
        // Steady in time, edge value outside.
        assert_eq!(w.height(13.0, 21.0, 1e6), w.height(13.0, 21.0, 0.0));
        assert_eq!(w.height(100.0, 100.0, 0.0), 4.0);
    }

    #[test]
    fn rejects_negative_nan_and_wrong_length() {
        let e = WaveField::new(grid(), vec![1.0, 1.0, -0.5, 1.0, 1.0, 1.0], "waves").unwrap_err();
        let msg = e.to_string();
        assert!(msg.starts_with("waves.heights") && msg.contains("value 2") && msg.contains("-0.5"), "{msg}");
        assert!(WaveField::new(grid(), vec![1.0, 1.0, 1.0, 1.0, f64::NAN, 1.0], "waves").is_err());
        assert!(WaveField::new(grid(), vec![1.0, f64::INFINITY, 1.0, 1.0, 1.0, 1.0], "waves").is_err());
        let e = WaveField::new(grid(), vec![1.0; 5], "waves").unwrap_err();
        assert!(e.to_string().contains("has 5 values"), "{e}");
    }

    #[test]
    fn ramp_in_x_matches_seed_004_profile() {
        // Nodes every 2.5 from 0 to 25: break points 10 and 20 fall on nodes.
        let g = RegularGrid2::new(0.0, 0.0, 2.5, 1.0, 11, 3, "g").unwrap();
        let w = WaveField::ramp_in_x(g, 10.0, 2.0, 20.0, 0.5, "waves").unwrap();
        for (x, h) in [(0.0, 2.0), (7.3, 2.0), (10.0, 2.0), (15.0, 1.25), (17.5, 0.875), (20.0, 0.5), (25.0, 0.5)] {
            assert!((w.height(x, 1.3, 0.0) - h).abs() < 1e-12, "x = {x}: {}", w.height(x, 1.3, 0.0));
        }
        assert!(WaveField::ramp_in_x(grid(), 20.0, 2.0, 10.0, 0.5, "waves").is_err());
        assert!(WaveField::ramp_in_x(grid(), 10.0, -2.0, 20.0, 0.5, "waves").is_err());
    }
}
