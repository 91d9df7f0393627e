//! scipy cross-checks of the rank-sum test.

use super::*;
use crate::stats::exact::exact_p_two_sided;

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
        -1.13893, 0.2706, 0.24184, 0.63413, -1.01386, -0.71565, -0.59324, -0.72395, 0.28455, 0.08501, 0.56537, 1.14606,
        -2.03771, -0.27447, 0.1791, -0.61745, -2.17264, -0.97226, -1.31894, 0.27553, -2.52579, 0.40404, -0.80994,
        -0.65308, 0.6123, -0.08909, 1.03588, -1.52454, -1.14116, 0.26962, 0.40754, -0.06981, -0.20759, -0.82378,
        0.71218, 0.87057, -1.64072, -0.76582, 0.426, -0.92478, 0.1591, -0.57044, 1.5316, -0.06026, 1.87514, 0.21844,
        0.72912, 0.12904, 0.67829, 0.91823,
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
