//! The smallest p-value the rank-sum test can return for given sample sizes: with few runs no
//! data can be significant, and a verdict must then say "undecidable", not "no difference".

use super::rank_sum::{normal_p_two_sided, Method};
use super::EXACT_SIZE_LIMIT;

/// The smallest two-sided p-value [`super::rank_sum_test`] can return with `method` for samples
/// of `nx` and `ny` values, over every possible data set.
///
/// * Exact (no ties): the two extreme orderings (every x below every y, or above) each have
///   probability `1 / C(nx + ny, nx)`, so `p >= 2 / C(nx + ny, nx)` (1 when a sample is empty).
/// * Normal approximation: |z| is largest when the samples are fully separated (|U - nx ny / 2|
///   at its maximum `nx ny / 2`) and each sample is one tied group (the tie correction removes
///   the most variance). Ties across the samples would pull U towards its mean. The bound holds
///   for any tie pattern, and for untied samples of 50 or more, whose variance is larger.
pub fn smallest_p(method: Method, nx: usize, ny: usize) -> f64 {
    if nx == 0 || ny == 0 {
        return 1.0;
    }
    match method {
        Method::Exact => {
            // C(nx + ny, nx) in floating point: a bound needs no exact integer, and run counts
            // up to --runs' limit would overflow one (the quotient then underflows to 0).
            let k = nx.min(ny);
            let c = (1..=k).fold(1.0, |acc: f64, i| acc * (nx + ny - k + i) as f64 / i as f64);
            (2.0 / c).min(1.0)
        }
        Method::Normal => {
            let (x, y) = (nx as f64, ny as f64);
            let tie_term = (x * x * x - x) + (y * y * y - y);
            // Groups: one per sample (two distinct values), so sigma is 0 only for 1 vs 1.
            normal_p_two_sided(0.0, nx, ny, tie_term, 2).1
        }
    }
}

/// The smallest p-value the test can return for these sample sizes with any data: the lower of
/// the two methods' bounds (the exact one only where R's size rule allows it).
pub fn smallest_p_any(nx: usize, ny: usize) -> f64 {
    let normal = smallest_p(Method::Normal, nx, ny);
    if nx < EXACT_SIZE_LIMIT && ny < EXACT_SIZE_LIMIT {
        normal.min(smallest_p(Method::Exact, nx, ny))
    } else {
        normal
    }
}
