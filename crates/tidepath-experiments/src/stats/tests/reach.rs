//! The smallest reachable p-value.

use super::*;

#[test]
fn smallest_p_matches_hand_computed_bounds() {
    // Exact: 2 / C(4, 2) = 1/3, 2 / C(6, 3) = 0.1, 2 / C(8, 4) = 1/35.
    assert_rel(smallest_p(Method::Exact, 2, 2), 1.0 / 3.0, 1e-15, "exact 2 vs 2");
    assert_rel(smallest_p(Method::Exact, 3, 3), 0.1, 1e-15, "exact 3 vs 3");
    assert_rel(smallest_p(Method::Exact, 4, 4), 1.0 / 35.0, 1e-15, "exact 4 vs 4");
    assert_eq!(smallest_p(Method::Exact, 1, 1), 1.0);
    // Normal, 2 vs 2, each sample one tied group: N = 4, sum(t^3 - t) = 12, variance
    // 4/12 (5 - 12/12) = 4/3, z = (2 - 0.5) / sqrt(4/3) = 1.29904, p = erfc(z / sqrt 2)
    // = 0.193931 (scipy.stats.norm.sf(1.29904) * 2).
    assert_rel(smallest_p(Method::Normal, 2, 2), 0.193_930_852_282_41, 1e-9, "normal 2 vs 2");
    // 3 vs 3: variance 9/12 (7 - 48/30) = 4.05, z = 4 / sqrt 4.05 = 1.98762, p = 0.0468542.
    assert_rel(smallest_p(Method::Normal, 3, 3), 0.046_854_177_603_87, 1e-9, "normal 3 vs 3");
    assert_eq!(smallest_p(Method::Normal, 1, 1), 1.0);
    assert_eq!(smallest_p(Method::Exact, 0, 5), 1.0);
    // Either method: the lower bound; 2 runs can never reach 0.05, 4 can.
    assert_rel(smallest_p_any(2, 2), 0.193_930_852_282_41, 1e-9, "any 2 vs 2");
    assert!(smallest_p_any(4, 4) < 0.05);
    // Beyond R's exact limit only the normal bound counts; huge run counts do not overflow.
    assert_eq!(smallest_p_any(60, 60), smallest_p(Method::Normal, 60, 60));
    assert_eq!(smallest_p(Method::Exact, 100_000, 100_000), 0.0);
}

/// Every data set of sizes up to 3 vs 3 over four values (every tie pattern): no p-value is
/// below the bound of the method that produced it, and the bound is reached.
#[test]
fn no_data_set_beats_the_smallest_p() {
    for (nx, ny) in [(1, 2), (2, 2), (2, 3), (3, 3), (1, 4)] {
        let mut lowest = [f64::INFINITY; 2];
        let n = nx + ny;
        for code in 0..4usize.pow(n as u32) {
            let values: Vec<f64> = (0..n).map(|i| (code / 4usize.pow(i as u32) % 4) as f64).collect();
            let r = rank_sum_test(&values[..nx], &values[nx..]);
            let k = (r.method == Method::Normal) as usize;
            let bound = smallest_p(r.method, nx, ny);
            assert!(r.p_value >= bound * (1.0 - 1e-12), "{nx} vs {ny}: {values:?} gives {} < {bound}", r.p_value);
            lowest[k] = lowest[k].min(r.p_value);
        }
        assert_rel(lowest[1], smallest_p(Method::Normal, nx, ny), 1e-12, "normal bound reached");
        // Untied data need n distinct values; four suffice up to n = 4.
        if n <= 4 {
            assert_rel(lowest[0], smallest_p(Method::Exact, nx, ny), 1e-12, "exact bound reached");
        }
    }
}
