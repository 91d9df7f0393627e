//! acopf2016 (Gao, Zhao, Guan, Wang & Zhang 2016), section 4: the improved ACOPF against the
//! plain ACO it improves on, planning a wave glider's path on the paper's 20 x 20 grid in its
//! three environments (Figs. 3-5) and a fourth of ours, with A*'s time and length optima on
//! the same cells. The paper prints figures only; its claims are read as measurable
//! statements (paper.rs). Readings: docs/papers/acopf2016.md.
//!
//! Parts: `figures` runs the paper's setting in each environment and draws the plan view of
//! the best paths (Figs. 3-5 and environment 4; the main tables and the claims come from the
//! same runs); `tables` runs the paper's setting for the tables and claims and adds the
//! variant with the ants rewarding travel time (objective = cost). Either part runs the
//! paper's setting once. `ocean` runs both settings on `glider-ocean`, a forecast-driven
//! 200 x 200-cell sea, for the gap to A*'s optimum where an engineer would plan.

pub mod cost;
pub mod environment;
pub mod ocean;
pub mod paper;
pub mod runs;
pub mod tables;
#[cfg(test)]
mod tests;
pub mod verdicts;

use super::{ExperimentOutcome, ReproduceOptions};
use tidepath::error::Result;

/// The parts `--only` can pick.
pub const PARTS: &[&str] = &["figures", "tables", "ocean"];

fn stopped(opts: &ReproduceOptions) -> bool {
    opts.stop.as_ref().is_some_and(|f| f.load(std::sync::atomic::Ordering::Relaxed))
}

pub(super) fn run(opts: &ReproduceOptions, progress: &(dyn Fn(usize, usize) + Sync)) -> Result<Vec<ExperimentOutcome>> {
    let runs = opts.runs as usize;
    let per_setting = paper::ENVIRONMENTS.len() * paper::PLANNERS.len() * runs;
    let per_env = paper::PLANNERS.len() * runs;
    let figures = opts.wants("figures");
    // The paper's setting serves both the figures and the tables; `--only ocean` skips it.
    let environments = figures || opts.wants("tables");
    let ocean = 2 * paper::PLANNERS.len() * runs;
    let total = if environments { per_setting } else { 0 }
        + if opts.wants("tables") { per_setting } else { 0 }
        + if opts.wants("ocean") { ocean } else { 0 };
    let mut outcomes = Vec::new();
    let mut done = 0;
    for k in (0..paper::ENVIRONMENTS.len()).filter(|_| environments) {
        if stopped(opts) {
            return Ok(outcomes);
        }
        outcomes.push(environment::experiment(k, opts, figures, &|n| progress(done + n, total))?);
        done += per_env;
    }
    if opts.wants("tables") && !stopped(opts) {
        outcomes.push(cost::experiment(opts, &|n| progress(done + n, total))?);
        done += per_setting;
    }
    if opts.wants("ocean") && !stopped(opts) {
        outcomes.push(ocean::experiment(opts, &|n| progress(done + n, total))?);
    }
    Ok(outcomes)
}
