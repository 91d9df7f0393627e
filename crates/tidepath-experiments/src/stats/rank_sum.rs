//! The two-sided Wilcoxon rank-sum / Mann-Whitney U test: ranking, the exact/normal choice and
//! the normal approximation.

use std::f64::consts::SQRT_2;

use serde::{Deserialize, Serialize};

use super::exact::exact_p_two_sided;
use super::normal::erfc;
use super::EXACT_SIZE_LIMIT;

/// How the p-value of a [`RankSumResult`] was obtained.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Method {
    /// Exact null distribution of U (no ties, both samples smaller than [`EXACT_SIZE_LIMIT`]).
    Exact,
    /// Normal approximation with tie correction and continuity correction.
    Normal,
}

/// Outcome of a two-sided Wilcoxon rank-sum (Mann-Whitney U) test of `x` against `y`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct RankSumResult {
    /// U of the first sample, `R_x - n_x (n_x + 1) / 2`: the number of pairs with `x_i > y_j`
    /// plus half the tied pairs. Small values mean `x` tends to be smaller. Equal to R's `W`
    /// and to the `statistic` of `scipy.stats.mannwhitneyu(x, y)`.
    pub u_x: f64,
    /// Two-sided p-value, in `[0, 1]`.
    pub p_value: f64,
    pub method: Method,
    /// Standardised statistic `(U_x - n_x n_y / 2 - 0.5 sign) / sigma` of the normal
    /// approximation (continuity-corrected, so 0 when U is within 0.5 of its mean); `None` for
    /// the exact test and when sigma = 0 (all values tied, or a sample empty).
    pub z: Option<f64>,
}

/// Two-sided Wilcoxon rank-sum / Mann-Whitney U test (Mann & Whitney 1947), as R's
/// `wilcox.test(x, y)` with its defaults, except that NaN values are dropped, infinite values
/// are kept and ranked (all `+inf` tie), and an empty sample gives `p = 1` (see the module
/// documentation for why).
///
/// Exact p-value: `min(1, 2 min(P(U <= u), P(U >= u)))` from the exact null distribution
/// (R's `pwilcox`). Normal approximation: tie-corrected variance
/// `n_x n_y / 12 ((N + 1) - sum(t^3 - t) / (N (N - 1)))`, continuity correction 0.5 towards the
/// mean, `p = erfc(|z| / sqrt 2)`; p = 1 when the variance is 0.
pub fn rank_sum_test(x: &[f64], y: &[f64]) -> RankSumResult {
    test_without_nan(x, y).0
}

/// The test on NaN-free copies, also returning the sample sizes that were used.
pub(super) fn test_without_nan(x: &[f64], y: &[f64]) -> (RankSumResult, usize, usize) {
    let x: Vec<f64> = x.iter().copied().filter(|v| !v.is_nan()).collect();
    let y: Vec<f64> = y.iter().copied().filter(|v| !v.is_nan()).collect();
    let (nx, ny) = (x.len(), y.len());
    let ranks = rank(&x, &y);
    let nxf = nx as f64;
    let u_x = ranks.rank_sum_x - nxf * (nxf + 1.0) / 2.0;
    let result = if !ranks.has_ties && nx < EXACT_SIZE_LIMIT && ny < EXACT_SIZE_LIMIT {
        // Without ties all ranks are integers, so U is an exact integer in f64.
        let p_value = exact_p_two_sided(u_x.round() as usize, nx, ny);
        RankSumResult { u_x, p_value, method: Method::Exact, z: None }
    } else {
        let (z, p_value) = normal_p_two_sided(u_x, nx, ny, ranks.tie_term, ranks.groups);
        RankSumResult { u_x, p_value, method: Method::Normal, z }
    };
    (result, nx, ny)
}

/// What the test needs from the joint ranking of two NaN-free samples.
struct Ranks {
    /// Sum of the (average) ranks of the first sample.
    rank_sum_x: f64,
    /// `sum(t^3 - t)` over groups of `t` tied values.
    tie_term: f64,
    has_ties: bool,
    /// Number of distinct values.
    groups: usize,
}

/// Ranks the pooled samples (1-based, average ranks for ties). Values are sorted with
/// `total_cmp` and grouped with `==`, so `-0.0` and `0.0` tie, and equal infinities tie.
fn rank(x: &[f64], y: &[f64]) -> Ranks {
    let mut pooled: Vec<(f64, bool)> = x.iter().map(|&v| (v, true)).chain(y.iter().map(|&v| (v, false))).collect();
    pooled.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut ranks = Ranks { rank_sum_x: 0.0, tie_term: 0.0, has_ties: false, groups: 0 };
    let mut start = 0;
    while start < pooled.len() {
        let value = pooled[start].0;
        let end = start + pooled[start..].iter().take_while(|(v, _)| *v == value).count();
        // Positions start..end hold ranks start+1..=end; their mean is (start + 1 + end) / 2.
        let average_rank = (start + 1 + end) as f64 / 2.0;
        let in_x = pooled[start..end].iter().filter(|(_, is_x)| *is_x).count();
        ranks.rank_sum_x += in_x as f64 * average_rank;
        let t = (end - start) as f64;
        if end - start > 1 {
            ranks.has_ties = true;
            ranks.tie_term += t * t * t - t;
        }
        ranks.groups += 1;
        start = end;
    }
    ranks
}

/// Normal approximation with tie correction and R's / scipy's continuity correction; returns
/// `(z, p)`. `groups` is the number of distinct values: with at most one, every value is tied
/// and sigma is exactly 0, which is tested directly instead of trusting the rounding of the
/// tie term.
pub(super) fn normal_p_two_sided(u_x: f64, nx: usize, ny: usize, tie_term: f64, groups: usize) -> (Option<f64>, f64) {
    let (nxf, nyf) = (nx as f64, ny as f64);
    let n = nxf + nyf;
    if nx == 0 || ny == 0 || groups < 2 {
        return (None, 1.0);
    }
    let variance = nxf * nyf / 12.0 * ((n + 1.0) - tie_term / (n * (n - 1.0)));
    if variance <= 0.0 {
        return (None, 1.0);
    }
    let d = u_x - nxf * nyf / 2.0;
    // R: CORRECTION <- sign(z) * 0.5 (f64::signum would give 1 for d = 0).
    let correction = if d > 0.0 {
        0.5
    } else if d < 0.0 {
        -0.5
    } else {
        0.0
    };
    let z = (d - correction) / variance.sqrt();
    // 2 (1 - Phi(|z|)) = erfc(|z| / sqrt 2), without cancellation for large |z|.
    let p = erfc(z.abs() / SQRT_2).min(1.0);
    (Some(z), p)
}
