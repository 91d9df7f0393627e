//! The firefly algorithm (FA), amfa2015's baseline.
//!
//! Follows Yang, "Firefly algorithms for multimodal optimization" (SAGA 2009, LNCS 5792) in
//! the form amfa2015 (Liu, Zhao, Gao & Liu 2015) gives as its eq. 1 and uses as the baseline
//! "FA" of its Tables 2 and 4:
//!
//! ```text
//! r      = ‖x_i − x_j‖                                        (Euclidean, all D coordinates)
//! β      = (β₀ − β_min) exp(−γ r²) + β_min                     (β_min: Yang's code, below)
//! x_i   <- x_i + β (x_j − x_i) + α (rand(D) − 0.5)                for each brighter j
//! x_b   <- x_b + α (rand(D) − 0.5)                                 the brightest firefly
//! ```
//!
//! with amfa2015's section 5 values β₀ = 1, γ = 1, α = 1 and 40 fireflies (the defaults,
//! [`FaParams::amfa2015`]). Every move is kept (no autonomous flight strategy; that is AMFA's,
//! [`super::amfa`]).
//!
//! Readings (docs/papers/amfa2015.md, A2 for the random vector):
//! * **The random term is in absolute units** (`alpha_scale = "absolute"`, the amfa2015 preset
//!   [`FaParams::amfa2015`] that `reproduce amfa2015` runs; the defaults use `"range"`, below,
//!   because a step of ±0.5 in a path's metres would never leave its first waypoints):
//!   α (rand − 0.5) with no factor for the box width. amfa2015 says so when it motivates AMFA
//!   (section 3): "the random movement step is 1 and the changing range of the random part is
//!   −0.5 to 0.5, the convergence speed is very slow in solving problems with a large range",
//!   which only holds if the step does not grow with the range. Yang's published code scales
//!   the term by the range of each dimension; `alpha_scale = "range"` runs that reading,
//!   α (rand − 0.5) (upper_d − lower_d).
//! * **α shrinks over the run as in Yang's code** (`alpha_end = 1e-4/0.9`, the default):
//!   α_t = α · alpha_end^(t/N), so α = 1 at the start and 1.1e-4 at the end (Yang's
//!   `alpha_new`: α₀ = 0.9 reaches 10⁻⁴ after the last generation). amfa2015 gives only
//!   "α = 1.0", but its FA results (Sphere 2.76e-6 in 30 dimensions, Table 2) cannot come from
//!   a constant step of ±0.5 per coordinate, which leaves a firefly about 2.5 from any point it
//!   aims at; with the reduction they can. `alpha_end = 1` keeps α constant (the paper's
//!   values taken literally). t/N is the run's progress as AMFA reads it ([`progress`], A3):
//!   evaluations used over the budget, else iterations over the iteration limit, taken at the
//!   start of each sweep.
//! * **A floor on the attraction, β_min = 0.2 (Yang's code).** Eq. 1 has β₀ e^{−γ r²}, which
//!   with γ = 1 and r in the objective's units is below 10⁻⁷ beyond r = 4: fireflies in a box
//!   of width 10 in 10 dimensions (r about 13) do not attract at all, and FA is a random walk
//!   (measured: Sphere D = 10, 20,000 evaluations, best 18, no better than random search).
//!   Yang's published code adds β_min = 0.2; `beta_min = 0` is eq. 1 as printed.
//! * **One iteration (`step`) is one sweep, evaluated once (Yang's code).** The fireflies are
//!   ranked by cost at the start of the sweep (ties: lower index first; NaN last). From the
//!   worst to the second brightest, each firefly i moves toward each firefly j ranked before
//!   it, brightest first, one move after another (each move starts where the last ended and
//!   draws its own random term). The brighter fireflies move after it, so each attraction is
//!   toward x_j's current position, the one its cost was measured at (Yang's code keeps the
//!   old positions for the same purpose). The firefly ranked first, which has no brighter one,
//!   moves randomly (rule 2 of the paper's section 2). Every firefly is then clamped to the
//!   box, repaired by the objective, and the swarm is evaluated as one population: n
//!   evaluations per sweep, every move kept. Evaluating after every pairwise move instead
//!   (Yang 2009's pseudo-code) would cost n(n−1)/2 evaluations per sweep and, with a step of
//!   fixed size, leaves FA no better than random search on Sphere in 10 dimensions.
//! * A stop during a sweep leaves the moved fireflies unevaluated (+inf costs); the run ends
//!   there.
//!
//! Random draws, in order: per move, D uniform numbers (one per coordinate, at 32-bit
//! resolution, two per word of the stream: [`fill_unit_f64_32`]), fireflies from the worst to
//! the brightest. The population is
//! evaluated with [`Context::evaluate_population`], so results do not depend on the thread
//! count.

use super::MAX_POPULATION;
use super::{clamp, Context, Optimizer, Population};
use crate::params::{Bound, Checked, Range, Word};
use crate::rng::fill_unit_f64_32;

/// How FA's random term α (rand − 0.5) relates to the box.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum AlphaScale {
    /// α (rand − 0.5) as it stands, in the objective's units (amfa2015's reading).
    #[default]
    Absolute,
    /// α (rand − 0.5) (upper_d − lower_d): Yang's published code.
    Range,
}

impl Word for AlphaScale {
    const WORDS: &'static [(&'static str, Self)] = &[("absolute", AlphaScale::Absolute), ("range", AlphaScale::Range)];
}

crate::params::word_param!(AlphaScale);

crate::params! {
    /// FA parameters. Defaults: amfa2015's baseline setting (section 5).
    pub struct FaParams {
        /// Number of fireflies.
        population: usize = 40, Range::integer(2, MAX_POPULATION as u64), "amfa2015 section 5";
        /// Attractiveness at distance 0, β₀ (beyond 2 a move overshoots x_j by more than
        /// x_i's distance to it).
        beta0: f64 = 1.0, Range::closed(0.0, 2.0), "amfa2015 section 5";
        /// Attractiveness at any distance, β_min: β = (β₀ − β_min) e^{−γ r²} + β_min (Yang's
        /// code); 0 is eq. 1 as printed.
        beta_min: f64 = 0.2, Range::closed(0.0, 2.0), "Yang's FA code (see the module documentation)";
        /// Light absorption coefficient γ.
        gamma: f64 = 1.0, Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded }, "amfa2015 section 5";
        /// Randomization coefficient α.
        alpha: f64 = 1.0, Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded }, "amfa2015 section 5";
        /// Whether α (rand − 0.5) is in absolute units ("absolute") or multiplied by each
        /// dimension's box width ("range", Yang's code).
        alpha_scale: AlphaScale = AlphaScale::Range, Range::Choice(&["absolute", "range"]), "Yang's FA code; amfa2015 section 3 for absolute (see the module documentation)";
        /// α at the end of the run as a fraction of `alpha`, reached geometrically
        /// (α_t = α · alpha_end^(t/N), Yang's code); 1 keeps α constant.
        alpha_end: f64 = YANG_ALPHA_END, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1.0) }, "Yang's FA code (see the module documentation)";
    }
}

/// Yang's reduction of α over a run: α₀ = 0.9 reaches 10⁻⁴ (`alpha_new` in his FA code).
pub const YANG_ALPHA_END: f64 = 1.0e-4 / 0.9;

impl FaParams {
    /// amfa2015 (Liu et al. 2015, section 5): β₀ = 1, γ = 1, α = 1, 40 fireflies, random term
    /// in absolute units (section 3), α reduced as in Yang's code. The defaults differ only in
    /// the random term, scaled by each dimension's width as in Yang's code, so a planner's
    /// step suits any box (a sliced path in metres as much as a unit box).
    pub fn amfa2015() -> Self {
        Self {
            population: 40,
            beta0: 1.0,
            beta_min: 0.2,
            gamma: 1.0,
            alpha: 1.0,
            alpha_scale: AlphaScale::Absolute,
            alpha_end: YANG_ALPHA_END,
        }
    }

    /// α at progress `t/N` = `frac` (clamped to [0, 1]): α · alpha_end^(t/N).
    pub fn alpha_at(&self, frac: f64) -> f64 {
        self.alpha * self.alpha_end.powf(frac.clamp(0.0, 1.0))
    }
}

/// Progress t/N of a run (amfa2015 A3): evaluations used over the evaluation budget; without a
/// budget, `iteration` over the run's iteration limit (`Context::max_iterations`, which the
/// runner sets for every run that limits neither); with neither, 0. In [0, 1].
pub(crate) fn progress(ctx: &Context<'_>, iteration: u64) -> f64 {
    let used = ctx.evaluations();
    // The context holds "no budget" as a limit of u64::MAX.
    let budget = used.saturating_add(ctx.remaining_evaluations());
    if budget != u64::MAX {
        return if budget == 0 { 1.0 } else { (used as f64 / budget as f64).min(1.0) };
    }
    match ctx.max_iterations() {
        Some(n) if n > 0 => (iteration as f64 / n as f64).min(1.0),
        _ => 0.0,
    }
}

/// A firefly swarm: positions, costs, the sweep's ranking and reused buffers. FA's sweep is
/// here; AMFA's ([`super::amfa`]) evaluates every move.
#[derive(Clone, Debug)]
pub(crate) struct Swarm {
    pub x: Population,
    pub cost: Vec<f64>,
    /// Firefly indices by cost at the start of the sweep, brightest first.
    pub order: Vec<usize>,
    /// The firefly being moved, or the candidate of the current move (reused, so a sweep does
    /// not allocate).
    pub cand: Vec<f64>,
    /// The current move's U(0,1) draws.
    pub u: Vec<f64>,
    /// Moves since the last poll of the stop flag.
    pub since_poll: u32,
}

impl Swarm {
    pub fn empty() -> Self {
        Self {
            x: Population::zeros(0, 0),
            cost: Vec::new(),
            order: Vec::new(),
            cand: Vec::new(),
            u: Vec::new(),
            since_poll: 0,
        }
    }

    /// `n` fireflies drawn in the box (warm starts first), repaired and evaluated.
    pub fn init(&mut self, n: usize, ctx: &mut Context<'_>) {
        (self.x, self.cost) = Population::initial_evaluated(n, ctx);
        self.order = (0..n).collect();
        self.cand = vec![0.0; ctx.dim()];
        self.u = vec![0.0; ctx.dim()];
        self.since_poll = 0;
    }

    /// Ranks the fireflies by cost, brightest first; ties by index, NaN as +inf.
    pub fn rank(&mut self) {
        let cost = &self.cost;
        let key = |k: usize| if cost[k].is_nan() { f64::INFINITY } else { cost[k] };
        for (k, o) in self.order.iter_mut().enumerate() {
            *o = k;
        }
        self.order.sort_unstable_by(|&a, &b| key(a).total_cmp(&key(b)).then(a.cmp(&b)));
    }
}

impl Swarm {
    /// FA's sweep (Yang's code): every firefly, worst first, moves toward each brighter one,
    /// brightest first, then the brightest moves randomly; every move is kept, and the moved
    /// swarm is evaluated once at the end, as one population. Worst first means the brighter
    /// fireflies have not moved yet, so each attraction is toward the position whose cost
    /// ranked it.
    #[allow(clippy::too_many_arguments)]
    pub fn sweep_then_evaluate(
        &mut self,
        ctx: &mut Context<'_>,
        beta0: f64,
        beta_min: f64,
        gamma: f64,
        alpha: f64,
        weights: &[f64],
    ) {
        let n = self.x.len();
        if n == 0 || ctx.exhausted() || ctx.should_stop() {
            return;
        }
        self.rank();
        for k in (0..n).rev() {
            if ctx.should_stop() {
                return;
            }
            let i = self.order[k];
            self.cand.copy_from_slice(self.x.row(i));
            for m in 0..k {
                let xj = self.x.row(self.order[m]);
                fill_unit_f64_32(ctx.rng(), &mut self.u);
                let beta = (beta0 - beta_min) * (-gamma * distance2(&self.cand, xj)).exp() + beta_min;
                move_in_place(&mut self.cand, xj, beta, alpha, weights, &self.u, ctx.lower(), ctx.upper());
            }
            if k == 0 {
                // The brightest: a random move.
                fill_unit_f64_32(ctx.rng(), &mut self.u);
                let xb = self.x.row(i);
                move_in_place(&mut self.cand, xb, 0.0, alpha, weights, &self.u, ctx.lower(), ctx.upper());
            }
            ctx.repair(&mut self.cand);
            self.x.row_mut(i).copy_from_slice(&self.cand);
        }
        ctx.evaluate_population(&self.x, &mut self.cost);
    }
}

/// `x <- x + beta (xj − x) + step w (u − 0.5)`, clamped to the box: one move of eq. 1.
#[allow(clippy::too_many_arguments)]
#[inline]
pub(crate) fn move_in_place(
    x: &mut [f64],
    xj: &[f64],
    beta: f64,
    step: f64,
    weights: &[f64],
    u: &[f64],
    lower: &[f64],
    upper: &[f64],
) {
    let dim = x.len();
    let (xj, weights, u, lower, upper) = (&xj[..dim], &weights[..dim], &u[..dim], &lower[..dim], &upper[..dim]);
    let sources = xj.iter().zip(weights.iter().zip(u)).zip(lower.iter().zip(upper));
    for (o, ((&b, (&w, &u)), (&lo, &hi))) in x.iter_mut().zip(sources) {
        let a = *o;
        *o = clamp(a + beta * (b - a) + step * w * (u - 0.5), lo, hi);
    }
}

/// ‖a − b‖².
#[inline]
pub(crate) fn distance2(a: &[f64], b: &[f64]) -> f64 {
    // Four partial sums, so the loop vectorizes (a fixed order: the result is deterministic).
    let mut s = [0.0f64; 4];
    let (ca, cb) = (a.chunks_exact(4), b.chunks_exact(4));
    let (ra, rb) = (ca.remainder(), cb.remainder());
    for (x, y) in ca.zip(cb) {
        for k in 0..4 {
            let d = x[k] - y[k];
            s[k] += d * d;
        }
    }
    let mut tail = 0.0;
    for (x, y) in ra.iter().zip(rb) {
        let d = x - y;
        tail += d * d;
    }
    (s[0] + s[1]) + (s[2] + s[3]) + tail
}

/// Yang's firefly algorithm, built from checked parameters.
#[derive(Clone, Debug)]
pub struct Fa {
    params: FaParams,
    swarm: Swarm,
    /// The random term's per-dimension factor: 1, or the box width.
    weights: Vec<f64>,
    /// Sweeps started, for the iteration-based progress.
    iteration: u64,
}

impl Fa {
    pub fn new(params: Checked<FaParams>) -> Self {
        Self { params: params.into_inner(), swarm: Swarm::empty(), weights: Vec::new(), iteration: 0 }
    }

    pub fn params(&self) -> &FaParams {
        &self.params
    }
}

impl Optimizer for Fa {
    fn id(&self) -> &'static str {
        "fa"
    }

    fn population(&self) -> usize {
        self.params.population
    }

    fn init(&mut self, ctx: &mut Context<'_>) {
        self.weights = (0..ctx.dim())
            .map(|d| match self.params.alpha_scale {
                AlphaScale::Absolute => 1.0,
                AlphaScale::Range => ctx.range(d),
            })
            .collect();
        self.iteration = 0;
        self.swarm.init(self.params.population, ctx);
    }

    fn step(&mut self, ctx: &mut Context<'_>) {
        // t/N before this sweep's evaluations (its iteration count: sweeps completed).
        let alpha = self.params.alpha_at(progress(ctx, self.iteration));
        self.iteration += 1;
        let p = &self.params;
        self.swarm.sweep_then_evaluate(ctx, p.beta0, p.beta_min, p.gamma, alpha, &self.weights);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::optim::functions::{Function, FunctionObjective};
    use crate::optim::{run, test_support};
    use crate::rng::run_rng;
    use crate::termination::Termination;

    fn fa(p: FaParams) -> Fa {
        Fa::new(p.checked("t").unwrap())
    }

    #[test]
    fn defaults_are_the_papers() {
        let p = FaParams::default();
        assert_eq!(FaParams { alpha_scale: AlphaScale::Absolute, ..p.clone() }, FaParams::amfa2015());
        assert_eq!((p.population, p.beta0, p.gamma, p.alpha), (40, 1.0, 1.0, 1.0));
        assert_eq!((p.beta_min, p.alpha_end), (0.2, 1.0e-4 / 0.9));
        assert_eq!((p.alpha_scale, FaParams::amfa2015().alpha_scale), (AlphaScale::Range, AlphaScale::Absolute));
        assert!(p.checked("p").is_ok());
        let t: toml::Table = toml::from_str("alpha_scale = \"absolute\"\ngamma = 0.5").unwrap();
        let q = FaParams::from_table(&t, "p").unwrap();
        assert_eq!(*q.get(), FaParams { alpha_scale: AlphaScale::Absolute, gamma: 0.5, ..FaParams::default() });
        assert_eq!(*FaParams::from_table(&FaParams::default().to_table(), "p").unwrap().get(), FaParams::default());
    }

    #[test]
    fn check_rejects_bad_values() {
        let d = FaParams::default();
        for bad in [
            FaParams { population: 1, ..d.clone() },
            FaParams { beta0: -0.1, ..d.clone() },
            FaParams { beta0: 2.5, ..d.clone() },
            FaParams { beta0: f64::NAN, ..d.clone() },
            FaParams { gamma: -1.0, ..d.clone() },
            FaParams { gamma: f64::INFINITY, ..d.clone() },
            FaParams { alpha: -0.5, ..d.clone() },
            FaParams { alpha: f64::NAN, ..d.clone() },
            FaParams { beta_min: -0.2, ..d.clone() },
            FaParams { alpha_end: 0.0, ..d.clone() },
            FaParams { alpha_end: 1.5, ..d.clone() },
        ] {
            let e = bad.checked("planner.params.fa").unwrap_err().to_string();
            assert!(e.starts_with("planner.params.fa."), "{e}");
        }
        let t: toml::Table = toml::from_str("alpha_scale = \"box\"").unwrap();
        let e = FaParams::from_table(&t, "planner.params.fa").unwrap_err().to_string();
        assert!(e.starts_with("planner.params.fa.alpha_scale"), "{e}");
        assert!(FaParams::from_table(&toml::from_str("delta = 0.97").unwrap(), "p").is_err());
    }

    #[test]
    fn distance_and_move_by_hand() {
        assert_eq!(distance2(&[1.0, 2.0, 3.0, 4.0, 5.0], &[1.0, 0.0, 3.0, 1.0, 6.0]), 4.0 + 9.0 + 1.0);
        // r = 1 (x_j − x_i = (1, 0)), γ = 1: β = e^{-1}.
        let beta = (-1.0f64).exp();
        let mut x = [0.0, 0.0];
        move_in_place(&mut x, &[1.0, 0.0], beta, 2.0, &[1.0, 3.0], &[0.75, 0.25], &[-9.0; 2], &[9.0; 2]);
        assert_eq!(x, [beta + 2.0 * 0.25, 2.0 * 3.0 * -0.25]);
        // Clamped to the box.
        let mut x = [0.0, 0.0];
        move_in_place(&mut x, &[1.0, 0.0], 1.0, 100.0, &[1.0, 1.0], &[1.0, 0.0], &[-5.0; 2], &[5.0; 2]);
        assert_eq!(x, [5.0, -5.0]);
    }

    /// One sweep of two fireflies, recomputed from the same random numbers: the worse moves
    /// toward the brighter (β = 0.8 e^{−r²} + 0.2), the brighter moves randomly, both are
    /// evaluated; α = alpha_end^(2/100) (t/N = 2 evaluations of 100).
    #[test]
    fn a_sweep_matches_a_hand_computation() {
        let obj = FunctionObjective::new(Function::Sphere, 3, -2.0, 2.0);
        let mut opt = fa(FaParams { population: 2, alpha_scale: AlphaScale::Absolute, ..FaParams::default() });
        let mut rng = run_rng(11, 0);
        let mut ctx = Context::new(&obj, &mut rng, Some(100), false, &[]);
        opt.init(&mut ctx);
        let (x0, cost0) = (opt.swarm.x.clone(), opt.swarm.cost.clone());
        let mut twin = ctx.rng().clone();
        let (mut u1, mut u2) = ([0.0; 3], [0.0; 3]);
        fill_unit_f64_32(&mut twin, &mut u1);
        fill_unit_f64_32(&mut twin, &mut u2);
        opt.step(&mut ctx);
        assert_eq!(ctx.evaluations(), 4);
        let (b, w) = if cost0[0] <= cost0[1] { (0, 1) } else { (1, 0) };
        let (xw, xb) = (x0.row(w), x0.row(b));
        let r2: f64 = xw.iter().zip(xb).map(|(a, b)| (a - b) * (a - b)).sum();
        let beta = 0.8 * (-r2).exp() + 0.2;
        let alpha = YANG_ALPHA_END.powf(0.02);
        for d in 0..3 {
            let want_w = (xw[d] + beta * (xb[d] - xw[d]) + alpha * (u1[d] - 0.5)).clamp(-2.0, 2.0);
            let want_b = (xb[d] + alpha * (u2[d] - 0.5)).clamp(-2.0, 2.0);
            assert!((opt.swarm.x.row(w)[d] - want_w).abs() < 1e-12, "{d}");
            assert!((opt.swarm.x.row(b)[d] - want_b).abs() < 1e-12, "{d}");
        }
        for k in 0..2 {
            assert_eq!(opt.swarm.cost[k], Function::Sphere.value(opt.swarm.x.row(k)));
        }
    }

    #[test]
    fn alpha_schedule_by_hand() {
        let p = FaParams::default();
        assert_eq!(p.alpha_at(0.0), 1.0);
        assert!((p.alpha_at(0.5) - (1.0e-4f64 / 0.9).sqrt()).abs() < 1e-15);
        assert!((p.alpha_at(1.0) - 1.0e-4 / 0.9).abs() < 1e-18);
        let constant = FaParams { alpha_end: 1.0, alpha: 0.7, ..p };
        assert_eq!((constant.alpha_at(0.0), constant.alpha_at(0.5), constant.alpha_at(1.0)), (0.7, 0.7, 0.7));
    }

    #[test]
    fn converges_on_sphere_and_stays_in_the_box() {
        let obj = FunctionObjective::new(Function::Sphere, 5, -5.12, 5.12);
        let mut opt = fa(FaParams::default());
        let r = run(&mut opt, &obj, &Termination::evaluations(20_000), &mut run_rng(3, 0), false, &[], &mut |_| {});
        assert!(r.best_cost < 1e-6, "{}", r.best_cost);
        assert!(opt.swarm.x.rows().all(|x| x.iter().all(|v| (-5.12..=5.12).contains(v))));
        for (x, &c) in opt.swarm.x.rows().zip(&opt.swarm.cost) {
            assert_eq!(Function::Sphere.value(x), c);
        }
        // The range-scaled reading also runs and stays inside.
        let mut opt = fa(FaParams { alpha_scale: AlphaScale::Range, ..FaParams::default() });
        let r = run(&mut opt, &obj, &Termination::evaluations(5_000), &mut run_rng(3, 0), false, &[], &mut |_| {});
        assert!(r.best_cost.is_finite());
        assert!(opt.swarm.x.rows().all(|x| x.iter().all(|v| (-5.12..=5.12).contains(v))));
    }

    #[test]
    fn stops_exactly_at_the_evaluation_budget() {
        let obj = FunctionObjective::new(Function::Rastrigin, 7, -5.12, 5.12);
        test_support::assert_exact_budgets(&obj, &[1u64, 39, 40, 41, 1000, 3001], || Box::new(fa(FaParams::default())));
    }

    #[test]
    fn same_seed_same_bits() {
        let obj = FunctionObjective::new(Function::Ackley, 10, -32.0, 32.0);
        test_support::assert_same_bits(&obj, || Box::new(fa(FaParams::default())));
    }
}
