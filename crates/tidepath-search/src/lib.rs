//! Exact graph and grid search for tidepath.
//!
//! Pure algorithms with no dependency on the rest of tidepath: the core
//! rasterises its worlds into [`Grid2`] / [`Grid3`] and prices moves with
//! closures; this crate finds optimal routes, proves that none exists, or says
//! plainly that it gave up (limits), never confusing the last two.
//!
//! * [`astar`] / [`astar_in`]: A* (Dijkstra with a zero heuristic), time-dependent
//!   costs via `g_from`.
//! * [`theta_star`] / [`theta_star_in`]: any-angle Theta* with exact line of sight.
//! * [`best_first()`]: the one best-first loop both are built on, with an
//!   expansion hook ([`Expand`]); on grids [`OnGrid`] narrows it to a
//!   per-neighbour hook ([`Relax`]). Later planners reuse it.
//! * [`visibility::shortest_path`]: exact 2-D shortest path among circles and
//!   polygons (tangent visibility graph).
//! * [`maximin`]: bottleneck (e.g. deepest-water) path and where it pinches.
//! * [`connected`]: flood fill, 2-D and 3-D.
//!
//! Grid connectivity (no corner cutting) is described in [`grid`], line of
//! sight in [`los`]; the two rules agree on single moves.
//!
//! ```
//! use tidepath_search::{astar, connected, Grid2, Limits, SearchStatus};
//!
//! // A 7 x 7 grid with a wall at x = 3 that has one gap at y = 5.
//! let mut grid = Grid2::new(7, 7)?;
//! for j in (0..7).filter(|&j| j != 5) {
//!     grid.set_blocked(3, j, true);
//! }
//! let (start, goal) = (grid.index(0, 0), grid.index(6, 0));
//! let out = astar(
//!     &grid,
//!     start,
//!     goal,
//!     |from, to, _g_from| Some(grid.step_length(from, to)), // metres per cell = 1
//!     |cell| grid.octile(cell, goal),
//!     &Limits::none(),
//! )?;
//! assert_eq!(out.status, SearchStatus::Found);
//! assert!((out.cost - (8.0 + 4.0 * 2f64.sqrt())).abs() < 1e-9);
//! assert!(out.path.contains(&grid.index(3, 5)));
//!
//! grid.set_blocked(3, 5, true);
//! assert!(!connected(&grid, start, goal)?);
//! # Ok::<(), tidepath_search::SearchError>(())
//! ```

pub mod arena;
pub mod astar;
pub mod best_first;
pub mod connected;
pub mod error;
pub mod grid;
pub mod los;
pub mod maximin;
pub mod outcome;
pub mod relax;
pub mod theta;
pub mod visibility;

pub use arena::SearchArena;
pub use astar::{astar, astar_in};
pub use best_first::{best_first, Expand, Expanded, Frontier};
pub use connected::{connected, connected_in};
pub use error::SearchError;
pub use grid::{Grid2, Grid3, SearchGrid, MAX_CELLS};
pub use los::LineOfSight;
pub use maximin::{maximin, maximin_in, Bottleneck};
pub use outcome::{Limits, SearchOutcome, SearchStatus, StopReason, POLL_EVERY};
pub use relax::{best_first_on_grid, OnGrid, Relax};
pub use theta::{theta_star, theta_star_in};
