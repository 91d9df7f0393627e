//! The one loop every optimizer runs in: termination, history, stop reason, progress reporting.

use std::time::Duration;

use super::{Context, Objective, Optimizer};
use crate::rng::Rng;
use crate::termination::{StopReason, Termination, Usage};

/// Iterations given to a run whose termination limits neither iterations nor evaluations, so
/// a run always ends on its own (a wall-time limit is a safety net, not a budget).
pub const DEFAULT_ITERATIONS: u64 = 100;

/// Reported to the observer after every iteration.
#[derive(Clone, Copy, Debug)]
pub struct Progress {
    pub iteration: u64,
    pub evaluations: u64,
    pub best_cost: f64,
    pub elapsed: Duration,
    /// Fraction of the binding limit used, in [0, 1].
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

/// Runs `optimizer` on `objective` until `termination` fires. `seeds` are starting points
/// (a warm start): optimizers place them in their initial population. A termination limiting
/// neither iterations nor evaluations gets [`DEFAULT_ITERATIONS`].
pub fn run(
    optimizer: &mut dyn Optimizer,
    objective: &dyn Objective,
    termination: &Termination,
    rng: &mut Rng,
    parallel: bool,
    seeds: &[Vec<f64>],
    observer: &mut dyn FnMut(&Progress),
) -> RunResult {
    // Optimizers count iterations and evaluations: without a limit in either (a target cost
    // or an expansion limit bounds nothing here), the default iteration count applies.
    let unbounded = termination.max_iterations.is_none() && termination.max_evaluations.is_none();
    let defaulted;
    let termination = if unbounded {
        defaulted = Termination { max_iterations: Some(DEFAULT_ITERATIONS), ..termination.clone() };
        &defaulted
    } else {
        termination
    };
    let watch = termination.start();
    let mut ctx =
        Context::new(objective, rng, termination.max_evaluations, parallel, seeds).with_termination(termination);
    optimizer.init(&mut ctx);
    let mut history = vec![ctx.best_cost()];
    let mut iterations = 0u64;
    let usage =
        |ctx: &Context<'_>, iterations| Usage { iterations, evaluations: ctx.evaluations(), ..Usage::default() };
    let stop_reason = loop {
        if let Some(r) = watch.stop_reason(usage(&ctx, iterations), ctx.best_cost()) {
            break r;
        }
        optimizer.step(&mut ctx);
        iterations += 1;
        history.push(ctx.best_cost());
        observer(&Progress {
            iteration: iterations,
            evaluations: ctx.evaluations(),
            best_cost: ctx.best_cost(),
            elapsed: watch.elapsed(),
            fraction: watch.fraction(usage(&ctx, iterations)),
        });
    };
    RunResult {
        best_x: ctx.best_x().to_vec(),
        best_cost: ctx.best_cost(),
        evaluations: ctx.evaluations(),
        iterations,
        history,
        stop_reason,
        elapsed: watch.elapsed(),
    }
}
