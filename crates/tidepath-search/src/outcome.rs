//! Search limits and outcomes shared by the grid searches.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

/// How often (in expansions) the stop flag and the deadline are polled.
///
/// Reading the clock costs about 20 ns; an expansion costs from a few
/// nanoseconds (plain A*) to milliseconds (3-D Theta*, whose relaxations test
/// long lines of sight and motions), so a deadline is kept within about 16 of
/// the slowest expansions.
pub const POLL_EVERY: u64 = 16;

/// Optional budgets for one search. The default is unlimited (the grid size
/// still bounds the work: each cell is expanded at most once).
#[derive(Debug, Clone, Copy, Default)]
pub struct Limits<'a> {
    /// Stop after this many expansions.
    pub max_expansions: Option<u64>,
    /// Stop when this flag becomes `true` (polled every [`POLL_EVERY`] expansions).
    pub stop: Option<&'a AtomicBool>,
    /// Stop once this instant has passed (polled every [`POLL_EVERY`] expansions).
    pub deadline: Option<Instant>,
}

impl Limits<'_> {
    /// No limits.
    pub fn none() -> Self {
        Self::default()
    }

    /// The stop flag or the deadline, polled now: for loops that count no expansions (graph
    /// construction), which call it every few dozen steps.
    pub fn interrupted(&self) -> Option<StopReason> {
        if self.stop.is_some_and(|f| f.load(Ordering::Relaxed)) {
            return Some(StopReason::StopFlag);
        }
        if self.deadline.is_some_and(|d| Instant::now() >= d) {
            return Some(StopReason::Deadline);
        }
        None
    }

    /// Checks the limits before expansion number `expansions + 1`.
    #[inline]
    pub(crate) fn check(&self, expansions: u64) -> Option<StopReason> {
        if let Some(max) = self.max_expansions {
            if expansions >= max {
                return Some(StopReason::MaxExpansions);
            }
        }
        if expansions % POLL_EVERY == 0 {
            if let Some(flag) = self.stop {
                if flag.load(Ordering::Relaxed) {
                    return Some(StopReason::StopFlag);
                }
            }
            if let Some(deadline) = self.deadline {
                if Instant::now() >= deadline {
                    return Some(StopReason::Deadline);
                }
            }
        }
        None
    }
}

/// Why a search gave up before it could prove anything.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StopReason {
    /// [`Limits::max_expansions`] was reached.
    MaxExpansions,
    /// [`Limits::stop`] was raised.
    StopFlag,
    /// [`Limits::deadline`] passed.
    Deadline,
}

/// What a search established.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SearchStatus {
    /// A path was found; with an admissible heuristic (and FIFO edge costs) it is optimal.
    Found,
    /// Proved: the open list emptied without reaching the goal.
    NoPath,
    /// Gave up; nothing is proved about the existence of a path.
    Stopped(StopReason),
}

/// Result of a grid search.
#[derive(Debug, Clone, PartialEq)]
pub struct SearchOutcome {
    /// Found, proved unreachable, or stopped.
    pub status: SearchStatus,
    /// Cells from start to goal inclusive when [`SearchStatus::Found`], empty otherwise.
    pub path: Vec<usize>,
    /// Path cost when found, `f64::INFINITY` otherwise.
    pub cost: f64,
    /// Number of cells expanded (closed).
    pub expansions: u64,
}

impl SearchOutcome {
    /// `true` when a path was found.
    pub fn found(&self) -> bool {
        self.status == SearchStatus::Found
    }
}
