//! Tests of the statistics, by area; shared assertion helpers and samples live here.

use super::*;

mod exact;
mod marks;
mod normal;
mod rank_sum;
mod reach;
mod summary;
mod textbook;

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

// Samples shared by the rank-sum and marks tests; their provenance is given in
// `rank_sum::thirty_vs_thirty_exact`.
const A30: [f64; 30] = [
    9.9145, 9.5712, 7.1265, 13.2452, 10.1467, 11.3116, 10.3509, 9.2796, 10.8165, 7.8824, 10.2939, 10.564, 9.0211,
    8.9986, 10.5715, 10.5924, 8.8581, 8.5586, 12.0935, 10.5132, 10.0295, 8.8319, 9.1114, 9.4416, 9.4413, 9.4265,
    12.058, 10.5782, 8.5825, 10.4664,
];
const B30: [f64; 30] = [
    8.4578, 9.7677, 10.3404, 11.8614, 9.3013, 10.6857, 10.9075, 8.9966, 10.2711, 11.8577, 10.7888, 9.8887, 10.4822,
    11.1338, 9.8205, 8.6615, 12.0007, 10.6926, 10.3353, 10.3738, 12.1633, 10.9316, 12.3193, 13.0165, 8.9361, 11.1415,
    11.3483, 13.4825, 11.3477, 12.3384,
];
