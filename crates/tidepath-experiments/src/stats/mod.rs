//! Statistics for comparing planners over many seeded runs.
//!
//! The papers report each planner as best / mean / std / worst over 30 runs and mark every
//! competitor with '+', '≈' or '-' from a two-sided Wilcoxon rank-sum test at alpha = 0.05
//! against the proposed method (lfhh2019 cites W. Haynes, "Wilcoxon Rank Sum Test", Springer
//! 2013). Tables built here must be checkable against R and scipy, so the test follows
//! R's `wilcox.test` (two-sided, `exact = NULL`, `correct = TRUE`) closely:
//!
//! * U of the first sample is `R_x - n_x (n_x + 1) / 2` (Mann & Whitney 1947), the `W` that R
//!   prints and the `statistic` that `scipy.stats.mannwhitneyu` returns;
//! * the exact null distribution is used when there are no ties and both samples have fewer
//!   than 50 values (R's rule, `exact <- (n.x < 50) && (n.y < 50)`); otherwise the normal
//!   approximation with tie-corrected variance and a 0.5 continuity correction.
//!
//! Deliberate differences from R, because costs here come from planner runs:
//!
//! * NaN values are dropped (R's `NA` handling, scipy's `nan_policy='omit'`); a NaN is a bug
//!   upstream, not a cost.
//! * Infinite values are kept, where R drops them: an infeasible run scored `+inf` is the worst
//!   possible outcome and must count against its planner. All `+inf` values tie with each other
//!   (as in scipy, which ranks them).
//! * Empty samples (after dropping NaN) give `p = 1` instead of an error, so a planner with no
//!   usable runs is marked '≈' (no evidence) instead of stopping a whole table.
//!
//! The normal tail uses [`erfc`], W. J. Cody's rational Chebyshev approximation, so that tiny
//! p-values keep their relative precision instead of cancelling in `1 - Phi(z)`.

mod exact;
mod mark;
mod normal;
mod rank_sum;
mod reach;
mod summary;
#[cfg(test)]
mod tests;

pub use mark::{compare_to_reference, Mark};
pub use normal::{erfc, normal_cdf};
pub use rank_sum::{rank_sum_test, Method, RankSumResult};
pub use reach::{smallest_p, smallest_p_any};
pub use summary::Summary;

/// Significance level used by the papers for the '+', '≈', '-' marks.
pub const DEFAULT_ALPHA: f64 = 0.05;

/// R's size rule for the exact test: both samples must have fewer than this many values.
/// Kept identical to R (strictly fewer than 50) so that tidepath tables can be reproduced
/// with `wilcox.test` defaults.
pub const EXACT_SIZE_LIMIT: usize = 50;
