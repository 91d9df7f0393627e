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

use crate::arena::{OpenEntry, SearchArena, NO_PARENT};
use crate::astar::{check_endpoints, stopped, valid_cost};
use crate::grid::SearchGrid;
use crate::los::LineOfSight;
use crate::outcome::{Limits, SearchOutcome, SearchStatus};
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
    mut segment_cost: C,
    mut heuristic: H,
    limits: &Limits,
) -> Result<SearchOutcome, SearchError>
where
    G: SearchGrid + LineOfSight,
    C: FnMut(usize, usize, f64) -> Option<f64>,
    H: FnMut(usize) -> f64,
{
    check_endpoints(grid, start, goal)?;
    arena.reset(grid.cell_count());
    arena.g[start] = 0.0;
    arena.open.push(OpenEntry::new(heuristic(start), 0.0, start));
    let mut expansions = 0u64;
    while let Some(entry) = arena.open.pop() {
        let u = entry.cell();
        if arena.is_closed(u) {
            continue;
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
        let pu = arena.parent[u];
        let SearchArena { g, parent, closed, open, .. } = arena;
        grid.for_each_neighbour(u, |v| {
            if closed[v >> 6] & (1u64 << (v & 63)) != 0 {
                return;
            }
            let mut best: Option<(f64, u32)> =
                segment_cost(u, v, gu).and_then(|c| valid_cost(c, u, v)).map(|c| (gu + c, u as u32));
            if pu != NO_PARENT {
                let p = pu as usize;
                let gp = g[p];
                if grid.line_of_sight(p, v) {
                    if let Some(c) = segment_cost(p, v, gp).and_then(|c| valid_cost(c, p, v)) {
                        // Ties go to the parent: fewer turning points.
                        if best.is_none_or(|(b, _)| gp + c <= b) {
                            best = Some((gp + c, pu));
                        }
                    }
                }
            }
            if let Some((ng, from)) = best {
                if ng < g[v] {
                    g[v] = ng;
                    parent[v] = from;
                    let h = heuristic(v);
                    debug_assert!(!h.is_nan(), "heuristic is NaN at cell {v}");
                    open.push(OpenEntry::new(ng + h, ng, v));
                }
            }
        });
    }
    Ok(SearchOutcome { status: SearchStatus::NoPath, path: Vec::new(), cost: f64::INFINITY, expansions })
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
