//! What an optimizer may touch during a run: the bounds, the RNG and evaluation.

use rayon::prelude::*;

use super::{Objective, Population, Scratch};
use crate::rng::Rng;

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
}

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
        }
    }

    pub fn dim(&self) -> usize {
        self.objective.dim()
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
    pub fn rng(&mut self) -> &mut Rng {
        self.rng
    }

    /// The warm-start points of this run (already inside the bounds and repaired).
    pub fn seeds(&self) -> &[Vec<f64>] {
        &self.seeds
    }

    pub fn repair(&self, x: &mut [f64]) {
        self.objective.repair(x)
    }

    pub fn evaluations(&self) -> u64 {
        self.evaluations
    }

    pub fn remaining_evaluations(&self) -> u64 {
        self.eval_limit - self.evaluations
    }

    /// True once the evaluation budget is spent.
    pub fn exhausted(&self) -> bool {
        self.evaluations >= self.eval_limit
    }

    pub fn best_cost(&self) -> f64 {
        self.best_f
    }

    pub fn best_x(&self) -> &[f64] {
        &self.best_x
    }

    /// Evaluates one point. Past the evaluation budget returns +inf without counting.
    pub fn evaluate(&mut self, x: &[f64]) -> f64 {
        if self.exhausted() {
            return f64::INFINITY;
        }
        let f = self.objective.evaluate(x, &mut self.scratch);
        self.evaluations += 1;
        self.offer(x, f);
        f
    }

    /// Evaluates every row of `pop` into `out`, in parallel when it pays. Rows beyond the
    /// remaining evaluation budget get +inf and are not counted.
    pub fn evaluate_population(&mut self, pop: &Population, out: &mut [f64]) {
        assert_eq!(out.len(), pop.len());
        let n = (pop.len() as u64).min(self.remaining_evaluations()) as usize;
        let dim = pop.dim();
        let objective = self.objective;
        let flat = &pop.as_flat()[..n * dim];
        if self.parallel && n > 1 {
            out[..n]
                .par_iter_mut()
                .zip(flat.par_chunks_exact(dim.max(1)))
                .with_min_len(2)
                .for_each_init(Scratch::default, |scratch, (o, x)| *o = objective.evaluate(x, scratch));
        } else {
            for (o, x) in out[..n].iter_mut().zip(flat.chunks_exact(dim.max(1))) {
                *o = objective.evaluate(x, &mut self.scratch);
            }
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
