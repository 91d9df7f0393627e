//! AMFA, the modified firefly algorithm of amfa2015 (Liu, Zhao, Gao & Liu 2015, "Three-
//! Dimensional Path Planning Method for Autonomous Underwater Vehicle Based on Modified Firefly
//! Algorithm", section 3, eqs. 3–4).
//!
//! ```text
//! r      = ‖x_i − x_j‖                                        (Euclidean, all D coordinates)
//! γ(t)   = γ_b + (t/N)(γ_e − γ_b)                              (eq. 4)
//! α(t)   = α_b + (t/N)(α_e − α_b)                              (eq. 4)
//! cand   = x_i + β₀ exp(−γ(t) r²)(x_j − x_i) + α(t) r (rand(D) − 0.5)     (eq. 3, A1)
//!          (r in the random term: per coordinate by default, see below)
//! x_i   <- cand  only if f(cand) < f(x_i)                      (autonomous flight strategy)
//! ```
//!
//! Defaults (section 5, [`AmfaParams::amfa2015`]): β₀ = 1, γ_b = 1, γ_e = 2, α_b = 2.0,
//! α_e = 0.8, 40 fireflies.
//!
//! Readings (docs/papers/amfa2015.md):
//! * **A1, attraction.** Eq. 3 prints β (x_i − x_j), a repulsion; eq. 1 and the text describe
//!   attraction, so the move is β (x_j − x_i).
//! * **A2, the random vector.** rand(D) − 0.5: one U(0, 1) per coordinate, minus 0.5.
//! * **The distance r of the random step (`step_distance`).** docs/papers/amfa2015.md reads r
//!   as the Euclidean distance over all D coordinates (`"euclidean"`), and so does the
//!   attraction β₀ e^{−γ r²} here in both readings. Measured: with that r the random step
//!   α r (rand − 0.5) has a length of about α r √(D/12), 3.2 r at D = 30 and α = 2, so nearly
//!   every candidate overshoots and AFS refuses it; on Sphere in 30 dimensions (60,000
//!   evaluations, three seeds) no firefly improves on the initial population at all, where the
//!   paper reports 0, and in 10 dimensions AMFA does not beat random search by the factor the
//!   generic optimizer tests ask. The default, `"coordinate"`, scales each coordinate's random
//!   term by that coordinate's distance, α(t) |x_jd − x_id| (rand − 0.5) (the brightest: by
//!   |x_kd − x_bd|): the step still is "the distance between two fireflies" and shrinks as
//!   they gather, as the paper describes; Sphere in 30 dimensions then reaches about 0.07
//!   ([−5.12, 5.12]) and 0.1 ([−100, 100]). Neither reading reproduces the paper's zeros; this
//!   is open.
//! * **A3, progress t/N.** With an evaluation budget (the paper's 60,000), t/N is the
//!   evaluations used over the budget, read at every move, so γ and α change smoothly within a
//!   sweep. A run without an evaluation budget uses iterations instead: t/N = k/N for the k-th
//!   sweep (1-based) of the run's iteration limit N (`Context::max_iterations`; the runner gives
//!   one to every run that limits neither), so the last sweep uses γ_e and α_e. A run with
//!   neither (a bare `Context`) stays at γ_b, α_b. When a run has both limits the evaluation
//!   budget sets the schedule, as in the paper, even if the iteration limit ends the run first.
//!   t/N is clamped to [0, 1].
//! * **A4, the brightest firefly.** After the pairwise moves, the firefly ranked first (it had
//!   no brighter one) makes a random move x + α(t) r_k (rand(D) − 0.5), r_k its distance to a
//!   firefly drawn uniformly among the others, accepted under the AFS.
//! * **One iteration (`step`) is one sweep**, as in [`super::fa`]: rank by cost at the start of
//!   the sweep (ties: lower index; NaN last); each firefly i, in that order, moves toward each
//!   firefly ranked before it, brightest first, using x_j's current position; every candidate
//!   is clamped to the box, repaired by the objective (for paths with the `exclude-contract`
//!   repair, eqs. 9–10, [`Optimizer::default_repair`]), evaluated at once and kept only if it
//!   is strictly better (AFS, so a firefly's cost never increases). Then the brightest's move.
//!   A sweep cut by the budget or a stop ends at once.
//!
//! Random draws, in order: per pairwise move, D uniform numbers (32-bit resolution, two per
//! word of the stream: [`fill_unit_f64_32`]); for the brightest's move, the other firefly (one
//! `random_range`), then D uniform numbers. Candidates are evaluated one at
//! a time (the AFS decides before the next move), so results do not depend on the thread count.

use rand::Rng as _;

use super::fa::{distance2, progress, Swarm};
use super::MAX_POPULATION;
use super::{clamp, Context, Optimizer};
use crate::params::{Bound, Checked, Range, Word};
use crate::rng::fill_unit_f64_32;

crate::params! {
    /// AMFA parameters. Defaults: amfa2015's section 5.
    pub struct AmfaParams {
        /// Number of fireflies.
        population: usize = 40, Range::integer(2, MAX_POPULATION as u64), "amfa2015 section 5";
        /// Attractiveness at distance 0, β₀ (beyond 2 a move overshoots x_j by more than
        /// x_i's distance to it).
        beta0: f64 = 1.0, Range::closed(0.0, 2.0), "amfa2015 section 5";
        /// Absorption coefficient at the start of the run, γ_b.
        gamma_b: f64 = 1.0, Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded }, "amfa2015 section 5";
        /// Absorption coefficient at the end of the run, γ_e.
        gamma_e: f64 = 2.0, Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded }, "amfa2015 section 5";
        /// Random coefficient at the start of the run, α_b (times the distance r).
        alpha_b: f64 = 2.0, Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded }, "amfa2015 section 5";
        /// Random coefficient at the end of the run, α_e.
        alpha_e: f64 = 0.8, Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded }, "amfa2015 section 5";
        /// The distance r that scales the random step: "euclidean" (‖x_i − x_j‖ over all
        /// coordinates) or "coordinate" (|x_jd − x_id| per coordinate d).
        step_distance: StepDistance = StepDistance::Coordinate, Range::Choice(&["euclidean", "coordinate"]), "docs/papers/amfa2015.md (see the module documentation)";
    }
}

/// Which distance scales AMFA's random step α(t) r (rand − 0.5).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum StepDistance {
    /// r = ‖x_i − x_j‖, one number for all coordinates (the reading of docs/papers/amfa2015.md).
    Euclidean,
    /// r_d = |x_jd − x_id|, per coordinate (the default; see the module documentation).
    #[default]
    Coordinate,
}

impl Word for StepDistance {
    const WORDS: &'static [(&'static str, Self)] =
        &[("euclidean", StepDistance::Euclidean), ("coordinate", StepDistance::Coordinate)];
}

crate::params::word_param!(StepDistance);

impl AmfaParams {
    /// amfa2015 (Liu et al. 2015, section 5): β₀ = 1, γ 1 → 2, α 2.0 → 0.8, 40 fireflies. The
    /// default.
    pub fn amfa2015() -> Self {
        Self {
            population: 40,
            beta0: 1.0,
            gamma_b: 1.0,
            gamma_e: 2.0,
            alpha_b: 2.0,
            alpha_e: 0.8,
            step_distance: StepDistance::Coordinate,
        }
    }

    /// (γ(t), α(t)) of eq. 4 at progress `t/N` = `frac` (clamped to [0, 1]).
    pub fn schedule(&self, frac: f64) -> (f64, f64) {
        let f = frac.clamp(0.0, 1.0);
        (self.gamma_b + f * (self.gamma_e - self.gamma_b), self.alpha_b + f * (self.alpha_e - self.alpha_b))
    }
}

/// Moves between two polls of the run's stop flag and deadline (a poll reads the clock, about
/// 25 ns; a move on a cheap test function costs a few hundred).
const POLL_MOVES: u32 = 16;

impl Swarm {
    /// True when the sweep must end: the budget is spent, or (polled every [`POLL_MOVES`]
    /// moves) the run was stopped. Between polls no stop can take effect, so a move that passed
    /// this check is always evaluated.
    fn must_end(&mut self, ctx: &mut Context<'_>) -> bool {
        if ctx.exhausted() {
            return true;
        }
        self.since_poll += 1;
        if self.since_poll >= POLL_MOVES {
            self.since_poll = 0;
            return ctx.should_stop();
        }
        false
    }

    /// Repairs and evaluates the candidate; it replaces firefly `i` only if its cost is
    /// strictly lower (AFS), or is a number where firefly `i`'s is NaN.
    fn try_candidate(&mut self, ctx: &mut Context<'_>, i: usize) {
        ctx.repair(&mut self.cand);
        let f = ctx.evaluate(&self.cand);
        let old = self.cost[i];
        if f < old || (old.is_nan() && !f.is_nan()) {
            self.x.row_mut(i).copy_from_slice(&self.cand);
            self.cost[i] = f;
        }
    }

    /// AMFA's sweep (see the module documentation): every firefly toward every brighter one,
    /// each move evaluated and kept under the AFS, then the brightest's random move (A4).
    /// `coefficients` gives (γ, α) at the moment of each move.
    pub(crate) fn sweep_afs(
        &mut self,
        ctx: &mut Context<'_>,
        beta0: f64,
        per_coordinate: bool,
        coefficients: impl Fn(&Context<'_>) -> (f64, f64),
    ) {
        let n = self.x.len();
        if n < 2 || ctx.should_stop() {
            return;
        }
        self.rank();
        for k in 1..n {
            let i = self.order[k];
            for m in 0..k {
                if self.must_end(ctx) {
                    return;
                }
                let j = self.order[m];
                let (gamma, alpha) = coefficients(ctx);
                fill_unit_f64_32(ctx.rng(), &mut self.u);
                let (xi, xj) = (self.x.row(i), self.x.row(j));
                let r2 = distance2(xi, xj);
                let beta = beta0 * (-gamma * r2).exp();
                if per_coordinate {
                    amfa_move_per_coordinate(
                        xi,
                        xj,
                        xj,
                        beta,
                        alpha,
                        &self.u,
                        ctx.lower(),
                        ctx.upper(),
                        &mut self.cand,
                    );
                } else {
                    amfa_move(xi, xj, beta, alpha * r2.sqrt(), &self.u, ctx.lower(), ctx.upper(), &mut self.cand);
                }
                self.try_candidate(ctx, i);
            }
        }
        if self.must_end(ctx) {
            return;
        }
        // The brightest of the ranking: a random move scaled by its distance r_k to a random
        // other firefly (A4).
        let b = self.order[0];
        let (_, alpha) = coefficients(ctx);
        let other = ctx.rng().random_range(0..n - 1);
        let other = if other >= b { other + 1 } else { other };
        let (xb, xk) = (self.x.row(b), self.x.row(other));
        fill_unit_f64_32(ctx.rng(), &mut self.u);
        if per_coordinate {
            amfa_move_per_coordinate(xb, xb, xk, 0.0, alpha, &self.u, ctx.lower(), ctx.upper(), &mut self.cand);
        } else {
            let step = alpha * distance2(xb, xk).sqrt();
            amfa_move(xb, xb, 0.0, step, &self.u, ctx.lower(), ctx.upper(), &mut self.cand);
        }
        self.try_candidate(ctx, b);
    }
}

/// `out = xi + beta (xj − xi) + step (u − 0.5)`, clamped to the box: eq. 3 read as attraction
/// (A1), with `step` = α(t) r.
#[allow(clippy::too_many_arguments)]
#[inline]
pub(crate) fn amfa_move(
    xi: &[f64],
    xj: &[f64],
    beta: f64,
    step: f64,
    u: &[f64],
    lower: &[f64],
    upper: &[f64],
    out: &mut [f64],
) {
    let dim = out.len();
    let (xi, xj, u, lower, upper) = (&xi[..dim], &xj[..dim], &u[..dim], &lower[..dim], &upper[..dim]);
    let sources = xi.iter().zip(xj).zip(u).zip(lower.iter().zip(upper));
    for (o, (((&a, &b), &u), (&lo, &hi))) in out.iter_mut().zip(sources) {
        *o = clamp(a + beta * (b - a) + step * (u - 0.5), lo, hi);
    }
}

/// `out = xi + beta (xj − xi) + alpha |y_d − xi_d| (u − 0.5)`, clamped to the box: the
/// per-coordinate reading of eq. 3's r (`step_distance = "coordinate"`), with `y` = x_j for a
/// pairwise move and the random other firefly for the brightest's.
#[allow(clippy::too_many_arguments)]
#[inline]
pub(crate) fn amfa_move_per_coordinate(
    xi: &[f64],
    xj: &[f64],
    y: &[f64],
    beta: f64,
    alpha: f64,
    u: &[f64],
    lower: &[f64],
    upper: &[f64],
    out: &mut [f64],
) {
    let dim = out.len();
    let (xi, xj, y, u, lower, upper) = (&xi[..dim], &xj[..dim], &y[..dim], &u[..dim], &lower[..dim], &upper[..dim]);
    let sources = xi.iter().zip(xj).zip(y.iter().zip(u)).zip(lower.iter().zip(upper));
    for (o, (((&a, &b), (&c, &u)), (&lo, &hi))) in out.iter_mut().zip(sources) {
        *o = clamp(a + beta * (b - a) + alpha * (c - a).abs() * (u - 0.5), lo, hi);
    }
}

/// AMFA, built from checked parameters.
#[derive(Clone, Debug)]
pub struct Amfa {
    params: AmfaParams,
    swarm: Swarm,
    /// Sweeps started, for the iteration-based schedule.
    iteration: u64,
}

impl Amfa {
    pub fn new(params: Checked<AmfaParams>) -> Self {
        Self { params: params.into_inner(), swarm: Swarm::empty(), iteration: 0 }
    }

    pub fn params(&self) -> &AmfaParams {
        &self.params
    }
}

impl Optimizer for Amfa {
    fn id(&self) -> &'static str {
        "amfa"
    }

    fn population(&self) -> usize {
        self.params.population
    }

    fn init(&mut self, ctx: &mut Context<'_>) {
        self.iteration = 0;
        self.swarm.init(self.params.population, ctx);
    }

    fn step(&mut self, ctx: &mut Context<'_>) {
        self.iteration += 1;
        let (params, iteration) = (&self.params, self.iteration);
        let per_coordinate = params.step_distance == StepDistance::Coordinate;
        self.swarm.sweep_afs(ctx, params.beta0, per_coordinate, |c| params.schedule(progress(c, iteration)));
    }

    /// amfa2015 applies its excluding and contracting operators (eqs. 9–10) to every candidate
    /// path.
    fn default_repair(&self) -> Option<&'static str> {
        Some("exclude-contract")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::optim::functions::{Function, FunctionObjective};
    use crate::optim::{run, test_support};
    use crate::rng::run_rng;
    use crate::termination::Termination;

    fn amfa(p: AmfaParams) -> Amfa {
        Amfa::new(p.checked("t").unwrap())
    }

    #[test]
    fn defaults_are_the_papers() {
        let p = AmfaParams::default();
        assert_eq!(p, AmfaParams::amfa2015());
        assert_eq!((p.population, p.beta0, p.gamma_b, p.gamma_e, p.alpha_b, p.alpha_e), (40, 1.0, 1.0, 2.0, 2.0, 0.8));
        assert_eq!(p.step_distance, StepDistance::Coordinate);
        assert!(p.checked("p").is_ok());
        assert_eq!(amfa(AmfaParams::default()).default_repair(), Some("exclude-contract"));
        let q = AmfaParams::from_table(&toml::from_str("alpha_e = 0.5").unwrap(), "p").unwrap();
        assert_eq!(*q.get(), AmfaParams { alpha_e: 0.5, ..AmfaParams::default() });
    }

    #[test]
    fn check_rejects_bad_values() {
        let d = AmfaParams::default();
        for bad in [
            AmfaParams { population: 1, ..d.clone() },
            AmfaParams { beta0: -1.0, ..d.clone() },
            AmfaParams { beta0: 3.0, ..d.clone() },
            AmfaParams { gamma_b: -0.1, ..d.clone() },
            AmfaParams { gamma_e: f64::NAN, ..d.clone() },
            AmfaParams { alpha_b: f64::INFINITY, ..d.clone() },
            AmfaParams { alpha_e: -0.8, ..d.clone() },
        ] {
            let e = bad.checked("planner.params.amfa").unwrap_err().to_string();
            assert!(e.starts_with("planner.params.amfa."), "{e}");
        }
        assert!(AmfaParams::from_table(&toml::from_str("gamma = 1.0").unwrap(), "p").is_err());
    }

    #[test]
    fn schedule_by_hand() {
        let p = AmfaParams::default();
        assert_eq!(p.schedule(0.0), (1.0, 2.0));
        assert_eq!(p.schedule(0.5), (1.5, 1.4));
        assert_eq!(p.schedule(1.0), (2.0, 0.8));
        assert_eq!(p.schedule(2.0), (2.0, 0.8));
        assert_eq!(p.schedule(-1.0), (1.0, 2.0));
    }

    #[test]
    fn progress_counts_evaluations_or_iterations() {
        let obj = FunctionObjective::new(Function::Sphere, 2, -1.0, 1.0);
        let mut rng = run_rng(0, 0);
        let mut ctx = Context::new(&obj, &mut rng, Some(60_000), false, &[]);
        assert_eq!(progress(&ctx, 7), 0.0);
        for _ in 0..30_000 {
            ctx.evaluate(&[0.5, 0.5]);
        }
        assert_eq!(progress(&ctx, 7), 0.5);
        // Without an evaluation budget: iterations over the run's iteration limit.
        let t = Termination::iterations(200);
        let mut rng = run_rng(0, 0);
        let ctx = Context::new(&obj, &mut rng, None, false, &[]).with_termination(&t);
        assert_eq!((progress(&ctx, 0), progress(&ctx, 100), progress(&ctx, 200)), (0.0, 0.5, 1.0));
        let mut rng = run_rng(0, 0);
        let ctx = Context::new(&obj, &mut rng, None, false, &[]);
        assert_eq!(progress(&ctx, 100), 0.0);
    }

    /// The first move of the first sweep, recomputed by hand from the same random numbers:
    /// cand = x_i + e^{-γ r²}(x_j − x_i) + α r (u − 0.5) with γ, α at t/N = 4/5.
    #[test]
    fn first_move_matches_a_hand_computation() {
        // A box where r is about 1, so β = e^{-γ r²} is neither 0 nor 1.
        let obj = FunctionObjective::new(Function::Sphere, 3, -1.0, 1.0);
        let mut opt =
            amfa(AmfaParams { population: 4, step_distance: StepDistance::Euclidean, ..AmfaParams::default() });
        let mut rng = run_rng(4, 0);
        let mut ctx = Context::new(&obj, &mut rng, Some(5), false, &[]);
        opt.init(&mut ctx);
        let (x0, cost0) = (opt.swarm.x.clone(), opt.swarm.cost.clone());
        let mut twin = ctx.rng().clone();
        let mut u = [0.0; 3];
        fill_unit_f64_32(&mut twin, &mut u);
        opt.step(&mut ctx);
        assert_eq!(ctx.evaluations(), 5);
        let mut by_cost: Vec<usize> = (0..4).collect();
        by_cost.sort_by(|&a, &b| cost0[a].total_cmp(&cost0[b]));
        let (j, i) = (by_cost[0], by_cost[1]);
        let (xi, xj) = (x0.row(i), x0.row(j));
        let r2: f64 = xi.iter().zip(xj).map(|(a, b)| (a - b) * (a - b)).sum();
        let (gamma, alpha) = (1.0 + 0.8 * 1.0, 2.0 + 0.8 * (0.8 - 2.0));
        let beta = (-gamma * r2).exp();
        assert!(beta > 1e-3 && beta < 0.999, "{beta}");
        let cand: Vec<f64> = (0..3)
            .map(|d| (xi[d] + beta * (xj[d] - xi[d]) + alpha * r2.sqrt() * (u[d] - 0.5)).clamp(-1.0, 1.0))
            .collect();
        let f = Function::Sphere.value(&cand);
        // AFS: the candidate replaces x_i only if it is better.
        let (want_x, want_f) = if f < cost0[i] { (&cand[..], f) } else { (xi, cost0[i]) };
        for (d, (&got, &want)) in opt.swarm.x.row(i).iter().zip(want_x).enumerate() {
            assert!((got - want).abs() < 1e-9, "{d}: {} vs {}", got, want);
        }
        assert!((opt.swarm.cost[i] - want_f).abs() <= 1e-9 * want_f.max(1.0));
        assert!((ctx.best_cost() - f.min(cost0.iter().copied().fold(f64::INFINITY, f64::min))).abs() < 1e-9);
    }

    /// The brightest's move (A4): α r_k (u − 0.5) with r_k the distance to the drawn other
    /// firefly, recomputed from the same draws on a two-firefly swarm.
    #[test]
    fn brightest_move_matches_a_hand_computation() {
        let obj = FunctionObjective::new(Function::Sphere, 2, -100.0, 100.0);
        let mut opt =
            amfa(AmfaParams { population: 2, step_distance: StepDistance::Euclidean, ..AmfaParams::default() });
        let mut rng = run_rng(8, 1);
        // Budget: init (2), one pairwise move, the brightest's move.
        let mut ctx = Context::new(&obj, &mut rng, Some(4), false, &[]);
        opt.init(&mut ctx);
        let b = if opt.swarm.cost[0] <= opt.swarm.cost[1] { 0 } else { 1 };
        let mut twin = ctx.rng().clone();
        let mut skip = [0.0; 2];
        fill_unit_f64_32(&mut twin, &mut skip); // the pairwise move's draws
        let other = twin.random_range(0..1usize);
        assert_eq!(other, 0); // the only other firefly, index 1 − b after the skip
        let mut u = [0.0; 2];
        fill_unit_f64_32(&mut twin, &mut u);
        let x_before = opt.swarm.x.clone();
        let cost_b = opt.swarm.cost[b];
        // Run the pairwise move, then look at the positions the brightest's move sees.
        let worse = 1 - b;
        opt.step(&mut ctx);
        assert_eq!(ctx.evaluations(), 4);
        let x_worse_after = opt.swarm.x.row(worse).to_vec();
        let xb = x_before.row(b);
        let rk = distance2(xb, &x_worse_after).sqrt();
        let alpha = 2.0 + 0.75 * (0.8 - 2.0); // t/N = 3/4 at the brightest's move
        let cand: Vec<f64> = (0..2).map(|d| (xb[d] + alpha * rk * (u[d] - 0.5)).clamp(-100.0, 100.0)).collect();
        let f = Function::Sphere.value(&cand);
        let want = if f < cost_b { cand } else { xb.to_vec() };
        for (&got, &want) in opt.swarm.x.row(b).iter().zip(&want) {
            assert!((got - want).abs() < 1e-9);
        }
    }

    #[test]
    fn per_coordinate_move_by_hand() {
        // β = 0.5; x_j − x_i = (2, −1); α = 1.5; u = (0.75, 0.0).
        let mut out = [0.0; 2];
        amfa_move_per_coordinate(
            &[0.0, 0.0],
            &[2.0, -1.0],
            &[2.0, -1.0],
            0.5,
            1.5,
            &[0.75, 0.0],
            &[-9.0; 2],
            &[9.0; 2],
            &mut out,
        );
        assert_eq!(out, [1.0 + 1.5 * 2.0 * 0.25, -0.5 + 1.5 * 1.0 * -0.5]);
        let mut out = [0.0; 2];
        amfa_move(&[0.0, 0.0], &[2.0, -1.0], 0.5, 3.0, &[0.75, 0.0], &[-1.0; 2], &[1.0; 2], &mut out);
        assert_eq!(out, [1.0, -1.0]); // (1.75, −2): clamped
    }

    #[test]
    fn afs_never_increases_a_fireflys_cost() {
        let obj = FunctionObjective::new(Function::Rastrigin, 6, -5.12, 5.12);
        let t = Termination::evaluations(6_000);
        let mut rng = run_rng(2, 0);
        let mut ctx = Context::new(&obj, &mut rng, t.max_evaluations, false, &[]);
        let mut opt = amfa(AmfaParams { population: 12, ..AmfaParams::default() });
        opt.init(&mut ctx);
        let mut before = opt.swarm.cost.clone();
        let mut sweeps = 0;
        while !ctx.exhausted() {
            opt.step(&mut ctx);
            sweeps += 1;
            for (k, (&now, &was)) in opt.swarm.cost.iter().zip(&before).enumerate() {
                assert!(now <= was, "firefly {k}: {was} -> {now} in sweep {sweeps}");
                assert_eq!(Function::Rastrigin.value(opt.swarm.x.row(k)), now);
            }
            before.clone_from(&opt.swarm.cost);
        }
        assert!(sweeps > 50);
    }

    #[test]
    fn converges_on_sphere_and_stays_in_the_box() {
        let obj = FunctionObjective::new(Function::Sphere, 5, -5.12, 5.12);
        let mut opt = amfa(AmfaParams::default());
        let r = run(&mut opt, &obj, &Termination::evaluations(20_000), &mut run_rng(3, 0), false, &[], &mut |_| {});
        assert!(r.best_cost < 1e-8, "{}", r.best_cost);
        assert!(opt.swarm.x.rows().all(|x| x.iter().all(|v| (-5.12..=5.12).contains(v))));
        let mut opt = amfa(AmfaParams { step_distance: StepDistance::Euclidean, ..AmfaParams::default() });
        let r = run(&mut opt, &obj, &Termination::evaluations(20_000), &mut run_rng(3, 0), false, &[], &mut |_| {});
        assert!(r.best_cost < 1e-4, "euclidean: {}", r.best_cost);
        // Iteration-limited runs use the iteration schedule and converge too.
        let mut opt = amfa(AmfaParams::default());
        let r = run(&mut opt, &obj, &Termination::iterations(40), &mut run_rng(3, 0), false, &[], &mut |_| {});
        assert!(r.best_cost < 1e-4, "{}", r.best_cost);
        assert!(opt.swarm.x.rows().all(|x| x.iter().all(|v| (-5.12..=5.12).contains(v))));
    }

    #[test]
    fn stops_exactly_at_the_evaluation_budget() {
        let obj = FunctionObjective::new(Function::Rastrigin, 7, -5.12, 5.12);
        test_support::assert_exact_budgets(&obj, &[1u64, 39, 40, 41, 780, 821, 3001], || {
            Box::new(amfa(AmfaParams::default()))
        });
    }

    #[test]
    fn same_seed_same_bits() {
        let obj = FunctionObjective::new(Function::Griewank, 10, -600.0, 600.0);
        test_support::assert_same_bits(&obj, || Box::new(amfa(AmfaParams::default())));
    }
}
