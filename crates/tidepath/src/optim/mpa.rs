//! The marine predators algorithm (MPA), a baseline of ijs2023.
//!
//! Follows Faramarzi, Heidarinejad, Mirjalili & Gandomi, "Marine Predators Algorithm: A
//! nature-inspired metaheuristic" (Expert Systems with Applications 152, 2020), eqs. 10–16, in
//! the form of the authors' MATLAB code (`MPA.m`), which fixes what the text leaves open. With
//! the Elite the top predator (the best position so far) copied to every row, the prey X_i,
//! R ~ U(0, 1)^D, R_B standard normal (Brownian) and R_L = 0.05 Lévy steps (Mantegna, β = 1.5,
//! [`super::levy`]), all per prey and coordinate, P = 0.5 and t/T the run's progress:
//!
//! ```text
//! CF = (1 − t/T)^(2 t/T)
//! t/T < 1/3, phase 1:          X_i ← X_i + P R ⊙ R_B ⊙ (Elite − R_B ⊙ X_i)           (eq. 12)
//! 1/3 ≤ t/T < 2/3, phase 2:    first half of the prey,
//!                              X_i ← X_i + P R ⊙ R_L ⊙ (Elite − R_L ⊙ X_i)           (eq. 13)
//!                              second half,
//!                              X_i ← Elite + P CF R_B ⊙ (R_B ⊙ Elite − X_i)          (eq. 14)
//! t/T ≥ 2/3, phase 3:          X_i ← Elite + P CF R_L ⊙ (R_L ⊙ Elite − X_i)          (eq. 15)
//! marine memory:               each prey keeps the better of its old and new position
//! FADs (eq. 16), once per iteration, u ~ U(0, 1):
//!   u < FADs:  X_i ← X_i + CF (LB + R ⊙ (UB − LB)) ⊙ U,  U_d = [rand < FADs]
//!   else:      X_i ← X_i + (FADs (1 − r) + r)(X_{π₁(i)} − X_{π₂(i)}),  r ~ U(0, 1),
//!              π₁, π₂ random permutations
//! marine memory again
//! ```
//!
//! Defaults ([`MpaParams`]): P = 0.5, FADs = 0.2 (the paper and the code), 0.05 for R_L (the
//! code), β = 1.5, 45 prey (ijs2023's Np for every algorithm; the paper used 25).
//!
//! Readings (docs/papers/shared.md, MPA):
//! * **Eq. 16 is decided once per iteration**, as in the code (`if rand() < FADs` before the
//!   matrix update): the whole population takes the FADs jump, or the whole population the
//!   eddy step with one r and two random permutations (`randperm`). The paper's text can be
//!   read per prey (an r per X_i); MEALPY draws it per prey. The jump's mask U and its R are
//!   per prey and coordinate.
//! * **Two population evaluations per iteration**, as the code counts them: after the phase
//!   move (the code's evaluation at the end of its loop body) and after the FADs step (the
//!   code's evaluation at the top of the next iteration), each followed by the marine memory
//!   (a prey goes back to its old position when the old cost is strictly lower,
//!   `fit_old < fitness`). The initial population is evaluated once. So a run of k
//!   iterations costs N (1 + 2k) evaluations; MEALPY's OriginalMPA evaluates once per epoch.
//! * **The memory applies from the first move.** The code's `if Iter==0` resets the memory
//!   after the first phase move as well as before it, so its very first move is kept
//!   unconditionally; here every move is judged the same way.
//! * **Phases by the run's progress** t/T ([`progress`]: evaluations used over the budget at
//!   the start of the iteration, or completed iterations over the iteration limit): phase 1
//!   while t/T < 1/3, phase 2 while t/T < 2/3, then phase 3. The code's `Iter>Max_iter/3 &&
//!   Iter<2*Max_iter/3` sends an iteration exactly at T/3 to phase 3; not copied.
//! * **The halves of phase 2**: the first ⌊N/2⌋ prey (by index) move by eq. 13, the rest by
//!   eq. 14 (the code's `i>size(Prey,1)/2`, 1-based).
//! * **R is one uniform per prey and coordinate** (the code draws `R=rand()` inside its
//!   coordinate loop). CF uses the same t/T as the phases.
//! * **Boundaries**: every moved prey is repaired (clamped to the box, then the encoding's
//!   constraints) before it is evaluated, as the code clamps before each evaluation.
//! * **The top predator** is the best position evaluated so far (strictly lower wins; ties
//!   keep the earlier point; NaN never wins), updated after each population evaluation.
//!
//! Random draws, in order, per iteration: per prey, by phase: phase 1, R_B (D normals) then R
//! (D uniforms at 32-bit resolution, [`fill_unit_f64_32`]); phase 2, first half R_L (D Lévy
//! steps, two normals each) then R, second half R_B; phase 3, R_L. Then u; for the jump, per
//! prey, U's D uniforms then R's D uniforms; for the eddy, r, then π₁ and π₂ (Fisher–Yates,
//! from the last position down). Populations are evaluated with
//! [`Context::evaluate_population`], so results do not depend on the thread count.

use rand::Rng as _;

use super::fa::progress;
use super::levy::{fill_standard_normal, Levy};
use super::MAX_POPULATION;
use super::{Context, Optimizer, Population};
use crate::params::{Bound, Checked, Range};
use crate::rng::{fill_unit_f64_32, Rng};

crate::params! {
    /// MPA parameters. Defaults: the paper's and its code's, with ijs2023's population.
    pub struct MpaParams {
        /// Number of prey (search agents) N.
        population: usize = 45, Range::integer(2, MAX_POPULATION as u64), "ijs2023 (Np = 45 for every algorithm; Faramarzi et al. 2020 used 25)";
        /// The constant P of eqs. 12–15.
        p: f64 = 0.5, Range::closed(0.0, 2.0), "Faramarzi et al. 2020 (P = 0.5)";
        /// Probability of the FADs effect (eq. 16).
        fads: f64 = 0.2, Range::closed(0.0, 1.0), "Faramarzi et al. 2020 (FADs = 0.2)";
        /// Lévy exponent β of R_L (Mantegna's algorithm holds on [0.3, 1.99]).
        levy_beta: f64 = 1.5, Range::closed(0.3, 1.99), "Faramarzi et al. 2020 (β = 1.5)";
        /// Factor of the Lévy steps R_L.
        levy_scale: f64 = 0.05, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1.0) }, "the authors' MATLAB code (RL = 0.05*levy)";
    }
}

/// The three phases of the run (eqs. 12–15).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase {
    /// t/T < 1/3: Brownian prey (eq. 12).
    One,
    /// 1/3 ≤ t/T < 2/3: half Lévy prey (eq. 13), half Brownian predator (eq. 14).
    Two,
    /// t/T ≥ 2/3: Lévy predator (eq. 15).
    Three,
}

/// The phase at progress `frac` = t/T.
pub fn phase(frac: f64) -> Phase {
    if frac < 1.0 / 3.0 {
        Phase::One
    } else if frac < 2.0 / 3.0 {
        Phase::Two
    } else {
        Phase::Three
    }
}

/// The adaptive factor CF = (1 − t/T)^(2 t/T), `frac` clamped to [0, 1].
pub fn cf(frac: f64) -> f64 {
    let f = frac.clamp(0.0, 1.0);
    (1.0 - f).powf(2.0 * f)
}

/// Eqs. 12 and 13, the prey moves: `x ← x + P R ⊙ step ⊙ (Elite − step ⊙ x)`, `step` = R_B
/// (eq. 12) or R_L (eq. 13).
pub(crate) fn prey_move(x: &mut [f64], elite: &[f64], step: &[f64], r: &[f64], p: f64) {
    for ((v, &e), (&s, &r)) in x.iter_mut().zip(elite).zip(step.iter().zip(r)) {
        let stepsize = s * (e - s * *v);
        *v += p * r * stepsize;
    }
}

/// Eqs. 14 and 15, the predator moves: `x ← Elite + P CF step ⊙ (step ⊙ Elite − x)`, `step` =
/// R_B (eq. 14) or R_L (eq. 15).
pub(crate) fn predator_move(x: &mut [f64], elite: &[f64], step: &[f64], p: f64, cf: f64) {
    for ((v, &e), &s) in x.iter_mut().zip(elite).zip(step) {
        let stepsize = s * (s * e - *v);
        *v = e + p * cf * stepsize;
    }
}

/// Eq. 16, the FADs jump: `x_d ← x_d + CF (LB_d + rand_d (UB_d − LB_d))` where `mask_d < fads`.
pub(crate) fn fads_jump(x: &mut [f64], mask: &[f64], rand: &[f64], fads: f64, cf: f64, lower: &[f64], upper: &[f64]) {
    let sources = mask.iter().zip(rand).zip(lower.iter().zip(upper));
    for (v, ((&m, &u), (&lo, &hi))) in x.iter_mut().zip(sources) {
        if m < fads {
            *v += cf * (lo + u * (hi - lo));
        }
    }
}

/// Eq. 16, the eddy: `x ← x + (FADs (1 − r) + r)(a − b)`.
pub(crate) fn eddy(x: &mut [f64], a: &[f64], b: &[f64], fads: f64, r: f64) {
    let k = fads * (1.0 - r) + r;
    for ((v, &p), &q) in x.iter_mut().zip(a).zip(b) {
        *v += k * (p - q);
    }
}

/// The marine memory: prey `i` goes back to `old` when its old cost is strictly lower (or a
/// number where the new cost is NaN).
pub(crate) fn remember(x: &mut Population, cost: &mut [f64], old: &Population, old_cost: &[f64]) {
    for (i, (c, &o)) in cost.iter_mut().zip(old_cost).enumerate() {
        if o < *c || (c.is_nan() && !o.is_nan()) {
            *c = o;
            x.copy_row_from(i, old, i);
        }
    }
}

/// `perm` set to a random permutation of 0..len: the identity, then Fisher–Yates from the
/// last position down (one `random_range(0..=k)` per position k ≥ 1).
fn random_permutation(rng: &mut Rng, perm: &mut [usize]) {
    for (k, p) in perm.iter_mut().enumerate() {
        *p = k;
    }
    for k in (1..perm.len()).rev() {
        let j = rng.random_range(0..=k);
        perm.swap(k, j);
    }
}

/// The marine predators algorithm, built from checked parameters.
#[derive(Clone, Debug)]
pub struct Mpa {
    params: MpaParams,
    levy: Levy,
    x: Population,
    cost: Vec<f64>,
    /// The positions and costs before the current move (the code's Prey_old, fit_old).
    old: Population,
    old_cost: Vec<f64>,
    /// The top predator and its cost.
    elite: Vec<f64>,
    elite_cost: f64,
    /// One prey's random vectors (R_B or R_L, R or the jump's mask and R).
    step: Vec<f64>,
    r: Vec<f64>,
    perm1: Vec<usize>,
    perm2: Vec<usize>,
    /// Iterations completed, for the iteration-based progress.
    iteration: u64,
}

impl Mpa {
    pub fn new(params: Checked<MpaParams>) -> Self {
        let params = params.into_inner();
        Self {
            levy: Levy::new(params.levy_beta, params.levy_scale),
            params,
            x: Population::zeros(0, 0),
            cost: Vec::new(),
            old: Population::zeros(0, 0),
            old_cost: Vec::new(),
            elite: Vec::new(),
            elite_cost: f64::INFINITY,
            step: Vec::new(),
            r: Vec::new(),
            perm1: Vec::new(),
            perm2: Vec::new(),
            iteration: 0,
        }
    }

    pub fn params(&self) -> &MpaParams {
        &self.params
    }

    fn save_old(&mut self) {
        self.old.as_flat_mut().copy_from_slice(self.x.as_flat());
        self.old_cost.copy_from_slice(&self.cost);
    }

    /// Repairs every prey, evaluates the population, applies the marine memory against the
    /// saved positions and updates the top predator.
    fn evaluate_and_remember(&mut self, ctx: &mut Context<'_>) {
        for i in 0..self.x.len() {
            ctx.repair(self.x.row_mut(i));
        }
        ctx.evaluate_population(&self.x, &mut self.cost);
        remember(&mut self.x, &mut self.cost, &self.old, &self.old_cost);
        self.update_elite();
    }

    fn update_elite(&mut self) {
        for (i, &c) in self.cost.iter().enumerate() {
            if c < self.elite_cost {
                self.elite_cost = c;
                self.elite.copy_from_slice(self.x.row(i));
            }
        }
    }

    /// Eqs. 12–15 for every prey (no evaluation).
    fn phase_moves(&mut self, ctx: &mut Context<'_>, phase: Phase, cf: f64) {
        let n = self.x.len();
        let p = self.params.p;
        for i in 0..n {
            let rng = ctx.rng();
            let x = self.x.row_mut(i);
            match phase {
                Phase::One => {
                    fill_standard_normal(rng, &mut self.step);
                    fill_unit_f64_32(rng, &mut self.r);
                    prey_move(x, &self.elite, &self.step, &self.r, p);
                }
                Phase::Two if i < n / 2 => {
                    self.levy.fill(rng, &mut self.step);
                    fill_unit_f64_32(rng, &mut self.r);
                    prey_move(x, &self.elite, &self.step, &self.r, p);
                }
                Phase::Two => {
                    fill_standard_normal(rng, &mut self.step);
                    predator_move(x, &self.elite, &self.step, p, cf);
                }
                Phase::Three => {
                    self.levy.fill(rng, &mut self.step);
                    predator_move(x, &self.elite, &self.step, p, cf);
                }
            }
        }
    }

    /// Eq. 16 for every prey, decided once (no evaluation). `old` holds the positions.
    fn fads(&mut self, ctx: &mut Context<'_>, cf: f64) {
        let n = self.x.len();
        let fads = self.params.fads;
        let u: f64 = ctx.rng().random();
        if u < fads {
            for i in 0..n {
                fill_unit_f64_32(ctx.rng(), &mut self.step);
                fill_unit_f64_32(ctx.rng(), &mut self.r);
                fads_jump(self.x.row_mut(i), &self.step, &self.r, fads, cf, ctx.lower(), ctx.upper());
            }
        } else {
            let rng = ctx.rng();
            let r: f64 = rng.random();
            random_permutation(rng, &mut self.perm1);
            random_permutation(rng, &mut self.perm2);
            for i in 0..n {
                eddy(self.x.row_mut(i), self.old.row(self.perm1[i]), self.old.row(self.perm2[i]), fads, r);
            }
        }
    }
}

impl Optimizer for Mpa {
    fn id(&self) -> &'static str {
        "mpa"
    }

    fn population(&self) -> usize {
        self.params.population
    }

    fn init(&mut self, ctx: &mut Context<'_>) {
        let (n, dim) = (self.params.population, ctx.dim());
        (self.x, self.cost) = Population::initial_evaluated(n, ctx);
        self.old = Population::zeros(n, dim);
        self.old_cost = vec![f64::INFINITY; n];
        self.elite = self.x.row(0).to_vec();
        self.elite_cost = f64::INFINITY;
        self.step = vec![0.0; dim];
        self.r = vec![0.0; dim];
        self.perm1 = vec![0; n];
        self.perm2 = vec![0; n];
        self.iteration = 0;
        self.update_elite();
    }

    fn step(&mut self, ctx: &mut Context<'_>) {
        if self.x.is_empty() || ctx.exhausted() || ctx.should_stop() {
            return;
        }
        // t/T before this iteration's evaluations (t: iterations completed).
        let frac = progress(ctx, self.iteration);
        self.iteration += 1;
        let cf = cf(frac);
        self.save_old();
        self.phase_moves(ctx, phase(frac), cf);
        self.evaluate_and_remember(ctx);
        if ctx.exhausted() || ctx.should_stop() {
            return;
        }
        self.save_old();
        self.fads(ctx, cf);
        self.evaluate_and_remember(ctx);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::optim::functions::{Function, FunctionObjective};
    use crate::optim::{run, test_support};
    use crate::rng::run_rng;
    use crate::termination::Termination;

    fn mpa(p: MpaParams) -> Mpa {
        Mpa::new(p.checked("t").unwrap())
    }

    #[test]
    fn defaults_are_the_papers() {
        let p = MpaParams::default();
        assert_eq!((p.population, p.p, p.fads, p.levy_beta, p.levy_scale), (45, 0.5, 0.2, 1.5, 0.05));
        assert!(p.clone().checked("p").is_ok());
        assert_eq!(*MpaParams::from_table(&p.to_table(), "p").unwrap().get(), p);
        let q = MpaParams::from_table(&toml::from_str("fads = 0.3").unwrap(), "p").unwrap();
        assert_eq!(*q.get(), MpaParams { fads: 0.3, ..MpaParams::default() });
        assert_eq!(mpa(MpaParams::default()).id(), "mpa");
    }

    #[test]
    fn check_rejects_bad_values() {
        let d = MpaParams::default();
        for bad in [
            MpaParams { population: 1, ..d.clone() },
            MpaParams { p: -0.1, ..d.clone() },
            MpaParams { p: f64::NAN, ..d.clone() },
            MpaParams { fads: 1.1, ..d.clone() },
            MpaParams { levy_beta: 2.0, ..d.clone() },
            MpaParams { levy_scale: 0.0, ..d.clone() },
        ] {
            let e = bad.checked("planner.params.mpa").unwrap_err().to_string();
            assert!(e.starts_with("planner.params.mpa."), "{e}");
        }
    }

    #[test]
    fn schedule_by_hand() {
        assert_eq!(cf(0.0), 1.0);
        assert_eq!(cf(1.0), 0.0);
        // (1 − 0.5)^(1) = 0.5; (0.75)^(0.5) = 0.8660.
        assert_eq!(cf(0.5), 0.5);
        assert!((cf(0.25) - 0.75f64.sqrt()).abs() < 1e-15);
        assert_eq!(
            (phase(0.0), phase(0.33), phase(1.0 / 3.0), phase(0.66)),
            (Phase::One, Phase::One, Phase::Two, Phase::Two)
        );
        assert_eq!((phase(2.0 / 3.0), phase(0.99)), (Phase::Three, Phase::Three));
    }

    /// Eqs. 12–15, by hand, on two coordinates.
    #[test]
    fn phase_moves_by_hand() {
        let elite = [1.0, -2.0];
        // Eq. 12/13: x = (2, 1), step = (0.5, −1), R = (0.5, 0.25), P = 0.5:
        // 0.5 (1 − 1) = 0 → 2;  −1 (−2 + 1) = 1 → 1 + 0.5 · 0.25 · 1 = 1.125.
        let mut x = [2.0, 1.0];
        prey_move(&mut x, &elite, &[0.5, -1.0], &[0.5, 0.25], 0.5);
        assert_eq!(x, [2.0, 1.125]);
        // x = (0, 4), step = (2, 0.5): 2 (1 − 0) = 2 → 0 + 0.5 · 0.5 · 2 = 0.5;
        // 0.5 (−2 − 2) = −2 → 4 + 0.5 · 0.25 · (−2) = 3.75.
        let mut x = [0.0, 4.0];
        prey_move(&mut x, &elite, &[2.0, 0.5], &[0.5, 0.25], 0.5);
        assert_eq!(x, [0.5, 3.75]);
        // Eq. 14/15: x = (2, 1), step = (0.5, −1), P = 0.5, CF = 0.5:
        // 0.5 (0.5 − 2) = −0.75 → 1 + 0.25 (−0.75) = 0.8125;  −1 (2 − 1) = −1 → −2 − 0.25 = −2.25.
        let mut x = [2.0, 1.0];
        predator_move(&mut x, &elite, &[0.5, -1.0], 0.5, 0.5);
        assert_eq!(x, [0.8125, -2.25]);
    }

    /// Eq. 16 by hand, and the marine memory.
    #[test]
    fn fads_and_memory_by_hand() {
        // Jump: mask (0.1, 0.5) < 0.2 only in the first coordinate; box [−4, 4] × [0, 2],
        // R = (0.25, 0.9), CF = 0.5: 1 + 0.5 (−4 + 2) = 0.
        let mut x = [1.0, 1.0];
        fads_jump(&mut x, &[0.1, 0.5], &[0.25, 0.9], 0.2, 0.5, &[-4.0, 0.0], &[4.0, 2.0]);
        assert_eq!(x, [0.0, 1.0]);
        // Eddy: r = 0.5: 0.2 · 0.5 + 0.5 = 0.6; x + 0.6 ((3, 1) − (1, 2)) = (1 + 1.2, 1 − 0.6).
        let mut x = [1.0, 1.0];
        eddy(&mut x, &[3.0, 1.0], &[1.0, 2.0], 0.2, 0.5);
        assert_eq!(x, [1.0 + 0.6 * 2.0, 1.0 - 0.6]);
        // Memory: prey 0 improved (kept), prey 1 got worse (restored), prey 2 tied (kept new),
        // prey 3 became NaN (restored).
        let mut x = Population::zeros(4, 1);
        x.as_flat_mut().copy_from_slice(&[10.0, 11.0, 12.0, 13.0]);
        let mut old = Population::zeros(4, 1);
        old.as_flat_mut().copy_from_slice(&[0.0, 1.0, 2.0, 3.0]);
        let mut cost = [1.0, 5.0, 2.0, f64::NAN];
        remember(&mut x, &mut cost, &old, &[2.0, 4.0, 2.0, 7.0]);
        assert_eq!(x.as_flat(), &[10.0, 1.0, 12.0, 3.0]);
        assert_eq!(cost, [1.0, 4.0, 2.0, 7.0]);
        let mut rng = run_rng(1, 0);
        let mut perm = vec![0; 9];
        random_permutation(&mut rng, &mut perm);
        let mut sorted = perm.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..9).collect::<Vec<_>>());
    }

    /// One phase-1 iteration replayed from a twin of the stream: the moves of eq. 12 from the
    /// same numbers, the memory, then eq. 16 and the memory again; 2N evaluations.
    #[test]
    fn an_iteration_matches_a_replay() {
        let (dim, n, lo, hi) = (3, 6, -2.0, 2.0);
        let obj = FunctionObjective::new(Function::Sphere, dim, lo, hi);
        let mut opt = mpa(MpaParams { population: n, ..MpaParams::default() });
        let mut rng = run_rng(8, 0);
        let t = Termination::iterations(10);
        let mut ctx = Context::new(&obj, &mut rng, None, false, &[]).with_termination(&t);
        opt.init(&mut ctx);
        let f = |x: &[f64]| Function::Sphere.value(x);
        for it in 0..10u64 {
            let (x0, c0, elite) = (opt.x.clone(), opt.cost.clone(), opt.elite.clone());
            let mut twin = ctx.rng().clone();
            let frac = it as f64 / 10.0;
            let cfv = cf(frac);
            let mut x1 = x0.clone();
            let levy = Levy::new(1.5, 0.05);
            for i in 0..n {
                let (mut s, mut r) = (vec![0.0; dim], vec![0.0; dim]);
                let row = x1.row_mut(i);
                match phase(frac) {
                    Phase::One => {
                        fill_standard_normal(&mut twin, &mut s);
                        fill_unit_f64_32(&mut twin, &mut r);
                        prey_move(row, &elite, &s, &r, 0.5);
                    }
                    Phase::Two if i < n / 2 => {
                        levy.fill(&mut twin, &mut s);
                        fill_unit_f64_32(&mut twin, &mut r);
                        prey_move(row, &elite, &s, &r, 0.5);
                    }
                    Phase::Two => {
                        fill_standard_normal(&mut twin, &mut s);
                        predator_move(row, &elite, &s, 0.5, cfv);
                    }
                    Phase::Three => {
                        levy.fill(&mut twin, &mut s);
                        predator_move(row, &elite, &s, 0.5, cfv);
                    }
                }
                row.iter_mut().for_each(|v| *v = v.clamp(lo, hi));
            }
            let mut c1: Vec<f64> = x1.rows().map(f).collect();
            remember(&mut x1, &mut c1, &x0, &c0);
            let mut x2 = x1.clone();
            if twin.random::<f64>() < 0.2 {
                for i in 0..n {
                    let (mut m, mut r) = (vec![0.0; dim], vec![0.0; dim]);
                    fill_unit_f64_32(&mut twin, &mut m);
                    fill_unit_f64_32(&mut twin, &mut r);
                    fads_jump(x2.row_mut(i), &m, &r, 0.2, cfv, &[lo; 3], &[hi; 3]);
                }
            } else {
                let r: f64 = twin.random();
                let (mut p1, mut p2) = (vec![0; n], vec![0; n]);
                random_permutation(&mut twin, &mut p1);
                random_permutation(&mut twin, &mut p2);
                for i in 0..n {
                    eddy(x2.row_mut(i), x1.row(p1[i]), x1.row(p2[i]), 0.2, r);
                }
            }
            for i in 0..n {
                x2.row_mut(i).iter_mut().for_each(|v| *v = v.clamp(lo, hi));
            }
            let mut c2: Vec<f64> = x2.rows().map(f).collect();
            remember(&mut x2, &mut c2, &x1, &c1);
            let before = ctx.evaluations();
            opt.step(&mut ctx);
            assert_eq!(ctx.evaluations() - before, 2 * n as u64, "iteration {it}");
            assert_eq!(opt.x, x2, "iteration {it}");
            assert_eq!(opt.cost, c2, "iteration {it}");
            // The memory never lets a prey's cost rise.
            assert!(opt.cost.iter().zip(&c0).all(|(a, b)| a <= b));
        }
        assert_eq!(ctx.evaluations(), (n * (1 + 2 * 10)) as u64);
    }

    #[test]
    fn converges_on_sphere_and_stays_in_the_box() {
        let obj = FunctionObjective::new(Function::Sphere, 10, -5.12, 5.12);
        let mut opt = mpa(MpaParams::default());
        let r = run(&mut opt, &obj, &Termination::evaluations(20_000), &mut run_rng(3, 0), false, &[], &mut |_| {});
        assert!(r.best_cost < 1e-6, "{}", r.best_cost);
        assert!(opt.x.rows().all(|x| x.iter().all(|v| (-5.12..=5.12).contains(v))));
        let r = run(&mut opt, &obj, &Termination::iterations(200), &mut run_rng(4, 0), false, &[], &mut |_| {});
        assert!(r.best_cost < 1e-6, "{}", r.best_cost);
    }

    #[test]
    fn stops_exactly_at_the_evaluation_budget() {
        let obj = FunctionObjective::new(Function::Rastrigin, 7, -5.12, 5.12);
        test_support::assert_exact_budgets(&obj, &[1u64, 44, 45, 46, 90, 136, 1000, 3001], || {
            Box::new(mpa(MpaParams::default()))
        });
    }

    #[test]
    fn same_seed_same_bits() {
        let obj = FunctionObjective::new(Function::Griewank, 10, -600.0, 600.0);
        test_support::assert_same_bits(&obj, || Box::new(mpa(MpaParams::default())));
    }
}
