//! Claims a paper makes, checked against our runs with the rank-sum test.

use crate::compare::Comparison;
use crate::stats::rank_sum_test;
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
    /// Our runs show no significant difference.
    Inconclusive { p: f64 },
    /// Our runs show the opposite, significantly.
    Contradicted { p: f64 },
    /// A planner the claim needs did not run.
    NotRun,
}

impl ClaimVerdict {
    pub fn label(&self) -> &'static str {
        match self {
            ClaimVerdict::Reproduced { .. } => "reproduced",
            ClaimVerdict::Inconclusive { .. } => "not reproduced (no significant difference)",
            ClaimVerdict::Contradicted { .. } => "NOT reproduced (significantly the other way)",
            ClaimVerdict::NotRun => "not checked (planner not run)",
        }
    }
}

impl Claim {
    pub fn lower(problem: &str, a: &str, b: &str, text: String) -> Self {
        Self { text, problem: problem.into(), a: a.into(), b: b.into(), direction: Direction::Lower }
    }

    pub fn check(&self, c: &Comparison) -> ClaimVerdict {
        let costs = |p: &str| c.records_of(&self.problem, p).map(|r| r.cost).collect::<Vec<_>>();
        let (a, b) = (costs(&self.a), costs(&self.b));
        if a.is_empty() || b.is_empty() {
            return ClaimVerdict::NotRun;
        }
        let r = rank_sum_test(&a, &b);
        if r.p_value >= ALPHA {
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
