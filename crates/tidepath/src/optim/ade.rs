//! Adaptive DE (a labelled reading: the cited rules could not be checked), the adaptive
//! differential evolution baseline of lfhh2019.
//!
//! lfhh2019 compares against the adaptive DE path planner of Zhang, Gong, Li and Lin (GECCO
//! 2014) with alpha = 0, beta = 0.4, F0 = 0.6 (Table 1). That paper's adaptation rules could not
//! be checked (docs/papers/lfhh2019.md A7), so this is a placeholder with standard adaptive
//! rules (docs/papers/shared.md, adaptive DE), DE/rand/1/bin as in [`super::de`] with
//!
//! ```text
//! F_g  = F0 2^lambda_g,   lambda_g = exp(1 - G / (G + 1 - g))     g = 0, 1, ..., G
//! CR_i ~ U[alpha, alpha + beta]                                   per individual, per generation
//! ```
//!
//! F starts at F0 2^(e^(1/(G+1))), slightly above 2 F0 (1.208 for F0 = 0.6 and G = 100), and
//! decays to F0 2^(e^(1-G)), about F0, in the last generation.
//!
//! Choices:
//! * **G, the generation budget.** The `generations` parameter when set; else the fewer of the
//!   run's iteration limit ([`Context::max_iterations`]) and the evaluation budget left after
//!   the initial population divided by NP, rounded up, whichever the run sets; else
//!   [`DEFAULT_ITERATIONS`]. Past G (a run stopped by wall time or a target cost ends sooner;
//!   one that outlives G cannot), g is held at G, so F stays at its last value (never the
//!   negative denominator of g > G + 1).
//! * **g** is the number of generations done before the current one (0 in the first step).
//! * Bounds: a mutant component outside the box goes to the midpoint between the parent's
//!   component and the violated bound ([`super::de::bounce_to_midpoint`]), then the objective's
//!   repair runs. Selection is DE's one-to-one greedy replacement (ties take the trial).
//! * Random draws per target `i`, in order: r1, r2, r3 (rejection sampling), jrand, one U(0,1)
//!   for CR_i, then one U(0,1) per component.

use rand::Rng as _;

use super::de::Generations;
use super::{Context, Optimizer, DEFAULT_ITERATIONS, MAX_POPULATION};
use crate::error::Result;
use crate::params::{field_error, Bound, Checked, Range};
use crate::termination::MAX_COUNT;

crate::params! {
    /// Adaptive DE parameters (lfhh2019 Table 1).
    pub struct AdeParams {
        /// Population NP.
        population: usize = 200, Range::integer(4, MAX_POPULATION as u64), "lfhh2019 Table 1";
        /// Base differential weight F0 of F_g = F0 2^(exp(1 - G/(G + 1 - g))).
        f0: f64 = 0.6, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1.0) }, "lfhh2019 Table 1";
        /// Lower end alpha of the crossover rate's range U[alpha, alpha + beta].
        alpha: f64 = 0.0, Range::closed(0.0, 1.0), "lfhh2019 Table 1";
        /// Width beta of the crossover rate's range U[alpha, alpha + beta] (alpha + beta <= 1).
        beta: f64 = 0.4, Range::closed(0.0, 1.0), "lfhh2019 Table 1";
        /// The generation budget G of F's schedule; absent: the run's evaluation budget over NP,
        /// else the default iteration count (see the module documentation).
        generations: Option<u64> = None, Range::integer(1, MAX_COUNT), "tidepath (the run's budget in lfhh2019)";
    }
    check = check_cr_range;
}

impl AdeParams {
    /// lfhh2019 Table 1: NP = 200, F0 = 0.6, alpha = 0, beta = 0.4; G from the run's budget
    /// (the defaults).
    pub fn lfhh2019() -> Self {
        Self { population: 200, f0: 0.6, alpha: 0.0, beta: 0.4, generations: None }
    }
}

/// The crossover rate's range must stay in [0, 1].
fn check_cr_range(p: &AdeParams, prefix: &str) -> Result<()> {
    if p.alpha + p.beta > 1.0 {
        return Err(field_error(
            prefix,
            "beta",
            format!("alpha + beta must be at most 1, got {} + {}", p.alpha, p.beta),
        ));
    }
    Ok(())
}

/// F of generation `g` (0-based) in a budget of `big_g` generations:
/// `f0 2^(exp(1 - G/(G + 1 - g)))`, with g held at G beyond it.
pub fn f_schedule(f0: f64, g: u64, big_g: u64) -> f64 {
    let big = big_g as f64;
    let g = g.min(big_g) as f64;
    f0 * (1.0 - big / (big + 1.0 - g)).exp().exp2()
}

/// Adaptive DE (placeholder rules), built from checked parameters.
#[derive(Clone, Debug)]
pub struct Ade {
    params: AdeParams,
    gens: Generations,
    /// Generations done.
    g: u64,
    /// The schedule's G for this run.
    big_g: u64,
}

impl Ade {
    pub fn new(params: Checked<AdeParams>) -> Self {
        Self { params: params.into_inner(), gens: Generations::empty(), g: 0, big_g: DEFAULT_ITERATIONS }
    }

    pub fn params(&self) -> &AdeParams {
        &self.params
    }

    /// G for a run limited to `iterations` (if any) with `remaining` evaluations after the
    /// initial population (`limited` false when evaluations are not limited).
    pub fn generation_budget(&self, iterations: Option<u64>, remaining: u64, limited: bool) -> u64 {
        let by_evaluations = limited.then(|| remaining.div_ceil(self.params.population as u64).max(1));
        match (self.params.generations, iterations, by_evaluations) {
            (Some(g), ..) => g,
            (None, Some(i), Some(e)) => i.min(e).max(1),
            (None, Some(i), None) => i.max(1),
            (None, None, Some(e)) => e,
            (None, None, None) => DEFAULT_ITERATIONS,
        }
    }
}

impl Optimizer for Ade {
    fn id(&self) -> &'static str {
        "ade"
    }

    fn population(&self) -> usize {
        self.params.population
    }

    fn init(&mut self, ctx: &mut Context<'_>) {
        // Unlimited runs have u64::MAX evaluations; more than any limit can be (MAX_COUNT).
        let limited = ctx.remaining_evaluations() <= MAX_COUNT;
        self.gens.init(self.params.population, ctx);
        self.g = 0;
        self.big_g = self.generation_budget(ctx.max_iterations(), ctx.remaining_evaluations(), limited);
    }

    fn step(&mut self, ctx: &mut Context<'_>) {
        let f = f_schedule(self.params.f0, self.g, self.big_g);
        let (alpha, beta) = (self.params.alpha, self.params.beta);
        self.gens.step(ctx, f, |ctx| alpha + beta * ctx.rng().random::<f64>());
        self.g += 1;
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
        let p = AdeParams::default();
        assert_eq!((p.population, p.f0, p.alpha, p.beta, p.generations), (200, 0.6, 0.0, 0.4, None));
        assert!(p.clone().checked("p").is_ok());
        let e = AdeParams { alpha: 0.7, beta: 0.4, ..p.clone() }.checked("planner.params.ade").unwrap_err();
        assert!(e.to_string().starts_with("planner.params.ade.beta: alpha + beta must be at most 1"), "{e}");
        assert!(AdeParams { alpha: 0.6, beta: 0.4, ..p.clone() }.checked("p").is_ok());
        assert!(AdeParams { f0: 0.0, ..p }.checked("p").is_err());
    }

    #[test]
    fn f_schedule_by_hand() {
        // G = 1: g = 0 gives exp(1 - 1/2) = e^0.5 = 1.6487, 2^1.6487 = 3.1357, F = 1.8814 (F0 0.6).
        let f = f_schedule(0.6, 0, 1);
        assert!((f - 0.6 * 2f64.powf(0.5f64.exp())).abs() < 1e-15);
        assert!((f - 1.8814).abs() < 1e-4, "{f}");
        // g = G = 1: exp(1 - 1/1) = 1, F = 2 F0.
        assert!((f_schedule(0.6, 1, 1) - 1.2).abs() < 1e-15);
        // G = 100: g = 0 is just above 2 F0: 2^(e^(1/101)) F0 = 2.0138 x 0.6 = 1.2083.
        let f = f_schedule(0.6, 0, 100);
        assert!((f - 1.2083).abs() < 1e-4, "{f}");
        // g = G = 100: 2^(e^-99) F0, F0 to 16 digits.
        assert!((f_schedule(0.6, 100, 100) - 0.6).abs() < 1e-15);
        // Halfway, g = 50: exp(1 - 100/51) = e^(-49/51) = 0.38255, 2^0.38255 = 1.30373.
        assert!((f_schedule(0.6, 50, 100) - 0.6 * 1.30373).abs() < 1e-4);
        // It decreases over the run, and past G it stays at F_G.
        let fs: Vec<f64> = (0..=100).map(|g| f_schedule(0.6, g, 100)).collect();
        assert!(fs.windows(2).all(|w| w[1] < w[0] || w[1] == 0.6));
        assert_eq!(f_schedule(0.6, 102, 100), f_schedule(0.6, 100, 100));
        assert_eq!(f_schedule(0.6, 10_000, 100), f_schedule(0.6, 100, 100));
    }

    #[test]
    fn the_generation_budget_comes_from_the_parameter_or_the_run_limits() {
        let ade = |generations| {
            Ade::new(AdeParams { population: 10, generations, ..AdeParams::default() }.checked("p").unwrap())
        };
        assert_eq!(ade(Some(7)).generation_budget(Some(300), 1000, true), 7);
        assert_eq!(ade(None).generation_budget(None, 1000, true), 100);
        assert_eq!(ade(None).generation_budget(None, 1001, true), 101);
        assert_eq!(ade(None).generation_budget(None, 0, true), 1);
        assert_eq!(ade(None).generation_budget(None, u64::MAX - 10, false), DEFAULT_ITERATIONS);
        assert_eq!(ade(None).generation_budget(Some(300), u64::MAX - 10, false), 300);
        assert_eq!(ade(None).generation_budget(Some(300), 1000, true), 100);
        assert_eq!(ade(None).generation_budget(Some(30), 1000, true), 30);
        // Through a run: 10 + 50 evaluations of population 10 gives G = 5.
        let obj = FunctionObjective::new(Function::Sphere, 3, -1.0, 1.0);
        let mut a = ade(None);
        run(&mut a, &obj, &Termination::evaluations(60), &mut crate::rng::run_rng(1, 0), false, &[], &mut |_| {});
        assert_eq!((a.big_g, a.g), (5, 5));
        let mut a = ade(None);
        run(&mut a, &obj, &Termination::iterations(3), &mut crate::rng::run_rng(1, 0), false, &[], &mut |_| {});
        assert_eq!((a.big_g, a.g), (3, 3));
    }

    #[test]
    fn converges_on_sphere_and_stays_in_the_box() {
        let obj = FunctionObjective::new(Function::Sphere, 5, -5.12, 5.12);
        let mut ade = Ade::new(AdeParams::default().checked("p").unwrap());
        let r = run(
            &mut ade,
            &obj,
            &Termination::evaluations(60_000),
            &mut crate::rng::run_rng(1, 0),
            false,
            &[],
            &mut |_| {},
        );
        assert!(r.best_cost < 1e-8, "{}", r.best_cost);
        assert!(ade.gens.x.rows().all(|x| x.iter().all(|v| (-5.12..=5.12).contains(v))));
        assert!(r.history.windows(2).all(|w| w[1] <= w[0]));
    }

    #[test]
    fn same_seed_same_bits() {
        let obj = FunctionObjective::new(Function::Rastrigin, 6, -5.12, 5.12);
        let go = |seed| {
            let mut ade = Ade::new(AdeParams { population: 12, ..AdeParams::default() }.checked("p").unwrap());
            run(
                &mut ade,
                &obj,
                &Termination::iterations(25),
                &mut crate::rng::run_rng(seed, 0),
                false,
                &[],
                &mut |_| {},
            )
        };
        let (a, b, c) = (go(3), go(3), go(4));
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&a.best_x), bits(&b.best_x));
        assert_eq!(bits(&a.history), bits(&b.history));
        assert_ne!(bits(&a.history), bits(&c.history));
    }
}
