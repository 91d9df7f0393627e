//! Free cells of a waypoint's section, for lfhh2019's safe-cell sampling (Fig. 11, Algorithm
//! 2): before a rectangle of histogram bins is accepted for a waypoint, it must overlap at
//! least one free cell of that waypoint's section.
//!
//! The paper cuts each 20 x 20 km section into 20 x 20 cells of 1 km, a cell blocked when it
//! lies under the seabed or inside a sphere. tidepath cuts the box of a waypoint's variables
//! (a sliced plane's lateral and height ranges) into [`CELLS`] cells per variable, whatever the
//! world's size, and calls a cell free when the point at its centre is a valid state (domain,
//! seabed with the safety distance, obstacles, current data) at the mission's departure time:
//! the paper's obstacles are still between two changes; a moving one is judged where it is at
//! departure (our reading, docs/papers/lfhh2019.md A9).

use crate::encoding::Encoding;
use crate::path::PathModel;

/// Cells per variable: lfhh2019's 20 x 20 sections.
pub const CELLS: usize = 20;

/// Most variables one waypoint has (the free encoding's x, y, z): queries keep their cell
/// ranges on the stack.
pub const MAX_VARS: usize = 3;

/// One waypoint's cells over the box of its variables.
#[derive(Clone, Debug)]
pub struct SectionCells {
    lo: Vec<f64>,
    width: Vec<f64>,
    /// Cells per variable (1 where the variable's range is empty).
    n: Vec<usize>,
    /// Row-major over the variables, the first slowest.
    free: Vec<bool>,
}

impl SectionCells {
    /// The cells of interior waypoint `k` of `enc` over its variables' bounds `lo..=hi`.
    pub fn new(model: &PathModel<'_>, enc: &dyn Encoding, k: usize, lo: &[f64], hi: &[f64]) -> Self {
        let n: Vec<usize> = lo.iter().zip(hi).map(|(l, h)| if h > l { CELLS } else { 1 }).collect();
        let width: Vec<f64> = lo.iter().zip(hi).zip(&n).map(|((l, h), &c)| (h - l) / c as f64).collect();
        let total: usize = n.iter().product();
        let mut free = Vec::with_capacity(total);
        let mut centre = vec![0.0; lo.len()];
        for cell in 0..total {
            let mut rest = cell;
            for d in (0..lo.len()).rev() {
                let i = rest % n[d];
                rest /= n[d];
                centre[d] = lo[d] + (i as f64 + 0.5) * width[d];
            }
            let p = enc.waypoint_at(k, &centre);
            free.push(model.validator.state(p, model.departure_time).is_ok());
        }
        Self { lo: lo.to_vec(), width, n, free }
    }

    /// Whether the box `lo..=hi` (clipped to the cells) overlaps a free cell. Allocation-free
    /// (samplers ask it for every waypoint of every child).
    pub fn overlaps_free(&self, lo: &[f64], hi: &[f64]) -> bool {
        let dims = self.n.len();
        debug_assert!(dims <= MAX_VARS);
        let range = |d: usize| {
            let at = |v: f64| {
                if self.width[d] > 0.0 {
                    (((v - self.lo[d]) / self.width[d]).floor().max(0.0) as usize).min(self.n[d] - 1)
                } else {
                    0
                }
            };
            (at(lo[d].min(hi[d])), at(lo[d].max(hi[d])))
        };
        let mut ranges = [(0usize, 0usize); MAX_VARS];
        let mut index = [0usize; MAX_VARS];
        for d in 0..dims {
            ranges[d] = range(d);
            index[d] = ranges[d].0;
        }
        let (ranges, index) = (&ranges[..dims], &mut index[..dims]);
        loop {
            let flat = index.iter().zip(&self.n).fold(0, |acc, (&i, &n)| acc * n + i);
            if self.free[flat] {
                return true;
            }
            // The next cell of the box, the last variable fastest.
            let mut d = index.len();
            loop {
                if d == 0 {
                    return false;
                }
                d -= 1;
                if index[d] < ranges[d].1 {
                    index[d] += 1;
                    for (i, r) in index[d + 1..].iter_mut().zip(&ranges[d + 1..]) {
                        *i = r.0;
                    }
                    break;
                }
            }
        }
    }

    /// Whether any cell is free.
    pub fn any_free(&self) -> bool {
        self.free.iter().any(|&f| f)
    }
}
