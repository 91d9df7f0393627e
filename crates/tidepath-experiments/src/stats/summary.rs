//! [`Summary`]: best / mean / std / worst and quartiles of one planner's costs.

use serde::{Deserialize, Serialize};

/// Descriptive statistics of one planner's costs over its runs, as in the papers' tables.
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
