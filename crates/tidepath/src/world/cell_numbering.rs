//! acopf2016's cell numbering (eq. 3): the cells of an M x N grid of square cells of side a
//! are numbered s = 1..M N row by row from the south-west corner, and cell s has its centre at
//!
//!   x = x0 + a (mod(s, M) - 0.5),   y = y0 + a (ceil(s / M) - 0.5).
//!
//! Read literally the formula fails for the last cell of every row: mod(s, M) = 0 there, which
//! would put the cell half a cell west of the grid. The paper leaves that case out; we read it
//! as the row's last column, x = x0 + a (M - 0.5), which is what numbering "row by row" means
//! (with a = 1, M = 20: cell 20 is at (19.5, 0.5), cell 21 at (0.5, 1.5)).

/// The numbering of a grid of `columns` x `rows` square cells of side `cell` whose south-west
/// corner is `origin`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CellNumbering {
    pub origin: (f64, f64),
    /// Side a of a cell (m).
    pub cell: f64,
    /// M, cells per row (west to east).
    pub columns: usize,
    /// N, rows (south to north).
    pub rows: usize,
}

impl CellNumbering {
    /// How many cells the grid has (M N); 0 when it overflows.
    pub fn len(&self) -> usize {
        self.columns.checked_mul(self.rows).unwrap_or(0)
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The centre of cell `s` (eq. 3, 1-based), `None` outside 1..=M N.
    pub fn centre(&self, s: usize) -> Option<(f64, f64)> {
        let m = self.columns;
        if s == 0 || s > self.len() {
            return None;
        }
        // mod(s, M) = 0 is the row's last column (the case eq. 3 leaves out).
        let column = match s % m {
            0 => m,
            r => r,
        };
        let row = s.div_ceil(m);
        let a = self.cell;
        Some((self.origin.0 + a * (column as f64 - 0.5), self.origin.1 + a * (row as f64 - 0.5)))
    }

    /// The number of the cell holding (x, y), `None` outside the grid. A point on the edge
    /// between two cells belongs to the east or north one; the grid's own east and north edges
    /// belong to its last column and row.
    pub fn number(&self, x: f64, y: f64) -> Option<usize> {
        if self.is_empty() || self.cell.is_nan() || self.cell <= 0.0 {
            return None;
        }
        let u = (x - self.origin.0) / self.cell;
        let v = (y - self.origin.1) / self.cell;
        let (m, n) = (self.columns as f64, self.rows as f64);
        if !(u >= 0.0 && u <= m && v >= 0.0 && v <= n) {
            return None;
        }
        let i = (u.floor() as usize).min(self.columns - 1);
        let j = (v.floor() as usize).min(self.rows - 1);
        Some(j * self.columns + i + 1)
    }
}

#[cfg(test)]
mod tests;
