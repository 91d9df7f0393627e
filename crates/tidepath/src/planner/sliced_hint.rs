//! "Must every route here turn back along the start-goal axis?" A sliced encoding lays one
//! waypoint on each plane across the axis, so its routes only ever move forward along it; when
//! the answer is yes, no amount of search makes it feasible, and the user should hear why.
//!
//! The check is a flood fill on a coarse *optimistic* raster (a blocked cell is blocked
//! everywhere in it) that only takes steps not moving back along the axis by more than one
//! cell diagonal, and never beyond the start or goal planes by more than that. A forward-only
//! route in free space visits cells that are not fully blocked, and consecutive cell centres
//! differ along the axis by at least minus one cell diagonal; so if the fill does not reach the
//! goal, no forward-only route exists at this resolution. It is a hint, not a proof (the raster
//! ignores moving obstacles), so it only adds a sentence to an infeasible plan's reason.

use tidepath_search::{connected, SearchGrid};

use super::Problem;
use crate::encoding::SliceAxis;
use crate::raster::Raster;
use crate::world::Dims;

/// Cells along the longer side of the coarse raster: cheap enough to run after every
/// infeasible sliced plan.
const CELLS_2D: usize = 100;
const CELLS_3D: usize = 32;
const LAYERS_3D: usize = 6;

/// `true` when every route of mission `i` must go back along the encoding's axis (`slices`: the
/// start-goal direction or a world axis), judged on a
/// coarse raster; `false` when a forward-only route may exist or the question does not apply
/// (no axis, start or goal cell blocked, or start and goal not connected at all).
pub fn must_turn_back(problem: &Problem<'_>, i: usize, slices: SliceAxis) -> bool {
    let w = problem.world;
    let m = &problem.missions[i];
    let size = w.bounds.size();
    let three_d = w.dims == Dims::Three;
    let cell = size.x.max(size.y) / if three_d { CELLS_3D } else { CELLS_2D } as f64;
    let band = (w.bounds.max.z.min(m.vehicle.z_max()) - w.bounds.min.z.max(m.vehicle.z_min())).max(1e-9);
    let Ok(r) = Raster::new(w, &m.vehicle, cell, band / LAYERS_3D as f64, m.start.z) else { return false };
    let mut axis = (m.goal - m.start).truncate();
    match slices {
        SliceAxis::Path => {}
        SliceAxis::X => axis.y = 0.0,
        SliceAxis::Y => axis.x = 0.0,
    }
    let len = axis.length();
    if len.is_nan() || len <= 0.0 {
        return false;
    }
    let dir = axis / len;
    let along: Vec<f64> = (0..r.len()).map(|c| (r.centre(c) - m.start).truncate().dot(dir)).collect();
    let tol = r.dx.hypot(r.dy) * (1.0 + 1e-9);
    let (s, g) = (r.cell_of(m.start), r.cell_of(m.goal));
    let forward = |a: usize, b: usize| along[b] >= along[a] - tol && along[b] >= -tol && along[b] <= len + tol;
    let answer = |any: Result<bool, _>, fwd: Result<bool, _>| matches!((any, fwd), (Ok(true), Ok(false)));
    if r.three_d {
        let grid = r.grid3(false);
        answer(connected(&grid, s, g), connected(&Forward { grid: &grid, forward }, s, g))
    } else {
        let grid = r.grid2(false);
        answer(connected(&grid, s, g), connected(&Forward { grid: &grid, forward }, s, g))
    }
}

/// A grid whose moves are restricted to those `forward` allows.
struct Forward<'a, G, F> {
    grid: &'a G,
    forward: F,
}

impl<G: SearchGrid, F: Fn(usize, usize) -> bool> SearchGrid for Forward<'_, G, F> {
    fn cell_count(&self) -> usize {
        self.grid.cell_count()
    }

    fn is_blocked(&self, cell: usize) -> bool {
        self.grid.is_blocked(cell)
    }

    fn for_each_neighbour<H: FnMut(usize)>(&self, cell: usize, mut f: H) {
        self.grid.for_each_neighbour(cell, |v| {
            if (self.forward)(cell, v) {
                f(v)
            }
        })
    }
}
