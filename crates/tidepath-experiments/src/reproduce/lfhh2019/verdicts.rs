//! Claims on feasibility: a planner's runs lie below (or above) F = 2, by the exact two-sided
//! sign test of the runs' F against 2; claims between two rows use the rank-sum test of
//! reproduce/claims.rs.

use super::super::{Claim, ClaimVerdict};
use super::paper::FEASIBLE_BELOW;
use crate::table::ALPHA;

/// Two-sided exact sign test of `below` runs under a bound and `above` runs over it (ties
/// take no part): p = min(1, 2 P(X <= min(below, above))) for X ~ Binomial(n, 1/2).
pub fn sign_test_p(below: usize, above: usize) -> f64 {
    let n = below + above;
    if n == 0 {
        return 1.0;
    }
    let k = below.min(above);
    // P(X <= k) summed in logs of binomial coefficients (n is at most a few hundred runs).
    let ln_half_n = -(n as f64) * std::f64::consts::LN_2;
    let mut ln_c = 0.0f64; // ln C(n, 0)
    let mut tail = 0.0;
    for i in 0..=k {
        if i > 0 {
            ln_c += ((n - i + 1) as f64).ln() - (i as f64).ln();
        }
        tail += (ln_c + ln_half_n).exp();
    }
    (2.0 * tail).min(1.0)
}

/// The smallest p the sign test can return with `n` untied runs.
pub fn sign_test_floor(n: usize) -> f64 {
    sign_test_p(n, 0)
}

/// The verdict on "`values` lie below F = 2" (`below`) or "above" it.
pub fn feasibility_verdict(values: &[f64], below: bool) -> ClaimVerdict {
    let v: Vec<f64> = values.iter().copied().filter(|x| !x.is_nan()).collect();
    if v.is_empty() {
        return ClaimVerdict::NotRun;
    }
    let under = v.iter().filter(|&&x| x < FEASIBLE_BELOW).count();
    let over = v.iter().filter(|&&x| x > FEASIBLE_BELOW).count();
    let p = sign_test_p(under, over);
    let n = under + over;
    if p >= ALPHA {
        let floor = sign_test_floor(n);
        if floor >= ALPHA {
            return ClaimVerdict::Undecidable { p, smallest_p: floor, runs: (n, n) };
        }
        return ClaimVerdict::Inconclusive { p };
    }
    if (under > over) == below {
        ClaimVerdict::Reproduced { p }
    } else {
        ClaimVerdict::Contradicted { p }
    }
}

/// "`planner` is feasible (F < 2) on `problem`" or "... infeasible (F > 2) ...", judged on
/// `values` (its runs' F), the counts in the text.
pub fn feasibility_claim(
    problem: &str,
    planner: &str,
    name: &str,
    below: bool,
    values: &[f64],
) -> (Claim, ClaimVerdict) {
    let under = values.iter().filter(|&&x| x < FEASIBLE_BELOW).count();
    let what = if below { "feasible (F < 2)" } else { "infeasible (F > 2)" };
    let text = format!(
        "{name} is {what} on {problem} (sign test of the runs' F against 2; ours: {under} of {} runs below 2)",
        values.len()
    );
    let (a, b) = if below { (planner, "F = 2") } else { ("F = 2", planner) };
    (Claim::lower(problem, a, b, text), feasibility_verdict(values, below))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sign_test_is_the_binomial_tail() {
        // 30 of 30 below: 2 / 2^30.
        assert!((sign_test_p(30, 0) - 2.0 / 2f64.powi(30)).abs() < 1e-20);
        // 8 against 2 of 10: 2 (1 + 10 + 45) / 1024 = 112/1024.
        assert!((sign_test_p(8, 2) - 112.0 / 1024.0).abs() < 1e-15);
        assert!((sign_test_p(2, 8) - 112.0 / 1024.0).abs() < 1e-15);
        assert_eq!(sign_test_p(5, 5), 1.0);
        assert_eq!(sign_test_p(0, 0), 1.0);
        assert_eq!(sign_test_floor(2), 0.5);
        assert!(sign_test_floor(5) > ALPHA && sign_test_floor(6) < ALPHA);
    }

    #[test]
    fn feasibility_verdicts_follow_the_counts() {
        let low = [0.6; 8];
        let high = [3.0; 8];
        assert!(matches!(feasibility_verdict(&low, true), ClaimVerdict::Reproduced { .. }));
        assert!(matches!(feasibility_verdict(&low, false), ClaimVerdict::Contradicted { .. }));
        assert!(matches!(feasibility_verdict(&high, false), ClaimVerdict::Reproduced { .. }));
        let mixed = [0.5, 3.0, 0.7, 2.5, 0.9, 2.1, 1.0, 4.0];
        assert!(matches!(feasibility_verdict(&mixed, true), ClaimVerdict::Inconclusive { .. }));
        assert_eq!(
            feasibility_verdict(&[0.5, 0.6], true),
            ClaimVerdict::Undecidable { p: 0.5, smallest_p: 0.5, runs: (2, 2) }
        );
        assert_eq!(feasibility_verdict(&[], true), ClaimVerdict::NotRun);
        let (claim, _) = feasibility_claim("2d x", "lfhh", "LFHH", true, &mixed);
        assert_eq!(
            claim.text,
            "LFHH is feasible (F < 2) on 2d x (sign test of the runs' F against 2; ours: 4 of 8 runs below 2)"
        );
    }
}
