//! What an optimizer may touch during a run: the bounds, the RNG and evaluation.

use std::sync::atomic::Ordering;

use rayon::prelude::*;

use super::{Objective, Population, Scratch};
use crate::rng::Rng;
use crate::termination::Termination;

/// Evaluation gateway. Counts evaluations, enforces the evaluation budget exactly and tracks
/// the best point seen, in evaluation order (ties keep the earlier point).
pub struct Context<'a> {
    objective: &'a dyn Objective,
    /// Copies of the bounds, so optimizers' inner loops read them without a virtual call.
    lower: Vec<f64>,
    upper: Vec<f64>,
    rng: &'a mut Rng,
    /// Warm-start points, repaired, that [`Population::initial`] places first.
    seeds: Vec<Vec<f64>>,
    evaluations: u64,
    eval_limit: u64,
    best_x: Vec<f64>,
    best_f: f64,
    scratch: Scratch,
    parallel: bool,
    /// The objective's [`Objective::parallel_hint`]: its evaluation and repair are costly.
    parallel_hint: bool,
    /// The run's termination: its stop flag and deadline are polled between chunks of a
    /// population's evaluation and by [`Context::should_stop`].
    termination: Option<&'a Termination>,
    /// Set once a poll found the run interrupted: no further point is evaluated.
    interrupted: bool,
    /// Which rows of a parallel evaluation were evaluated (reused, so no allocation).
    done: Vec<bool>,
    /// The measured time of one evaluation (ns, from the last population evaluated), to keep
    /// small populations of cheap rows off the thread pool; `None` until one is measured.
    row_ns: Option<f64>,
}

/// Estimated work (ns) below which a population is evaluated on the calling thread: handing
/// rows to rayon's pool and waiting for them costs tens of microseconds (a futex wake and a
/// wait), more than a wolf pack's five scouting candidates of a few microseconds each take.
/// Which thread evaluates a row never changes its cost, so results do not depend on it.
const PARALLEL_MIN_WORK_NS: f64 = 100_000.0;

/// Rows of a cheap objective (an analytic test function, tens of nanoseconds) evaluated
/// between two polls of the stop flag and the deadline (a poll costs about 25 ns).
const POLL_ROWS: usize = 64;

impl<'a> Context<'a> {
    pub fn new(
        objective: &'a dyn Objective,
        rng: &'a mut Rng,
        eval_limit: Option<u64>,
        parallel: bool,
        seeds: &[Vec<f64>],
    ) -> Self {
        let seeds = seeds
            .iter()
            .filter(|s| s.len() == objective.dim())
            .map(|s| {
                let mut s = s.clone();
                objective.repair(&mut s);
                s
            })
            .collect();
        Self {
            objective,
            lower: objective.lower().to_vec(),
            upper: objective.upper().to_vec(),
            rng,
            seeds,
            evaluations: 0,
            eval_limit: eval_limit.unwrap_or(u64::MAX),
            best_x: Vec::new(),
            best_f: f64::INFINITY,
            scratch: Scratch::default(),
            parallel: parallel && objective.parallel_hint(),
            parallel_hint: objective.parallel_hint(),
            termination: None,
            interrupted: false,
            done: Vec::new(),
            row_ns: None,
        }
    }

    /// This context polling `termination`'s stop flag and deadline (on the run's clock)
    /// inside generations: only a wall-time or cancel stop may cut a generation, so a run
    /// limited by evaluations or iterations is unchanged.
    pub fn with_termination(mut self, termination: &'a Termination) -> Self {
        self.termination = Some(termination);
        self
    }

    /// True once the run's stop flag is raised or its deadline has passed: for algorithms
    /// with inner loops (scouting wolves, jellyfish phases, ant tours) to leave them early.
    #[inline]
    pub fn should_stop(&mut self) -> bool {
        if !self.interrupted {
            self.interrupted = self.termination.is_some_and(|t| t.interrupted().is_some());
        }
        self.interrupted
    }

    #[inline]
    pub fn dim(&self) -> usize {
        self.objective.dim()
    }

    /// The run's iteration limit (the runner's default when the run sets neither iterations
    /// nor evaluations), for optimizers whose schedules depend on the generation budget.
    pub fn max_iterations(&self) -> Option<u64> {
        self.termination.and_then(|t| t.max_iterations)
    }

    #[inline]
    pub fn lower(&self) -> &[f64] {
        &self.lower
    }

    #[inline]
    pub fn upper(&self) -> &[f64] {
        &self.upper
    }

    /// Width of the box in dimension `d`.
    #[inline]
    pub fn range(&self, d: usize) -> f64 {
        self.upper()[d] - self.lower()[d]
    }

    /// The run's random stream. Draw everything an iteration needs from here, in a fixed order.
    #[inline]
    pub fn rng(&mut self) -> &mut Rng {
        self.rng
    }

    /// The random stream and the bounds at once ([`Context::rng`], [`Context::lower`],
    /// [`Context::upper`]), for a loop that draws and reads the box in the same pass.
    #[inline]
    pub fn rng_and_bounds(&mut self) -> (&mut Rng, &[f64], &[f64]) {
        (self.rng, &self.lower, &self.upper)
    }

    /// The warm-start points of this run (already inside the bounds and repaired).
    pub fn seeds(&self) -> &[Vec<f64>] {
        &self.seeds
    }

    /// The objective's repair of `x`. A costly objective's repair (a path's: its encoding and
    /// any repair operators, which judge points and segments against the world) is skipped for
    /// the plain box clamp once the run is interrupted, so loops that repair a whole population
    /// (an initial swarm of thousands) end with the run's clock; nothing repaired after that is
    /// evaluated.
    #[inline]
    pub fn repair(&self, x: &mut [f64]) {
        if self.parallel_hint && (self.interrupted || self.termination.is_some_and(|t| t.interrupted().is_some())) {
            for ((v, &lo), &hi) in x.iter_mut().zip(&self.lower).zip(&self.upper) {
                *v = super::clamp(*v, lo, hi);
            }
            return;
        }
        self.objective.repair(x)
    }

    #[inline]
    pub fn evaluations(&self) -> u64 {
        self.evaluations
    }

    #[inline]
    pub fn remaining_evaluations(&self) -> u64 {
        self.eval_limit - self.evaluations
    }

    /// True once the evaluation budget is spent.
    #[inline]
    pub fn exhausted(&self) -> bool {
        self.evaluations >= self.eval_limit
    }

    pub fn best_cost(&self) -> f64 {
        self.best_f
    }

    pub fn best_x(&self) -> &[f64] {
        &self.best_x
    }

    /// Evaluates one point. Past the evaluation budget, or once the run is interrupted,
    /// returns +inf without counting.
    pub fn evaluate(&mut self, x: &[f64]) -> f64 {
        // A costly objective (microseconds and up) polls the clock and the stop flag before
        // every point, so optimizers that evaluate one point at a time stop in time.
        if self.exhausted() || self.interrupted || (self.parallel_hint && self.should_stop()) {
            return f64::INFINITY;
        }
        let f = self.objective.evaluate(x, &mut self.scratch);
        self.evaluations += 1;
        self.offer(x, f);
        f
    }

    /// Whether `x` satisfies the objective's constraints ([`Objective::feasible`]). A check
    /// costs about an evaluation and counts as one; `None` when the objective has no
    /// constraints (not counted), past the evaluation budget, or once the run is interrupted.
    pub fn feasible(&mut self, x: &[f64]) -> Option<bool> {
        if self.exhausted() || self.interrupted {
            return None;
        }
        let verdict = self.objective.feasible(x, &mut self.scratch)?;
        self.evaluations += 1;
        Some(verdict)
    }

    /// lfhh2019's smooth method on `x` through the objective's encoding
    /// ([`Objective::smooth_path`]); not an evaluation. False when the objective has no path.
    pub fn smooth_path(&mut self, x: &mut [f64]) -> bool {
        self.objective.smooth_path(x, &mut self.scratch)
    }

    /// The variable groups that each place one waypoint ([`Objective::waypoint_groups`]).
    pub fn waypoint_groups(&self) -> Vec<std::ops::Range<usize>> {
        self.objective.waypoint_groups()
    }

    /// Whether a box of one group's variables overlaps free water ([`Objective::region_free`]).
    pub fn region_free(&self, group: usize, lo: &[f64], hi: &[f64]) -> Option<bool> {
        self.objective.region_free(group, lo, hi)
    }

    /// Evaluates every row of `pop` into `out`, in parallel when it pays. Rows beyond the
    /// remaining evaluation budget get +inf and are not counted; so do the rows left when the
    /// run is interrupted, so the best point evaluated so far is kept and nothing more is
    /// spent. Costly objectives (path costs: microseconds to milliseconds each) poll the stop
    /// flag and the deadline before every row, in every worker; cheap ones every
    /// [`POLL_ROWS`] rows.
    pub fn evaluate_population(&mut self, pop: &Population, out: &mut [f64]) {
        assert_eq!(out.len(), pop.len());
        let budget = (pop.len() as u64).min(self.remaining_evaluations()) as usize;
        let dim = pop.dim().max(1);
        let objective = self.objective;
        let rows = &pop.as_flat()[..budget * pop.dim()];
        let termination = self.termination;
        if self.interrupted {
            out.fill(f64::INFINITY);
            return;
        }
        // One worker thread: the pool would only hand the rows back and forth.
        let pooled = self.parallel
            && budget > 1
            && rayon::current_num_threads() > 1
            && self.row_ns.is_none_or(|ns| ns * budget as f64 >= PARALLEL_MIN_WORK_NS);
        let started = self.parallel.then(std::time::Instant::now);
        let n = if pooled {
            // Each worker polls before each row; a row skipped after a stop is marked.
            let stopped = std::sync::atomic::AtomicBool::new(false);
            let done = &mut self.done;
            done.clear();
            done.resize(budget, false);
            out[..budget]
                .par_iter_mut()
                .zip(rows.par_chunks_exact(dim))
                .zip(done.par_iter_mut())
                .with_min_len(2)
                .for_each_init(Scratch::default, |scratch, ((o, x), d)| {
                    let stop = stopped.load(Ordering::Relaxed)
                        || termination.is_some_and(|t| t.interrupted().is_some()) && {
                            stopped.store(true, Ordering::Relaxed);
                            true
                        };
                    if !stop {
                        *o = objective.evaluate(x, scratch);
                        *d = true;
                    }
                });
            if stopped.load(Ordering::Relaxed) {
                self.interrupted = true;
                // Rows some worker skipped are not evaluations: +inf, not counted.
                let mut n = 0;
                for (o, &d) in out[..budget].iter_mut().zip(done.iter()) {
                    if d {
                        n += 1;
                    } else {
                        *o = f64::INFINITY;
                    }
                }
                self.evaluations += n as u64;
                let done = std::mem::take(&mut self.done);
                for (i, (&d, &f)) in done.iter().zip(out.iter()).enumerate() {
                    if d {
                        self.offer(pop.row(i), f);
                    }
                }
                self.done = done;
                out[budget..].fill(f64::INFINITY);
                return;
            }
            budget
        } else {
            let every = if objective.parallel_hint() { 1 } else { POLL_ROWS };
            let mut n = 0;
            for (o, x) in out[..budget].iter_mut().zip(rows.chunks_exact(dim)) {
                if n % every == 0 && termination.is_some() && self.should_stop() {
                    break;
                }
                *o = objective.evaluate(x, &mut self.scratch);
                n += 1;
            }
            n
        };
        if let Some(t0) = started.filter(|_| n > 0) {
            let threads = if pooled { rayon::current_num_threads().min(n) } else { 1 };
            self.row_ns = Some(t0.elapsed().as_nanos() as f64 * threads as f64 / n as f64);
        }
        for o in &mut out[n..] {
            *o = f64::INFINITY;
        }
        self.evaluations += n as u64;
        for (i, &f) in out[..n].iter().enumerate() {
            self.offer(pop.row(i), f);
        }
    }

    fn offer(&mut self, x: &[f64], f: f64) {
        // NaN never becomes the best; a strictly lower cost does.
        if f < self.best_f || (self.best_x.is_empty() && !f.is_nan()) {
            self.best_f = f;
            self.best_x.clear();
            self.best_x.extend_from_slice(x);
        }
    }
}
