//! Theta* (Nash, Daniel, Koenig & Felner 2007): any-angle paths on grids.
//!
//! This is the original ("basic") Theta*, not Lazy Theta*: when a neighbour `v`
//! of the expanded cell `u` is relaxed, the straight segment from `u`'s parent
//! `p` to `v` is tried if `p` sees `v` (exact test, [`crate::los`]), and the grid
//! move `u → v` is always tried as well; the cheaper one wins. Keeping the grid
//! move as a candidate (the paper drops it when `p` sees `v`) costs one closure
//! call and guarantees, for any costs, that each relaxation is at least as good
//! as A*'s; for costs obeying the triangle inequality (e.g. Euclidean length)
//! it changes nothing. With a consistent heuristic this gives
//! **Theta* cost ≤ A* cost** on the same grid (each cell's g at expansion is at
//! most its A* distance, by the usual Dijkstra induction). Theta* is not
//! guaranteed to find the shortest any-angle path.
//!
//! The path is returned as the turning cells only (start, corners, goal);
//! consecutive cells see each other.
//!
//! The search loop is the crate's one [`mod@crate::best_first`] loop, as for A*;
//! Theta* differs only in its per-neighbour step ([`crate::Relax`]).

use crate::arena::SearchArena;
use crate::best_first::{Expanded, Frontier};
use crate::grid::SearchGrid;
use crate::los::LineOfSight;
use crate::outcome::{Limits, SearchOutcome};
use crate::relax::{best_first_on_grid, valid_cost, Relax};
use crate::SearchError;

/// Theta* with fresh buffers. See [`theta_star_in`].
pub fn theta_star<G, C, H>(
    grid: &G,
    start: usize,
    goal: usize,
    segment_cost: C,
    heuristic: H,
    limits: &Limits,
) -> Result<SearchOutcome, SearchError>
where
    G: SearchGrid + LineOfSight,
    C: FnMut(usize, usize, f64) -> Option<f64>,
    H: FnMut(usize) -> f64,
{
    theta_star_in(&mut SearchArena::new(), grid, start, goal, segment_cost, heuristic, limits)
}

/// Theta* from `start` to `goal`, reusing `arena`.
///
/// * `segment_cost(from, to, g_from)`: cost (≥ 0) of the straight segment
///   between the centres of two mutually visible cells (a grid move is such a
///   segment), leaving `from` at `g_from`; `None` if it may not be taken. Price
///   by length, or by travel time through currents.
/// * `heuristic(cell)`: consistent lower bound (e.g. Euclidean distance).
///
/// `path` holds the turning cells; `cost` is the sum of the segment costs.
pub fn theta_star_in<G, C, H>(
    arena: &mut SearchArena,
    grid: &G,
    start: usize,
    goal: usize,
    segment_cost: C,
    heuristic: H,
    limits: &Limits,
) -> Result<SearchOutcome, SearchError>
where
    G: SearchGrid + LineOfSight,
    C: FnMut(usize, usize, f64) -> Option<f64>,
    H: FnMut(usize) -> f64,
{
    let relax = ThroughParent { grid, segment_cost };
    best_first_on_grid(arena, grid, start, goal, relax, heuristic, limits)
}

/// Theta*'s relaxation: the grid move `u → v`, and the segment from `u`'s
/// parent straight to `v` when the parent sees `v`; the cheaper is offered.
struct ThroughParent<'g, G, C> {
    grid: &'g G,
    segment_cost: C,
}

impl<G, C> Relax for ThroughParent<'_, G, C>
where
    G: LineOfSight,
    C: FnMut(usize, usize, f64) -> Option<f64>,
{
    #[inline]
    fn relax<H: FnMut(usize) -> f64>(&mut self, u: Expanded, v: usize, frontier: &mut Frontier<'_, H>) {
        let cost = &mut self.segment_cost;
        let mut best = cost(u.node, v, u.g).and_then(|c| valid_cost(c, u.node, v)).map(|c| (u.g + c, u.node));
        if let Some(p) = u.parent {
            let gp = frontier.g(p);
            if self.grid.line_of_sight(p, v) {
                if let Some(c) = cost(p, v, gp).and_then(|c| valid_cost(c, p, v)) {
                    // Ties go to the parent: fewer turning points.
                    if best.is_none_or(|(b, _)| gp + c <= b) {
                        best = Some((gp + c, p));
                    }
                }
            }
        }
        if let Some((g, from)) = best {
            frontier.offer(v, g, from);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{astar, Grid2, Grid3};

    #[test]
    fn straight_line_on_empty_grids() {
        let g = Grid2::new(10, 10).unwrap();
        let t = g.index(9, 5);
        let o =
            theta_star(&g, 0, t, |a, b, _| Some(g.euclidean(a, b)), |c| g.euclidean(c, t), &Limits::none()).unwrap();
        assert_eq!(o.path, vec![0, t]);
        assert!((o.cost - 106f64.sqrt()).abs() < 1e-9);
        let g = Grid3::new(8, 8, 8).unwrap();
        let t = g.index(7, 2, 5);
        let o =
            theta_star(&g, 0, t, |a, b, _| Some(g.euclidean(a, b)), |c| g.euclidean(c, t), &Limits::none()).unwrap();
        assert_eq!(o.path, vec![0, t]);
        assert!((o.cost - 78f64.sqrt()).abs() < 1e-9);
    }

    #[test]
    fn bends_at_the_wall_end_and_beats_astar() {
        // A wall x = 3, y = 0..=4 on a 7 x 7 grid; from (0,0) to (6,0).
        let mut g = Grid2::new(7, 7).unwrap();
        for j in 0..5 {
            g.set_blocked(3, j, true);
        }
        let (s, t) = (g.index(0, 0), g.index(6, 0));
        let o =
            theta_star(&g, s, t, |a, b, _| Some(g.euclidean(a, b)), |c| g.euclidean(c, t), &Limits::none()).unwrap();
        let a = astar(&g, s, t, |a, b, _| Some(g.step_length(a, b)), |c| g.octile(c, t), &Limits::none()).unwrap();
        assert!(o.cost < a.cost - 0.5, "{} vs {}", o.cost, a.cost);
        // Turning cells see each other and the cost is their summed length.
        let sum: f64 = o.path.windows(2).map(|w| g.euclidean(w[0], w[1])).sum();
        assert!((sum - o.cost).abs() < 1e-9);
        assert!(o.path.windows(2).all(|w| g.line_of_sight(w[0], w[1])));
        // Passing the wall end (3,4) needs row 5 clear of its corners: the
        // best turning points are (2,5) and (4,5): 2 * sqrt(4 + 25) + 2.
        assert!(o.cost >= 2.0 * 29f64.sqrt() + 2.0 - 1e-9);
    }
}
