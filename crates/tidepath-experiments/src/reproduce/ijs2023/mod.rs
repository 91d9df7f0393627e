//! ijs2023 (Guo, Chen & Pang 2023), section IV: IJS against JS, QPSO, PSO, HHO and MPA on the
//! paper's time-optimal AUV path problem, static (Table 1) and in a meandering jet at 0.5, 0.8
//! and 1.2 x the AUV's speed (Tables 2-3, with the current penalty of Figs. 14-16), and the
//! three-AUV fleet of section IV-C. Readings: docs/papers/ijs2023.md.

pub mod fleet;
pub mod paper;
pub mod tables;
#[cfg(test)]
mod tests;

use super::{ExperimentOutcome, ReproduceOptions};
use tidepath::error::Result;

/// The parts `--only` can pick.
pub const PARTS: &[&str] = &["tables", "fleet"];

fn stopped(opts: &ReproduceOptions) -> bool {
    opts.stop.as_ref().is_some_and(|f| f.load(std::sync::atomic::Ordering::Relaxed))
}

pub(super) fn run(opts: &ReproduceOptions, progress: &(dyn Fn(usize, usize) + Sync)) -> Result<Vec<ExperimentOutcome>> {
    let runs = opts.runs as usize;
    let per_table = paper::PLANNERS.len() * runs;
    let tables = if opts.wants("tables") { paper::SETTINGS.len() } else { 0 };
    let fleet_runs = if opts.wants("fleet") { fleet::PLANNERS.len() * runs } else { 0 };
    let total = tables * per_table + fleet_runs;
    let mut outcomes = Vec::new();
    let mut done = 0;
    if opts.wants("tables") {
        for s in &paper::SETTINGS {
            if stopped(opts) {
                return Ok(outcomes);
            }
            outcomes.push(tables::experiment(s, opts, &|n| progress(done + n, total))?);
            done += per_table;
        }
    }
    if opts.wants("fleet") && !stopped(opts) {
        outcomes.push(fleet::experiment(opts, &|n| progress(done + n, total))?);
    }
    Ok(outcomes)
}
