//! Exact null distribution of the Mann-Whitney U statistic (no ties).

/// Two-sided exact p-value for U = `u` with sample sizes `m` and `n`, as R computes it:
/// the null distribution is symmetric about `m n / 2`, so twice the smaller tail is
/// `2 P(U <= min(u, m n - u))`. Counts are exact integers; the only roundings are the two
/// conversions to f64 and the division, so p has a relative error of a few ulp.
pub(super) fn exact_p_two_sided(u: usize, m: usize, n: usize) -> f64 {
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
pub(super) fn u_counts(m: usize, n: usize, max_u: usize) -> Vec<i128> {
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
pub(super) fn binomial(n: usize, k: usize) -> u128 {
    let k = k.min(n - k);
    (1..=k).fold(1u128, |acc, i| acc * (n - k + i) as u128 / i as u128)
}
