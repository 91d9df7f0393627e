//! Claims a paper makes, checked against our runs with the rank-sum test.

use crate::compare::Comparison;
use crate::stats::{rank_sum_test, smallest_p};
use crate::table::ALPHA;
use crate::RunRecord;

/// Which way a claim orders two planners' values of its metric on a problem.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// `a` reaches lower values than `b`.
    Lower,
}

/// What a claim compares: each run's final cost (the default), its path length, or its wall
/// time.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Metric {
    #[default]
    Cost,
    /// The final path's length (`length_m`); runs without one (nothing planned, benchmark
    /// functions) take no part.
    Length,
    /// The run's wall time (`elapsed_s`): machine-dependent, unlike every other metric.
    Time,
}

impl Metric {
    /// The run's value of this metric; `None` (the run takes no part) when it has none.
    pub fn value(self, r: &RunRecord) -> Option<f64> {
        let v = match self {
            Metric::Cost => Some(r.cost),
            Metric::Length => r.length_m,
            Metric::Time => Some(r.elapsed_s),
        };
        v.filter(|v| !v.is_nan())
    }

    pub fn id(self) -> &'static str {
        match self {
            Metric::Cost => "cost",
            Metric::Length => "length",
            Metric::Time => "wall time",
        }
    }
}

#[derive(Clone, Debug)]
pub struct Claim {
    /// The claim in words, e.g. "PSO beats GA on Sphere (small range)".
    pub text: String,
    pub problem: String,
    pub a: String,
    pub b: String,
    pub direction: Direction,
    pub metric: Metric,
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
    /// `a` reaches lower costs than `b` on `problem`.
    pub fn lower(problem: &str, a: &str, b: &str, text: String) -> Self {
        Self {
            text,
            problem: problem.into(),
            a: a.into(),
            b: b.into(),
            direction: Direction::Lower,
            metric: Metric::Cost,
        }
    }

    /// The same claim on another metric.
    pub fn on(self, metric: Metric) -> Self {
        Self { metric, ..self }
    }

    /// The verdict on the claim's metric over the runs of `c`.
    pub fn check(&self, c: &Comparison) -> ClaimVerdict {
        let values = |p: &str| c.records_of(&self.problem, p).filter_map(|r| self.metric.value(r)).collect::<Vec<_>>();
        self.judge(&values(&self.a), &values(&self.b))
    }

    /// The verdict on values of `a`'s and `b`'s runs measured outside the run records (e.g. a
    /// path's length before smoothing); NaN values take no part.
    pub fn judge(&self, a: &[f64], b: &[f64]) -> ClaimVerdict {
        let clean = |v: &[f64]| v.iter().copied().filter(|v| !v.is_nan()).collect::<Vec<_>>();
        let (a, b) = (clean(a), clean(b));
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
        // U of `a` below its null mean means `a` tends to the lower values.
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

    /// Runs of a scenario: `cost` rises with the index while `length_m` and `elapsed_s` fall,
    /// so each metric orders the planners its own way.
    fn runs(planner: &str, base: f64) -> Vec<RunRecord> {
        (0..5)
            .map(|i| RunRecord {
                problem: "s".into(),
                planner: planner.into(),
                run: i,
                cost: base + i as f64,
                length_m: Some(1000.0 - base - i as f64),
                elapsed_s: 50.0 - base - i as f64,
                feasible: true,
                ..RunRecord::default()
            })
            .collect()
    }

    /// A claim on length or wall time reads that field, not the cost: a planner with the
    /// lower costs can have the longer paths and the longer runs.
    #[test]
    fn claims_on_length_and_time_read_their_own_metric() {
        let records = [runs("a", 0.0), runs("b", 10.0)].concat();
        let c = from_records("scenario", &["s"], &["a", "b"], 5, records);
        let claim = Claim::lower("s", "a", "b", "a below b".into());
        let p = 2.0 / 252.0;
        assert_eq!(claim.metric, Metric::Cost);
        assert_eq!(claim.check(&c), ClaimVerdict::Reproduced { p });
        assert_eq!(claim.clone().on(Metric::Length).check(&c), ClaimVerdict::Contradicted { p });
        assert_eq!(claim.clone().on(Metric::Time).check(&c), ClaimVerdict::Contradicted { p });
        // b below a on length: reproduced.
        let b_shorter = Claim::lower("s", "b", "a", "b shorter".into()).on(Metric::Length);
        assert_eq!(b_shorter.check(&c), ClaimVerdict::Reproduced { p });
    }

    /// Runs without a length (nothing planned) take no part; with none left the claim is not
    /// checked, whatever the costs.
    #[test]
    fn runs_without_the_metric_take_no_part() {
        let mut a = runs("a", 0.0);
        for r in &mut a[..3] {
            r.length_m = None;
        }
        let b = runs("b", 10.0);
        let c = from_records("scenario", &["s"], &["a", "b"], 5, [a.clone(), b.clone()].concat());
        let claim = Claim::lower("s", "b", "a", "b shorter".into()).on(Metric::Length);
        // Two runs of a against five of b, fully separated: exact p = 2 / C(7, 2) = 2/21,
        // which no data of these sizes can push below 0.05.
        let v = claim.check(&c);
        assert_eq!(v, ClaimVerdict::Undecidable { p: 2.0 / 21.0, smallest_p: 2.0 / 21.0, runs: (5, 2) }, "{v:?}");
        for r in &mut a {
            r.length_m = None;
        }
        let c = from_records("scenario", &["s"], &["a", "b"], 5, [a, b].concat());
        assert_eq!(claim.check(&c), ClaimVerdict::NotRun);
        assert_eq!(claim.on(Metric::Cost).check(&c), ClaimVerdict::Contradicted { p: 2.0 / 252.0 });
    }

    /// `judge` decides on values measured outside the records, NaN left out.
    #[test]
    fn judge_takes_values_from_outside_the_records() {
        let claim = Claim::lower("s", "a", "b", "a below b".into()).on(Metric::Length);
        let p = 2.0 / 252.0;
        assert_eq!(
            claim.judge(&[1.0, 2.0, 3.0, 4.0, 5.0], &[6.0, 7.0, 8.0, 9.0, 10.0]),
            ClaimVerdict::Reproduced { p }
        );
        assert_eq!(claim.judge(&[f64::NAN], &[1.0]), ClaimVerdict::NotRun);
        assert_eq!(claim.judge(&[], &[1.0, 2.0]), ClaimVerdict::NotRun);
    }
}
