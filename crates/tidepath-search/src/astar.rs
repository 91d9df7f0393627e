//! A* (and Dijkstra, with a zero heuristic) on a [`SearchGrid`].
//!
//! Edge costs come from a closure `edge_cost(from, to, g_from)`. Passing
//! `g_from` lets a caller run a time-dependent search in which `g` is the arrival
//! time: as long as edges are FIFO (leaving later never arrives earlier), label
//! setting on arrival time is exact. `None` means the move is not allowed.
//!
//! The result is optimal when the heuristic is consistent
//! (`h(u) ≤ c(u, v) + h(v)`, e.g. the octile distance times the smallest cost
//! per unit length) — each cell is expanded at most once (closed set, no
//! re-opening), which also bounds the work by the grid size.

use crate::arena::{OpenEntry, SearchArena};
use crate::grid::SearchGrid;
use crate::outcome::{Limits, SearchOutcome, SearchStatus};
use crate::SearchError;

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

/// A* with fresh buffers. See [`astar_in`].
pub fn astar<G, C, H>(
    grid: &G,
    start: usize,
    goal: usize,
    edge_cost: C,
    heuristic: H,
    limits: &Limits,
) -> Result<SearchOutcome, SearchError>
where
    G: SearchGrid,
    C: FnMut(usize, usize, f64) -> Option<f64>,
    H: FnMut(usize) -> f64,
{
    astar_in(&mut SearchArena::new(), grid, start, goal, edge_cost, heuristic, limits)
}

/// A* from `start` to `goal`, reusing `arena`'s buffers.
///
/// * `edge_cost(from, to, g_from)`: cost of the grid move (≥ 0), or `None` if
///   it may not be taken.
/// * `heuristic(cell)`: a consistent lower bound on the cost to `goal`
///   (`|_| 0.0` gives Dijkstra).
///
/// Errors when start or goal is outside the grid or blocked. Otherwise the
/// status is `Found` (path start..goal and its cost), `NoPath` (proved: the
/// open list emptied) or `Stopped` (a limit hit; nothing proved).
pub fn astar_in<G, C, H>(
    arena: &mut SearchArena,
    grid: &G,
    start: usize,
    goal: usize,
    mut edge_cost: C,
    mut heuristic: H,
    limits: &Limits,
) -> Result<SearchOutcome, SearchError>
where
    G: SearchGrid,
    C: FnMut(usize, usize, f64) -> Option<f64>,
    H: FnMut(usize) -> f64,
{
    check_endpoints(grid, start, goal)?;
    arena.reset(grid.cell_count());
    arena.g[start] = 0.0;
    arena.open.push(OpenEntry { f: heuristic(start), g: 0.0, cell: start as u32 });
    let mut expansions = 0u64;
    while let Some(entry) = arena.open.pop() {
        let u = entry.cell as usize;
        if arena.is_closed(u) {
            continue; // a stale duplicate: u was reached more cheaply before
        }
        if u == goal {
            return Ok(SearchOutcome {
                status: SearchStatus::Found,
                path: arena.path_to(goal),
                cost: arena.g[goal],
                expansions,
            });
        }
        if let Some(reason) = limits.check(expansions) {
            return Ok(stopped(reason, expansions));
        }
        arena.close(u);
        expansions += 1;
        let gu = arena.g[u];
        let SearchArena { g, parent, closed, open, .. } = arena;
        grid.for_each_neighbour(u, |v| {
            if closed[v >> 6] & (1u64 << (v & 63)) != 0 {
                return;
            }
            let Some(c) = edge_cost(u, v, gu).and_then(|c| valid_cost(c, u, v)) else {
                return;
            };
            let ng = gu + c;
            if ng < g[v] {
                g[v] = ng;
                parent[v] = u as u32;
                open.push(OpenEntry { f: ng + heuristic(v), g: ng, cell: v as u32 });
            }
        });
    }
    Ok(SearchOutcome { status: SearchStatus::NoPath, path: Vec::new(), cost: f64::INFINITY, expansions })
}

pub(crate) fn stopped(reason: crate::StopReason, expansions: u64) -> SearchOutcome {
    SearchOutcome { status: SearchStatus::Stopped(reason), path: Vec::new(), cost: f64::INFINITY, expansions }
}
