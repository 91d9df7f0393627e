//! acopf2016's claims judged on the runs' measures: the two-sample ones (ACOPF against ACO)
//! by the rank-sum test of reproduce/claims.rs, claim 4 (two optimal paths of equal length in
//! environment 1) by counting, since it is a statement about paths, not a difference between
//! planners.

use super::super::{Claim, ClaimVerdict, Metric};
use super::paper::{CLAIM_CONVERGES, CLAIM_CURRENT, CLAIM_QUICKER, CLAIM_SHORTER, CLAIM_WAVES};
use super::runs::Measure;
use crate::table::num;

/// `planner`'s measures.
pub fn of<'a>(ms: &'a [Measure], planner: &'a str) -> impl Iterator<Item = &'a Measure> + 'a {
    ms.iter().filter(move |m| m.planner == planner)
}

/// `f` of every run of `planner`, a failed run ranked after every successful one (a failure is
/// worse than any path, whatever its length or time).
pub fn ranked(ms: &[Measure], planner: &str, f: fn(&Measure) -> f64) -> Vec<f64> {
    of(ms, planner).map(|m| if m.success { f(m) } else { f64::INFINITY }).collect()
}

/// `f` of `planner`'s successful runs.
pub fn successful(ms: &[Measure], planner: &str, f: fn(&Measure) -> f64) -> Vec<f64> {
    of(ms, planner).filter(|m| m.success).map(f).collect()
}

fn judged(claim: Claim, a: &[f64], b: &[f64]) -> (Claim, ClaimVerdict) {
    let v = claim.judge(a, b);
    (claim, v)
}

/// Claim 1: ACOPF's runs reach their final best in fewer iterations than ACO's (runs that
/// found a path at all).
pub fn converges_faster(problem: &str, ms: &[Measure]) -> (Claim, ClaimVerdict) {
    let it = |p: &str| of(ms, p).map(|m| m.converged).collect::<Vec<_>>();
    judged(Claim::lower(problem, "acopf", "aco", CLAIM_CONVERGES.into()), &it("acopf"), &it("aco"))
}

/// Claim 2: shorter paths, failures ranked last.
pub fn shorter(problem: &str, ms: &[Measure]) -> (Claim, ClaimVerdict) {
    let claim = Claim::lower(problem, "acopf", "aco", CLAIM_SHORTER.into()).on(Metric::Length);
    judged(claim, &ranked(ms, "acopf", |m| m.length), &ranked(ms, "aco", |m| m.length))
}

/// Claim 3: quicker paths in the glider's travel time, failures ranked last.
pub fn quicker(problem: &str, ms: &[Measure]) -> (Claim, ClaimVerdict) {
    judged(
        Claim::lower(problem, "acopf", "aco", CLAIM_QUICKER.into()),
        &ranked(ms, "acopf", |m| m.time),
        &ranked(ms, "aco", |m| m.time),
    )
}

/// Claim 5: a higher mean wave height along the path than ACO's, over the successful runs
/// (tested as ACOPF's negated heights lower than ACO's).
pub fn follows_waves(problem: &str, ms: &[Measure]) -> (Claim, ClaimVerdict) {
    let neg = |p: &str| successful(ms, p, |m| -m.wave_mean);
    judged(Claim::lower(problem, "acopf", "aco", CLAIM_WAVES.into()), &neg("acopf"), &neg("aco"))
}

/// Claim 6: a larger share of the path inside the current band than ACO's, over the
/// successful runs.
pub fn uses_current(problem: &str, ms: &[Measure]) -> (Claim, ClaimVerdict) {
    let neg = |p: &str| successful(ms, p, |m| -m.band_share.unwrap_or(f64::NAN));
    judged(Claim::lower(problem, "acopf", "aco", CLAIM_CURRENT.into()), &neg("acopf"), &neg("aco"))
}

/// A verdict in words, for claims no two-sample test decides.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Word {
    Reproduced,
    Partly,
    NotReproduced,
}

impl Word {
    pub fn label(self) -> &'static str {
        match self {
            Word::Reproduced => "reproduced",
            Word::Partly => "partly reproduced",
            Word::NotReproduced => "NOT reproduced",
        }
    }
}

/// Claim 4 on ACOPF's runs in environment 1.
#[derive(Clone, Debug, PartialEq)]
pub struct TwoOptima {
    /// A*'s length optimum on the same cells (m); `None` when it found none.
    pub optimum: Option<f64>,
    /// ACOPF's successful runs whose path has the optimum's length, of all its runs.
    pub at_optimum: usize,
    pub runs: usize,
    /// Distinct paths among those.
    pub distinct: usize,
    /// ACOPF's shortest path over the runs (m).
    pub best: Option<f64>,
    pub verdict: Word,
}

/// Relative tolerance for "the same length": lengths are sums of at most a few hundred steps.
pub const SAME_LENGTH: f64 = 1e-9;

/// Claim 4: reproduced when ACOPF's runs find at least two distinct paths of the optimal
/// length, partly when they find the optimal length on one path only, not reproduced when no
/// run reaches it (or A* found no optimum to check against).
pub fn two_optima(ms: &[Measure], optimum: Option<f64>) -> TwoOptima {
    let runs = of(ms, "acopf").count();
    let best = successful(ms, "acopf", |m| m.length).into_iter().reduce(f64::min);
    let at: Vec<&Measure> = match optimum {
        Some(l) => of(ms, "acopf").filter(|m| m.success && (m.length - l).abs() <= SAME_LENGTH * l.abs()).collect(),
        None => Vec::new(),
    };
    let mut keys: Vec<&Vec<[i64; 2]>> = at.iter().map(|m| &m.key).collect();
    keys.sort();
    keys.dedup();
    let verdict = match keys.len() {
        0 => Word::NotReproduced,
        1 => Word::Partly,
        _ => Word::Reproduced,
    };
    TwoOptima { optimum, at_optimum: at.len(), runs, distinct: keys.len(), best, verdict }
}

impl TwoOptima {
    /// The finding in words, with the numbers.
    pub fn note(&self) -> String {
        let optimum = self.optimum.map_or("none found".into(), |l| format!("{} m", num(l)));
        format!(
            "{}: **{}**. A*'s length optimum on the same cells: {optimum}. ACOPF's shortest path: {} m; {} of its {} \
             runs end on a path of the optimal length, along {} distinct path(s){}.",
            super::paper::CLAIM_TWO_OPTIMA,
            self.verdict.label(),
            self.best.map_or("—".into(), num),
            self.at_optimum,
            self.runs,
            self.distinct,
            match self.verdict {
                Word::Reproduced => " (on an 8-connected grid many step orders have one length; the paper shows two)",
                Word::Partly => ": the optimal length is reached, but every run found the same path",
                Word::NotReproduced => ": no run reached the optimal length",
            }
        )
    }
}
