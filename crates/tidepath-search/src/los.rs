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
//! slab `[2c, 2c + 2]` with rational arithmetic in integers (`i64` on grids up to
//! 2^19 cells a side, `i128` beyond). No floating point is
//! involved, so the answer is exact and symmetric in `a`, `b`. The work is
//! proportional to the number of touched cells (plus one per slab).

use crate::grid::{Grid2, Grid3};

/// Grids with an exact line-of-sight test between cell centres.
pub trait LineOfSight {
    /// `true` iff the segment between the centres of `a` and `b` touches only free cells.
    fn line_of_sight(&self, a: usize, b: usize) -> bool;
}

/// The integer type of the exact arithmetic: `i64` when every grid side is at most
/// [`SMALL_SIDE`] cells, `i128` otherwise. With side S, doubled coordinates are at most
/// 2S + 1, slab parameters t = n/d have |n| <= d <= 2S, a coordinate at t has numerator at most
/// 8S² over d, and comparing two of those multiplies up to 16S³: below 2^63 for S <= 2^19. Same answers, the narrow type is several times faster.
trait Int:
    Copy
    + Ord
    + std::ops::Add<Output = Self>
    + std::ops::Sub<Output = Self>
    + std::ops::Mul<Output = Self>
    + std::ops::Neg<Output = Self>
{
    fn of(v: i64) -> Self;
    fn to_i64(self) -> i64;
    fn div_e(self, d: Self) -> Self;
}

impl Int for i64 {
    fn of(v: i64) -> Self {
        v
    }
    fn to_i64(self) -> i64 {
        self
    }
    fn div_e(self, d: Self) -> Self {
        self.div_euclid(d)
    }
}

impl Int for i128 {
    fn of(v: i64) -> Self {
        v as i128
    }
    fn to_i64(self) -> i64 {
        self as i64
    }
    fn div_e(self, d: Self) -> Self {
        self.div_euclid(d)
    }
}

/// Longest grid side for which the `i64` arithmetic cannot overflow.
const SMALL_SIDE: i64 = 1 << 19;

/// A non-negative-denominator rational.
#[derive(Debug, Clone, Copy)]
struct Q<I> {
    n: I,
    d: I,
}

impl<I: Int> Q<I> {
    fn new(n: I, d: I) -> Self {
        debug_assert!(d != I::of(0));
        if d < I::of(0) {
            Q { n: -n, d: -d }
        } else {
            Q { n, d }
        }
    }
    fn le(self, o: Self) -> bool {
        self.n * o.d <= o.n * self.d
    }
    fn max(self, o: Self) -> Self {
        if self.le(o) {
            o
        } else {
            self
        }
    }
    fn min(self, o: Self) -> Self {
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
    if dims.iter().all(|&n| n <= SMALL_SIDE) {
        recurse::<D, i64>(&a, &b, &dims, 0, Q::new(0, 1), Q::new(1, 1), &mut cell, visit)
    } else {
        recurse::<D, i128>(&a, &b, &dims, 0, Q::new(0, 1), Q::new(1, 1), &mut cell, visit)
    }
}

#[allow(clippy::too_many_arguments)]
fn recurse<const D: usize, I: Int>(
    a: &[i64; D],
    b: &[i64; D],
    dims: &[i64; D],
    axis: usize,
    tlo: Q<I>,
    thi: Q<I>,
    cell: &mut [i64; D],
    visit: &mut impl FnMut([i64; D]) -> bool,
) -> bool {
    if axis == D {
        return visit(*cell);
    }
    let (one, two) = (I::of(1), I::of(2));
    // Doubled coordinate along this axis: p(t) = p0 + t * dp.
    let p0 = two * I::of(a[axis]) + one;
    let dp = two * I::of(b[axis] - a[axis]);
    let at = |t: Q<I>| Q { n: p0 * t.d + t.n * dp, d: t.d };
    let (x, y) = (at(tlo), at(thi));
    let (lo, hi) = (x.min(y), x.max(y));
    // Cells c with [2c, 2c + 2] ∩ [lo, hi] ≠ ∅: ceil(lo / 2) - 1 ≤ c ≤ floor(hi / 2).
    let cmin = ((-((-lo.n).div_e(two * lo.d))) - one).to_i64().max(0);
    let cmax = hi.n.div_e(two * hi.d).to_i64().min(dims[axis] - 1);
    for c in cmin..=cmax {
        let (slo, shi) = if dp == I::of(0) {
            (tlo, thi)
        } else {
            let t1 = Q::new(two * I::of(c) - p0, dp);
            let t2 = Q::new(two * I::of(c) + two - p0, dp);
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

    /// Both integer widths enumerate the same cells, up to the largest side the narrow one
    /// is used for (segments spanning the whole side, where products are largest).
    #[test]
    fn narrow_and_wide_arithmetic_agree() {
        let touched = |wide: bool, a: [i64; 3], b: [i64; 3], dims: [i64; 3]| {
            let mut out = Vec::new();
            let mut visit = |c: [i64; 3]| {
                out.push(c);
                true
            };
            let mut cell = [0i64; 3];
            if wide {
                recurse::<3, i128>(&a, &b, &dims, 0, Q::new(0, 1), Q::new(1, 1), &mut cell, &mut visit);
            } else {
                recurse::<3, i64>(&a, &b, &dims, 0, Q::new(0, 1), Q::new(1, 1), &mut cell, &mut visit);
            }
            out
        };
        let s = SMALL_SIDE;
        let cases = [
            ([0, 0, 0], [s - 1, s - 2, s - 3], [s, s, s]),
            ([s - 1, 0, 7], [0, s - 1, 3], [s, s, 8]),
            ([3, 5, 0], [s - 7, 11, 1], [s, 16, 2]),
            ([0, 0, 0], [9, 4, 6], [10, 10, 10]),
        ];
        for (a, b, dims) in cases {
            assert_eq!(touched(false, a, b, dims), touched(true, a, b, dims), "{a:?} -> {b:?}");
        }
    }

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
