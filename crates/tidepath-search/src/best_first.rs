//! The one best-first search loop behind A*, Theta* and the planners to come.
//!
//! Every label-setting search in this crate pops the open node with the
//! smallest `f = g + h`, stops at a goal, checks the [`Limits`], closes the node
//! and then *expands* it: offers its successors with a candidate `g` and
//! parent. Only the expansion differs between planners, so it is the hook
//! ([`Expand`]); the loop owns everything that must behave the same everywhere:
//! stale-entry skipping, the goal test, the limits (polled every
//! [`crate::POLL_EVERY`] expansions), expansion counting, tie-breaking (see
//! [`crate::arena`]) and the three outcomes.
//!
//! # Nodes are indices, not cells
//!
//! The loop sees nodes `0..nodes` and nothing else: g, parent and the closed
//! set live in a [`SearchArena`] indexed by node. On a grid a node is a cell
//! ([`crate::relax`] adapts grids and keeps the per-neighbour step as a
//! smaller hook). A search whose states are not cells — Hybrid-A* over motion
//! primitives, with a continuous pose per state — numbers its discretised
//! states (e.g. cell × heading bin) as nodes and keeps the continuous part in
//! its own table indexed by node, written when [`Frontier::offer`] says the
//! offer was taken; its goal test ("within tolerance of the goal pose") is the
//! `is_goal` predicate, and an analytic shot to the goal can be offered as an
//! extra goal node. Lazy Theta* will need one more hook, run when a node is
//! popped and before the goal test (to check the assumed line of sight); it is
//! not here because nothing uses it yet.

use std::collections::BinaryHeap;

use crate::arena::{OpenEntry, SearchArena, NO_PARENT};
use crate::grid::MAX_CELLS;
use crate::outcome::{Limits, SearchOutcome, SearchStatus};
use crate::SearchError;

/// The node being expanded, read once per expansion so the hook does not
/// re-read it for every successor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Expanded {
    /// The node's index.
    pub node: usize,
    /// Its cost from the start (final: the node is closed).
    pub g: f64,
    /// The node it was reached from; `None` for the start.
    pub parent: Option<usize>,
}

/// The expansion hook: what a planner does with a node it has just closed.
pub trait Expand {
    /// Offers the successors of `u` to `frontier` ([`Frontier::offer`]).
    /// Successors that are already closed must be skipped
    /// ([`Frontier::is_closed`]): their g is final.
    fn expand<H: FnMut(usize) -> f64>(&mut self, u: Expanded, frontier: &mut Frontier<'_, H>);
}

/// The search state an [`Expand`] hook may read (g, parents, closed set) and
/// the one way it may change it ([`Frontier::offer`]), so that the loop's
/// invariants (closed g is final, every improvement is queued) cannot be broken
/// by a hook.
pub struct Frontier<'a, H> {
    g: &'a mut [f64],
    parent: &'a mut [u32],
    closed: &'a mut [u64],
    open: &'a mut BinaryHeap<OpenEntry>,
    heuristic: H,
}

impl<H: FnMut(usize) -> f64> Frontier<'_, H> {
    /// `true` when `node` has been expanded (its g is final).
    #[inline]
    pub fn is_closed(&self, node: usize) -> bool {
        self.closed[node >> 6] & (1u64 << (node & 63)) != 0
    }

    /// The best cost found so far to `node` (+∞ if not reached).
    #[inline]
    pub fn g(&self, node: usize) -> f64 {
        self.g[node]
    }

    /// The node `node` is currently reached from (`None` for the start or an
    /// unreached node).
    #[inline]
    pub fn parent(&self, node: usize) -> Option<usize> {
        let p = self.parent[node];
        (p != NO_PARENT).then_some(p as usize)
    }

    /// Offers reaching `node` at cost `g` from `parent`: taken (and queued with
    /// `f = g + h(node)`) iff `g` is strictly below the best so far, so among
    /// equal offers the first one stays. Returns whether it was taken.
    /// `node` must not be closed.
    #[inline]
    pub fn offer(&mut self, node: usize, g: f64, parent: usize) -> bool {
        debug_assert!(!self.is_closed(node), "offer to closed node {node}");
        if g < self.g[node] {
            self.g[node] = g;
            self.parent[node] = parent as u32;
            let h = (self.heuristic)(node);
            debug_assert!(!h.is_nan(), "heuristic is NaN at node {node}");
            self.open.push(OpenEntry::new(g + h, g, node));
            true
        } else {
            false
        }
    }
}

/// Best-first search over nodes `0..nodes` from `start` until a node
/// satisfying `is_goal` is popped, growing through `expand`.
///
/// * `heuristic(node)`: a lower bound on the cost to a goal; the result is
///   optimal when it is consistent and each node's g is final when it is
///   popped (as for A*; Theta* is not optimal any-angle anyway).
/// * Each node is expanded at most once (no re-opening), so `nodes` bounds
///   the work.
///
/// Status `Found` (path of nodes start..goal and the goal's g), `NoPath`
/// (proved: the open list emptied) or `Stopped` (a limit hit; nothing proved).
/// Errors when `nodes` is 0 or above [`MAX_CELLS`] (parents are `u32`) or
/// `start` is not below `nodes`; checking that the start is usable is the
/// caller's business.
pub fn best_first<E, H, T>(
    arena: &mut SearchArena,
    nodes: usize,
    start: usize,
    mut is_goal: T,
    mut heuristic: H,
    expand: &mut E,
    limits: &Limits,
) -> Result<SearchOutcome, SearchError>
where
    E: Expand,
    H: FnMut(usize) -> f64,
    T: FnMut(usize) -> bool,
{
    if nodes == 0 || nodes > MAX_CELLS {
        return Err(SearchError::GridSize { dims: format!("{nodes} nodes"), cells: nodes as u128 });
    }
    if start >= nodes {
        return Err(SearchError::CellOutOfRange { cell: start, cells: nodes });
    }
    arena.reset(nodes);
    arena.g[start] = 0.0;
    arena.open.push(OpenEntry::new(heuristic(start), 0.0, start));
    let mut expansions = 0u64;
    let SearchArena { g, parent, closed, open, .. } = arena;
    let mut frontier = Frontier { g, parent, closed, open, heuristic };
    let end = loop {
        let Some(entry) = frontier.open.pop() else {
            break None;
        };
        let u = entry.cell();
        if frontier.is_closed(u) {
            continue; // a stale duplicate: u was reached more cheaply before
        }
        if is_goal(u) {
            break Some(Ok(u));
        }
        if let Some(reason) = limits.check(expansions) {
            break Some(Err(reason));
        }
        frontier.closed[u >> 6] |= 1u64 << (u & 63);
        expansions += 1;
        let here = Expanded { node: u, g: frontier.g[u], parent: frontier.parent(u) };
        expand.expand(here, &mut frontier);
    };
    Ok(match end {
        Some(Ok(goal)) => {
            SearchOutcome { status: SearchStatus::Found, path: arena.path_to(goal), cost: arena.g[goal], expansions }
        }
        Some(Err(reason)) => not_found(SearchStatus::Stopped(reason), expansions),
        None => not_found(SearchStatus::NoPath, expansions),
    })
}

fn not_found(status: SearchStatus, expansions: u64) -> SearchOutcome {
    debug_assert!(!matches!(status, SearchStatus::Found));
    SearchOutcome { status, path: Vec::new(), cost: f64::INFINITY, expansions }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::StopReason;

    /// A plain weighted digraph: nodes that are not grid cells.
    struct Graph {
        edges: Vec<Vec<(usize, f64)>>,
        /// Offers taken, in order: `(node, g, parent)`.
        taken: Vec<(usize, f64, usize)>,
    }

    impl Expand for Graph {
        fn expand<H: FnMut(usize) -> f64>(&mut self, u: Expanded, frontier: &mut Frontier<'_, H>) {
            for &(v, c) in &self.edges[u.node] {
                if !frontier.is_closed(v) && frontier.offer(v, u.g + c, u.node) {
                    self.taken.push((v, u.g + c, u.node));
                }
            }
        }
    }

    fn graph(edges: &[(usize, usize, f64)], nodes: usize) -> Graph {
        let mut adj = vec![Vec::new(); nodes];
        for &(a, b, c) in edges {
            adj[a].push((b, c));
        }
        Graph { edges: adj, taken: Vec::new() }
    }

    #[test]
    fn dijkstra_on_a_graph_with_two_goals() {
        // 0 -> 1 -> 3 costs 2, 0 -> 2 -> 3 costs 3; 3 -> 4 (goal) 5; 0 -> 5 (goal) 6.
        let mut gr = graph(&[(0, 1, 1.0), (1, 3, 1.0), (0, 2, 1.0), (2, 3, 2.0), (3, 4, 5.0), (0, 5, 6.0)], 6);
        let mut arena = SearchArena::new();
        let o = best_first(&mut arena, 6, 0, |u| u == 4 || u == 5, |_| 0.0, &mut gr, &Limits::none()).unwrap();
        assert_eq!(o.status, SearchStatus::Found);
        assert_eq!((o.path, o.cost), (vec![0, 5], 6.0));
        // 3 was first offered from 1 (g 2) and later from 2 (g 3): refused.
        assert_eq!(gr.taken.iter().filter(|t| t.0 == 3).collect::<Vec<_>>(), vec![&(3, 2.0, 1)]);
        // Expanded 0, 1, 2, 3 (g 0, 1, 1, 2); 5 (g 6) pops before 4 (g 7).
        assert_eq!(o.expansions, 4);
    }

    #[test]
    fn heuristic_orders_the_open_list_and_equal_offers_keep_the_first() {
        // Two routes of cost 2 to node 3; the heuristic steers towards 2.
        let mut gr = graph(&[(0, 1, 1.0), (0, 2, 1.0), (1, 3, 1.0), (2, 3, 1.0)], 4);
        let h = |u: usize| {
            if u == 1 {
                1.5
            } else if u == 2 {
                1.0
            } else {
                0.0
            }
        };
        let o = best_first(&mut SearchArena::new(), 4, 0, |u| u == 3, h, &mut gr, &Limits::none()).unwrap();
        assert_eq!((o.path, o.cost, o.expansions), (vec![0, 2, 3], 2.0, 2));
        // Without the heuristic, tie-breaking (same f and g: smaller node) expands 1 first.
        let mut gr = graph(&[(0, 1, 1.0), (0, 2, 1.0), (1, 3, 1.0), (2, 3, 1.0)], 4);
        let o = best_first(&mut SearchArena::new(), 4, 0, |u| u == 3, |_| 0.0, &mut gr, &Limits::none()).unwrap();
        assert_eq!((o.path, o.expansions), (vec![0, 1, 3], 3));
    }

    #[test]
    fn no_path_is_proved_and_limits_only_stop() {
        let mut gr = graph(&[(0, 1, 1.0), (1, 0, 1.0)], 3);
        let o = best_first(&mut SearchArena::new(), 3, 0, |u| u == 2, |_| 0.0, &mut gr, &Limits::none()).unwrap();
        assert_eq!((o.status, o.expansions, o.cost), (SearchStatus::NoPath, 2, f64::INFINITY));
        let lim = Limits { max_expansions: Some(1), ..Limits::none() };
        let o = best_first(&mut SearchArena::new(), 3, 0, |u| u == 2, |_| 0.0, &mut gr, &lim).unwrap();
        assert_eq!((o.status, o.expansions), (SearchStatus::Stopped(StopReason::MaxExpansions), 1));
        assert!(o.path.is_empty());
        // The start may itself be a goal: found before any expansion.
        let o = best_first(&mut SearchArena::new(), 3, 1, |u| u == 1, |_| 0.0, &mut gr, &lim).unwrap();
        assert_eq!((o.path, o.cost, o.expansions), (vec![1], 0.0, 0));
    }

    #[test]
    fn bad_node_counts_and_starts_are_errors() {
        let mut gr = graph(&[], 1);
        let mut arena = SearchArena::new();
        let mut run = |nodes, start| best_first(&mut arena, nodes, start, |_| false, |_| 0.0, &mut gr, &Limits::none());
        assert!(matches!(run(0, 0), Err(SearchError::GridSize { .. })));
        assert!(matches!(run(MAX_CELLS + 1, 0), Err(SearchError::GridSize { .. })));
        assert_eq!(run(1, 1), Err(SearchError::CellOutOfRange { cell: 1, cells: 1 }));
    }
}
