//! Exact distribution.

use crate::stats::exact::{binomial, u_counts};

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
fn exact_distribution_fifty_vs_fifty_is_consistent() {
    let half = u_counts(50, 50, 1250);
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
}
