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
///
/// `f` is stored as an order-preserving integer key ([`key`]), so the heap's
/// sift loops do plain integer compares; `g` only breaks ties, so it is kept
/// as the same kind of key of its `f32` rounding, making an entry 16 bytes.
/// (Rounding can only merge near-ties in `g`, which the cell index then breaks:
/// still deterministic, and optimality never depends on tie-breaking.)
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct OpenEntry {
    f: u64,
    g: u32,
    cell: u32,
}

/// Maps an `f64` to a `u64` whose unsigned order is `f64::total_cmp`'s order.
#[inline]
pub(crate) fn key(x: f64) -> u64 {
    let b = x.to_bits();
    if b >> 63 == 1 {
        !b
    } else {
        b | (1 << 63)
    }
}

/// [`key`] for `f32`.
#[inline]
fn key32(x: f32) -> u32 {
    let b = x.to_bits();
    if b >> 31 == 1 {
        !b
    } else {
        b | (1 << 31)
    }
}

impl OpenEntry {
    #[inline]
    pub fn new(f: f64, g: f64, cell: usize) -> Self {
        Self { f: key(f), g: key32(g as f32), cell: cell as u32 }
    }
    #[inline]
    pub fn cell(&self) -> usize {
        self.cell as usize
    }
}

impl PartialOrd for OpenEntry {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for OpenEntry {
    #[inline]
    fn cmp(&self, other: &Self) -> Ordering {
        other.f.cmp(&self.f).then_with(|| self.g.cmp(&other.g)).then_with(|| other.cell.cmp(&self.cell))
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_follow_total_order() {
        let xs = [f64::NEG_INFINITY, -3.5, -0.0, 0.0, 1e-300, 1.0, 2.5, f64::INFINITY];
        for w in xs.windows(2) {
            assert!(key(w[0]) < key(w[1]), "{} {}", w[0], w[1]);
            assert!(key32(w[0] as f32) < key32(w[1] as f32) || w[0] as f32 == w[1] as f32);
        }
        let mut h = BinaryHeap::new();
        h.push(OpenEntry::new(2.0, 1.0, 5));
        h.push(OpenEntry::new(1.0, 0.5, 9));
        h.push(OpenEntry::new(1.0, 0.9, 7));
        h.push(OpenEntry::new(1.0, 0.9, 3));
        let order: Vec<usize> = std::iter::from_fn(|| h.pop().map(|e| e.cell())).collect();
        assert_eq!(order, vec![3, 7, 9, 5]);
    }
}
