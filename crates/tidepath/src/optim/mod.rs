//! Box-bounded continuous minimisation.
//!
//! An optimizer sees only a bounded vector and a cost ([`Objective`]). It implements `init` and
//! `step`; the [`runner`] owns the loop, the budget, the best-so-far history, the evaluation
//! count and the parallelism, so every algorithm gets them the same way.
//!
//! Determinism: optimizers draw all random numbers for an iteration from `ctx.rng()` in a fixed
//! order and only then evaluate the population with [`Context::evaluate_population`]. Evaluation
//! is a pure function of the vector, so results are bit-identical for any rayon thread count.

pub mod ade;
pub mod amfa;
pub mod context;
pub mod de;
pub mod eda_g;
pub mod fa;
pub mod functions;
pub mod ga;
pub mod hho;
pub mod histogram;
pub mod ijs;
pub mod js;
pub mod levy;
pub mod mpa;
pub mod mwpa;
pub mod population;
pub mod pso;
pub mod qpso;
pub mod runner;
#[cfg(test)]
mod test_support;
mod wolf;
pub mod wpa;

pub use crate::termination::{StopReason, Termination};
pub use context::Context;
pub use population::Population;
pub use runner::{run, Progress, RunResult, DEFAULT_ITERATIONS};

/// The largest population any optimizer accepts: beyond it memory, not search, is the limit
/// (a 40-waypoint 3-D path at 100,000 individuals already holds 64 MB of vectors).
pub const MAX_POPULATION: usize = 100_000;

/// Most decision values (population x dimension) a run may hold: 20 million f64 (160 MB per
/// copy; optimizers keep a few copies). Checked before any allocation.
pub const MAX_POPULATION_VALUES: usize = 20_000_000;

/// Checks that `population` individuals of `dim` variables fit [`MAX_POPULATION_VALUES`].
pub fn check_memory(population: usize, dim: usize) -> crate::error::Result<()> {
    match population.checked_mul(dim) {
        Some(n) if n <= MAX_POPULATION_VALUES => Ok(()),
        _ => Err(crate::error::Error::input(
            "planner.params.population",
            format!(
                "{population} individuals of {dim} variables exceed the limit of {MAX_POPULATION_VALUES} values; use fewer individuals or waypoints"
            ),
        )),
    }
}

/// Checks a population size against `min` and [`MAX_POPULATION`].
pub fn check_population(n: usize, min: usize) -> crate::error::Result<()> {
    if n < min || n > MAX_POPULATION {
        return Err(crate::error::Error::input(
            "planner.params.population",
            format!("must be in [{min}, {MAX_POPULATION}], got {n}"),
        ));
    }
    Ok(())
}

pub use crate::scratch::Scratch;

/// `x.clamp(lo, hi)` (the same value, NaN included) for bounds with `lo <= hi`, without
/// `f64::clamp`'s check of the bounds, so loops over coordinates have no branch and vectorize.
#[inline(always)]
pub(crate) fn clamp(x: f64, lo: f64, hi: f64) -> f64 {
    debug_assert!(lo <= hi, "clamp bounds {lo} > {hi}");
    // f64::clamp's own two steps.
    let x = if x < lo { lo } else { x };
    if x > hi {
        hi
    } else {
        x
    }
}

/// A box-bounded cost to minimise.
pub trait Objective: Sync {
    fn dim(&self) -> usize;
    fn lower(&self) -> &[f64];
    fn upper(&self) -> &[f64];
    /// The cost of `x`. Must be a pure function of `x` (no interior randomness).
    fn evaluate(&self, x: &[f64], scratch: &mut Scratch) -> f64;
    /// Brings `x` back into the feasible box (and any per-step limits the encoding owns).
    /// The default clamps to the bounds.
    fn repair(&self, x: &mut [f64]) {
        for ((v, &lo), &hi) in x.iter_mut().zip(self.lower()).zip(self.upper()) {
            *v = clamp(*v, lo, hi);
        }
    }
    /// Whether `x` satisfies the problem's constraints (a path: no collision, out-of-domain
    /// waypoint or broken vehicle limit), for optimizers that act on feasibility, such as
    /// wpa2017's Step 7 which replaces infeasible wolves. `None`: the objective has no
    /// constraints beyond its box (benchmark functions), so nothing is infeasible. Costs about
    /// one evaluation; [`Context::feasible`] counts it as one.
    fn feasible(&self, _x: &[f64], _scratch: &mut Scratch) -> Option<bool> {
        None
    }
    /// Applies lfhh2019's smooth method (eq. 15, [`crate::path::midpoint_smooth`]) to the
    /// path(s) `x` encodes: decode, move each interior waypoint to the midpoint of its longer
    /// leg, write back only the encoding's free coordinates, repair. Evaluates nothing (the
    /// caller evaluates the result like any other child) and is a pure function of `x`, so it
    /// keeps runs deterministic. Returns false, leaving `x` as it was, when the objective has
    /// no path (benchmark functions).
    fn smooth_path(&self, _x: &mut [f64], _scratch: &mut Scratch) -> bool {
        false
    }
    /// The groups of variables that each place one waypoint (a sliced plane's lateral offset
    /// and height), for samplers that draw a waypoint's variables together, such as
    /// lfhh2019's safe-cell sampling. Empty: no such structure (benchmark functions).
    fn waypoint_groups(&self) -> Vec<std::ops::Range<usize>> {
        Vec::new()
    }
    /// Whether the box `lo..=hi` of group `group`'s variables (one value per variable of the
    /// group) overlaps a free cell of that waypoint's section: lfhh2019's Fig. 11 test before
    /// a rectangle of histogram bins is accepted. `None`: not known (no such structure).
    fn region_free(&self, _group: usize, _lo: &[f64], _hi: &[f64]) -> Option<bool> {
        None
    }
    /// True when one evaluation is costly enough (microseconds) that a population should be
    /// evaluated in parallel. Cheap analytic test functions say false.
    fn parallel_hint(&self) -> bool {
        false
    }
}

/// One iteration-based minimiser.
pub trait Optimizer: Send {
    /// The planner id (`pso`, `ga`, ...).
    fn id(&self) -> &'static str;
    /// Individuals held at once, for the memory check before a run.
    fn population(&self) -> usize;
    /// Creates and evaluates the initial population.
    fn init(&mut self, ctx: &mut Context<'_>);
    /// One iteration (generation).
    fn step(&mut self, ctx: &mut Context<'_>);
    /// The repair operators (an id of [`crate::repair::REPAIRS`]) this optimizer applies to
    /// every candidate path when the scenario names none (`[encoding] repair`): amfa2015's AMFA
    /// excludes and contracts as part of its move. `None`: only the encoding's own repair.
    fn default_repair(&self) -> Option<&'static str> {
        None
    }
}
