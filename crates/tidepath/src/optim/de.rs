//! Differential evolution, DE/rand/1/bin.
//!
//! Follows Storn & Price, "Differential Evolution – A Simple and Efficient Heuristic for Global
//! Optimization over Continuous Spaces" (J. Global Optimization 11, 1997), section 2:
//!
//! ```text
//! mutation (eq. 2):   v = x_r1 + F (x_r2 - x_r3)        r1, r2, r3 distinct, all != i
//! crossover (eq. 4):  u_j = v_j  if rand_j <= CR or j == jrand,  else x_ij
//! selection:          x_i <- u  if f(u) <= f(x_i)       (one-to-one, greedy)
//! ```
//!
//! `jrand` (Storn & Price's `rnbr(i)`) guarantees that at least one component comes from the
//! mutant. Defaults F = 0.5, CR = 0.9, NP = 40.
//!
//! Choices:
//! * Bounds: a mutant component outside the box is set to the midpoint between the parent's
//!   component and the violated bound (the rule used by JADE, Zhang & Sanderson 2009; Storn &
//!   Price 1997 leave bounds open), so trial vectors stay inside the box without piling up on
//!   the bound; the objective's own repair runs afterwards.
//! * Generational: all trial vectors are built from the population of the previous generation,
//!   then evaluated together, then selected.
//! * Random draws per target `i`, in order: r1, r2, r3 (rejection sampling), jrand, then one
//!   U(0,1) per component (drawn for every component, including jrand).
//! * `rand_j < CR` is used (a continuous draw, so the same as `<=` in distribution).

use rand::Rng as _;

use super::MAX_POPULATION;
use super::{Context, Optimizer, Population};
use crate::params::{Bound, Checked, Range};
use crate::rng::fill_unit_f64;

crate::params! {
    /// DE/rand/1/bin parameters.
    pub struct DeParams {
        /// Population size NP.
        population: usize = 40, Range::integer(4, MAX_POPULATION as u64), "Storn & Price 1997";
        /// Differential weight F.
        f: f64 = 0.5, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(2.0) }, "Storn & Price 1997";
        /// Crossover rate CR.
        cr: f64 = 0.9, Range::closed(0.0, 1.0), "Storn & Price 1997";
    }
}

/// DE/rand/1/bin, built from checked parameters.
#[derive(Clone, Debug)]
pub struct De {
    params: DeParams,
    gens: Generations,
}

/// The state of a DE/rand/1/bin run and its two phases, shared by `de` and `ade` (which
/// differ only in where F and CR come from).
#[derive(Clone, Debug)]
pub(crate) struct Generations {
    pub x: Population,
    pub cost: Vec<f64>,
    trial: Population,
    trial_cost: Vec<f64>,
    /// One target's crossover draws (reused, so a step does not allocate).
    u: Vec<f64>,
}

impl Generations {
    pub fn empty() -> Self {
        Self {
            x: Population::zeros(0, 0),
            cost: Vec::new(),
            trial: Population::zeros(0, 0),
            trial_cost: Vec::new(),
            u: Vec::new(),
        }
    }

    /// `n` individuals drawn in the box (warm starts first), repaired and evaluated.
    pub fn init(&mut self, n: usize, ctx: &mut Context<'_>) {
        (self.x, self.cost) = Population::initial_evaluated(n, ctx);
        self.trial = self.x.clone();
        self.trial_cost = vec![f64::INFINITY; n];
        self.u = vec![0.0; ctx.dim()];
    }

    /// One generation with weight `f`; `cr` gives each target's crossover rate after its
    /// partners and jrand are drawn (`ade` draws it there; `de` draws nothing).
    pub fn step(&mut self, ctx: &mut Context<'_>, f: f64, mut cr: impl FnMut(&mut Context<'_>) -> f64) {
        for i in 0..self.x.len() {
            let (r, jrand) = partners(ctx, self.x.len(), i, self.x.dim());
            let cr = cr(ctx);
            // One U(0,1) per component, drawn in bulk into a reused buffer.
            fill_unit_f64(ctx.rng(), &mut self.u);
            rand1_bin(ctx, &self.x, i, r, jrand, f, cr, &self.u, self.trial.row_mut(i));
        }
        ctx.evaluate_population(&self.trial, &mut self.trial_cost);
        select_greedy(&mut self.x, &mut self.cost, &self.trial, &self.trial_cost);
    }
}

impl De {
    pub fn new(params: Checked<DeParams>) -> Self {
        Self { params: params.into_inner(), gens: Generations::empty() }
    }

    pub fn params(&self) -> &DeParams {
        &self.params
    }
}

/// The bound rule for one mutant component: inside the box it is kept; below `lo` it becomes
/// `(parent + lo) / 2`, above `hi` it becomes `(parent + hi) / 2`.
#[inline]
pub fn bounce_to_midpoint(mutant: f64, parent: f64, lo: f64, hi: f64) -> f64 {
    if mutant < lo {
        0.5 * (parent + lo)
    } else if mutant > hi {
        0.5 * (parent + hi)
    } else {
        mutant
    }
}

impl Optimizer for De {
    fn id(&self) -> &'static str {
        "de"
    }

    fn population(&self) -> usize {
        self.params.population
    }

    fn init(&mut self, ctx: &mut Context<'_>) {
        self.gens.init(self.params.population, ctx);
    }

    fn step(&mut self, ctx: &mut Context<'_>) {
        let cr = self.params.cr;
        self.gens.step(ctx, self.params.f, |_| cr);
    }
}

/// Target `i`'s three partners r1, r2, r3 (distinct, none `i`; drawn in that order by
/// rejection) and the forced component jrand: the first draws of DE/rand/1/bin per target.
fn partners(ctx: &mut Context<'_>, n: usize, i: usize, dim: usize) -> ([usize; 3], usize) {
    let mut r = [0usize; 3];
    for k in 0..3 {
        r[k] = loop {
            let c = ctx.rng().random_range(0..n);
            if c != i && !r[..k].contains(&c) {
                break c;
            }
        };
    }
    (r, ctx.rng().random_range(0..dim.max(1)))
}

/// Writes target `i`'s trial vector into `trial`: the mutant x_r1 + f (x_r2 - x_r3), each
/// component outside the box bounced to the midpoint with the parent's, taken where
/// `u_j < cr` or j = jrand (binomial crossover, eq. 4), then the objective's repair.
#[allow(clippy::too_many_arguments)]
fn rand1_bin(
    ctx: &Context<'_>,
    x: &Population,
    i: usize,
    [r1, r2, r3]: [usize; 3],
    jrand: usize,
    f: f64,
    cr: f64,
    u: &[f64],
    trial: &mut [f64],
) {
    let dim = x.dim();
    let (lower, upper) = (&ctx.lower()[..dim], &ctx.upper()[..dim]);
    let (parent, a, b, c) = (x.row(i), x.row(r1), x.row(r2), x.row(r3));
    // The mutant component is computed for every j (it is pure) and kept where the
    // crossover takes it, so the loop has no branch.
    let sources = parent.iter().zip(a).zip(b.iter().zip(c)).zip(lower.iter().zip(upper)).zip(u);
    for (j, (t, ((((&p, &a), (&b, &c)), (&lo, &hi)), &u))) in trial.iter_mut().zip(sources).enumerate() {
        let mutant = bounce_to_midpoint(a + f * (b - c), p, lo, hi);
        *t = if (u < cr) | (j == jrand) { mutant } else { p };
    }
    ctx.repair(trial);
}

/// DE's one-to-one selection: each target is replaced by its trial when the trial is no worse.
fn select_greedy(x: &mut Population, cost: &mut [f64], trial: &Population, trial_cost: &[f64]) {
    for i in 0..x.len() {
        if trial_cost[i] <= cost[i] {
            cost[i] = trial_cost[i];
            x.copy_row_from(i, trial, i);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::optim::functions::{Function, FunctionObjective};
    use crate::optim::run;
    use crate::termination::Termination;

    #[test]
    fn defaults_and_check() {
        let p = DeParams::default();
        assert_eq!((p.population, p.f, p.cr), (40, 0.5, 0.9));
        assert!(p.clone().checked("p").is_ok());
        for bad in [
            DeParams { population: 3, ..p.clone() },
            DeParams { f: 0.0, ..p.clone() },
            DeParams { f: f64::NAN, ..p.clone() },
            DeParams { f: 2.5, ..p.clone() },
            DeParams { cr: -0.1, ..p.clone() },
            DeParams { cr: f64::NAN, ..p.clone() },
        ] {
            let e = bad.checked("planner.params.de").unwrap_err().to_string();
            assert!(e.starts_with("planner.params.de."), "{e}");
        }
        let q = DeParams::from_table(&toml::from_str("cr = 0.3").unwrap(), "p").unwrap();
        assert_eq!(*q.get(), DeParams { cr: 0.3, ..DeParams::default() });
        assert!(DeParams::from_table(&toml::from_str("F = 0.3").unwrap(), "p").is_err());
    }

    #[test]
    fn bound_rule_is_midpoint_to_violated_bound() {
        assert_eq!(bounce_to_midpoint(-7.0, 1.0, -5.0, 5.0), -2.0);
        assert_eq!(bounce_to_midpoint(9.0, 1.0, -5.0, 5.0), 3.0);
        assert_eq!(bounce_to_midpoint(4.0, 1.0, -5.0, 5.0), 4.0);
    }

    #[test]
    fn converges_on_sphere_and_never_worsens() {
        let obj = FunctionObjective::new(Function::Sphere, 5, -5.12, 5.12);
        let mut de = De::new(DeParams::default().checked("p").unwrap());
        let r =
            run(&mut de, &obj, &Termination::iterations(200), &mut crate::rng::run_rng(1, 0), false, &[], &mut |_| {});
        assert!(r.best_cost < 1e-8, "{}", r.best_cost);
        assert!(de.gens.x.rows().all(|x| x.iter().all(|v| (-5.12..=5.12).contains(v))));
        let min = de.gens.cost.iter().copied().fold(f64::INFINITY, f64::min);
        assert_eq!(min, r.best_cost);
    }
}
