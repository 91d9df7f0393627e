//! Exact line of sight between cell centres on [`Grid2`] and [`Grid3`].
//!
//! # Rule
//!
//! The segment between the centres of cells `a` and `b` is **visible iff every
//! cell whose closed unit box (faces, edges and corners included) intersects the
//! closed segment is free.** A segment that merely grazes the corner of a
//! blocked cell is therefore blocked (conservative), and a segment running
//! exactly along a grid line needs the cells on both sides free.
//!
//! For a single grid move this is exactly the no-corner-cutting box rule of
//! [`crate::grid`]: the segment of a diagonal move passes through the shared
//! corner (2-D) or edge/vertex (3-D) of the box, which touches every cell of the
//! box. Hence every grid move is visible, and Theta* (which may always fall back
//! to the grid move) is never longer than A*.
//!
//! # Exactness
//!
//! Coordinates are doubled so cell centres are odd integers and cell boundaries
//! even integers; the segment is parametrised by `t ∈ [0, 1]`, and the set of
//! touched cells is enumerated axis by axis, clipping the `t` interval to each
//! slab `[2c, 2c + 2]` with rational arithmetic in `i128`. No floating point is
//! involved, so the answer is exact and symmetric in `a`, `b`. The work is
//! proportional to the number of touched cells (plus one per slab).

use crate::grid::{Grid2, Grid3};

/// Grids with an exact line-of-sight test between cell centres.
pub trait LineOfSight {
    /// `true` iff the segment between the centres of `a` and `b` touches only free cells.
    fn line_of_sight(&self, a: usize, b: usize) -> bool;
}

/// A non-negative-denominator rational.
#[derive(Debug, Clone, Copy)]
struct Q {
    n: i128,
    d: i128,
}

impl Q {
    fn new(n: i128, d: i128) -> Self {
        debug_assert!(d != 0);
        if d < 0 {
            Q { n: -n, d: -d }
        } else {
            Q { n, d }
        }
    }
    fn le(self, o: Q) -> bool {
        self.n * o.d <= o.n * self.d
    }
    fn max(self, o: Q) -> Q {
        if self.le(o) {
            o
        } else {
            self
        }
    }
    fn min(self, o: Q) -> Q {
        if self.le(o) {
            self
        } else {
            o
        }
    }
}

/// Calls `visit(cell)` for every cell whose closed box meets the closed segment
/// between the centres of cells `a` and `b` (integer cell coordinates, grid
/// `dims`), stopping early (and returning `false`) when `visit` returns `false`.
pub(crate) fn for_each_touched<const D: usize>(
    a: [i64; D],
    b: [i64; D],
    dims: [i64; D],
    visit: &mut impl FnMut([i64; D]) -> bool,
) -> bool {
    let mut cell = [0i64; D];
    recurse(&a, &b, &dims, 0, Q::new(0, 1), Q::new(1, 1), &mut cell, visit)
}

#[allow(clippy::too_many_arguments)]
fn recurse<const D: usize>(
    a: &[i64; D],
    b: &[i64; D],
    dims: &[i64; D],
    axis: usize,
    tlo: Q,
    thi: Q,
    cell: &mut [i64; D],
    visit: &mut impl FnMut([i64; D]) -> bool,
) -> bool {
    if axis == D {
        return visit(*cell);
    }
    // Doubled coordinate along this axis: p(t) = p0 + t * dp.
    let p0 = 2 * a[axis] as i128 + 1;
    let dp = 2 * (b[axis] - a[axis]) as i128;
    let at = |t: Q| Q { n: p0 * t.d + t.n * dp, d: t.d };
    let (x, y) = (at(tlo), at(thi));
    let (lo, hi) = (x.min(y), x.max(y));
    // Cells c with [2c, 2c + 2] ∩ [lo, hi] ≠ ∅: ceil(lo / 2) - 1 ≤ c ≤ floor(hi / 2).
    let cmin = ((-((-lo.n).div_euclid(2 * lo.d))) - 1).max(0) as i64;
    let cmax = (hi.n.div_euclid(2 * hi.d) as i64).min(dims[axis] - 1);
    for c in cmin..=cmax {
        let (slo, shi) = if dp == 0 {
            (tlo, thi)
        } else {
            let t1 = Q::new(2 * c as i128 - p0, dp);
            let t2 = Q::new(2 * c as i128 + 2 - p0, dp);
            (tlo.max(t1.min(t2)), thi.min(t1.max(t2)))
        };
        if !slo.le(shi) {
            continue;
        }
        cell[axis] = c;
        if !recurse(a, b, dims, axis + 1, slo, shi, cell, visit) {
            return false;
        }
    }
    true
}

impl Grid2 {
    /// Every cell touched by the segment between the centres of `a` and `b`
    /// (see the module docs), in a fixed order.
    pub fn touched_cells(&self, a: usize, b: usize) -> Vec<usize> {
        let mut out = Vec::new();
        let (ai, aj) = self.coords(a);
        let (bi, bj) = self.coords(b);
        let dims = [self.nx() as i64, self.ny() as i64];
        for_each_touched([ai as i64, aj as i64], [bi as i64, bj as i64], dims, &mut |[i, j]| {
            out.push(self.index(i as usize, j as usize));
            true
        });
        out
    }
}

impl LineOfSight for Grid2 {
    fn line_of_sight(&self, a: usize, b: usize) -> bool {
        let (ai, aj) = self.coords(a);
        let (bi, bj) = self.coords(b);
        let dims = [self.nx() as i64, self.ny() as i64];
        let blocked = self.blocked();
        for_each_touched([ai as i64, aj as i64], [bi as i64, bj as i64], dims, &mut |[i, j]| {
            !blocked[i as usize + self.nx() * j as usize]
        })
    }
}

impl Grid3 {
    /// Every cell touched by the segment between the centres of `a` and `b`.
    pub fn touched_cells(&self, a: usize, b: usize) -> Vec<usize> {
        let mut out = Vec::new();
        let (ai, aj, ak) = self.coords(a);
        let (bi, bj, bk) = self.coords(b);
        let dims = [self.nx() as i64, self.ny() as i64, self.nz() as i64];
        for_each_touched(
            [ai as i64, aj as i64, ak as i64],
            [bi as i64, bj as i64, bk as i64],
            dims,
            &mut |[i, j, k]| {
                out.push(self.index(i as usize, j as usize, k as usize));
                true
            },
        );
        out
    }
}

impl LineOfSight for Grid3 {
    fn line_of_sight(&self, a: usize, b: usize) -> bool {
        let (ai, aj, ak) = self.coords(a);
        let (bi, bj, bk) = self.coords(b);
        let dims = [self.nx() as i64, self.ny() as i64, self.nz() as i64];
        let blocked = self.blocked();
        for_each_touched([ai as i64, aj as i64, ak as i64], [bi as i64, bj as i64, bk as i64], dims, &mut |[i, j, k]| {
            !blocked[self.index(i as usize, j as usize, k as usize)]
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn knight_move_touches_the_shared_edge_cells() {
        // (0.5,0.5) -> (2.5,1.5) passes through (1.5, 1.0): on the edge between
        // (1,0) and (1,1), which both count.
        let g = Grid2::new(4, 3).unwrap();
        let mut t = g.touched_cells(g.index(0, 0), g.index(2, 1));
        t.sort();
        assert_eq!(t, vec![g.index(0, 0), g.index(1, 0), g.index(1, 1), g.index(2, 1)]);
    }

    #[test]
    fn diagonal_touches_corner_cells() {
        let mut g = Grid2::new(3, 3).unwrap();
        let mut t = g.touched_cells(0, g.index(2, 2));
        t.sort();
        // The three diagonal cells plus the four cells meeting the diagonal at the two corners.
        assert_eq!(t, vec![0, 1, 3, 4, 5, 7, 8]);
        assert!(g.line_of_sight(0, 8));
        g.set_blocked(2, 1, true); // touches the corner (2, 2)
        assert!(!g.line_of_sight(0, 8) && !g.line_of_sight(8, 0));
        // A straight row only touches its own row.
        assert_eq!(g.touched_cells(0, 2), vec![0, 1, 2]);
    }

    #[test]
    fn shallow_line() {
        // (0.5,0.5) -> (5.5,1.5): crosses y = 1 at x = 3, a corner: touches
        // columns 0..=2 in row 0 and 2..=5 in row 1, plus (3,0) at that corner.
        let g = Grid2::new(6, 2).unwrap();
        let mut t = g.touched_cells(0, g.index(5, 1));
        t.sort();
        let mut want = vec![0, 1, 2, 3, g.index(2, 1), g.index(3, 1), g.index(4, 1), g.index(5, 1)];
        want.sort();
        assert_eq!(t, want);
    }

    #[test]
    fn grid3_space_diagonal_touches_the_whole_box() {
        let g = Grid3::new(2, 2, 2).unwrap();
        let mut t = g.touched_cells(0, 7);
        t.sort();
        assert_eq!(t, (0..8).collect::<Vec<_>>());
        let mut g = g;
        g.set_blocked(1, 0, 0, true);
        assert!(!g.line_of_sight(0, 7));
        assert!(g.line_of_sight(0, g.index(0, 1, 1)));
    }
}
