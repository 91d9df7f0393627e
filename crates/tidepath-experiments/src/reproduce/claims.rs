//! Claims a paper makes, checked against our runs with the rank-sum test.

use crate::compare::Comparison;
use crate::stats::{rank_sum_test, smallest_p};
use crate::table::ALPHA;

/// Which way a claim orders two planners' costs on a problem.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// `a` reaches lower costs than `b`.
    Lower,
}

#[derive(Clone, Debug)]
pub struct Claim {
    /// The claim in words, e.g. "PSO beats GA on Sphere (small range)".
    pub text: String,
    pub problem: String,
    pub a: String,
    pub b: String,
    pub direction: Direction,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ClaimVerdict {
    /// Our runs agree: the difference is significant in the claimed direction.
    Reproduced { p: f64 },
    /// Our runs show no significant difference, at run counts where one could have shown.
    Inconclusive { p: f64 },
    /// Our runs show the opposite, significantly.
    Contradicted { p: f64 },
    /// No data of these sizes could have given p < alpha: the test cannot decide the claim
    /// with `runs` (a's and b's) runs, whatever the costs. `smallest_p` is the bound.
    Undecidable { p: f64, smallest_p: f64, runs: (usize, usize) },
    /// A planner the claim needs did not run.
    NotRun,
}

impl ClaimVerdict {
    pub fn label(&self) -> String {
        match self {
            ClaimVerdict::Reproduced { .. } => "reproduced".into(),
            ClaimVerdict::Inconclusive { .. } => "not reproduced (no significant difference)".into(),
            ClaimVerdict::Contradicted { .. } => "NOT reproduced (significantly the other way)".into(),
            ClaimVerdict::Undecidable { runs: (a, b), .. } if a == b => format!("undecidable with {a} runs"),
            ClaimVerdict::Undecidable { runs: (a, b), .. } => format!("undecidable with {a} and {b} runs"),
            ClaimVerdict::NotRun => "not checked (planner not run)".into(),
        }
    }

    /// The test's p-value, when the test ran.
    pub fn p(&self) -> Option<f64> {
        match self {
            ClaimVerdict::Reproduced { p }
            | ClaimVerdict::Inconclusive { p }
            | ClaimVerdict::Contradicted { p }
            | ClaimVerdict::Undecidable { p, .. } => Some(*p),
            ClaimVerdict::NotRun => None,
        }
    }
}

impl Claim {
    pub fn lower(problem: &str, a: &str, b: &str, text: String) -> Self {
        Self { text, problem: problem.into(), a: a.into(), b: b.into(), direction: Direction::Lower }
    }

    pub fn check(&self, c: &Comparison) -> ClaimVerdict {
        let costs =
            |p: &str| c.records_of(&self.problem, p).map(|r| r.cost).filter(|v| !v.is_nan()).collect::<Vec<_>>();
        let (a, b) = (costs(&self.a), costs(&self.b));
        if a.is_empty() || b.is_empty() {
            return ClaimVerdict::NotRun;
        }
        let r = rank_sum_test(&a, &b);
        if r.p_value >= ALPHA {
            let floor = smallest_p(r.method, a.len(), b.len());
            if floor >= ALPHA {
                return ClaimVerdict::Undecidable { p: r.p_value, smallest_p: floor, runs: (a.len(), b.len()) };
            }
            return ClaimVerdict::Inconclusive { p: r.p_value };
        }
        // U of `a` below its null mean means `a` tends to the lower costs.
        let a_lower = r.u_x < (a.len() * b.len()) as f64 / 2.0;
        match (self.direction, a_lower) {
            (Direction::Lower, true) => ClaimVerdict::Reproduced { p: r.p_value },
            (Direction::Lower, false) => ClaimVerdict::Contradicted { p: r.p_value },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compare::from_records;
    use crate::RunRecord;

    fn comparison(a: &[f64], b: &[f64]) -> Comparison {
        let f = |planner: &str, run: usize, cost: f64| RunRecord {
            problem: "f".into(),
            planner: planner.into(),
            run: run as u64,
            cost,
            feasible: true,
            ..RunRecord::default()
        };
        let records =
            a.iter().enumerate().map(|(i, c)| f("a", i, *c)).chain(b.iter().enumerate().map(|(i, c)| f("b", i, *c)));
        from_records("functions", &["f"], &["a", "b"], a.len() as u64, records.collect())
    }

    /// With 5 runs each a verdict is possible (smallest p 2 / C(10, 5) = 2/252): interleaved
    /// costs are "no significant difference", not undecidable.
    #[test]
    fn five_runs_can_decide() {
        let claim = Claim::lower("f", "a", "b", "a below b".into());
        let (low, high) = ([1.0, 2.0, 3.0, 4.0, 5.0], [6.0, 7.0, 8.0, 9.0, 10.0]);
        assert_eq!(claim.check(&comparison(&low, &high)), ClaimVerdict::Reproduced { p: 2.0 / 252.0 });
        assert_eq!(claim.check(&comparison(&high, &low)), ClaimVerdict::Contradicted { p: 2.0 / 252.0 });
        // a = 1, 3, 5, 7, 9 against b = 2, 4, ..., 10: U_a = 10, P(U <= 10) = 87/252, p = 174/252.
        let verdict = claim.check(&comparison(&[1.0, 3.0, 5.0, 7.0, 9.0], &[2.0, 4.0, 6.0, 8.0, 10.0]));
        let ClaimVerdict::Inconclusive { p } = verdict else { panic!("{verdict:?}") };
        assert!((p - 174.0 / 252.0).abs() < 1e-15, "{p}");
    }
}
