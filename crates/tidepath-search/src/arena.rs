//! Reusable buffers for the grid searches.
//!
//! A search on a 1000 × 1000 grid needs ~13 MB of per-cell state; allocating it
//! on every call would dominate short searches, so callers that search the same
//! world repeatedly keep one [`SearchArena`] and pass it to the `*_in` functions.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// "No parent" marker in the `u32` parent array (cells are < 2^31).
pub(crate) const NO_PARENT: u32 = u32::MAX;

/// An open-list entry. The heap is a max-heap, so the order is reversed on `f`:
/// the smallest `f` pops first; among equal `f` the largest `g` (the deeper
/// node, fewer re-expansions of the frontier) and then the smallest cell index,
/// so ties are broken deterministically.
#[derive(Debug, Clone, Copy)]
pub(crate) struct OpenEntry {
    pub f: f64,
    pub g: f64,
    pub cell: u32,
}

impl PartialEq for OpenEntry {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for OpenEntry {}
impl PartialOrd for OpenEntry {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for OpenEntry {
    #[inline]
    fn cmp(&self, other: &Self) -> Ordering {
        other.f.total_cmp(&self.f).then_with(|| self.g.total_cmp(&other.g)).then_with(|| other.cell.cmp(&self.cell))
    }
}

/// Per-cell scratch state for A*, Theta* and the flood fills. Keep one between
/// searches to avoid reallocating; it resizes itself to the grid it is used on.
#[derive(Debug, Default)]
pub struct SearchArena {
    pub(crate) g: Vec<f64>,
    pub(crate) parent: Vec<u32>,
    pub(crate) closed: Vec<u64>,
    pub(crate) open: BinaryHeap<OpenEntry>,
    pub(crate) stack: Vec<u32>,
}

impl SearchArena {
    /// An empty arena; buffers grow on first use.
    pub fn new() -> Self {
        Self::default()
    }

    /// Prepares the buffers for a search over `cells` cells: g = +∞, no parents,
    /// nothing closed, empty open list.
    pub(crate) fn reset(&mut self, cells: usize) {
        self.g.clear();
        self.g.resize(cells, f64::INFINITY);
        self.parent.clear();
        self.parent.resize(cells, NO_PARENT);
        self.reset_closed(cells);
        self.open.clear();
        self.stack.clear();
    }

    /// Clears only the closed/visited bitset (for flood fills).
    pub(crate) fn reset_closed(&mut self, cells: usize) {
        self.closed.clear();
        self.closed.resize(cells.div_ceil(64), 0);
    }

    #[inline]
    pub(crate) fn is_closed(&self, cell: usize) -> bool {
        self.closed[cell >> 6] & (1u64 << (cell & 63)) != 0
    }

    #[inline]
    pub(crate) fn close(&mut self, cell: usize) {
        self.closed[cell >> 6] |= 1u64 << (cell & 63);
    }

    /// Walks the parent chain back from `goal` and returns start..goal.
    pub(crate) fn path_to(&self, goal: usize) -> Vec<usize> {
        let mut path = vec![goal];
        let mut c = goal;
        // Bounded: a parent chain visits each cell at most once.
        while self.parent[c] != NO_PARENT {
            c = self.parent[c] as usize;
            path.push(c);
            debug_assert!(path.len() <= self.parent.len());
        }
        path.reverse();
        path
    }
}
