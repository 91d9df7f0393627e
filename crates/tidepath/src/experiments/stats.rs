//! Statistics for comparing planners over many seeded runs.
//!
//! The seed papers report each planner as best / mean / std / worst over 30 runs and mark every
//! competitor with '+', '≈' or '-' from a two-sided Wilcoxon rank-sum test at alpha = 0.05
//! against the proposed method (seed 001 cites W. Haynes, "Wilcoxon Rank Sum Test", Springer
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

use std::f64::consts::SQRT_2;
use std::fmt;

use serde::{Deserialize, Serialize};

/// Significance level used by the seed papers for the '+', '≈', '-' marks.
pub const DEFAULT_ALPHA: f64 = 0.05;

/// R's size rule for the exact test: both samples must have fewer than this many values.
/// Kept identical to R (strictly fewer than 50) so that tidepath tables can be reproduced
/// with `wilcox.test` defaults.
pub const EXACT_SIZE_LIMIT: usize = 50;

/// Descriptive statistics of one planner's costs over its runs, as in the seed papers' tables.
///
/// NaN values are skipped (`n` counts only the values used). Infinite values are kept: `+inf`
/// sorts last, so an infeasible run shows up as `worst = inf`; `mean` is then infinite (NaN if
/// both `+inf` and `-inf` occur) and `std` is `+inf` (for `n >= 2`), because the spread of such a
/// sample is unbounded. Quantiles interpolate towards an infinite neighbour and become infinite.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Summary {
    /// Number of values used (NaN excluded).
    pub n: usize,
    /// Smallest value (costs are minimised).
    pub best: f64,
    /// Largest value.
    pub worst: f64,
    pub mean: f64,
    /// Sample standard deviation (divisor `n - 1`), matching the papers' "standard variance"
    /// column and numpy's `std(ddof=1)`; 0 for a single value.
    pub std: f64,
    pub median: f64,
    /// First quartile, linear interpolation (R type 7, numpy's default).
    pub q1: f64,
    /// Third quartile, linear interpolation (R type 7, numpy's default).
    pub q3: f64,
}

impl Summary {
    /// Summarises `values`; `None` when no non-NaN value is left, since no statistic exists.
    pub fn of(values: &[f64]) -> Option<Summary> {
        let mut sorted: Vec<f64> = values.iter().copied().filter(|v| !v.is_nan()).collect();
        if sorted.is_empty() {
            return None;
        }
        sorted.sort_by(f64::total_cmp);
        let n = sorted.len();
        let nf = n as f64;
        let all_finite = sorted.iter().all(|v| v.is_finite());
        let (mean, std) = if all_finite {
            // Corrected two-pass algorithm (Chan, Golub & LeVeque 1983): the second pass removes
            // the rounding error of the first mean, so costs with a large common offset keep
            // their spread.
            let m0 = sorted.iter().sum::<f64>() / nf;
            let (s1, s2) = sorted.iter().fold((0.0, 0.0), |(s1, s2), &v| {
                let d = v - m0;
                (s1 + d, s2 + d * d)
            });
            let mean = m0 + s1 / nf;
            let std = if n < 2 { 0.0 } else { ((s2 - s1 * s1 / nf) / (nf - 1.0)).max(0.0).sqrt() };
            (mean, std)
        } else {
            let mean = sorted.iter().sum::<f64>() / nf;
            (mean, if n < 2 { 0.0 } else { f64::INFINITY })
        };
        Some(Summary {
            n,
            best: sorted[0],
            worst: sorted[n - 1],
            mean,
            std,
            median: quantile_sorted(&sorted, 0.5),
            q1: quantile_sorted(&sorted, 0.25),
            q3: quantile_sorted(&sorted, 0.75),
        })
    }
}

/// Quantile of sorted, NaN-free, non-empty data by linear interpolation (Hyndman & Fan 1996
/// type 7). Equal neighbours are returned as is, so two `+inf` values do not produce
/// `inf - inf = NaN`.
fn quantile_sorted(sorted: &[f64], p: f64) -> f64 {
    let h = (sorted.len() - 1) as f64 * p;
    let lo = h.floor() as usize;
    let frac = h - lo as f64;
    let a = sorted[lo];
    if frac == 0.0 || lo + 1 >= sorted.len() {
        return a;
    }
    let b = sorted[lo + 1];
    if a == b {
        a
    } else if a.is_finite() && b.is_finite() {
        a + frac * (b - a)
    } else {
        // The limit of the interpolation: finite + inf = inf, -inf + finite = -inf.
        (1.0 - frac) * a + frac * b
    }
}

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
fn test_without_nan(x: &[f64], y: &[f64]) -> (RankSumResult, usize, usize) {
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

/// Two-sided exact p-value for U = `u` with sample sizes `m` and `n`, as R computes it:
/// the null distribution is symmetric about `m n / 2`, so twice the smaller tail is
/// `2 P(U <= min(u, m n - u))`. Counts are exact integers; the only roundings are the two
/// conversions to f64 and the division, so p has a relative error of a few ulp.
fn exact_p_two_sided(u: usize, m: usize, n: usize) -> f64 {
    let tail_u = u.min((m * n).saturating_sub(u));
    let count: i128 = u_counts(m, n, tail_u).iter().sum();
    (2.0 * count as f64 / binomial(m + n, m) as f64).min(1.0)
}

/// Largest `m + n` for which [`u_counts`] cannot overflow i128: C(128, 64) ~ 2.4e37, and the
/// intermediate products stay below twice that, well under i128::MAX ~ 1.7e38.
const MAX_EXACT_TOTAL: usize = 128;

/// Number of orderings of `m` x-values and `n` y-values with U = 0..=`max_u` (truncated to
/// `U <= max_u`, which is all the lower tail needs).
///
/// Mann & Whitney (1947) count these by the recursion
/// `f(i, j; u) = f(i - 1, j; u - j) + f(i, j - 1; u)` (is the largest value an x or a y?); its
/// generating function is the Gaussian binomial coefficient
/// `[m + n choose m]_q = prod_{i=1..m} (1 - q^(n+i)) / (1 - q^i)`, built here one factor pair
/// at a time. Every partial product is itself `[n + i choose i]_q`, a polynomial with
/// non-negative coefficients at most C(n + i, i), so exact i128 arithmetic cannot overflow up
/// to [`MAX_EXACT_TOTAL`] and nothing is rounded. Truncating at `max_u` is exact because both
/// steps only move counts upwards. About 2 m max_u integer additions: 125 000 for 50 vs 50.
fn u_counts(m: usize, n: usize, max_u: usize) -> Vec<i128> {
    assert!(m + n <= MAX_EXACT_TOTAL, "exact U distribution limited to m + n <= {MAX_EXACT_TOTAL}");
    let mut c = vec![0i128; max_u + 1];
    c[0] = 1;
    for i in 1..=m {
        // Multiply by (1 - q^(n+i)): from the top down, so c[u - k] is still the old value.
        let k = n + i;
        for u in (k..=max_u).rev() {
            c[u] -= c[u - k];
        }
        // Divide by (1 - q^i), i.e. multiply by 1 + q^i + q^(2i) + ...: from the bottom up,
        // so c[u - i] already holds the new value.
        for u in i..=max_u {
            c[u] += c[u - i];
        }
    }
    c
}

/// C(n, k) exactly (the running product is C(n - k + i, i), an integer, at every step).
fn binomial(n: usize, k: usize) -> u128 {
    let k = k.min(n - k);
    (1..=k).fold(1u128, |acc, i| acc * (n - k + i) as u128 / i as u128)
}

/// Normal approximation with tie correction and R's / scipy's continuity correction; returns
/// `(z, p)`. `groups` is the number of distinct values: with at most one, every value is tied
/// and sigma is exactly 0, which is tested directly instead of trusting the rounding of the
/// tie term.
fn normal_p_two_sided(u_x: f64, nx: usize, ny: usize, tie_term: f64, groups: usize) -> (Option<f64>, f64) {
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

/// The '+', '≈', '-' marks of the seed papers' tables.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Mark {
    /// The reference planner is significantly better (lower costs).
    Better,
    /// No significant difference.
    Similar,
    /// The reference planner is significantly worse (higher costs).
    Worse,
}

impl Mark {
    pub fn symbol(self) -> &'static str {
        match self {
            Mark::Better => "+",
            Mark::Similar => "≈",
            Mark::Worse => "-",
        }
    }
}

impl fmt::Display for Mark {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.symbol())
    }
}

/// Marks `other` against the reference planner (the first planner listed) as seed 001 does:
/// '+' means the reference is significantly better. Costs are minimised, so with `p < alpha`
/// the mark is [`Mark::Better`] when the reference's U is below its null mean `n_r n_o / 2`
/// (its mean rank is lower: its costs tend to be smaller) and [`Mark::Worse`] when above;
/// otherwise [`Mark::Similar`]. The returned result is the test of `reference` against `other`,
/// so `u_x` is the reference's U.
pub fn compare_to_reference(reference: &[f64], other: &[f64], alpha: f64) -> (Mark, RankSumResult) {
    let (result, nr, no) = test_without_nan(reference, other);
    let null_mean = nr as f64 * no as f64 / 2.0;
    let mark = if result.p_value < alpha {
        if result.u_x < null_mean {
            Mark::Better
        } else if result.u_x > null_mean {
            Mark::Worse
        } else {
            Mark::Similar
        }
    } else {
        Mark::Similar
    };
    (mark, result)
}

/// Standard normal CDF, `Phi(x) = erfc(-x / sqrt 2) / 2`; keeps full relative precision in the
/// lower tail.
pub fn normal_cdf(x: f64) -> f64 {
    0.5 * erfc(-x / SQRT_2)
}

/// Complementary error function with a relative error of a few 1e-16 (at most 2e-15, near the
/// interval break at 4, measured against 40-digit mpmath) for all finite `x`; 0 beyond x ~ 26.5,
/// where the result underflows; NaN for NaN.
///
/// W. J. Cody's rational Chebyshev approximations ("Rational Chebyshev approximations for the
/// error function", Math. Comp. 23 (1969) 631-637), as in his Netlib SPECFUN routine `CALERF`
/// (1990), with its coefficients and interval breaks 0.46875 and 4: erf on `|x| <= 0.46875`,
/// erfc on `(0.46875, 4]` and an asymptotic-form rational function above 4. `exp(-x^2)` is
/// split as `exp(-t^2) exp(-(x - t)(x + t))` with `t = trunc(16 x) / 16`, as in CALERF, so
/// that the rounding of `x^2` does not cost relative accuracy in the far tail.
#[allow(clippy::excessive_precision)] // Cody's published digits, kept verbatim for checking.
pub fn erfc(x: f64) -> f64 {
    const A: [f64; 5] = [
        3.16112374387056560e00,
        1.13864154151050156e02,
        3.77485237685302021e02,
        3.20937758913846947e03,
        1.85777706184603153e-1,
    ];
    const B: [f64; 4] =
        [2.36012909523441209e01, 2.44024637934444173e02, 1.28261652607737228e03, 2.84423683343917062e03];
    const C: [f64; 9] = [
        5.64188496988670089e-1,
        8.88314979438837594e00,
        6.61191906371416295e01,
        2.98635138197400131e02,
        8.81952221241769090e02,
        1.71204761263407058e03,
        2.05107837782607147e03,
        1.23033935479799725e03,
        2.15311535474403846e-8,
    ];
    const D: [f64; 8] = [
        1.57449261107098347e01,
        1.17693950891312499e02,
        5.37181101862009858e02,
        1.62138957456669019e03,
        3.29079923573345963e03,
        4.36261909014324716e03,
        3.43936767414372164e03,
        1.23033935480374942e03,
    ];
    const P: [f64; 6] = [
        3.05326634961232344e-1,
        3.60344899949804439e-1,
        1.25781726111229246e-1,
        1.60837851487422766e-2,
        6.58749161529837803e-4,
        1.63153871373020978e-2,
    ];
    const Q: [f64; 5] = [
        2.56852019228982242e00,
        1.87295284992346047e00,
        5.27905102951428412e-1,
        6.05183413124413191e-2,
        2.33520497626869185e-3,
    ];
    /// 1 / sqrt(pi).
    const SQRPI: f64 = 5.6418958354775628695e-1;
    const THRESH: f64 = 0.46875;
    /// Below this, x^2 is negligible next to 1 (IEEE double value from CALERF).
    const XSMALL: f64 = 1.11e-16;
    /// Above this, erfc(x) underflows (IEEE double value from CALERF).
    const XBIG: f64 = 26.543;

    // exp(-y^2) without the rounding error of y^2 (CALERF's AINT(16 y) / 16 split).
    fn exp_minus_square(y: f64) -> f64 {
        let t = (y * 16.0).trunc() / 16.0;
        let del = (y - t) * (y + t);
        (-t * t).exp() * (-del).exp()
    }

    let y = x.abs();
    if y <= THRESH {
        let ysq = if y > XSMALL { y * y } else { 0.0 };
        let mut xnum = A[4] * ysq;
        let mut xden = ysq;
        for (a, b) in A[..3].iter().zip(&B[..3]) {
            xnum = (xnum + a) * ysq;
            xden = (xden + b) * ysq;
        }
        return 1.0 - x * (xnum + A[3]) / (xden + B[3]);
    }
    let tail = if y <= 4.0 {
        let mut xnum = C[8] * y;
        let mut xden = y;
        for (c, d) in C[..7].iter().zip(&D[..7]) {
            xnum = (xnum + c) * y;
            xden = (xden + d) * y;
        }
        exp_minus_square(y) * (xnum + C[7]) / (xden + D[7])
    } else if y >= XBIG {
        0.0
    } else {
        let ysq = 1.0 / (y * y);
        let mut xnum = P[5] * ysq;
        let mut xden = ysq;
        for (p, q) in P[..4].iter().zip(&Q[..4]) {
            xnum = (xnum + p) * ysq;
            xden = (xden + q) * ysq;
        }
        let r = ysq * (xnum + P[4]) / (xden + Q[4]);
        exp_minus_square(y) * ((SQRPI - r) / y)
    };
    if x < 0.0 {
        2.0 - tail
    } else {
        tail
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// |actual - expected| <= tol * |expected|.
    fn assert_rel(actual: f64, expected: f64, tol: f64, what: &str) {
        let err = (actual - expected).abs();
        assert!(
            err <= tol * expected.abs(),
            "{what}: got {actual:e}, expected {expected:e} (relative error {:e} > {tol:e})",
            err / expected.abs()
        );
    }

    /// |actual - expected| <= tol.
    fn assert_abs(actual: f64, expected: f64, tol: f64, what: &str) {
        assert!((actual - expected).abs() <= tol, "{what}: got {actual}, expected {expected} (tolerance {tol})");
    }

    // ---------------------------------------------------------------- erfc / normal CDF

    #[test]
    #[allow(clippy::excessive_precision)] // reference digits kept as printed by mpmath
    fn erfc_matches_high_precision_values() {
        // Reference: mpmath 1.4.1 with mp.dps = 40, `mpmath.erfc(mpmath.mpf(x))`, rounded to 20
        // significant digits. Covers every interval of Cody's approximation, both interval
        // breaks (0.46875 and 4), negative arguments and the far tail down to 1e-307.
        let table: [(f64, f64); 25] = [
            (-5.0, 1.9999999999984625402),
            (-2.5, 1.9995930479825550411),
            (-1.0, 1.8427007929497148693),
            (-0.3, 1.3286267594591274276),
            (0.0, 1.0),
            (1e-10, 9.9999999988716208329e-1),
            (0.1, 8.875370839817151078e-1),
            (0.46875, 5.0738652678206200841e-1),
            (0.47, 5.0625494911391786348e-1),
            (0.5, 4.7950012218695346232e-1),
            (1.0, 1.5729920705028513066e-1),
            (1.5, 3.3894853524689272933e-2),
            (2.0, 4.6777349810472658379e-3),
            (3.0, 2.2090496998585441373e-5),
            (3.99, 1.6739211364520843377e-8),
            (4.0, 1.5417257900280018852e-8),
            (4.01, 1.4196939421371026189e-8),
            (5.0, 1.5374597944280348502e-12),
            (6.0, 2.1519736712498913117e-17),
            (8.0, 1.122429717298292708e-29),
            (10.0, 2.088487583762544757e-45),
            (15.0, 7.2129941724512066666e-100),
            (20.0, 5.3958656116079009289e-176),
            (26.0, 5.6631924088561428465e-296),
            (26.5, 2.2109076642637342759e-307),
        ];
        for (x, expected) in table {
            assert_rel(erfc(x), expected, 1e-14, &format!("erfc({x})"));
        }
    }

    #[test]
    fn erfc_edge_cases() {
        assert_eq!(erfc(30.0), 0.0);
        assert_eq!(erfc(f64::INFINITY), 0.0);
        assert_eq!(erfc(-30.0), 2.0);
        assert_eq!(erfc(f64::NEG_INFINITY), 2.0);
        assert!(erfc(f64::NAN).is_nan());
        assert_eq!(normal_cdf(0.0), 0.5);
    }

    #[test]
    #[allow(clippy::excessive_precision)] // reference digits kept as printed by mpmath
    fn normal_cdf_known_values() {
        // Values given in the brief, and mpmath 1.4.1 (`mpmath.ncdf`, mp.dps = 40) for the rest.
        assert_rel(normal_cdf(1.96), 0.9750021048517795, 1e-12, "Phi(1.96)");
        assert_rel(erfc(3.0), 2.209049699858544e-05, 1e-12, "erfc(3)");
        assert_rel(normal_cdf(-1.96), 0.024997895148220434137, 1e-12, "Phi(-1.96)");
        assert_rel(normal_cdf(0.5), 0.69146246127401310364, 1e-12, "Phi(0.5)");
        // Lower tail keeps relative precision where 1 - Phi(8) would be 0 in f64.
        assert_rel(normal_cdf(-8.0), 6.2209605742717841235e-16, 1e-12, "Phi(-8)");
    }

    // ---------------------------------------------------------------- Summary

    #[test]
    fn summary_hand_computed_even_n() {
        // sorted: 1 1 2 3 4 5 6 9; mean = 31 / 8; sum of squared deviations = 173 - 8 * 3.875^2
        // = 52.875, std = sqrt(52.875 / 7); type 7: q1 at h = 1.75 -> 1 + 0.75 * (2 - 1),
        // median at h = 3.5 -> (3 + 4) / 2, q3 at h = 5.25 -> 5 + 0.25 * (6 - 5).
        let s = Summary::of(&[3.0, 1.0, 4.0, 1.0, 5.0, 9.0, 2.0, 6.0]).unwrap();
        assert_eq!(s.n, 8);
        assert_eq!(s.best, 1.0);
        assert_eq!(s.worst, 9.0);
        assert_abs(s.mean, 3.875, 1e-15, "mean");
        assert_abs(s.std, (52.875f64 / 7.0).sqrt(), 1e-14, "std");
        // numpy: np.std(v, ddof=1) = 2.748376143938713
        assert_abs(s.std, 2.748376143938713, 1e-14, "std (numpy)");
        assert_abs(s.median, 3.5, 1e-15, "median");
        assert_abs(s.q1, 1.75, 1e-15, "q1");
        assert_abs(s.q3, 5.25, 1e-15, "q3");
    }

    #[test]
    fn summary_hand_computed_odd_n() {
        // sorted: 1 2.5 4.5 7 10; mean 5; squared deviations 16 + 6.25 + 0.25 + 4 + 25 = 51.5,
        // std = sqrt(51.5 / 4); quartiles fall on data points (h = 1, 2, 3).
        let s = Summary::of(&[2.5, 7.0, 1.0, 4.5, 10.0]).unwrap();
        assert_eq!(s.n, 5);
        assert_abs(s.mean, 5.0, 1e-15, "mean");
        assert_abs(s.std, (51.5f64 / 4.0).sqrt(), 1e-14, "std");
        assert_eq!((s.q1, s.median, s.q3), (2.5, 4.5, 7.0));
        assert_eq!((s.best, s.worst), (1.0, 10.0));
    }

    #[test]
    fn summary_single_empty_and_nan() {
        let s = Summary::of(&[4.25]).unwrap();
        assert_eq!(s.n, 1);
        assert_eq!(s.std, 0.0);
        assert_eq!((s.best, s.worst, s.mean), (4.25, 4.25, 4.25));
        assert_eq!((s.q1, s.median, s.q3), (4.25, 4.25, 4.25));

        assert!(Summary::of(&[]).is_none());
        assert!(Summary::of(&[f64::NAN, f64::NAN]).is_none());

        // NaN is skipped: same as [2, 4].
        let s = Summary::of(&[2.0, f64::NAN, 4.0]).unwrap();
        assert_eq!(s.n, 2);
        assert_abs(s.mean, 3.0, 1e-15, "mean");
        assert_abs(s.std, std::f64::consts::SQRT_2, 1e-15, "std");
        assert_abs(s.median, 3.0, 1e-15, "median");
    }

    #[test]
    fn summary_with_infinite_cost() {
        // An infeasible run scored +inf: it is the worst, mean and std are infinite, quartiles
        // interpolating towards it are infinite, the others stay finite.
        let s = Summary::of(&[2.0, f64::INFINITY, 1.0]).unwrap();
        assert_eq!(s.n, 3);
        assert_eq!(s.best, 1.0);
        assert_eq!(s.worst, f64::INFINITY);
        assert_eq!(s.mean, f64::INFINITY);
        assert_eq!(s.std, f64::INFINITY);
        assert_eq!(s.median, 2.0);
        assert_abs(s.q1, 1.5, 1e-15, "q1");
        assert_eq!(s.q3, f64::INFINITY);

        // Two infinities next to each other do not produce inf - inf = NaN.
        let s = Summary::of(&[f64::INFINITY, 1.0, f64::INFINITY, f64::INFINITY]).unwrap();
        assert_eq!(s.median, f64::INFINITY);
        assert_eq!(s.q3, f64::INFINITY);
        assert_eq!(s.q1, f64::INFINITY); // h = 0.75 between 1 and inf

        // Large common offset: the corrected two-pass mean keeps the spread.
        let s = Summary::of(&[1e9 + 1.0, 1e9 + 2.0, 1e9 + 3.0]).unwrap();
        assert_abs(s.mean, 1e9 + 2.0, 1e-6, "offset mean");
        assert_abs(s.std, 1.0, 1e-12, "offset std");
    }

    // ---------------------------------------------------------------- textbook cases

    #[test]
    fn textbook_hollander_wolfe_permeability_exact() {
        // Hollander & Wolfe (1973), p. 69 f., the two-sample example of R's ?wilcox.test:
        // permeability constants of the human chorioamnion at term (x) and at 12-26 weeks (y).
        // Published (R documentation example, alternative = "greater"): W = 35,
        // p-value = 0.1272, so the two-sided value is 0.2544 (the exact distribution is
        // symmetric).
        let x = [0.80, 0.83, 1.89, 1.04, 1.45, 1.38, 1.91, 1.64, 0.73, 1.46];
        let y = [1.15, 0.88, 0.90, 0.74, 1.21];
        let r = rank_sum_test(&x, &y);
        assert_eq!(r.method, Method::Exact);
        assert_eq!(r.z, None);
        assert_eq!(r.u_x, 35.0);
        assert_abs(r.p_value, 0.2544, 0.5e-4, "published two-sided p (4 d.p.)");
        assert_abs(r.p_value / 2.0, 0.1272, 0.5e-4, "published one-sided p (4 d.p.)");
        // scipy 1.17.1: scipy.stats.mannwhitneyu(x, y, alternative='two-sided',
        // method='exact') -> statistic 35.0, pvalue 0.2544122544122544 (= 764/3003).
        assert_rel(r.p_value, 0.2544122544122544, 1e-6, "scipy exact (relative)");
        assert_rel(r.p_value, 764.0 / 3003.0, 1e-14, "exact fraction");
    }

    #[test]
    fn textbook_shier_diabetes_ages_exact() {
        // R. Shier, "Statistics: 2.3 The Mann-Whitney U Test", Mathematics Learning Support
        // Centre (2004), as reproduced in the scipy.stats.mannwhitneyu documentation example:
        // age at diagnosis of type II diabetes. Published: U_M = 17, U_F = 3, p = 0.11.
        let males = [19.0, 22.0, 16.0, 29.0, 24.0];
        let females = [20.0, 11.0, 17.0, 12.0];
        let r = rank_sum_test(&males, &females);
        assert_eq!(r.method, Method::Exact);
        assert_eq!(r.u_x, 17.0);
        assert_eq!(rank_sum_test(&females, &males).u_x, 3.0);
        assert_abs(r.p_value, 0.11, 0.005, "published p (2 d.p.)");
        // scipy 1.17.1: mannwhitneyu(males, females, alternative='two-sided',
        // method='exact') -> 0.1111111111111111 (printed in the scipy docs too).
        assert_rel(r.p_value, 0.1111111111111111, 1e-6, "scipy exact (relative)");
        // The docs' asymptotic value for the same data, checking the normal branch on data
        // without ties: mannwhitneyu(males, females, method='asymptotic') (use_continuity=True)
        // -> 0.11134688653314041.
        let (z, p) = normal_p_two_sided(17.0, 5, 4, 0.0, 9);
        assert_rel(p, 0.11134688653314041, 1e-6, "scipy docs asymptotic (relative)");
        assert!(z.unwrap() > 0.0);
    }

    #[test]
    fn textbook_wikipedia_tortoise_hare_u() {
        // Wikipedia, "Mann-Whitney U test", section "Illustration of calculation methods":
        // finishing order T H H H H H T T T T T H, the first animal home gets rank 12.
        // Published: U_T = 11 (tortoise rank sum 32 - 21), U_H = 25, U_T + U_H = 36.
        let tortoises = [12.0, 6.0, 5.0, 4.0, 3.0, 2.0];
        let hares = [11.0, 10.0, 9.0, 8.0, 7.0, 1.0];
        let rt = rank_sum_test(&tortoises, &hares);
        let rh = rank_sum_test(&hares, &tortoises);
        assert_eq!(rt.u_x, 11.0);
        assert_eq!(rh.u_x, 25.0);
        assert_eq!(rt.method, Method::Exact);
        // Wikipedia: not significant (critical value 5 for 6 vs 6 at 0.05, two-tailed).
        // scipy 1.17.1: mannwhitneyu(tortoises, hares, alternative='two-sided',
        // method='exact') -> 0.30952380952380953 (= 13/42).
        assert_rel(rt.p_value, 0.30952380952380953, 1e-6, "scipy exact (relative)");
        assert_eq!(rt.p_value, rh.p_value);
    }

    #[test]
    fn textbook_r_mtcars_mpg_by_transmission_ties() {
        // R: wilcox.test(mpg ~ am, data = mtcars) (mtcars from R's datasets package; am = 0
        // automatic, 1 manual). Ties (e.g. 10.4, 15.2, 19.2, 21.4, 22.8, 30.4), so R uses the
        // normal approximation with continuity correction. Published output (stats.stackexchange
        // question 290830, "wilcox.test gives different results when using formula"):
        // p.value = 0.001871391.
        let automatic = [
            21.4, 18.7, 18.1, 14.3, 24.4, 22.8, 19.2, 17.8, 16.4, 17.3, 15.2, 10.4, 10.4, 14.7, 21.5, 15.5, 15.2, 13.3,
            19.2,
        ];
        let manual = [21.0, 21.0, 22.8, 32.4, 30.4, 33.9, 27.3, 26.0, 30.4, 15.8, 19.7, 15.0, 21.4];
        let r = rank_sum_test(&automatic, &manual);
        assert_eq!(r.method, Method::Normal);
        assert_eq!(r.u_x, 42.0);
        assert_abs(r.p_value, 0.001871391, 0.5e-9, "published p (9 d.p.)");
        // scipy 1.17.1: mannwhitneyu(automatic, manual, alternative='two-sided',
        // method='asymptotic', use_continuity=True) -> 42.0, 0.0018713913331785542.
        assert_rel(r.p_value, 0.0018713913331785542, 1e-6, "scipy asymptotic (relative)");
        assert!(r.z.unwrap() < 0.0);
    }

    #[test]
    fn textbook_r_wilcox_examples_with_ties() {
        // Published R output (endmemo.com/r/wilcoxon.php, "R wilcox.test"), both with the warning
        // "cannot compute exact p-value with ties":
        //   wilcox.test(x, y)  -> W = 51.5, p-value = 0.5966
        //   wilcox.test(x, y2) -> W = 0,    p-value = 0.001364
        let x = [1.0, 5.0, 9.0, 24.0, 56.0, 21.0, 3.0, 7.0, 21.0, 4.0];
        let y = [12.0, 15.0, 5.0, 9.0, 9.0, 14.0, 56.0, 22.0, 3.0, 7.0, 32.0, 5.0];
        let y2 = [1233.0, 4356.0, 987.0, 39999.0, 1111.0, 200000.0];
        let r = rank_sum_test(&x, &y);
        assert_eq!(r.method, Method::Normal);
        assert_eq!(r.u_x, 51.5);
        assert_abs(r.p_value, 0.5966, 0.5e-4, "published p (4 d.p.)");
        // scipy 1.17.1: mannwhitneyu(x, y, alternative='two-sided', method='asymptotic',
        // use_continuity=True) -> 51.5, 0.5965969026279817.
        assert_rel(r.p_value, 0.5965969026279817, 1e-6, "scipy asymptotic (relative)");

        let r = rank_sum_test(&x, &y2);
        assert_eq!(r.method, Method::Normal); // the tie (21, 21) is inside x
        assert_eq!(r.u_x, 0.0);
        assert_abs(r.p_value, 0.001364, 0.5e-6, "published p (6 d.p.)");
        // scipy 1.17.1: mannwhitneyu(x, y2, alternative='two-sided', method='asymptotic',
        // use_continuity=True) -> 0.0, 0.0013643929543816092.
        assert_rel(r.p_value, 0.0013643929543816092, 1e-6, "scipy asymptotic (relative)");
    }

    #[test]
    fn r_airquality_ozone_may_vs_august() {
        // R's ?wilcox.test formula example:
        // wilcox.test(Ozone ~ Month, data = airquality, subset = Month %in% c(5, 8)),
        // NA removed (26 days each). Only scipy's value is asserted here; R's printed output was
        // not available to check when this test was written.
        let may = [
            41.0, 36.0, 12.0, 18.0, 28.0, 23.0, 19.0, 8.0, 7.0, 16.0, 11.0, 14.0, 18.0, 14.0, 34.0, 6.0, 30.0, 11.0,
            1.0, 11.0, 4.0, 32.0, 23.0, 45.0, 115.0, 37.0,
        ];
        let august = [
            39.0, 9.0, 16.0, 78.0, 35.0, 66.0, 122.0, 89.0, 110.0, 44.0, 28.0, 65.0, 22.0, 59.0, 23.0, 31.0, 44.0,
            21.0, 9.0, 45.0, 168.0, 73.0, 76.0, 118.0, 84.0, 85.0,
        ];
        let r = rank_sum_test(&may, &august);
        assert_eq!(r.method, Method::Normal);
        assert_eq!(r.u_x, 127.5);
        // scipy 1.17.1: mannwhitneyu(may, august, alternative='two-sided',
        // method='asymptotic', use_continuity=True) -> 127.5, 0.00012080783076877434.
        assert_rel(r.p_value, 0.00012080783076877434, 1e-6, "scipy asymptotic (relative)");
    }

    // ---------------------------------------------------------------- scipy cross-checks

    #[test]
    fn small_exact_five_vs_six() {
        let x = [3.1, 4.7, 2.2, 5.9, 3.8];
        let y = [6.4, 5.1, 7.3, 4.9, 6.8, 8.0];
        let r = rank_sum_test(&x, &y);
        assert_eq!(r.method, Method::Exact);
        assert_eq!(r.u_x, 2.0);
        // scipy 1.17.1: mannwhitneyu(x, y, alternative='two-sided', method='exact')
        // -> 2.0, 0.017316017316017316 (= 4/231: U <= 2 in 2 of C(11, 5) = 462 orderings).
        assert_rel(r.p_value, 0.017316017316017316, 1e-6, "scipy exact (relative)");
        assert_rel(r.p_value, 4.0 / 231.0, 1e-14, "exact fraction");
    }

    const A30: [f64; 30] = [
        9.9145, 9.5712, 7.1265, 13.2452, 10.1467, 11.3116, 10.3509, 9.2796, 10.8165, 7.8824, 10.2939, 10.564, 9.0211,
        8.9986, 10.5715, 10.5924, 8.8581, 8.5586, 12.0935, 10.5132, 10.0295, 8.8319, 9.1114, 9.4416, 9.4413, 9.4265,
        12.058, 10.5782, 8.5825, 10.4664,
    ];
    const B30: [f64; 30] = [
        8.4578, 9.7677, 10.3404, 11.8614, 9.3013, 10.6857, 10.9075, 8.9966, 10.2711, 11.8577, 10.7888, 9.8887, 10.4822,
        11.1338, 9.8205, 8.6615, 12.0007, 10.6926, 10.3353, 10.3738, 12.1633, 10.9316, 12.3193, 13.0165, 8.9361,
        11.1415, 11.3483, 13.4825, 11.3477, 12.3384,
    ];

    #[test]
    fn thirty_vs_thirty_exact() {
        // Like our experiments: 30 runs per planner, continuous costs, no ties -> exact.
        // Data: numpy default_rng(20240607), normal(10, 1) and normal(10.8, 1.2), rounded to
        // 4 decimals. scipy 1.17.1: mannwhitneyu(A30, B30, alternative='two-sided',
        // method='exact') -> 278.0, 0.010501494914086952; an independent big-integer DP in
        // Python gives 0.010501494914086954.
        let r = rank_sum_test(&A30, &B30);
        assert_eq!(r.method, Method::Exact);
        assert_eq!(r.u_x, 278.0);
        assert_rel(r.p_value, 0.010501494914086952, 1e-6, "scipy exact (relative)");
        assert_rel(r.p_value, 0.010501494914086954, 1e-13, "big-integer DP");
        // Swapping the samples mirrors U and keeps p.
        let s = rank_sum_test(&B30, &A30);
        assert_eq!(s.u_x, 900.0 - 278.0);
        assert_rel(s.p_value, r.p_value, 1e-14, "swapped");
    }

    #[test]
    fn ties_normal_approximation() {
        let x = [3.0, 5.0, 5.0, 6.0, 7.0, 7.0, 7.0, 8.0, 9.0, 9.0, 10.0, 12.0, 12.0, 13.0];
        let y = [6.0, 8.0, 9.0, 10.0, 10.0, 11.0, 12.0, 13.0, 13.0, 14.0, 15.0, 15.0, 16.0, 17.0, 18.0];
        let r = rank_sum_test(&x, &y);
        assert_eq!(r.method, Method::Normal);
        assert_eq!(r.u_x, 35.0);
        // scipy 1.17.1: mannwhitneyu(x, y, alternative='two-sided', method='asymptotic',
        // use_continuity=True) -> 35.0, 0.00234829400064204.
        assert_rel(r.p_value, 0.00234829400064204, 1e-6, "scipy asymptotic (relative)");
    }

    #[test]
    fn plus_infinity_values() {
        let inf = f64::INFINITY;
        // Two +inf in x and one in y tie with each other -> normal approximation.
        let x = [1.2, 3.4, inf, 2.2, inf];
        let y = [0.5, 0.7, 1.1, 0.9, inf, 1.0];
        let r = rank_sum_test(&x, &y);
        assert_eq!(r.method, Method::Normal);
        assert_eq!(r.u_x, 26.0);
        // scipy 1.17.1: mannwhitneyu(x, y, alternative='two-sided', method='asymptotic',
        // use_continuity=True) with math.inf -> 26.0, 0.05302739120252687.
        assert_rel(r.p_value, 0.05302739120252687, 1e-6, "scipy asymptotic (relative)");

        // A single +inf is just the largest value -> still exact.
        let x = [1.0, 2.0, inf];
        let y = [0.5, 1.5, 3.0, 4.0];
        let r = rank_sum_test(&x, &y);
        assert_eq!(r.method, Method::Exact);
        assert_eq!(r.u_x, 7.0);
        // scipy 1.17.1: mannwhitneyu(x, y, alternative='two-sided', method='exact')
        // -> 7.0, 0.8571428571428571.
        assert_rel(r.p_value, 0.8571428571428571, 1e-6, "scipy exact (relative)");
    }

    #[test]
    fn tiny_p_value_keeps_relative_precision() {
        // 101 vs 100 with one tie: z ~ -12.2, p ~ 1.8e-34 (1 - Phi would round to 0).
        let x: Vec<f64> = (0..100).map(f64::from).chain([50.0]).collect();
        let y: Vec<f64> = (200..300).map(f64::from).collect();
        let r = rank_sum_test(&x, &y);
        assert_eq!(r.method, Method::Normal);
        assert_eq!(r.u_x, 0.0);
        // scipy 1.17.1: mannwhitneyu(x, y, alternative='two-sided', method='asymptotic',
        // use_continuity=True) -> 0.0, 1.7596551162812004e-34 (same for (y, x), U = 10100).
        assert_rel(r.p_value, 1.7596551162812004e-34, 1e-6, "scipy asymptotic (relative)");
        let s = rank_sum_test(&y, &x);
        assert_eq!(s.u_x, 10100.0);
        assert_rel(s.p_value, 1.7596551162812004e-34, 1e-6, "swapped");
        assert_eq!(r.z.unwrap(), -s.z.unwrap());
    }

    /// 49 or 50 values each, no ties: x = a permutation of 0..2k (first half), y = the second
    /// half + 10.5. Python: perm = [(i * 37) % (2 * k) for i in range(2 * k)].
    fn perm_samples(k: usize) -> (Vec<f64>, Vec<f64>) {
        let perm: Vec<f64> = (0..2 * k).map(|i| ((i * 37) % (2 * k)) as f64).collect();
        let x = perm[..k].to_vec();
        let y = perm[k..].iter().map(|v| v + 10.5).collect();
        (x, y)
    }

    #[test]
    fn size_rule_matches_r() {
        // 49 vs 49: exact. scipy 1.17.1: mannwhitneyu(x, y, alternative='two-sided',
        // method='exact') -> 926.0, 0.05126624782989249.
        let (x, y) = perm_samples(49);
        let r = rank_sum_test(&x, &y);
        assert_eq!(r.method, Method::Exact);
        assert_eq!(r.u_x, 926.0);
        assert_rel(r.p_value, 0.05126624782989249, 1e-6, "49 vs 49 scipy exact");

        // 50 vs 50: R switches to the normal approximation (n.x < 50 fails). scipy 1.17.1:
        // method='asymptotic', use_continuity=True -> 944.0, 0.03519896955647389;
        // method='exact' -> 0.03479524458608736, which our DP reproduces.
        let (x, y) = perm_samples(50);
        let r = rank_sum_test(&x, &y);
        assert_eq!(r.method, Method::Normal);
        assert_eq!(r.u_x, 944.0);
        assert_rel(r.p_value, 0.03519896955647389, 1e-6, "50 vs 50 scipy asymptotic");
        assert_rel(exact_p_two_sided(944, 50, 50), 0.03479524458608736, 1e-6, "50 vs 50 scipy exact");

        // 50 vs 10: normal. scipy 1.17.1 (numpy default_rng(20240607) continued, rounded to 5
        // decimals): method='asymptotic', use_continuity=True -> 205.0, 0.37741201623403664.
        let c = [
            -1.13893, 0.2706, 0.24184, 0.63413, -1.01386, -0.71565, -0.59324, -0.72395, 0.28455, 0.08501, 0.56537,
            1.14606, -2.03771, -0.27447, 0.1791, -0.61745, -2.17264, -0.97226, -1.31894, 0.27553, -2.52579, 0.40404,
            -0.80994, -0.65308, 0.6123, -0.08909, 1.03588, -1.52454, -1.14116, 0.26962, 0.40754, -0.06981, -0.20759,
            -0.82378, 0.71218, 0.87057, -1.64072, -0.76582, 0.426, -0.92478, 0.1591, -0.57044, 1.5316, -0.06026,
            1.87514, 0.21844, 0.72912, 0.12904, 0.67829, 0.91823,
        ];
        let d = [-0.38123, 1.20757, 0.43164, -1.89018, 0.33393, -0.90629, 0.708, -0.68215, 0.82672, 0.47213];
        let r = rank_sum_test(&c, &d);
        assert_eq!(r.method, Method::Normal);
        assert_eq!(r.u_x, 205.0);
        assert_rel(r.p_value, 0.37741201623403664, 1e-6, "50 vs 10 scipy asymptotic");
    }

    #[test]
    fn identical_and_all_tied_samples() {
        let r = rank_sum_test(&[1.0, 2.0, 3.0], &[1.0, 2.0, 3.0]);
        assert_eq!(r.method, Method::Normal);
        assert_eq!(r.u_x, 4.5);
        assert_eq!(r.p_value, 1.0); // scipy 1.17.1 asymptotic: 4.5, 1.0
        assert_eq!(r.z, Some(0.0));

        // Every value tied: sigma = 0, p = 1 (scipy returns NaN here).
        let r = rank_sum_test(&[5.0, 5.0, 5.0], &[5.0, 5.0]);
        assert_eq!(r.u_x, 3.0);
        assert_eq!(r.p_value, 1.0);
        assert_eq!(r.z, None);
        let inf = f64::INFINITY;
        let r = rank_sum_test(&[inf, inf], &[inf, inf, inf]);
        assert_eq!((r.p_value, r.z), (1.0, None));
    }

    #[test]
    fn empty_and_nan_inputs() {
        for (x, y) in
            [(&[][..], &[1.0, 2.0][..]), (&[1.0, 2.0][..], &[][..]), (&[][..], &[][..]), (&[f64::NAN][..], &[1.0][..])]
        {
            let r = rank_sum_test(x, y);
            assert_eq!(r.p_value, 1.0, "{x:?} vs {y:?}");
            assert_eq!(r.u_x, 0.0);
        }
        let big: Vec<f64> = (0..60).map(f64::from).collect();
        let r = rank_sum_test(&[], &big);
        assert_eq!((r.method, r.p_value, r.z), (Method::Normal, 1.0, None));
        assert_eq!(compare_to_reference(&[], &[1.0], 0.05).0, Mark::Similar);

        // NaN values are dropped: same result as without them.
        let x = [0.80, f64::NAN, 0.83, 1.89, 1.04, 1.45, 1.38, 1.91, 1.64, 0.73, 1.46];
        let y = [1.15, 0.88, 0.90, f64::NAN, 0.74, 1.21];
        let r = rank_sum_test(&x, &y);
        assert_eq!(r.u_x, 35.0);
        assert_rel(r.p_value, 764.0 / 3003.0, 1e-14, "NaN dropped");
    }

    // ---------------------------------------------------------------- exact distribution

    #[test]
    fn exact_distribution_matches_brute_force_and_recursion() {
        // Enumerate every subset of positions 0..m+n for x and count U directly.
        for (m, n) in [(1, 1), (2, 3), (4, 5), (5, 4), (3, 7), (6, 6), (1, 9)] {
            let mut freq = vec![0i128; m * n + 1];
            for mask in 0u32..(1 << (m + n)) {
                if mask.count_ones() as usize != m {
                    continue;
                }
                // U = sum over x positions of the number of y positions below them.
                let mut u = 0;
                let mut ys_below = 0;
                for pos in 0..m + n {
                    if mask & (1 << pos) != 0 {
                        u += ys_below;
                    } else {
                        ys_below += 1;
                    }
                }
                freq[u] += 1;
            }
            assert_eq!(u_counts(m, n, m * n), freq, "m = {m}, n = {n}");
            // Truncation keeps the lower tail unchanged.
            let half = m * n / 2;
            assert_eq!(u_counts(m, n, half), freq[..=half].to_vec());
        }
        // Mann & Whitney's recursion f(i, j; u) = f(i - 1, j; u - j) + f(i, j - 1; u), run
        // naively, agrees up to 30 vs 30 (our experiments' size).
        let (m, n) = (30, 30);
        let mut table: Vec<Vec<Vec<i128>>> = vec![vec![vec![1]; n + 1]; m + 1];
        for i in 1..=m {
            for j in 1..=n {
                let mut f = vec![0i128; i * j + 1];
                for (u, v) in table[i][j - 1].iter().enumerate() {
                    f[u] += v;
                }
                for (u, v) in table[i - 1][j].iter().enumerate() {
                    f[u + j] += v;
                }
                table[i][j] = f;
            }
        }
        assert_eq!(u_counts(m, n, m * n), table[m][n]);
        assert_eq!(u_counts(0, 5, 0), vec![1]);
        assert_eq!(u_counts(5, 0, 0), vec![1]);
    }

    #[test]
    fn exact_distribution_fifty_vs_fifty_is_fast_and_consistent() {
        let start = std::time::Instant::now();
        let half = u_counts(50, 50, 1250);
        let elapsed = start.elapsed();
        let full = u_counts(50, 50, 2500);
        // Symmetric about 1250, positive, summing to C(100, 50).
        for u in 0..=1250 {
            assert_eq!(full[u], full[2500 - u], "symmetry at {u}");
        }
        assert_eq!(half[..], full[..=1250]);
        assert!(full.iter().all(|&c| c > 0));
        let c_100_50: u128 = 100891344545564193334812497256;
        assert_eq!(full.iter().sum::<i128>() as u128, c_100_50);
        assert_eq!(binomial(100, 50), c_100_50);
        // Well under 1 ms with optimisations; the bound only guards against an algorithmic
        // regression without being flaky on a loaded machine.
        assert!(elapsed.as_millis() < 20, "50 vs 50 took {elapsed:?}");
    }

    // ---------------------------------------------------------------- marks

    #[test]
    fn marks_follow_minimisation() {
        assert_eq!(Mark::Better.symbol(), "+");
        assert_eq!(Mark::Similar.symbol(), "≈");
        assert_eq!(Mark::Worse.symbol(), "-");
        assert_eq!(Mark::Better.to_string(), "+");

        // The reference (A30) has the lower costs and p = 0.0105 < 0.05: '+'.
        let (mark, r) = compare_to_reference(&A30, &B30, DEFAULT_ALPHA);
        assert_eq!(mark, Mark::Better);
        assert_eq!(r.u_x, 278.0);
        // Reversed roles: the reference has the higher costs: '-'.
        let (mark, _) = compare_to_reference(&B30, &A30, DEFAULT_ALPHA);
        assert_eq!(mark, Mark::Worse);
        // Same data at alpha = 0.01: not significant, '≈'.
        let (mark, _) = compare_to_reference(&A30, &B30, 0.01);
        assert_eq!(mark, Mark::Similar);
        // Identical samples: '≈'.
        let (mark, r) = compare_to_reference(&A30, &A30, DEFAULT_ALPHA);
        assert_eq!((mark, r.p_value), (Mark::Similar, 1.0));
        // An always-failing competitor (+inf costs) is beaten: '+'.
        let failing = [f64::INFINITY; 30];
        let (mark, r) = compare_to_reference(&A30, &failing, DEFAULT_ALPHA);
        assert_eq!(mark, Mark::Better);
        assert_eq!(r.method, Method::Normal);
        assert_eq!(r.u_x, 0.0);
        // p < alpha is strict: the Hollander & Wolfe p (0.2544) at alpha = 0.2544 is '≈'.
        let x = [0.80, 0.83, 1.89, 1.04, 1.45, 1.38, 1.91, 1.64, 0.73, 1.46];
        let y = [1.15, 0.88, 0.90, 0.74, 1.21];
        let p = rank_sum_test(&x, &y).p_value;
        assert_eq!(compare_to_reference(&x, &y, p).0, Mark::Similar);
        assert_eq!(compare_to_reference(&x, &y, 0.3).0, Mark::Worse);
        assert_eq!(compare_to_reference(&y, &x, 0.3).0, Mark::Better);
    }
}
