//! "Is there any route at all?": iterative flood fill on a [`SearchGrid`].
//!
//! Uses the same moves as A* (no corner cutting), so `connected` is true iff A*
//! with any finite costs finds a path. Iterative (explicit stack, no recursion)
//! and bounded: each cell is pushed at most once.

use crate::arena::SearchArena;
use crate::grid::SearchGrid;
use crate::relax::check_endpoints;
use crate::SearchError;

/// `true` iff `goal` can be reached from `start` (fresh buffers).
/// Works for [`crate::Grid2`] (8-connected) and [`crate::Grid3`] (26-connected).
/// Errors like [`crate::astar`] on a blocked or out-of-range start or goal.
pub fn connected<G: SearchGrid>(grid: &G, start: usize, goal: usize) -> Result<bool, SearchError> {
    connected_in(&mut SearchArena::new(), grid, start, goal)
}

/// [`connected`] reusing `arena`.
pub fn connected_in<G: SearchGrid>(
    arena: &mut SearchArena,
    grid: &G,
    start: usize,
    goal: usize,
) -> Result<bool, SearchError> {
    check_endpoints(grid, start, goal)?;
    if start == goal {
        return Ok(true);
    }
    arena.reset_closed(grid.cell_count());
    arena.stack.clear();
    arena.close(start);
    arena.stack.push(start as u32);
    let SearchArena { closed, stack, .. } = arena;
    let mut found = false;
    while let Some(u) = stack.pop() {
        grid.for_each_neighbour(u as usize, |v| {
            let (w, bit) = (v >> 6, 1u64 << (v & 63));
            if closed[w] & bit == 0 {
                closed[w] |= bit;
                found |= v == goal;
                stack.push(v as u32);
            }
        });
        if found {
            return Ok(true);
        }
    }
    Ok(false)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Grid2, Grid3};

    #[test]
    fn wall_with_a_gap_in_2d_and_3d() {
        let mut g = Grid2::new(5, 5).unwrap();
        for j in 0..5 {
            g.set_blocked(2, j, true);
        }
        assert!(!connected(&g, 0, 4).unwrap());
        g.set_blocked(2, 3, false);
        assert!(connected(&g, 0, 4).unwrap());
        // Two blocked cells touching at a corner are a wall (no corner cutting).
        let mut g = Grid2::new(2, 2).unwrap();
        g.set_blocked(1, 0, true);
        g.set_blocked(0, 1, true);
        assert!(!connected(&g, 0, 3).unwrap());

        let mut g = Grid3::new(4, 4, 4).unwrap();
        for j in 0..4 {
            for k in 0..4 {
                g.set_blocked(2, j, k, true);
            }
        }
        let goal = g.index(3, 3, 3);
        assert!(!connected(&g, 0, goal).unwrap());
        g.set_blocked(2, 1, 2, false);
        assert!(connected(&g, 0, goal).unwrap());
        assert_eq!(connected(&g, g.index(2, 0, 0), goal), Err(SearchError::StartBlocked(g.index(2, 0, 0))));
    }
}
