//! Errors shared by every search in this crate.
//!
//! Giving up (limits) is not an error and not a "no path": it is
//! [`crate::SearchStatus::Stopped`]. Errors are reserved for inputs that make the
//! question itself ill-posed (a blocked start, a cell outside the grid, a grid
//! too large to index with the `u32` parent array).

/// Why a search could not be run at all.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SearchError {
    /// The grid would have more cells than [`crate::MAX_CELLS`] (or a dimension is zero).
    #[error("grid of {dims} = {cells} cells is not supported: need between 1 and {max} cells", max = crate::MAX_CELLS)]
    GridSize {
        /// The requested dimensions, e.g. `1000 x 1000`.
        dims: String,
        /// Their product (saturating).
        cells: u128,
    },
    /// A blocked-cell buffer or value buffer does not have one entry per cell.
    #[error("{what} has {got} entries but the grid has {cells} cells")]
    BufferLength {
        /// Which buffer.
        what: &'static str,
        /// Its length.
        got: usize,
        /// The grid's cell count.
        cells: usize,
    },
    /// A cell index (flat) is not inside the grid.
    #[error("cell {cell} is outside the grid of {cells} cells")]
    CellOutOfRange {
        /// The offending flat index.
        cell: usize,
        /// The grid's cell count.
        cells: usize,
    },
    /// The start cell is blocked, so no search is meaningful.
    #[error("start cell {0} is blocked")]
    StartBlocked(usize),
    /// The goal cell is blocked, so no search is meaningful.
    #[error("goal cell {0} is blocked")]
    GoalBlocked(usize),
    /// A per-cell value is NaN (maximin needs a total order).
    #[error("value at cell {0} is NaN")]
    NanValue(usize),
}
