//! Gridded currents: u, v layers on a regular grid, interpolated in space and time.

use crate::error::Result;
use crate::geom::{Aabb, Vec3};
use crate::world::grid::RegularGrid2;
use crate::world::node_gaps::{check_layers, check_times, lerp2, time_bracket, NodeGaps};

/// u, v components on a regular grid at a list of times; bilinear in space, linear in time.
///
/// Build it with `CurrentGrid::new`: `velocity` relies on its checks (at least one layer,
/// every layer full) and does not repeat them.
#[derive(Clone, Debug, PartialEq)]
pub struct CurrentGrid {
    pub grid: RegularGrid2,
    /// Strictly increasing times (s) of the layers.
    pub times: Vec<f64>,
    /// One row-major layer per time.
    pub u: Vec<Vec<f64>>,
    pub v: Vec<Vec<f64>>,
    /// Nodes where the forecast has no data (land or fill in the source file); their u, v are
    /// 0 so interpolation stays finite, and [`CurrentGrid::has_data`] tells motions through
    /// them apart, since guessing a current there would be inventing data.
    pub gaps: NodeGaps,
}

impl CurrentGrid {
    /// Checks the layers; `field` names the scenario field for error messages, which give the
    /// offending layer, node and value so a broken data file can be found.
    pub fn new(grid: RegularGrid2, times: Vec<f64>, u: Vec<Vec<f64>>, v: Vec<Vec<f64>>, field: &str) -> Result<Self> {
        check_times(&times, field)?;
        check_layers(&u, times.len(), &grid, &format!("{field}.u"))?;
        check_layers(&v, times.len(), &grid, &format!("{field}.v"))?;
        Ok(Self { grid, times, u, v, gaps: NodeGaps::default() })
    }

    /// Marks `nodes` (row-major indices, any order) as having no data; `field` names the
    /// scenario field for the error on an index outside the grid.
    pub fn with_gaps(mut self, nodes: Vec<usize>, field: &str) -> Result<Self> {
        self.gaps = NodeGaps::new(nodes, &self.grid, field)?;
        Ok(self)
    }

    /// True when the field has one time layer: it does not change in time.
    pub fn is_steady(&self) -> bool {
        self.times.len() == 1
    }

    /// Whether the velocity at (x, y) comes from data only (see [`NodeGaps::has_data`]).
    #[inline]
    pub fn has_data(&self, x: f64, y: f64) -> bool {
        self.gaps.has_data(&self.grid, x, y)
    }

    /// The first point of (ax, ay) -> (bx, by) whose velocity would come from a node without
    /// data (see [`NodeGaps::first_gap_on`]).
    pub fn first_gap_on(&self, ax: f64, ay: f64, bx: f64, by: f64) -> Option<(f64, f64)> {
        self.gaps.first_gap_on(&self.grid, ax, ay, bx, by)
    }

    #[inline]
    fn bracket(&self, t: f64) -> (usize, usize, f64) {
        time_bracket(&self.times, t)
    }

    /// Velocity at (x, y) and time t (s); w = 0. Outside the grid the edge values hold.
    #[inline]
    pub fn velocity(&self, x: f64, y: f64, t: f64) -> Vec3 {
        let g = &self.grid;
        let (i, j, fu, fv) = g.locate(x, y);
        let k = j * g.nx + i;
        let (l0, l1, w) = self.bracket(t);
        let mut u = lerp2(&self.u[l0], k, g.nx, fu, fv);
        let mut v = lerp2(&self.v[l0], k, g.nx, fu, fv);
        if w > 0.0 {
            u += (lerp2(&self.u[l1], k, g.nx, fu, fv) - u) * w;
            v += (lerp2(&self.v[l1], k, g.nx, fu, fv) - v) * w;
        }
        Vec3::new(u, v, 0.0)
    }

    /// Largest horizontal speed at time t over the nodes of the cells that touch `bounds`.
    /// Exact: an interpolated vector is a convex combination of node vectors, so its length
    /// never exceeds the longest of them.
    /// The largest horizontal speed anywhere and any time: bilinear and linear-in-time
    /// interpolation take convex combinations of node vectors, whose length never exceeds the
    /// longest node vector.
    pub fn speed_bound(&self) -> f64 {
        let mut peak: f64 = 0.0;
        for (u, v) in self.u.iter().zip(&self.v) {
            for (a, b) in u.iter().zip(v) {
                peak = peak.max(a.hypot(*b));
            }
        }
        peak
    }

    pub(super) fn max_speed(&self, bounds: &Aabb, t: f64) -> f64 {
        let g = &self.grid;
        let (i0, j0, _, _) = g.locate(bounds.min.x, bounds.min.y);
        let (i1, j1, _, _) = g.locate(bounds.max.x, bounds.max.y);
        let (l0, l1, w) = self.bracket(t);
        let mut peak: f64 = 0.0;
        for j in j0..=(j1 + 1) {
            for i in i0..=(i1 + 1) {
                let k = j * g.nx + i;
                let u = self.u[l0][k] + (self.u[l1][k] - self.u[l0][k]) * w;
                let v = self.v[l0][k] + (self.v[l1][k] - self.v[l0][k]) * w;
                peak = peak.max(u.hypot(v));
            }
        }
        peak
    }
}
