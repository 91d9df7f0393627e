//! Marks.

use super::*;

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
