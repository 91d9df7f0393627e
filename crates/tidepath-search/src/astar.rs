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
//!
//! The search loop is the crate's one [`mod@crate::best_first`] loop; A* adds only
//! its per-neighbour step (offer the neighbour from the expanded cell).

use crate::arena::SearchArena;
use crate::best_first::{Expanded, Frontier};
use crate::grid::SearchGrid;
use crate::outcome::{Limits, SearchOutcome};
use crate::relax::{best_first_on_grid, valid_cost, Relax};
use crate::SearchError;

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
    edge_cost: C,
    heuristic: H,
    limits: &Limits,
) -> Result<SearchOutcome, SearchError>
where
    G: SearchGrid,
    C: FnMut(usize, usize, f64) -> Option<f64>,
    H: FnMut(usize) -> f64,
{
    best_first_on_grid(arena, grid, start, goal, GridMove(edge_cost), heuristic, limits)
}

/// A*'s relaxation: the grid move from the expanded cell, priced by the
/// caller's `edge_cost(from, to, g_from)`.
struct GridMove<C>(C);

impl<C: FnMut(usize, usize, f64) -> Option<f64>> Relax for GridMove<C> {
    #[inline]
    fn relax<H: FnMut(usize) -> f64>(&mut self, u: Expanded, v: usize, frontier: &mut Frontier<'_, H>) {
        if let Some(c) = (self.0)(u.node, v, u.g).and_then(|c| valid_cost(c, u.node, v)) {
            frontier.offer(v, u.g + c, u.node);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Grid2, Grid3, SearchStatus, StopReason};
    use std::f64::consts::SQRT_2;
    use std::sync::atomic::AtomicBool;
    use std::time::{Duration, Instant};

    fn run(g: &Grid2, s: usize, t: usize, octile: bool) -> SearchOutcome {
        astar(
            g,
            s,
            t,
            |a, b, _| Some(g.step_length(a, b)),
            |c| if octile { g.octile(c, t) } else { 0.0 },
            &Limits::none(),
        )
        .unwrap()
    }

    #[test]
    fn octile_distance_on_empty_grid() {
        let g = Grid2::new(10, 10).unwrap();
        for octile in [false, true] {
            let o = run(&g, g.index(0, 0), g.index(9, 5), octile);
            assert_eq!(o.status, SearchStatus::Found);
            assert!((o.cost - (4.0 + 5.0 * SQRT_2)).abs() < 1e-9);
            assert_eq!(o.path.len(), 10);
            assert_eq!((o.path[0], *o.path.last().unwrap()), (0, g.index(9, 5)));
        }
        // The heuristic pays off: far fewer expansions than Dijkstra.
        let d = run(&g, 0, g.index(9, 5), false);
        let a = run(&g, 0, g.index(9, 5), true);
        assert!(a.expansions < d.expansions, "{} vs {}", a.expansions, d.expansions);
    }

    #[test]
    fn wall_with_one_gap() {
        let mut g = Grid2::new(7, 7).unwrap();
        for j in 0..7 {
            if j != 5 {
                g.set_blocked(3, j, true);
            }
        }
        // The gap must be entered and left orthogonally (no corner cutting):
        // (0,0) -> (2,5): 2√2 + 3, through the gap: 2, (4,5) -> (6,0): 2√2 + 3.
        let want = 8.0 + 4.0 * SQRT_2;
        for octile in [false, true] {
            let o = run(&g, g.index(0, 0), g.index(6, 0), octile);
            assert!((o.cost - want).abs() < 1e-9, "{}", o.cost);
            let gap = o.path.iter().position(|&c| c == g.index(3, 5)).expect("through the gap");
            assert_eq!(o.path[gap - 1], g.index(2, 5));
            assert_eq!(o.path[gap + 1], g.index(4, 5));
        }
        // Close the gap: a proved NoPath after expanding the whole left side.
        g.set_blocked(3, 5, true);
        let o = run(&g, g.index(0, 0), g.index(6, 0), true);
        assert_eq!(o.status, SearchStatus::NoPath);
        assert_eq!(o.expansions, 21);
        assert!(o.path.is_empty() && o.cost.is_infinite());
    }

    #[test]
    fn blocked_or_out_of_range_endpoints_are_errors() {
        let mut g = Grid2::new(4, 4).unwrap();
        g.set_blocked(0, 0, true);
        let f = |_: usize, _: usize, _: f64| Some(1.0);
        assert_eq!(astar(&g, 0, 5, f, |_| 0.0, &Limits::none()), Err(SearchError::StartBlocked(0)));
        assert_eq!(astar(&g, 5, 0, f, |_| 0.0, &Limits::none()), Err(SearchError::GoalBlocked(0)));
        assert!(matches!(astar(&g, 5, 16, f, |_| 0.0, &Limits::none()), Err(SearchError::CellOutOfRange { .. })));
    }

    #[test]
    fn limits_stop_without_claiming_no_path() {
        let g = Grid2::new(50, 50).unwrap();
        let f = |a: usize, b: usize, _: f64| Some(g.step_length(a, b));
        let goal = g.len() - 1;
        let lim = Limits { max_expansions: Some(5), ..Limits::none() };
        let o = astar(&g, 0, goal, f, |_| 0.0, &lim).unwrap();
        assert_eq!((o.status, o.expansions), (SearchStatus::Stopped(StopReason::MaxExpansions), 5));
        let flag = AtomicBool::new(true);
        let lim = Limits { stop: Some(&flag), ..Limits::none() };
        let o = astar(&g, 0, goal, f, |_| 0.0, &lim).unwrap();
        assert_eq!(o.status, SearchStatus::Stopped(StopReason::StopFlag));
        let lim = Limits { deadline: Some(Instant::now() - Duration::from_millis(1)), ..Limits::none() };
        let o = astar(&g, 0, goal, f, |_| 0.0, &lim).unwrap();
        assert_eq!(o.status, SearchStatus::Stopped(StopReason::Deadline));
        // Polled every POLL_EVERY expansions: a flag raised mid-search stops at the next poll.
        let flag = AtomicBool::new(false);
        let lim = Limits { stop: Some(&flag), ..Limits::none() };
        let o = astar(
            &g,
            0,
            goal,
            |a, b, gf| {
                if gf > 10.0 {
                    flag.store(true, std::sync::atomic::Ordering::Relaxed);
                }
                Some(g.step_length(a, b))
            },
            |_| 0.0,
            &lim,
        )
        .unwrap();
        assert_eq!(o.status, SearchStatus::Stopped(StopReason::StopFlag));
        assert_eq!(o.expansions % crate::POLL_EVERY, 0);
    }

    #[test]
    fn time_dependent_costs_see_the_arrival_time() {
        // A corridor whose moves get slower from time 2 on (FIFO: leaving later
        // never arrives earlier): arrivals 1, 2, 5, 8.
        let g = Grid2::new(5, 1).unwrap();
        let o = astar(&g, 0, 4, |_, _, t| Some(if t < 2.0 { 1.0 } else { 3.0 }), |_| 0.0, &Limits::none()).unwrap();
        assert_eq!(o.cost, 8.0);
        assert_eq!(o.path, vec![0, 1, 2, 3, 4]);
    }

    #[test]
    #[cfg(debug_assertions)]
    #[should_panic(expected = "is NaN or negative")]
    fn negative_edge_cost_is_a_bug() {
        let g = Grid2::new(3, 1).unwrap();
        let _ = astar(&g, 0, 2, |_, _, _| Some(-1.0), |_| 0.0, &Limits::none());
    }

    #[test]
    fn none_costs_forbid_moves() {
        // Forbid every diagonal: Manhattan distance.
        let g = Grid2::new(6, 6).unwrap();
        let o = astar(
            &g,
            0,
            g.index(5, 3),
            |a, b, _| (g.step_length(a, b) == 1.0).then_some(1.0),
            |_| 0.0,
            &Limits::none(),
        )
        .unwrap();
        assert_eq!(o.cost, 8.0);
    }

    #[test]
    fn arena_reuse_gives_identical_results() {
        let mut g = Grid2::new(20, 20).unwrap();
        for j in 0..15 {
            g.set_blocked(10, j, true);
        }
        let mut arena = SearchArena::new();
        let f = |a: usize, b: usize, _: f64| Some(g.step_length(a, b));
        let goal = g.index(19, 0);
        let first = astar_in(&mut arena, &g, 0, goal, f, |c| g.octile(c, goal), &Limits::none()).unwrap();
        let small = Grid2::new(3, 3).unwrap();
        astar_in(&mut arena, &small, 0, 8, |_, _, _| Some(1.0), |_| 0.0, &Limits::none()).unwrap();
        let again = astar_in(&mut arena, &g, 0, goal, f, |c| g.octile(c, goal), &Limits::none()).unwrap();
        assert_eq!(first, again);
    }

    #[test]
    fn grid3_space_diagonal() {
        let g = Grid3::new(6, 6, 6).unwrap();
        let goal = g.index(5, 3, 1);
        let o =
            astar(&g, 0, goal, |a, b, _| Some(g.step_length(a, b)), |c| g.octile(c, goal), &Limits::none()).unwrap();
        assert!((o.cost - (3f64.sqrt() + 2.0 * SQRT_2 + 2.0)).abs() < 1e-9);
    }
}
