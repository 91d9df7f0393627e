//! Nodes of a gridded forecast without data (land or fill in its file), shared by the current
//! and wave grids: a value interpolated from such a node would be invented, so points and
//! motions that depend on one are told apart.

use crate::error::{Error, Result};
use crate::world::grid::{walk_cells, RegularGrid2};

/// Sorted row-major indices of the nodes without data.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct NodeGaps(Vec<usize>);

impl NodeGaps {
    /// `nodes` in any order; `field` names the scenario field for the error on an index
    /// outside the grid.
    pub fn new(mut nodes: Vec<usize>, grid: &RegularGrid2, field: &str) -> Result<Self> {
        nodes.sort_unstable();
        nodes.dedup();
        if let Some(&k) = nodes.last() {
            if k >= grid.len() {
                return Err(Error::input(
                    format!("{field}.no_data"),
                    format!("node {k} is outside the grid of {} x {} nodes", grid.nx, grid.ny),
                ));
            }
        }
        Ok(Self(nodes))
    }

    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    pub fn contains(&self, node: &usize) -> bool {
        self.0.binary_search(node).is_ok()
    }

    /// The nodes, sorted.
    pub fn nodes(&self) -> &[usize] {
        &self.0
    }

    /// Whether a value at (x, y) comes from data only: every node with a positive weight in
    /// the bilinear interpolation has data. Always true without gaps.
    #[inline]
    pub fn has_data(&self, g: &RegularGrid2, x: f64, y: f64) -> bool {
        if self.0.is_empty() {
            return true;
        }
        let (i, j, fu, fv) = g.locate(x, y);
        let k = j * g.nx + i;
        let (right, up) = (fu > 0.0, fv > 0.0);
        !(self.contains(&k)
            || (right && self.contains(&(k + 1)))
            || (up && self.contains(&(k + g.nx)))
            || (right && up && self.contains(&(k + g.nx + 1))))
    }

    /// The first point of the horizontal segment (ax, ay) -> (bx, by) inside a cell with a gap
    /// at a corner, if any (the midpoint of the segment's stretch in that cell). Exact: walks
    /// the cells the segment crosses, at most nx + ny of them, so a segment that clips a corner
    /// of such a cell is found however short the stretch; the parts of the segment outside the
    /// grid are not judged (the grid covers the domain).
    pub fn first_gap_on(&self, g: &RegularGrid2, ax: f64, ay: f64, bx: f64, by: f64) -> Option<(f64, f64)> {
        if self.0.is_empty() {
            return None;
        }
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
            [k, k + 1, k + g.nx, k + g.nx + 1].iter().any(|n| self.contains(n))
        };
        if t0 == t1 {
            let (x, y) = world(t0);
            return (!self.has_data(g, x, y)).then_some((x, y));
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
}

/// The two layers of a forecast around `t` and the weight of the second; outside the time
/// range the nearest layer holds, since extrapolating a forecast in time is worse than
/// freezing it.
#[inline]
pub(crate) fn time_bracket(times: &[f64], t: f64) -> (usize, usize, f64) {
    let n = times.len();
    // NaN goes to the first layer rather than to an out-of-range index.
    if n == 1 || t.is_nan() || t <= times[0] {
        return (0, 0, 0.0);
    }
    if t >= times[n - 1] {
        return (n - 1, n - 1, 0.0);
    }
    let k = times.partition_point(|&s| s <= t);
    (k - 1, k, (t - times[k - 1]) / (times[k] - times[k - 1]))
}

/// Checks a forecast's layer times: at least one, finite, strictly increasing.
pub(crate) fn check_times(times: &[f64], field: &str) -> Result<()> {
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
    Ok(())
}

/// Checks one named set of layers against the times and the grid: one layer per time, each
/// full and finite; the error names the layer, node and value.
pub(crate) fn check_layers(layers: &[Vec<f64>], times: usize, grid: &RegularGrid2, name: &str) -> Result<()> {
    if layers.len() != times {
        return Err(Error::input(name, format!("has {} layers but times has {times}", layers.len())));
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
    Ok(())
}

/// `RegularGrid2::bilinear` for an already located cell, in the same operation order so the
/// results are bit-identical; locating once serves several interpolations.
#[inline]
pub(crate) fn lerp2(values: &[f64], k: usize, nx: usize, fu: f64, fv: f64) -> f64 {
    let (a, b) = (values[k], values[k + 1]);
    let (c, d) = (values[k + nx], values[k + nx + 1]);
    let lo = a + (b - a) * fu;
    let hi = c + (d - c) * fu;
    lo + (hi - lo) * fv
}
