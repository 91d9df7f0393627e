//! Gridded significant wave height: layers on a regular grid, bilinear in space, linear in time.

use crate::error::{Error, Result};
use crate::geom::Aabb;
use crate::world::grid::RegularGrid2;
use crate::world::node_gaps::{check_layers, check_times, lerp2, time_bracket, NodeGaps};

/// Heights (m) on a regular grid at a list of times.
///
/// Build it with `WaveGrid::new`: `height` relies on its checks (at least one layer, every
/// layer full, finite and not negative) and does not repeat them.
#[derive(Clone, Debug, PartialEq)]
pub struct WaveGrid {
    pub grid: RegularGrid2,
    /// Strictly increasing times (s) of the layers.
    pub times: Vec<f64>,
    /// One row-major layer of heights per time.
    pub heights: Vec<Vec<f64>>,
    /// Nodes without data (land or fill in the source file); their height is 0 so
    /// interpolation stays finite, and a glider's motion through their cells is invalid.
    pub gaps: NodeGaps,
}

impl WaveGrid {
    /// Checks the layers; `field` names the scenario field for error messages, which give the
    /// offending layer, node and value.
    pub fn new(grid: RegularGrid2, times: Vec<f64>, heights: Vec<Vec<f64>>, field: &str) -> Result<Self> {
        check_times(&times, field)?;
        let name = format!("{field}.height");
        check_layers(&heights, times.len(), &grid, &name)?;
        for (l, layer) in heights.iter().enumerate() {
            if let Some(k) = layer.iter().position(|&h| h < 0.0) {
                return Err(Error::input(
                    name,
                    format!(
                        "layer {l}, value {k} (node i = {}, j = {}) is {}; a wave height cannot be negative",
                        k % grid.nx,
                        k / grid.nx,
                        layer[k]
                    ),
                ));
            }
        }
        Ok(Self { grid, times, heights, gaps: NodeGaps::default() })
    }

    /// Marks `nodes` (row-major indices, any order) as having no data.
    pub fn with_gaps(mut self, nodes: Vec<usize>, field: &str) -> Result<Self> {
        self.gaps = NodeGaps::new(nodes, &self.grid, field)?;
        Ok(self)
    }

    /// True when the field has one time layer.
    pub fn is_steady(&self) -> bool {
        self.times.len() == 1
    }

    /// Height at (x, y) and time t (s). Outside the grid the edge values hold; outside the
    /// time range the nearest layer.
    #[inline]
    pub fn height(&self, x: f64, y: f64, t: f64) -> f64 {
        let g = &self.grid;
        let (i, j, fu, fv) = g.locate(x, y);
        let k = j * g.nx + i;
        let (l0, l1, w) = time_bracket(&self.times, t);
        let h = lerp2(&self.heights[l0], k, g.nx, fu, fv);
        if w > 0.0 {
            h + (lerp2(&self.heights[l1], k, g.nx, fu, fv) - h) * w
        } else {
            h
        }
    }

    /// The largest node height over every layer.
    pub fn height_bound(&self) -> f64 {
        self.heights.iter().flatten().fold(0.0, |m, &h| m.max(h))
    }

    /// Smallest and largest height over the nodes with data of the cells touching `bounds`, at
    /// any time.
    pub(super) fn range(&self, bounds: &Aabb) -> (f64, f64) {
        let g = &self.grid;
        let (i0, j0, _, _) = g.locate(bounds.min.x, bounds.min.y);
        let (i1, j1, _, _) = g.locate(bounds.max.x, bounds.max.y);
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for layer in &self.heights {
            for j in j0..=(j1 + 1) {
                for i in i0..=(i1 + 1) {
                    let k = j * g.nx + i;
                    if !self.gaps.contains(&k) {
                        lo = lo.min(layer[k]);
                        hi = hi.max(layer[k]);
                    }
                }
            }
        }
        if lo > hi {
            (0.0, 0.0)
        } else {
            (lo, hi)
        }
    }
}
