//! Figures of an experiment: how planners converge, how their final costs spread over seeded
//! runs, and the best path each one found.
//!
//! A comparison is only honest if it shows the spread over runs, not one lucky seed, so the
//! convergence figure draws the median with the interquartile band and the box plot shows
//! every quartile and outlier. Several problems go into one figure as a grid of panels with
//! one shared legend, so a planner keeps its colour (and the reader their bearings) across
//! panels and across the three figures: colours follow the order in which planners first
//! appear in `problems`, and the paths figure colours paths in the order given, so pass the
//! paths in that same planner order.
//!
//! Cost axes switch to log10 when the costs span more than two decades, as in the plan figure.
//! Function benchmarks often reach a cost of exactly 0, which a log axis cannot show; rather
//! than fall back to a linear axis that flattens every other value into the floor, zeros are
//! drawn on their own line labelled "0", a decade below the smallest positive cost and below a
//! break in the axis, and the axis label and the figure note say so.

mod boxplot_figure;
mod convergence_figure;
mod cost_axis;
pub(crate) mod layout;
mod paths_figure;
mod renderer;
#[cfg(test)]
mod tests;

use std::path::Path;

use super::{style, PlanFigure};
use tidepath::error::Result;
use tidepath_experiments::RunRecord;

pub use boxplot_figure::render_boxplot_figure;
pub use convergence_figure::{
    render_convergence_figure, render_convergence_figure_with, ConvergenceContext, HistoryUnit, ReferenceCost,
};
pub use paths_figure::render_paths_figure;
pub use renderer::ExperimentFigures;

/// One planner's runs on one problem.
#[derive(Clone, Debug, Default)]
pub struct PlannerRuns<'a> {
    pub planner: &'a str,
    /// Final cost of every run; non-finite costs (no solution) are counted, not plotted.
    pub costs: Vec<f64>,
    /// Best cost per iteration per run; NaN or infinite entries mean "no finite cost yet".
    pub histories: Vec<Vec<f64>>,
    /// A search ran before the iterations (a composite planner's reference): iteration 0 is
    /// where the refinement started from it, and is marked so.
    pub search_before_iterations: bool,
}

/// All planners' runs on one problem (one panel of the convergence and box plot figures).
#[derive(Clone, Debug, Default)]
pub struct ProblemRuns<'a> {
    pub problem: &'a str,
    pub planners: Vec<PlannerRuns<'a>>,
}

/// Groups run records by problem and planner, both in order of first appearance, so that the
/// figures show problems and colour planners in the order the experiment ran them.
pub fn group_runs(records: &[RunRecord]) -> Vec<ProblemRuns<'_>> {
    let mut out: Vec<ProblemRuns> = Vec::new();
    for r in records {
        let p = match out.iter().position(|p| p.problem == r.problem) {
            Some(k) => k,
            None => {
                out.push(ProblemRuns { problem: &r.problem, planners: Vec::new() });
                out.len() - 1
            }
        };
        let planners = &mut out[p].planners;
        let k = match planners.iter().position(|q| q.planner == r.planner) {
            Some(k) => k,
            None => {
                planners.push(PlannerRuns { planner: &r.planner, ..Default::default() });
                planners.len() - 1
            }
        };
        planners[k].costs.push(r.cost);
        planners[k].search_before_iterations |= seeded_by_search(r);
        planners[k].histories.push(r.history.iter().map(|v| v.unwrap_or(f64::INFINITY)).collect());
    }
    out
}

/// Whether a run searched before it iterated (expansions and iterations both counted, and a
/// history entry before the first iteration): the history then starts from the search's
/// result, not from a random population. The ant colonies count their steps as expansions but
/// record one entry per iteration only: no search before them.
pub fn seeded_by_search(r: &RunRecord) -> bool {
    r.expansions > 0 && r.iterations > 0 && r.history.len() as u64 > r.iterations
}

/// Label of a planner's best path in the paths figure, so the legend reads the same in every
/// report: "pso (best 1.23)".
pub fn best_path_label(planner: &str, cost: f64) -> String {
    if cost.is_finite() {
        format!("{planner} (best {})", style::fmt_sig(cost))
    } else {
        format!("{planner} (no finite cost)")
    }
}

/// Every planner of the experiment in order of first appearance; its position is its colour.
fn planner_order<'a>(problems: &[ProblemRuns<'a>]) -> Vec<&'a str> {
    let mut out: Vec<&str> = Vec::new();
    for p in problems.iter().flat_map(|p| &p.planners) {
        if !out.contains(&p.planner) {
            out.push(p.planner);
        }
    }
    out
}

fn color_index(order: &[&str], planner: &str) -> usize {
    order.iter().position(|p| *p == planner).unwrap_or(0)
}

/// Writes [`render_convergence_figure`] to `out` atomically.
pub fn write_convergence_figure(title: &str, problems: &[ProblemRuns], out: &Path) -> Result<()> {
    tidepath_io::write_atomic(out, render_convergence_figure(title, problems)?.as_bytes())
}

/// Writes [`render_boxplot_figure`] to `out` atomically.
pub fn write_boxplot_figure(title: &str, problems: &[ProblemRuns], out: &Path) -> Result<()> {
    tidepath_io::write_atomic(out, render_boxplot_figure(title, problems)?.as_bytes())
}

/// Writes [`render_paths_figure`] to `out` atomically.
pub fn write_paths_figure(fig: &PlanFigure, out: &Path) -> Result<()> {
    tidepath_io::write_atomic(out, render_paths_figure(fig)?.as_bytes())
}
