//! Maximin (bottleneck) paths on a [`Grid2`] with a value per cell.
//!
//! Finds the path from start to goal that maximises the smallest value it
//! depends on — e.g. with water depth as the value, the deepest route — and
//! reports that bottleneck and where it is, so a planner can say "the deepest
//! water connecting start and goal is 1 m at (i, j); this vehicle needs 22 m".
//!
//! # What a path "depends on"
//!
//! Moves follow the grid rule (8-connected, no corner cutting). A diagonal move
//! needs both orthogonal neighbours free, so it also depends on their values:
//! the value of a move is the minimum over every cell of its box (both end
//! cells and, for a diagonal, the two corner cells). The bottleneck of a path is
//! the minimum over its moves (and the start cell). Equivalently, the maximin
//! value is the largest threshold `T` such that start and goal are
//! [`crate::connected`] when every cell with value `< T` is also blocked.
//! Blocked cells are impassable whatever their value.
//!
//! # Algorithm
//!
//! Label-setting (Dijkstra-like) search with a max-heap on the bottleneck so
//! far; `min` is monotone along a path, so the first time a cell is popped its
//! label is final. O(n log n), each cell expanded once. Ties: larger bottleneck
//! first, then smaller cell index; the reported bottleneck cell is the first
//! (from the start) cell attaining the minimum along the chosen path.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use crate::arena::{SearchArena, NO_PARENT};
use crate::grid::{Grid2, SearchGrid};
use crate::relax::check_endpoints;
use crate::SearchError;

/// The best bottleneck between two cells.
#[derive(Debug, Clone, PartialEq)]
pub struct Bottleneck {
    /// The largest achievable minimum value.
    pub value: f64,
    /// The cell where that minimum is attained: on the returned path, or one of
    /// the two corner cells a diagonal move of the path depends on.
    pub cell: usize,
    /// Cells from start to goal.
    pub path: Vec<usize>,
}

#[derive(Debug, Clone, Copy)]
struct Entry {
    b: f64,
    cell: u32,
}
impl PartialEq for Entry {
    fn eq(&self, o: &Self) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}
impl Eq for Entry {}
impl PartialOrd for Entry {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Entry {
    fn cmp(&self, o: &Self) -> Ordering {
        self.b.total_cmp(&o.b).then_with(|| o.cell.cmp(&self.cell))
    }
}

/// The maximin path from `start` to `goal` on `grid` with `values[cell]`
/// (same flat indexing as the grid). `Ok(None)` when no path exists at all.
///
/// Errors: wrong `values` length, a NaN value, start/goal out of range or blocked.
pub fn maximin(grid: &Grid2, values: &[f64], start: usize, goal: usize) -> Result<Option<Bottleneck>, SearchError> {
    maximin_in(&mut SearchArena::new(), grid, values, start, goal)
}

/// [`maximin`] reusing `arena`.
pub fn maximin_in(
    arena: &mut SearchArena,
    grid: &Grid2,
    values: &[f64],
    start: usize,
    goal: usize,
) -> Result<Option<Bottleneck>, SearchError> {
    if values.len() != grid.len() {
        return Err(SearchError::BufferLength { what: "values", got: values.len(), cells: grid.len() });
    }
    if let Some(c) = values.iter().position(|v| v.is_nan()) {
        return Err(SearchError::NanValue(c));
    }
    check_endpoints(grid, start, goal)?;
    let n = grid.len();
    arena.reset(n);
    // g holds the bottleneck label (larger is better); `where_` the cell attaining it.
    let mut where_: Vec<u32> = vec![NO_PARENT; n];
    let mut heap = BinaryHeap::new();
    arena.g[start] = values[start];
    where_[start] = start as u32;
    heap.push(Entry { b: values[start], cell: start as u32 });
    let nx = grid.nx();
    while let Some(Entry { b, cell }) = heap.pop() {
        let u = cell as usize;
        if arena.is_closed(u) {
            continue;
        }
        if u == goal {
            return Ok(Some(Bottleneck { value: b, cell: where_[u] as usize, path: arena.path_to(goal) }));
        }
        arena.close(u);
        let SearchArena { g, parent, closed, .. } = arena;
        grid.for_each_neighbour(u, |v| {
            if closed[v >> 6] & (1u64 << (v & 63)) != 0 {
                return;
            }
            // Cells of the move's box other than u, in a fixed order: v, then the corners.
            let (mut m, mut at) = (values[v], v);
            let (ui, uj) = (u % nx, u / nx);
            let (vi, vj) = (v % nx, v / nx);
            if ui != vi && uj != vj {
                for c in [ui + nx * vj, vi + nx * uj] {
                    if values[c] < m {
                        (m, at) = (values[c], c);
                    }
                }
            }
            let (nb, nat) = if g[u] <= m { (g[u], where_[u] as usize) } else { (m, at) };
            // parent == NO_PARENT: not labelled yet (the start is closed first).
            if parent[v] == NO_PARENT || nb > g[v] {
                g[v] = nb;
                parent[v] = u as u32;
                where_[v] = nat as u32;
                heap.push(Entry { b: nb, cell: v as u32 });
            }
        });
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deepest_channel() {
        // Rows (j = 0, 1, 2) of a 5 x 3 depth map; the straight route crosses a
        // 1 m sill, the northern detour never goes below 3 m.
        let rows = [[10.0, 2.0, 2.0, 2.0, 10.0], [10.0, 10.0, 1.0, 10.0, 10.0], [10.0, 3.0, 3.0, 3.0, 10.0]];
        let values: Vec<f64> = rows.iter().flatten().copied().collect();
        let g = Grid2::new(5, 3).unwrap();
        let b = maximin(&g, &values, g.index(0, 1), g.index(4, 1)).unwrap().unwrap();
        assert_eq!(b.value, 3.0);
        assert_eq!(g.coords(b.cell).1, 2);
        assert_eq!(values[b.cell], 3.0);
        assert_eq!((b.path[0], *b.path.last().unwrap()), (g.index(0, 1), g.index(4, 1)));
        assert!(b.path.iter().all(|&c| values[c] >= 3.0));
    }

    #[test]
    fn diagonal_depends_on_its_corners() {
        let g = Grid2::new(2, 2).unwrap();
        let values = [5.0, 1.0, 1.0, 5.0];
        let b = maximin(&g, &values, 0, 3).unwrap().unwrap();
        assert_eq!(b.value, 1.0);
        assert!(b.cell == 1 || b.cell == 2);
    }

    #[test]
    fn unreachable_and_bad_input() {
        let mut g = Grid2::new(3, 1).unwrap();
        g.set_blocked(1, 0, true);
        assert_eq!(maximin(&g, &[1.0; 3], 0, 2).unwrap(), None);
        assert_eq!(maximin(&g, &[1.0, f64::NAN, 1.0], 0, 2), Err(SearchError::NanValue(1)));
        assert!(matches!(maximin(&g, &[1.0; 2], 0, 2), Err(SearchError::BufferLength { .. })));
        let g = Grid2::new(1, 1).unwrap();
        let b = maximin(&g, &[-4.0], 0, 0).unwrap().unwrap();
        assert_eq!((b.value, b.cell, b.path), (-4.0, 0, vec![0]));
    }
}
