//! amfa2015 (Liu, Zhao, Gao & Liu 2015), section 5: AMFA against FA, PSO and GA on six
//! functions in small and wide ranges (Tables 2 and 4), with every reading of the baselines'
//! printed settings side by side; and AMFA's two path experiments (Figs. 17-18) mirrored on the
//! Salish seabed, with FA, PSO and DE beside it and the excluding and contracting operators on
//! and off. Readings: docs/papers/amfa2015.md.

pub mod functions;
pub mod paper;
pub mod paths;
#[cfg(test)]
mod tests;

use super::{ExperimentOutcome, ReproduceOptions};
use tidepath::error::Result;

/// The parts `--only` can pick.
pub const PARTS: &[&str] = &["tables", "paths"];

fn stopped(opts: &ReproduceOptions) -> bool {
    opts.stop.as_ref().is_some_and(|f| f.load(std::sync::atomic::Ordering::Relaxed))
}

pub(super) fn run(opts: &ReproduceOptions, progress: &(dyn Fn(usize, usize) + Sync)) -> Result<Vec<ExperimentOutcome>> {
    let runs = opts.runs as usize;
    let per_table = paper::FUNCTIONS.len() * functions::PLANNERS.len() * runs;
    let per_path = paths::PLANNERS.len() * runs;
    let tables = if opts.wants("tables") { paper::TABLES.len() } else { 0 };
    let path_count = if opts.wants("paths") { paths::EXPERIMENTS.len() } else { 0 };
    let total = tables * per_table + path_count * per_path;
    let mut outcomes = Vec::new();
    let mut done = 0;
    if opts.wants("tables") {
        for t in &paper::TABLES {
            if stopped(opts) {
                return Ok(outcomes);
            }
            outcomes.push(functions::experiment(t, opts, &|n| progress(done + n, total))?);
            done += per_table;
        }
    }
    if opts.wants("paths") {
        for k in 0..paths::EXPERIMENTS.len() {
            if stopped(opts) {
                return Ok(outcomes);
            }
            outcomes.push(paths::experiment(k, opts, &|n| progress(done + n, total))?);
            done += per_path;
        }
    }
    Ok(outcomes)
}
