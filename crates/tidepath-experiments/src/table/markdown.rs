//! The Markdown table `compare` and `bench functions` print and write to `table.md`, and the
//! legend that says what each column counts: which runs (all, or feasible only), whether costs
//! include penalties, what the gap is measured against and what the marks mean.

use super::{PlannerRow, RowMark, ALPHA};
use crate::columns::{render, Column, ColumnFormat};
use crate::compare::Comparison;
use tidepath::planner::Status;

/// Shown instead of numbers in the feasible-only columns of a planner without a feasible run.
pub const NO_FEASIBLE_RUN: &str = "no feasible run";

/// A numeric column over feasible runs: `no feasible run` where a row has none.
fn feasible(header: &str, rows: &[PlannerRow], value: impl Fn(&PlannerRow) -> Option<f64>) -> Column {
    let f = ColumnFormat::of(rows.iter().filter_map(&value), 4);
    let cells = rows
        .iter()
        .map(|r| match value(r) {
            _ if r.feasible_runs == 0 => NO_FEASIBLE_RUN.to_string(),
            Some(v) => f.show(v),
            None => "—".to_string(),
        })
        .collect();
    Column::new(header, cells)
}

/// `k/N`: a count with its denominator.
fn of(k: usize, n: usize) -> String {
    format!("{k}/{n}")
}

/// The mark column: the row's verdict against the first planner with its p-value, or how
/// small a p-value could have been where no verdict is possible.
pub fn mark_cells(rows: &[PlannerRow]) -> Vec<String> {
    let f = ColumnFormat::of(rows.iter().flat_map(|r| [r.p_value, r.smallest_p]).flatten(), 2);
    rows.iter()
        .map(|r| match (r.mark, r.p_value, r.smallest_p) {
            (Some(RowMark::Undecidable), _, Some(floor)) => format!("undecidable (p ≥ {})", f.show(floor)),
            (Some(m), Some(p), _) => format!("{} (p={})", m.word(), f.show(p)),
            _ => "ref".into(),
        })
        .collect()
}

/// The gap of a row's feasible best and mean to the reference, `+1.23 / +4.56`.
fn gap(r: &PlannerRow) -> String {
    match (r.best_gap_percent, r.gap_percent) {
        _ if r.feasible_runs == 0 => NO_FEASIBLE_RUN.to_string(),
        (Some(b), Some(m)) => format!("{b:+.2} / {m:+.2}"),
        _ => "—".to_string(),
    }
}

/// A row's value for a numeric column.
type Value = fn(&PlannerRow) -> f64;

/// The papers' cost columns: over all runs.
const COSTS: [(&str, Value); 4] =
    [("best", |r| r.best), ("mean", |r| r.mean), ("std", |r| r.std), ("worst", |r| r.worst)];

/// The table of `c` (one row per problem and planner), without the legend.
pub fn markdown(c: &Comparison) -> String {
    let rows = &c.rows;
    let cells = |f: &dyn Fn(&PlannerRow) -> String| rows.iter().map(f).collect::<Vec<_>>();
    let numbers = |f: &dyn Fn(&PlannerRow) -> f64| rows.iter().map(f).collect::<Vec<_>>();
    let reference = c.planners.first().map_or("", String::as_str);
    let mut columns = Vec::new();
    if c.is_functions() {
        columns.push(Column::new("problem", cells(&|r| r.problem.clone())));
        columns.push(Column::new("planner", cells(&|r| r.planner.clone())));
        for (h, f) in COSTS {
            columns.push(Column::numbers(h, numbers(&f), 4));
        }
        columns.push(Column::new("f = 0", cells(&|r| of(r.zeros_exact, r.runs))));
        columns.push(Column::new("f < 1e-300", cells(&|r| of(r.zeros_tiny, r.runs))));
    } else {
        columns.push(Column::new("planner", cells(&|r| r.planner.clone())));
        columns.push(Column::new("feasible runs", cells(&|r| of(r.feasible_runs, r.runs))));
        for (h, f) in COSTS {
            columns.push(Column::numbers(format!("{h} (pen.)"), numbers(&f), 4));
        }
        let fc = ColumnFormat::of(rows.iter().flat_map(|r| [r.feasible_best, r.feasible_mean]).flatten(), 4);
        columns.push(Column::new(
            "feasible cost best / mean",
            cells(&|r| match (r.feasible_best, r.feasible_mean) {
                (Some(b), Some(m)) => format!("{} / {}", fc.show(b), fc.show(m)),
                _ => NO_FEASIBLE_RUN.to_string(),
            }),
        ));
        if c.reference.is_some() {
            columns.push(Column::new("gap % best / mean", cells(&gap)));
        }
        columns.push(feasible("length m", rows, |r| r.mean_length_m));
        columns.push(feasible("travel s", rows, |r| r.mean_travel_time_s));
        // A column for each status that occurred, in order of severity.
        for id in Status::ALL.iter().map(|s| s.id()) {
            let count = |r: &PlannerRow| r.statuses.iter().find(|(n, _)| n == id).map_or(0, |(_, k)| *k);
            if rows.iter().any(|r| count(r) > 0) {
                columns.push(Column::new(id, cells(&|r| count(r).to_string())));
            }
        }
    }
    columns.push(Column::new("evals/run", cells(&|r| format!("{:.0}", r.mean_evaluations))));
    columns.push(Column::numbers("wall s/run", numbers(&|r| r.mean_wall_s), 3));
    columns.push(Column::new(format!("vs {reference}"), mark_cells(rows)));
    render(&columns)
}

/// What the gap column measures against, or why there is none (scenario comparisons).
pub fn reference_line(c: &Comparison) -> Option<String> {
    if c.is_functions() {
        return None;
    }
    Some(match (&c.reference, &c.reference_planner) {
        (Some(r), _) => format!(
            "Reference: {} ({}), cost {}, run once with its defaults; gap % = 100 (cost - reference) / reference, \
             of the best and the mean cost over feasible runs.",
            r.planner,
            r.status,
            super::num(r.cost)
        ),
        (None, Some(p)) => format!("Reference: {p} found no feasible plan; no gap column."),
        (None, None) => "Reference: none asked for; no gap column.".to_string(),
    })
}

/// The legend under the table: one line per kind of column.
pub fn legend(c: &Comparison) -> String {
    let reference = c.planners.first().map_or("", String::as_str);
    let mut lines = Vec::new();
    if c.is_functions() {
        lines.push("best, mean, std, worst: the function value over all runs (every optimum is f = 0).".to_string());
        lines.push(
            "f = 0, f < 1e-300: runs that reach the optimum exactly, and to below 1e-300 (amfa2015's \"0 times\"), \
             of all runs."
                .to_string(),
        );
    } else {
        lines.push("feasible runs: runs whose path is feasible, of all runs.".to_string());
        lines.push(
            "best, mean, std, worst (pen.): cost over all runs, the cost model's penalties for violations \
             included; an infeasible run's cost is mostly penalty, not the cost of a route."
                .to_string(),
        );
        let gap = if c.reference.is_some() { ", gap %" } else { "" };
        lines.push(format!(
            "feasible cost{gap}, length m, travel s: over the feasible runs only (best and mean; means for length and \
             time); \"{NO_FEASIBLE_RUN}\" where a planner has none."
        ));
        let statuses: Vec<&str> = Status::ALL
            .iter()
            .map(|s| s.id())
            .filter(|id| c.rows.iter().any(|r| r.statuses.iter().any(|(n, k)| n == id && *k > 0)))
            .collect();
        if !statuses.is_empty() {
            lines.push(format!("{}: runs that ended with each plan status.", statuses.join(", ")));
        }
    }
    let what = if c.is_functions() { "values" } else { "costs (all runs, penalties included)" };
    lines.push(format!(
        "vs {reference}: this row's planner against {reference}, two-sided Wilcoxon rank-sum test on the {what} at \
         alpha {ALPHA}: better / worse = significantly lower / higher, ≈ = no significant difference, undecidable = \
         too few runs for any p below {ALPHA} (the smallest p the test can reach is shown); ref = {reference} itself."
    ));
    lines.iter().map(|l| format!("- {l}\n")).collect()
}
