//! Per-planner rows of a comparison: the statistics the papers report, computed once, each
//! over the runs it names (all runs, or the feasible ones).

mod markdown;

use serde::{Deserialize, Serialize};

pub use markdown::{legend, mark_cells, markdown, reference_line, NO_FEASIBLE_RUN};

use super::stats::{compare_to_reference, smallest_p, Mark, Summary};
use super::RunRecord;
use tidepath::planner::Status;

/// Significance level of the rank-sum marks (lfhh2019 uses 0.05).
pub const ALPHA: f64 = 0.05;

/// How a row's planner compares with the first planner in the rank-sum test (the table's last
/// column), worded from the row's side: "better" means this row's costs are significantly lower.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum RowMark {
    /// Significantly lower costs than the first planner.
    Better,
    /// Significantly higher costs than the first planner.
    Worse,
    /// No significant difference, at a sample size where one could have been found.
    Similar,
    /// No p-value below alpha is possible with these run counts, whatever the data.
    Undecidable,
}

impl RowMark {
    /// From the papers' mark (which speaks for the first planner) and the smallest p-value the
    /// test could have reached.
    pub fn from_reference_mark(mark: Mark, smallest_p: f64, alpha: f64) -> Self {
        match mark {
            Mark::Better => RowMark::Worse,
            Mark::Worse => RowMark::Better,
            Mark::Similar if smallest_p >= alpha => RowMark::Undecidable,
            Mark::Similar => RowMark::Similar,
        }
    }

    pub fn word(self) -> &'static str {
        match self {
            RowMark::Better => "better",
            RowMark::Worse => "worse",
            RowMark::Similar => "≈",
            RowMark::Undecidable => "undecidable",
        }
    }
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct PlannerRow {
    pub problem: String,
    pub planner: String,
    /// Runs that finished: the denominator of every all-runs statistic.
    pub runs: usize,
    /// Runs whose path is feasible (every run of a function benchmark): the denominator of the
    /// feasible-only statistics.
    #[serde(default)]
    pub feasible_runs: usize,
    /// Cost over all runs, penalties for violations included (an infeasible run's cost carries
    /// them): the papers' columns and what the rank-sum test compares.
    #[serde(deserialize_with = "crate::record::null_as_nan")]
    pub best: f64,
    #[serde(deserialize_with = "crate::record::null_as_nan")]
    pub mean: f64,
    #[serde(deserialize_with = "crate::record::null_as_nan")]
    pub std: f64,
    #[serde(deserialize_with = "crate::record::null_as_nan")]
    pub worst: f64,
    #[serde(deserialize_with = "crate::record::null_as_nan")]
    pub median: f64,
    /// Share of runs whose path is feasible: `feasible_runs / runs`.
    #[serde(deserialize_with = "crate::record::null_as_nan")]
    pub success_rate: f64,
    /// Best and mean cost over the feasible runs only; `None` without a feasible run.
    #[serde(default)]
    pub feasible_best: Option<f64>,
    #[serde(default)]
    pub feasible_mean: Option<f64>,
    /// Mean length and travel time over the feasible runs only (an infeasible path may be short
    /// because it cuts through an obstacle); `None` without a feasible run and for function
    /// benchmarks.
    pub mean_length_m: Option<f64>,
    pub mean_travel_time_s: Option<f64>,
    /// Over all runs.
    #[serde(deserialize_with = "crate::record::null_as_nan")]
    pub mean_evaluations: f64,
    /// Timing field: mean wall time per run (s), over all runs.
    #[serde(deserialize_with = "crate::record::null_as_nan")]
    pub mean_wall_s: f64,
    /// Runs whose cost is exactly 0, and below 1e-300 (amfa2015's "0 times" columns), of `runs`.
    pub zeros_exact: usize,
    pub zeros_tiny: usize,
    /// Two-sided Wilcoxon rank-sum test of this row's costs (all runs) against the first
    /// planner's, from this row's side: `better`, `worse`, `similar` or `undecidable`. `None`
    /// for the first planner itself.
    pub mark: Option<RowMark>,
    pub p_value: Option<f64>,
    /// The smallest p-value the test could have returned with these run counts, whatever the
    /// costs: at or above alpha the mark is `undecidable`.
    #[serde(default)]
    pub smallest_p: Option<f64>,
    /// Gap of the feasible runs' mean and best cost to the reference plan's cost, in percent.
    #[serde(default)]
    pub gap_percent: Option<f64>,
    #[serde(default)]
    pub best_gap_percent: Option<f64>,
    /// How many runs ended with each plan status, in order of severity (scenario runs only).
    #[serde(default)]
    pub statuses: Vec<(String, usize)>,
}

fn mean(xs: impl Iterator<Item = f64>) -> f64 {
    let (s, n) = xs.fold((0.0, 0usize), |(s, n), x| (s + x, n + 1));
    if n == 0 {
        f64::NAN
    } else {
        s / n as f64
    }
}

/// Mean of the values present; `None` when there is none.
fn mean_of(xs: impl Iterator<Item = Option<f64>>) -> Option<f64> {
    let v: Vec<f64> = xs.flatten().collect();
    (!v.is_empty()).then(|| mean(v.into_iter()))
}

/// The rank-sum verdict of `costs` against the first planner's `reference` costs, from the
/// row's side, with the p-value and the smallest p-value reachable at these sizes.
fn mark(reference: &[f64], costs: &[f64]) -> (RowMark, f64, f64) {
    let (m, r) = compare_to_reference(reference, costs, ALPHA);
    let n = |xs: &[f64]| xs.iter().filter(|v| !v.is_nan()).count();
    let floor = smallest_p(r.method, n(reference), n(costs));
    (RowMark::from_reference_mark(m, floor, ALPHA), r.p_value, floor)
}

/// Rows for one problem; `planners` in report order, the first is the one the others are
/// marked against.
pub fn rows_for(problem: &str, planners: &[String], records: &[RunRecord]) -> Vec<PlannerRow> {
    let of = |p: &str| records.iter().filter(|r| r.problem == problem && r.planner == p).collect::<Vec<_>>();
    let reference: Vec<f64> = planners.first().map(|p| of(p).iter().map(|r| r.cost).collect()).unwrap_or_default();
    planners
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let runs = of(p);
            let costs: Vec<f64> = runs.iter().map(|r| r.cost).collect();
            let s = Summary::of(&costs);
            let feasible: Vec<&&RunRecord> = runs.iter().filter(|r| r.feasible).collect();
            let feasible_costs: Vec<f64> = feasible.iter().map(|r| r.cost).collect();
            let fs = Summary::of(&feasible_costs);
            let (mark, p_value, smallest_p) = if i == 0 || costs.is_empty() || reference.is_empty() {
                (None, None, None)
            } else {
                let (m, p, floor) = mark(&reference, &costs);
                (Some(m), Some(p), Some(floor))
            };
            PlannerRow {
                problem: problem.to_string(),
                planner: p.clone(),
                runs: runs.len(),
                feasible_runs: feasible.len(),
                best: s.as_ref().map_or(f64::NAN, |s| s.best),
                mean: s.as_ref().map_or(f64::NAN, |s| s.mean),
                std: s.as_ref().map_or(f64::NAN, |s| s.std),
                worst: s.as_ref().map_or(f64::NAN, |s| s.worst),
                median: s.as_ref().map_or(f64::NAN, |s| s.median),
                success_rate: if runs.is_empty() { 0.0 } else { feasible.len() as f64 / runs.len() as f64 },
                feasible_best: fs.map(|s| s.best),
                feasible_mean: fs.map(|s| s.mean),
                mean_length_m: mean_of(feasible.iter().map(|r| r.length_m)),
                mean_travel_time_s: mean_of(feasible.iter().map(|r| r.travel_time_s)),
                mean_evaluations: mean(runs.iter().map(|r| r.evaluations as f64)),
                mean_wall_s: mean(runs.iter().map(|r| r.elapsed_s)),
                zeros_exact: costs.iter().filter(|c| **c == 0.0).count(),
                zeros_tiny: costs.iter().filter(|c| c.abs() < 1e-300).count(),
                mark,
                p_value,
                smallest_p,
                gap_percent: None,
                best_gap_percent: None,
                statuses: Status::ALL
                    .iter()
                    .map(|st| (st.id().to_string(), runs.iter().filter(|r| r.status == Some(*st)).count()))
                    .filter(|(_, n)| *n > 0)
                    .collect(),
            }
        })
        .collect()
}

/// Compact number for single values: 4 significant digits, scientific outside [1e-3, 1e5).
/// Table columns use [`crate::columns::ColumnFormat`] instead, one format per column.
pub fn num(x: f64) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    if x == 0.0 {
        return "0".into();
    }
    let a = x.abs();
    if (1e-3..1e5).contains(&a) {
        let digits = (3 - a.log10().floor() as i32).max(0) as usize;
        format!("{x:.digits$}")
    } else {
        format!("{x:.3e}")
    }
}

#[cfg(test)]
mod tests;
