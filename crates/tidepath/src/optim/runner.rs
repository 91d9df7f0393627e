//! The one loop every optimizer runs in: budget, history, stop reason, progress reporting.

use std::time::{Duration, Instant};

use super::{Context, Objective, Optimizer};
use crate::rng::Rng;

/// When to stop. Any limit that is reached stops the run; wall time is a safety net and is
/// reported as such, since it makes results machine-dependent.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Budget {
    pub max_iterations: Option<u64>,
    pub max_evaluations: Option<u64>,
    pub max_time: Option<Duration>,
}

impl Budget {
    pub fn iterations(n: u64) -> Self {
        Self { max_iterations: Some(n), ..Self::default() }
    }

    pub fn evaluations(n: u64) -> Self {
        Self { max_evaluations: Some(n), ..Self::default() }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StopReason {
    MaxIterations,
    MaxEvaluations,
    /// The wall-time safety net fired: the result depends on the machine's speed.
    WallTime,
}

/// Reported to the observer after every iteration.
#[derive(Clone, Copy, Debug)]
pub struct Progress {
    pub iteration: u64,
    pub evaluations: u64,
    pub best_cost: f64,
    pub elapsed: Duration,
    /// Fraction of the binding budget used, in [0, 1].
    pub fraction: f64,
}

#[derive(Clone, Debug)]
pub struct RunResult {
    pub best_x: Vec<f64>,
    pub best_cost: f64,
    pub evaluations: u64,
    pub iterations: u64,
    /// Best cost so far after initialisation (index 0) and after each iteration.
    pub history: Vec<f64>,
    pub stop_reason: StopReason,
    pub elapsed: Duration,
}

/// Runs `optimizer` on `objective` until the budget is spent. A budget with no limit at all is
/// given 100 iterations so a run always ends.
pub fn run(
    optimizer: &mut dyn Optimizer,
    objective: &dyn Objective,
    budget: &Budget,
    rng: Rng,
    parallel: bool,
    observer: &mut dyn FnMut(&Progress),
) -> RunResult {
    let start = Instant::now();
    let max_iter = match budget {
        Budget { max_iterations: None, max_evaluations: None, max_time: None } => Some(100),
        b => b.max_iterations,
    };
    let mut ctx = Context::new(objective, rng, budget.max_evaluations, parallel);
    optimizer.init(&mut ctx);
    let mut history = vec![ctx.best_cost()];
    let mut iterations = 0u64;
    let stop_reason = loop {
        if ctx.exhausted() {
            break StopReason::MaxEvaluations;
        }
        if max_iter.is_some_and(|m| iterations >= m) {
            break StopReason::MaxIterations;
        }
        if budget.max_time.is_some_and(|t| start.elapsed() >= t) {
            break StopReason::WallTime;
        }
        optimizer.step(&mut ctx);
        iterations += 1;
        history.push(ctx.best_cost());
        let elapsed = start.elapsed();
        let fraction = [
            max_iter.map(|m| iterations as f64 / m.max(1) as f64),
            budget.max_evaluations.map(|m| ctx.evaluations() as f64 / m.max(1) as f64),
            budget.max_time.map(|t| elapsed.as_secs_f64() / t.as_secs_f64().max(1e-9)),
        ]
        .into_iter()
        .flatten()
        .fold(0.0, f64::max)
        .min(1.0);
        observer(&Progress {
            iteration: iterations,
            evaluations: ctx.evaluations(),
            best_cost: ctx.best_cost(),
            elapsed,
            fraction,
        });
    };
    RunResult {
        best_x: ctx.best_x().to_vec(),
        best_cost: ctx.best_cost(),
        evaluations: ctx.evaluations(),
        iterations,
        history,
        stop_reason,
        elapsed: start.elapsed(),
    }
}
