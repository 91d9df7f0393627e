//! Occupancy grids: 8-connected [`Grid2`] and 26-connected [`Grid3`].
//!
//! # Connectivity rule (no corner cutting)
//!
//! A move from cell `c` by the offset `d` (each component in `{-1, 0, 1}`, not all
//! zero) is allowed iff **every cell of the axis-aligned box spanned by `c` and
//! `c + d` is free**, i.e. every cell `c + e` with `e_a ∈ {0, d_a}` for each axis `a`.
//!
//! * Orthogonal move: the box is the two cells themselves.
//! * 2-D diagonal `(±1, ±1)`: the box is 2×2, so both orthogonal neighbours
//!   must be free — a diagonal never squeezes between two blocked cells that touch
//!   at a corner, nor clips the corner of a single blocked cell.
//! * 3-D face diagonal (two non-zero components): a 2×2×1 box (4 cells).
//! * 3-D space diagonal (three non-zero components): the 2×2×2 box (8 cells).
//!
//! The rule is exactly "the straight segment between the two cell centres touches
//! only free cells (closed cells, corners and edges included)", which is the
//! line-of-sight rule of [`crate::los`]; so every grid move is a visible segment
//! and Theta* can always fall back to the grid move.
//!
//! Cells are flat `usize` indices: `i + nx * j` in 2-D, `i + nx * (j + ny * k)` in 3-D.
//! Cell size is the caller's concern: costs come from closures.

use std::sync::OnceLock;

use crate::SearchError;

/// Largest supported number of cells (2^31): parents are stored as `u32` with
/// `u32::MAX` as "none", and 2^31 cells already need 8 GiB for the g-scores.
pub const MAX_CELLS: usize = 1 << 31;

/// A grid the searches can run on.
pub trait SearchGrid {
    /// Number of cells; valid cells are `0..cell_count()`.
    fn cell_count(&self) -> usize;
    /// `true` when the cell cannot be entered.
    fn is_blocked(&self, cell: usize) -> bool;
    /// Calls `f(neighbour)` for every allowed move out of `cell` (see the module
    /// docs for the rule), in a fixed order. `cell` itself must be free.
    fn for_each_neighbour<F: FnMut(usize)>(&self, cell: usize, f: F);
}

fn check_dims(dims: &[usize]) -> Result<usize, SearchError> {
    let cells = dims.iter().fold(1u128, |acc, &d| acc.saturating_mul(d as u128));
    if cells == 0 || cells > MAX_CELLS as u128 {
        let dims = dims.iter().map(|d| d.to_string()).collect::<Vec<_>>().join(" x ");
        return Err(SearchError::GridSize { dims, cells });
    }
    Ok(cells as usize)
}

/// A 2-D occupancy grid, 8-connected without corner cutting.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Grid2 {
    nx: usize,
    ny: usize,
    blocked: Vec<bool>,
}

impl Grid2 {
    /// An all-free grid. Errors when `nx * ny` is zero or exceeds [`MAX_CELLS`].
    pub fn new(nx: usize, ny: usize) -> Result<Self, SearchError> {
        let cells = check_dims(&[nx, ny])?;
        Ok(Self { nx, ny, blocked: vec![false; cells] })
    }

    /// A grid from a flat blocked mask (`blocked[i + nx * j]`).
    pub fn from_blocked(nx: usize, ny: usize, blocked: Vec<bool>) -> Result<Self, SearchError> {
        let cells = check_dims(&[nx, ny])?;
        if blocked.len() != cells {
            return Err(SearchError::BufferLength { what: "blocked mask", got: blocked.len(), cells });
        }
        Ok(Self { nx, ny, blocked })
    }

    /// Cells along x.
    pub fn nx(&self) -> usize {
        self.nx
    }
    /// Cells along y.
    pub fn ny(&self) -> usize {
        self.ny
    }
    /// Number of cells.
    pub fn len(&self) -> usize {
        self.blocked.len()
    }
    /// Never true (a grid has at least one cell); for clippy's `len` convention.
    pub fn is_empty(&self) -> bool {
        self.blocked.is_empty()
    }
    /// Flat index of `(i, j)`. Panics in debug builds if out of range.
    #[inline]
    pub fn index(&self, i: usize, j: usize) -> usize {
        debug_assert!(i < self.nx && j < self.ny);
        i + self.nx * j
    }
    /// `(i, j)` of a flat index.
    #[inline]
    pub fn coords(&self, cell: usize) -> (usize, usize) {
        (cell % self.nx, cell / self.nx)
    }
    /// The blocked mask, `blocked[i + nx * j]`.
    pub fn blocked(&self) -> &[bool] {
        &self.blocked
    }
    /// Mutable blocked mask.
    pub fn blocked_mut(&mut self) -> &mut [bool] {
        &mut self.blocked
    }
    /// Marks `(i, j)` blocked or free.
    pub fn set_blocked(&mut self, i: usize, j: usize, blocked: bool) {
        let c = self.index(i, j);
        self.blocked[c] = blocked;
    }
    /// Length of one move in cell units: 1 orthogonal, √2 diagonal (the cells
    /// are assumed adjacent).
    #[inline]
    pub fn step_length(&self, from: usize, to: usize) -> f64 {
        let d = from.abs_diff(to);
        // Diagonal steps differ by nx ± 1, so a difference of 1 is orthogonal
        // unless nx == 2 (where nx - 1 == 1 too): then compare rows.
        let orthogonal = d == self.nx || (d == 1 && (self.nx != 2 || from / 2 == to / 2));
        if orthogonal {
            1.0
        } else {
            std::f64::consts::SQRT_2
        }
    }
    /// Euclidean distance between cell centres, in cell units.
    pub fn euclidean(&self, a: usize, b: usize) -> f64 {
        let (ai, aj) = self.coords(a);
        let (bi, bj) = self.coords(b);
        let dx = ai.abs_diff(bi) as f64;
        let dy = aj.abs_diff(bj) as f64;
        dx.hypot(dy)
    }
    /// Octile distance (the 8-connected shortest length on an empty grid), in
    /// cell units: an admissible and consistent heuristic for unit-length moves.
    #[inline]
    pub fn octile(&self, a: usize, b: usize) -> f64 {
        let (ai, aj) = self.coords(a);
        let (bi, bj) = self.coords(b);
        let dx = ai.abs_diff(bi) as f64;
        let dy = aj.abs_diff(bj) as f64;
        let (lo, hi) = if dx < dy { (dx, dy) } else { (dy, dx) };
        hi + (std::f64::consts::SQRT_2 - 1.0) * lo
    }
}

impl SearchGrid for Grid2 {
    #[inline]
    fn cell_count(&self) -> usize {
        self.blocked.len()
    }
    #[inline]
    fn is_blocked(&self, cell: usize) -> bool {
        self.blocked[cell]
    }
    #[inline]
    fn for_each_neighbour<F: FnMut(usize)>(&self, cell: usize, mut f: F) {
        let nx = self.nx;
        let (i, j) = (cell % nx, cell / nx);
        let b = &self.blocked;
        let has_w = i > 0;
        let has_e = i + 1 < nx;
        let has_s = j > 0;
        let has_n = j + 1 < self.ny;
        let w = has_w && !b[cell - 1];
        let e = has_e && !b[cell + 1];
        let s = has_s && !b[cell - nx];
        let n = has_n && !b[cell + nx];
        if e {
            f(cell + 1);
        }
        if n {
            f(cell + nx);
        }
        if w {
            f(cell - 1);
        }
        if s {
            f(cell - nx);
        }
        if n && e && !b[cell + nx + 1] {
            f(cell + nx + 1);
        }
        if n && w && !b[cell + nx - 1] {
            f(cell + nx - 1);
        }
        if s && w && !b[cell - nx - 1] {
            f(cell - nx - 1);
        }
        if s && e && !b[cell - nx + 1] {
            f(cell - nx + 1);
        }
    }
}

/// A 3-D occupancy grid, 26-connected without corner cutting (box rule, see the
/// module docs).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Grid3 {
    nx: usize,
    ny: usize,
    nz: usize,
    blocked: Vec<bool>,
    /// The 26 flat offsets sorted, with their number of non-zero components,
    /// when they are distinct (nx, ny ≥ 3): `step_length` then needs no division.
    offsets: Option<Vec<(isize, u8)>>,
}

/// One of the 26 moves, with the slots (in the 3×3×3 neighbourhood) of the moves
/// obtained by zeroing one of its non-zero components. By induction on the
/// number of non-zero components, "target free and every sub-move allowed" is
/// exactly the box rule.
#[derive(Debug, Clone, Copy)]
struct Move3 {
    d: [isize; 3],
    slot: usize,
    subs: [usize; 3],
    nsubs: usize,
    /// Axes (bits) along which the move goes down / up: it leaves the grid
    /// when it goes down at a low face or up at a high face.
    down: u8,
    up: u8,
}

fn slot(d: [isize; 3]) -> usize {
    ((d[0] + 1) + 3 * (d[1] + 1) + 9 * (d[2] + 1)) as usize
}

fn moves3() -> &'static [Move3; 26] {
    static TABLE: OnceLock<[Move3; 26]> = OnceLock::new();
    TABLE.get_or_init(|| {
        let mut all = Vec::with_capacity(26);
        for nnz in 1..=3 {
            for dk in -1..=1isize {
                for dj in -1..=1isize {
                    for di in -1..=1isize {
                        let d = [di, dj, dk];
                        if d.iter().filter(|&&x| x != 0).count() != nnz {
                            continue;
                        }
                        let mut subs = [0; 3];
                        let mut nsubs = 0;
                        if nnz > 1 {
                            for a in 0..3 {
                                if d[a] != 0 {
                                    let mut s = d;
                                    s[a] = 0;
                                    subs[nsubs] = slot(s);
                                    nsubs += 1;
                                }
                            }
                        }
                        let axes = |want: isize| (0..3).filter(|&a| d[a] == want).fold(0u8, |m, a| m | 1 << a);
                        all.push(Move3 { d, slot: slot(d), subs, nsubs, down: axes(-1), up: axes(1) });
                    }
                }
            }
        }
        all.try_into().expect("26 moves")
    })
}

impl Grid3 {
    /// An all-free grid. Errors when `nx * ny * nz` is zero or exceeds [`MAX_CELLS`].
    pub fn new(nx: usize, ny: usize, nz: usize) -> Result<Self, SearchError> {
        let cells = check_dims(&[nx, ny, nz])?;
        Self::from_blocked(nx, ny, nz, vec![false; cells])
    }

    /// A grid from a flat blocked mask (`blocked[i + nx * (j + ny * k)]`).
    pub fn from_blocked(nx: usize, ny: usize, nz: usize, blocked: Vec<bool>) -> Result<Self, SearchError> {
        let cells = check_dims(&[nx, ny, nz])?;
        if blocked.len() != cells {
            return Err(SearchError::BufferLength { what: "blocked mask", got: blocked.len(), cells });
        }
        let offsets = (nx >= 3 && ny >= 3).then(|| {
            let mut v: Vec<(isize, u8)> = moves3()
                .iter()
                .map(|m| {
                    let off = m.d[0] + m.d[1] * nx as isize + m.d[2] * (nx * ny) as isize;
                    (off, m.d.iter().filter(|&&x| x != 0).count() as u8)
                })
                .collect();
            v.sort();
            v
        });
        Ok(Self { nx, ny, nz, blocked, offsets })
    }

    /// Cells along x.
    pub fn nx(&self) -> usize {
        self.nx
    }
    /// Cells along y.
    pub fn ny(&self) -> usize {
        self.ny
    }
    /// Cells along z.
    pub fn nz(&self) -> usize {
        self.nz
    }
    /// Number of cells.
    pub fn len(&self) -> usize {
        self.blocked.len()
    }
    /// Never true (a grid has at least one cell).
    pub fn is_empty(&self) -> bool {
        self.blocked.is_empty()
    }
    /// Flat index of `(i, j, k)`.
    #[inline]
    pub fn index(&self, i: usize, j: usize, k: usize) -> usize {
        debug_assert!(i < self.nx && j < self.ny && k < self.nz);
        i + self.nx * (j + self.ny * k)
    }
    /// `(i, j, k)` of a flat index.
    #[inline]
    pub fn coords(&self, cell: usize) -> (usize, usize, usize) {
        let i = cell % self.nx;
        let r = cell / self.nx;
        (i, r % self.ny, r / self.ny)
    }
    /// The blocked mask.
    pub fn blocked(&self) -> &[bool] {
        &self.blocked
    }
    /// Mutable blocked mask.
    pub fn blocked_mut(&mut self) -> &mut [bool] {
        &mut self.blocked
    }
    /// Marks `(i, j, k)` blocked or free.
    pub fn set_blocked(&mut self, i: usize, j: usize, k: usize, blocked: bool) {
        let c = self.index(i, j, k);
        self.blocked[c] = blocked;
    }
    fn abs_deltas(&self, a: usize, b: usize) -> [f64; 3] {
        let (ai, aj, ak) = self.coords(a);
        let (bi, bj, bk) = self.coords(b);
        [ai.abs_diff(bi) as f64, aj.abs_diff(bj) as f64, ak.abs_diff(bk) as f64]
    }
    /// Length of one move in cell units: 1, √2 or √3 (cells assumed adjacent).
    #[inline]
    pub fn step_length(&self, from: usize, to: usize) -> f64 {
        const LEN: [f64; 4] = [0.0, 1.0, std::f64::consts::SQRT_2, 1.732_050_807_568_877_2];
        let nnz = match &self.offsets {
            Some(table) => {
                let d = to as isize - from as isize;
                match table.binary_search_by_key(&d, |e| e.0) {
                    Ok(k) => table[k].1,
                    Err(_) => self.nonzero_axes(from, to),
                }
            }
            None => self.nonzero_axes(from, to),
        };
        LEN[nnz.min(3) as usize]
    }
    fn nonzero_axes(&self, a: usize, b: usize) -> u8 {
        self.abs_deltas(a, b).iter().filter(|&&x| x != 0.0).count() as u8
    }
    /// Euclidean distance between cell centres, in cell units.
    pub fn euclidean(&self, a: usize, b: usize) -> f64 {
        let [dx, dy, dz] = self.abs_deltas(a, b);
        (dx * dx + dy * dy + dz * dz).sqrt()
    }
    /// The 26-connected shortest length on an empty grid (3-D "octile"): with
    /// sorted deltas `d1 ≥ d2 ≥ d3`, `√3·d3 + √2·(d2 − d3) + (d1 − d2)`.
    /// Admissible and consistent for unit-length moves.
    pub fn octile(&self, a: usize, b: usize) -> f64 {
        let mut d = self.abs_deltas(a, b);
        d.sort_by(|x, y| y.total_cmp(x));
        3f64.sqrt() * d[2] + std::f64::consts::SQRT_2 * (d[1] - d[2]) + (d[0] - d[1])
    }
}

impl SearchGrid for Grid3 {
    #[inline]
    fn cell_count(&self) -> usize {
        self.blocked.len()
    }
    #[inline]
    fn is_blocked(&self, cell: usize) -> bool {
        self.blocked[cell]
    }
    fn for_each_neighbour<F: FnMut(usize)>(&self, cell: usize, mut f: F) {
        let (i, j, k) = self.coords(cell);
        let (nx, sxy) = (self.nx as isize, (self.nx * self.ny) as isize);
        let at_low = (i == 0) as u8 | ((j == 0) as u8) << 1 | ((k == 0) as u8) << 2;
        let at_high = (i + 1 == self.nx) as u8 | ((j + 1 == self.ny) as u8) << 1 | ((k + 1 == self.nz) as u8) << 2;
        // allowed[slot] is filled in order of increasing number of non-zero
        // components, so sub-moves are decided before the moves built on them.
        let mut allowed = [false; 27];
        for m in moves3() {
            if m.down & at_low != 0 || m.up & at_high != 0 {
                continue;
            }
            let target = (cell as isize + m.d[0] + m.d[1] * nx + m.d[2] * sxy) as usize;
            if self.blocked[target] || !m.subs[..m.nsubs].iter().all(|&s| allowed[s]) {
                continue;
            }
            allowed[m.slot] = true;
            f(target);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn neighbours<G: SearchGrid>(g: &G, c: usize) -> Vec<usize> {
        let mut v = Vec::new();
        g.for_each_neighbour(c, |n| v.push(n));
        v.sort();
        v
    }

    #[test]
    fn index_round_trip() {
        let g = Grid2::new(7, 5).unwrap();
        for c in 0..g.len() {
            let (i, j) = g.coords(c);
            assert_eq!(g.index(i, j), c);
        }
        let g = Grid3::new(4, 3, 5).unwrap();
        for c in 0..g.len() {
            let (i, j, k) = g.coords(c);
            assert_eq!(g.index(i, j, k), c);
        }
    }

    #[test]
    fn refuses_absurd_sizes() {
        let e = Grid2::new(1 << 16, 1 << 16).unwrap_err();
        assert!(e.to_string().contains("65536 x 65536 = 4294967296 cells"), "{e}");
        assert!(Grid2::new(0, 4).is_err());
        assert!(Grid3::new(1 << 11, 1 << 10, 1 << 11).is_err());
        assert!(Grid3::new(1 << 10, 1 << 10, 1 << 11).is_ok_and(|g| g.len() == MAX_CELLS));
        assert!(matches!(Grid2::from_blocked(3, 3, vec![false; 8]), Err(SearchError::BufferLength { got: 8, .. })));
    }

    #[test]
    fn grid2_moves_and_corner_rule() {
        let mut g = Grid2::new(3, 3).unwrap();
        assert_eq!(neighbours(&g, g.index(1, 1)).len(), 8);
        assert_eq!(neighbours(&g, g.index(0, 0)), vec![1, 3, 4]);
        // One blocked orthogonal neighbour forbids the diagonal past its corner.
        g.set_blocked(1, 0, true);
        assert_eq!(neighbours(&g, g.index(0, 0)), vec![3]);
        // (1,1) loses the two diagonals that would clip (1,0).
        let n = neighbours(&g, g.index(1, 1));
        assert!(!n.contains(&g.index(0, 0)) && !n.contains(&g.index(2, 0)) && !n.contains(&g.index(1, 0)));
        assert_eq!(n.len(), 5);
    }

    #[test]
    fn grid3_moves_and_box_rule() {
        let mut g = Grid3::new(3, 3, 3).unwrap();
        assert_eq!(neighbours(&g, g.index(1, 1, 1)).len(), 26);
        assert_eq!(neighbours(&g, 0).len(), 7);
        g.set_blocked(1, 0, 0, true);
        // Only moves whose box avoids (1,0,0) remain: (0,1,0), (0,0,1), (0,1,1).
        let want = vec![g.index(0, 1, 0), g.index(0, 0, 1), g.index(0, 1, 1)];
        let mut want = want;
        want.sort();
        assert_eq!(neighbours(&g, 0), want);
        // Block an edge-adjacent cell: the space diagonal from (0,0,0) needs all 8.
        let mut g = Grid3::new(2, 2, 2).unwrap();
        g.set_blocked(1, 1, 0, true);
        let n = neighbours(&g, 0);
        assert!(!n.contains(&g.index(1, 1, 1)));
        assert!(n.contains(&g.index(1, 0, 1)) && n.contains(&g.index(0, 1, 1)) && n.contains(&g.index(1, 0, 0)));
        assert_eq!(n.len(), 5);
    }

    #[test]
    fn step_lengths_on_narrow_grids() {
        let g = Grid2::new(2, 3).unwrap();
        assert_eq!(g.step_length(1, 2), std::f64::consts::SQRT_2); // (1,0) -> (0,1)
        assert_eq!(g.step_length(0, 1), 1.0);
        assert_eq!(g.step_length(1, 3), 1.0);
        assert_eq!(g.step_length(0, 3), std::f64::consts::SQRT_2);
        let g = Grid2::new(1, 3).unwrap();
        assert_eq!(g.step_length(0, 1), 1.0);
    }

    #[test]
    fn step_lengths_3d_match_coordinates() {
        for (nx, ny, nz) in [(4, 5, 3), (2, 2, 2), (3, 1, 4)] {
            let g = Grid3::new(nx, ny, nz).unwrap();
            for c in 0..g.len() {
                g.for_each_neighbour(c, |n| {
                    assert_eq!(g.step_length(c, n), g.euclidean(c, n), "{nx}x{ny}x{nz}: {c} -> {n}");
                });
            }
        }
    }

    #[test]
    fn octile_distances() {
        let g = Grid2::new(10, 10).unwrap();
        let d = g.octile(g.index(0, 0), g.index(9, 5));
        assert!((d - (4.0 + 5.0 * std::f64::consts::SQRT_2)).abs() < 1e-12);
        let g = Grid3::new(10, 10, 10).unwrap();
        let d = g.octile(g.index(0, 0, 0), g.index(9, 5, 2));
        assert!((d - (2.0 * 3f64.sqrt() + 3.0 * std::f64::consts::SQRT_2 + 4.0)).abs() < 1e-12);
    }
}
