//! Summary.

use super::*;

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
