//! The best-first loop on a grid: the grid supplies the moves, a [`Relax`]
//! hook turns each move into offers.
//!
//! On a grid, planners differ only in how they relax one neighbour `v` of the
//! expanded cell `u`: A* offers `v` from `u`; Theta* first tries `v` straight
//! from `u`'s parent when it sees `v`. [`OnGrid`] walks the grid's neighbours,
//! skips the closed ones (before any cost is computed: on an open grid most
//! neighbours of an expanded cell are closed) and hands the rest to the hook.

use crate::arena::SearchArena;
use crate::best_first::{best_first, Expand, Expanded, Frontier};
use crate::grid::SearchGrid;
use crate::outcome::{Limits, SearchOutcome};
use crate::SearchError;

/// The per-neighbour step of a grid search.
pub trait Relax {
    /// Relaxes the move from the expanded cell `u` to its neighbour `v` (a
    /// free cell, not closed), offering `v` to `frontier` with whatever parent
    /// and cost the planner chooses.
    fn relax<H: FnMut(usize) -> f64>(&mut self, u: Expanded, v: usize, frontier: &mut Frontier<'_, H>);
}

/// An [`Expand`] hook that relaxes every open grid neighbour of the expanded cell.
#[derive(Debug)]
pub struct OnGrid<'g, G, R> {
    /// The grid whose moves are followed.
    pub grid: &'g G,
    /// The per-neighbour step.
    pub relax: R,
}

impl<G: SearchGrid, R: Relax> Expand for OnGrid<'_, G, R> {
    #[inline]
    fn expand<H: FnMut(usize) -> f64>(&mut self, u: Expanded, frontier: &mut Frontier<'_, H>) {
        let relax = &mut self.relax;
        self.grid.for_each_neighbour(u.node, |v| {
            if !frontier.is_closed(v) {
                relax.relax(u, v, frontier);
            }
        });
    }
}

/// [`best_first`] from cell `start` to cell `goal` of `grid`, relaxing moves
/// with `relax`. Errors when start or goal is outside the grid or blocked.
pub fn best_first_on_grid<G, R, H>(
    arena: &mut SearchArena,
    grid: &G,
    start: usize,
    goal: usize,
    relax: R,
    heuristic: H,
    limits: &Limits,
) -> Result<SearchOutcome, SearchError>
where
    G: SearchGrid,
    R: Relax,
    H: FnMut(usize) -> f64,
{
    check_endpoints(grid, start, goal)?;
    let mut on_grid = OnGrid { grid, relax };
    best_first(arena, grid.cell_count(), start, |u| u == goal, heuristic, &mut on_grid, limits)
}

/// Validates start and goal for a grid search.
pub(crate) fn check_endpoints<G: SearchGrid>(grid: &G, start: usize, goal: usize) -> Result<(), SearchError> {
    let cells = grid.cell_count();
    for cell in [start, goal] {
        if cell >= cells {
            return Err(SearchError::CellOutOfRange { cell, cells });
        }
    }
    if grid.is_blocked(start) {
        return Err(SearchError::StartBlocked(start));
    }
    if grid.is_blocked(goal) {
        return Err(SearchError::GoalBlocked(goal));
    }
    Ok(())
}

/// A validated edge cost: NaN or negative is a caller bug (debug assertion);
/// in release builds such an edge is skipped.
#[inline]
pub(crate) fn valid_cost(c: f64, from: usize, to: usize) -> Option<f64> {
    if c >= 0.0 {
        Some(c)
    } else {
        debug_assert!(false, "edge cost {c} from {from} to {to} is NaN or negative");
        None
    }
}
