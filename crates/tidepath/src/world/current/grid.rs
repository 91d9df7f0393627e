//! Gridded currents: u, v layers on a regular grid, interpolated in space and time.

use crate::error::{Error, Result};
use crate::geom::{Aabb, Vec3};
use crate::world::grid::{walk_cells, RegularGrid2};

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
    /// Nodes where the forecast has no data (land or fill in the source file), sorted; their
    /// u, v are 0 so interpolation stays finite, and [`CurrentGrid::has_data`] tells motions
    /// through them apart, since guessing a current there would be inventing data.
    pub gaps: Vec<usize>,
}

impl CurrentGrid {
    /// Checks the layers; `field` names the scenario field for error messages, which give the
    /// offending layer, node and value so a broken data file can be found.
    pub fn new(grid: RegularGrid2, times: Vec<f64>, u: Vec<Vec<f64>>, v: Vec<Vec<f64>>, field: &str) -> Result<Self> {
        if times.is_empty() {
            return Err(Error::input(format!("{field}.times"), "needs at least one layer, got none"));
        }
        for (k, &t) in times.iter().enumerate() {
            if !t.is_finite() {
                return Err(Error::input(format!("{field}.times"), format!("times[{k}] is {t}; must be finite")));
            }
            if k > 0 && t <= times[k - 1] {
                return Err(Error::input(
                    format!("{field}.times"),
                    format!(
                        "must be strictly increasing, but times[{k}] = {t} follows times[{}] = {}",
                        k - 1,
                        times[k - 1]
                    ),
                ));
            }
        }
        for (name, layers) in [("u", &u), ("v", &v)] {
            let name = format!("{field}.{name}");
            if layers.len() != times.len() {
                return Err(Error::input(name, format!("has {} layers but times has {}", layers.len(), times.len())));
            }
            for (l, layer) in layers.iter().enumerate() {
                if layer.len() != grid.len() {
                    return Err(Error::input(
                        name,
                        format!(
                            "layer {l} has {} values; the grid has {} x {} = {} nodes",
                            layer.len(),
                            grid.nx,
                            grid.ny,
                            grid.len()
                        ),
                    ));
                }
                if let Some(k) = layer.iter().position(|x| !x.is_finite()) {
                    return Err(Error::input(
                        name,
                        format!(
                            "layer {l}, value {k} (node i = {}, j = {}) is {}; must be finite",
                            k % grid.nx,
                            k / grid.nx,
                            layer[k]
                        ),
                    ));
                }
            }
        }
        Ok(Self { grid, times, u, v, gaps: Vec::new() })
    }

    /// Marks `nodes` (row-major indices, any order) as having no data; `field` names the
    /// scenario field for the error on an index outside the grid.
    pub fn with_gaps(mut self, mut nodes: Vec<usize>, field: &str) -> Result<Self> {
        nodes.sort_unstable();
        nodes.dedup();
        if let Some(&k) = nodes.last() {
            if k >= self.grid.len() {
                return Err(Error::input(
                    format!("{field}.no_data"),
                    format!("node {k} is outside the grid of {} x {} nodes", self.grid.nx, self.grid.ny),
                ));
            }
        }
        self.gaps = nodes;
        Ok(self)
    }

    /// Whether the velocity at (x, y) comes from data only: every node with a positive weight
    /// in the bilinear interpolation has data. Always true without gaps.
    #[inline]
    /// True when the field has one time layer: it does not change in time.
    pub fn is_steady(&self) -> bool {
        self.times.len() == 1
    }

    pub fn has_data(&self, x: f64, y: f64) -> bool {
        if self.gaps.is_empty() {
            return true;
        }
        let g = &self.grid;
        let (i, j, fu, fv) = g.locate(x, y);
        let k = j * g.nx + i;
        let gap = |n: usize| self.gaps.binary_search(&n).is_ok();
        let (right, up) = (fu > 0.0, fv > 0.0);
        !(gap(k) || (right && gap(k + 1)) || (up && gap(k + g.nx)) || (right && up && gap(k + g.nx + 1)))
    }

    /// The first point of the horizontal segment (ax, ay) -> (bx, by) inside a cell with a gap
    /// at a corner, if any (the midpoint of the segment's stretch in that cell). Exact: walks
    /// the cells the segment crosses, at most nx + ny of them, so a segment that clips a corner
    /// of such a cell is found however short the stretch; the parts of the segment outside the
    /// grid are not judged (the grid covers the domain).
    pub fn first_gap_on(&self, ax: f64, ay: f64, bx: f64, by: f64) -> Option<(f64, f64)> {
        if self.gaps.is_empty() {
            return None;
        }
        let g = &self.grid;
        let (u0, v0) = ((ax - g.x0) / g.dx, (ay - g.y0) / g.dy);
        let (du, dv) = ((bx - g.x0) / g.dx - u0, (by - g.y0) / g.dy - v0);
        let (umax, vmax) = ((g.nx - 1) as f64, (g.ny - 1) as f64);
        // Clip to the grid's rectangle in cell units.
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (p, d, hi) in [(u0, du, umax), (v0, dv, vmax)] {
            if d == 0.0 {
                if !(0.0..=hi).contains(&p) {
                    return None;
                }
            } else {
                let (ta, tb) = (-p / d, (hi - p) / d);
                t0 = t0.max(ta.min(tb));
                t1 = t1.min(ta.max(tb));
            }
        }
        if t0.is_nan() || t1.is_nan() || t0 > t1 {
            return None;
        }
        let at = |t: f64| (u0 + du * t, v0 + dv * t);
        let world = |t: f64| (ax + (bx - ax) * t, ay + (by - ay) * t);
        let gap_cell = |t: f64| {
            let (u, v) = at(t);
            let i = (u.floor().max(0.0) as usize).min(g.nx - 2);
            let j = (v.floor().max(0.0) as usize).min(g.ny - 2);
            let k = j * g.nx + i;
            [k, k + 1, k + g.nx, k + g.nx + 1].iter().any(|n| self.gaps.binary_search(n).is_ok())
        };
        if t0 == t1 {
            let (x, y) = world(t0);
            return (!self.has_data(x, y)).then_some((x, y));
        }
        // Inside the clipped range the edges between cells are the lines 1..=nx - 2.
        let mut found = None;
        walk_cells((u0, du), (v0, dv), (g.nx - 2, g.ny - 2), (t0, t1), |t, te| {
            let tm = 0.5 * (t + te);
            if te > t && gap_cell(tm) {
                found = Some(world(tm));
            }
            found.is_some()
        });
        found
    }

    /// The two layers around `t` and the weight of the second; outside the time range the
    /// nearest layer holds, since extrapolating a forecast in time is worse than freezing it.
    #[inline]
    fn bracket(&self, t: f64) -> (usize, usize, f64) {
        let n = self.times.len();
        // NaN goes to the first layer rather than to an out-of-range index.
        if n == 1 || t.is_nan() || t <= self.times[0] {
            return (0, 0, 0.0);
        }
        if t >= self.times[n - 1] {
            return (n - 1, n - 1, 0.0);
        }
        let k = self.times.partition_point(|&s| s <= t);
        (k - 1, k, (t - self.times[k - 1]) / (self.times[k] - self.times[k - 1]))
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

/// `RegularGrid2::bilinear` for an already located cell, in the same operation order so the
/// results are bit-identical; locating once serves all four interpolations.
#[inline]
fn lerp2(values: &[f64], k: usize, nx: usize, fu: f64, fv: f64) -> f64 {
    let (a, b) = (values[k], values[k + 1]);
    let (c, d) = (values[k + nx], values[k + nx + 1]);
    let lo = a + (b - a) * fu;
    let hi = c + (d - c) * fu;
    lo + (hi - lo) * fv
}
