//! Harris hawks optimization (HHO), a baseline of ijs2023.
//!
//! Follows Heidari, Mirjalili, Faris, Aljarah, Mafarja & Chen, "Harris hawks optimization:
//! Algorithm and applications" (Future Generation Computer Systems 97, 2019), eqs. 1–13, as
//! the paper prints them; the authors' MATLAB code settles what the text leaves open. Per
//! iteration t of T, for each hawk X_i, with the rabbit X_rabbit the best position so far and
//! X_m the flock's mean:
//!
//! ```text
//! E  = 2 E₀ (1 − t/T),  E₀ ~ U(−1, 1) per hawk per iteration        (eq. 3)
//! |E| ≥ 1, exploration, q ~ U(0, 1):                                  (eq. 1)
//!   q ≥ 0.5:  X ← X_rand − r₁ |X_rand − 2 r₂ X|
//!   q < 0.5:  X ← (X_rabbit − X_m) − r₃ (LB + r₄ (UB − LB))
//! X_m = (1/N) Σ X_k, per dimension                                    (eq. 2)
//! |E| < 1, exploitation, r ~ U(0, 1), J = 2 (1 − r₅):
//!   r ≥ 0.5, |E| ≥ 0.5, soft besiege:  X ← (X_rabbit − X) − E |J X_rabbit − X|    (eqs. 4–5)
//!   r ≥ 0.5, |E| < 0.5, hard besiege:  X ← X_rabbit − E |X_rabbit − X|            (eq. 6)
//!   r < 0.5, |E| ≥ 0.5, soft besiege with progressive rapid dives:
//!     Y = X_rabbit − E |J X_rabbit − X|                               (eq. 7)
//!     Z = Y + S ⊙ LF(D),  S ~ U(0, 1)^D                               (eq. 8)
//!     X ← Y if F(Y) < F(X);  else Z if F(Z) < F(X);  else X          (eq. 10)
//!   r < 0.5, |E| < 0.5, hard besiege with progressive rapid dives:
//!     Y = X_rabbit − E |J X_rabbit − X_m|,  Z as above, same rule     (eqs. 11–13)
//! LF = 0.01 u σ / |v|^(1/β), β = 1.5 (Mantegna, [`super::levy`])       (eq. 9)
//! ```
//!
//! Defaults ([`HhoParams`]): 45 hawks (ijs2023's Np for every algorithm; the paper used 30),
//! β = 1.5 and the factor 0.01 of eq. 9.
//!
//! Readings (docs/papers/shared.md, HHO):
//! * **X_m is the per-dimension mean of the flock** at the start of the iteration (eq. 2).
//!   MEALPY's `np.mean` without an axis averages all coordinates of all hawks into one scalar;
//!   that is not copied.
//! * **Synchronous moves.** Every hawk moves from the positions of iteration t: X_rand (any
//!   hawk, itself included, as the code's `floor(N rand + 1)`) and X_m are read from them, the
//!   new positions are written apart. The authors' code moves the hawks in place, so a later
//!   hawk may pick an already moved X_rand and a mean of mixed iterations; the paper writes
//!   X_rand(t) and X_m(t).
//! * **q ≥ 0.5 perches on a family member**, as the paper's eq. 1 prints it (the authors' code
//!   swaps the two cases, the same distribution).
//! * **r₁ … r₅, q, r, E₀ are scalars per hawk**, S a vector (eq. 8: "a random vector by size
//!   1 × D"), as in the code.
//! * **LF carries the paper's factor 0.01** (eq. 9; `levy_scale`). The authors' MATLAB `Levy`
//!   omits it (`levy_scale = 1`); MEALPY keeps 0.01 but draws one scalar step per dive.
//! * **Z is built from Y before repair**, both repaired (clamped to the box, then the
//!   encoding's constraints) before each is evaluated, as every moved individual here; the
//!   code evaluates Y and Z unclamped and clamps only at the next iteration's start.
//! * **Evaluations, as the code counts them, less its repeats.** One iteration evaluates every
//!   hawk once, as one population (the code's loop top, before it updates the rabbit), plus,
//!   for each diving hawk, Y, and Z only if Y did not beat X (the code's `else`). F(X) is the
//!   hawk's recorded cost: the code evaluates X again in each comparison (one or two more
//!   evaluations per dive) though a pure cost cannot change; those are not spent. The
//!   loop-top evaluation does re-evaluate the hawks that dived (their costs are already
//!   known), as the code does; so an iteration costs N + (1 or 2 per diving hawk)
//!   evaluations. The Y and Z of a dive are evaluated one at a time, in hawk order, before the
//!   flock's population evaluation.
//! * **The rabbit** is the best position evaluated so far, updated after each population
//!   evaluation (a dive that is kept is evaluated there again; one that is refused cannot beat
//!   the rabbit, since it did not beat its hawk). Ties keep the earlier point; NaN never wins.
//! * **t/T** is the run's progress ([`progress`]): evaluations used over the budget at the
//!   start of the iteration, or without one, completed iterations over the iteration limit.
//!
//! Random draws, in order, per hawk: E₀; with |E| ≥ 1, q, then the hawk index and r₁, r₂ (or
//! r₃, r₄); with |E| < 1, r and r₅ (J; drawn in every exploitation case so the count depends on
//! the case only), then for a dive S (D uniforms at 32-bit resolution, [`fill_unit_f64_32`]).
//! Then the dives, one at a time in hawk order with [`Context::evaluate`]: a hawk whose Y fails
//! draws LF (D Lévy steps, two normals each) for its Z then (most of a dive's random numbers,
//! so a Y that succeeds costs none of them). The flock is evaluated with
//! [`Context::evaluate_population`]; nothing random is drawn during a parallel evaluation, so
//! results do not depend on the thread count.

use rand::Rng as _;

use super::fa::progress;
use super::levy::{fill_standard_normal, Levy};
use super::MAX_POPULATION;
use super::{Context, Optimizer, Population};
use crate::params::{Bound, Checked, Range};
use crate::rng::fill_unit_f64_32;

crate::params! {
    /// HHO parameters. Defaults: the paper's (eq. 9) with ijs2023's population.
    pub struct HhoParams {
        /// Number of hawks N.
        population: usize = 45, Range::integer(2, MAX_POPULATION as u64), "ijs2023 (Np = 45 for every algorithm; Heidari et al. 2019 used 30)";
        /// Lévy exponent β of the rapid dives (Mantegna's algorithm holds on [0.3, 1.99]).
        levy_beta: f64 = 1.5, Range::closed(0.3, 1.99), "Heidari et al. 2019 eq. 9";
        /// Factor of the Lévy step LF (eq. 9's 0.01; the authors' MATLAB code uses 1).
        levy_scale: f64 = 0.01, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1.0) }, "Heidari et al. 2019 eq. 9";
    }
}

/// Dives between two polls of the run's stop flag and deadline (a costly objective's
/// evaluation polls on its own).
const POLL_DIVES: u32 = 16;

/// Eq. 1, q ≥ 0.5: perch on a random family member, `out = X_rand − r₁ |X_rand − 2 r₂ X|`.
pub(crate) fn perch_on_family(x_rand: &[f64], x: &[f64], r1: f64, r2: f64, out: &mut [f64]) {
    for ((o, &a), &b) in out.iter_mut().zip(x_rand).zip(x) {
        *o = a - r1 * (a - 2.0 * r2 * b).abs();
    }
}

/// Eq. 1, q < 0.5: perch on a random tall tree, `out = (X_rabbit − X_m) − r₃ (LB + r₄ (UB − LB))`.
pub(crate) fn perch_on_tree(
    rabbit: &[f64],
    mean: &[f64],
    r3: f64,
    r4: f64,
    lower: &[f64],
    upper: &[f64],
    out: &mut [f64],
) {
    let sources = rabbit.iter().zip(mean).zip(lower.iter().zip(upper));
    for (o, ((&b, &m), (&lo, &hi))) in out.iter_mut().zip(sources) {
        *o = (b - m) - r3 * (lo + r4 * (hi - lo));
    }
}

/// Eqs. 4–5, soft besiege: `out = (X_rabbit − X) − E |J X_rabbit − X|`.
pub(crate) fn soft_besiege(rabbit: &[f64], x: &[f64], e: f64, j: f64, out: &mut [f64]) {
    for ((o, &b), &v) in out.iter_mut().zip(rabbit).zip(x) {
        *o = (b - v) - e * (j * b - v).abs();
    }
}

/// Eq. 6, hard besiege: `out = X_rabbit − E |X_rabbit − X|`.
pub(crate) fn hard_besiege(rabbit: &[f64], x: &[f64], e: f64, out: &mut [f64]) {
    for ((o, &b), &v) in out.iter_mut().zip(rabbit).zip(x) {
        *o = b - e * (b - v).abs();
    }
}

/// The first candidate of a rapid dive, `y = X_rabbit − E |J X_rabbit − base|` (eq. 7 with
/// `base` = X, soft; eq. 12 with `base` = X_m, hard). The second, `z = y + S ⊙ LF` (eqs. 8
/// and 13), is built in `Hho::dives` only when `y` fails.
#[inline]
pub(crate) fn dive_y(rabbit: &[f64], base: &[f64], e: f64, j: f64, y: &mut [f64]) {
    for ((yo, &b), &v) in y.iter_mut().zip(rabbit).zip(base) {
        *yo = b - e * (j * b - v).abs();
    }
}

/// Both candidates of a rapid dive at once, `y` as [`dive_y`] and `z = y + S ⊙ LF`: the
/// tests' replay of an iteration.
#[cfg(test)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn dive(rabbit: &[f64], base: &[f64], e: f64, j: f64, s: &[f64], lf: &[f64], y: &mut [f64], z: &mut [f64]) {
    let sources = rabbit.iter().zip(base).zip(s.iter().zip(lf));
    for ((yo, zo), ((&b, &v), (&s, &l))) in y.iter_mut().zip(z.iter_mut()).zip(sources) {
        let yv = b - e * (j * b - v).abs();
        *yo = yv;
        *zo = yv + s * l;
    }
}

/// Whether a candidate of cost `f` replaces a hawk of cost `old` (eq. 10): strictly lower, or
/// a number where the hawk's cost is NaN.
#[inline]
pub(crate) fn beats(f: f64, old: f64) -> bool {
    f < old || (old.is_nan() && !f.is_nan())
}

/// The per-dimension mean of the rows of `x` (eq. 2).
fn mean_into(x: &Population, out: &mut [f64]) {
    out.fill(0.0);
    for row in x.rows() {
        for (o, &v) in out.iter_mut().zip(row) {
            *o += v;
        }
    }
    let n = x.len().max(1) as f64;
    for o in out.iter_mut() {
        *o /= n;
    }
}

/// Harris hawks optimization, built from checked parameters.
#[derive(Clone, Debug)]
pub struct Hho {
    params: HhoParams,
    levy: Levy,
    /// The flock X(t) and its costs.
    x: Population,
    cost: Vec<f64>,
    /// X(t + 1) as it is built; for a diving hawk, Y until its dive is decided.
    next: Population,
    /// Each diving hawk's S (eq. 10's random vector; other rows unused).
    z: Population,
    /// The standard normals (z_u, v) of one Z's Lévy steps, in pairs.
    normals: Vec<f64>,
    /// One Z's Lévy steps LF, from `normals`.
    lf: Vec<f64>,
    diving: Vec<bool>,
    rabbit: Vec<f64>,
    rabbit_cost: f64,
    mean: Vec<f64>,
    cand: Vec<f64>,
    /// Iterations completed, for the iteration-based progress.
    iteration: u64,
}

impl Hho {
    pub fn new(params: Checked<HhoParams>) -> Self {
        let params = params.into_inner();
        Self {
            levy: Levy::new(params.levy_beta, params.levy_scale),
            params,
            x: Population::zeros(0, 0),
            cost: Vec::new(),
            next: Population::zeros(0, 0),
            z: Population::zeros(0, 0),
            normals: Vec::new(),
            lf: Vec::new(),
            diving: Vec::new(),
            rabbit: Vec::new(),
            rabbit_cost: f64::INFINITY,
            mean: Vec::new(),
            cand: Vec::new(),
            iteration: 0,
        }
    }

    pub fn params(&self) -> &HhoParams {
        &self.params
    }

    /// The rabbit: the best hawk of any population evaluation so far (strictly lower wins).
    fn update_rabbit(&mut self) {
        for (i, &c) in self.cost.iter().enumerate() {
            if c < self.rabbit_cost {
                self.rabbit_cost = c;
                self.rabbit.copy_from_slice(self.x.row(i));
            }
        }
    }

    /// Draws the iteration's random numbers but the dives' Lévy steps and builds each hawk's
    /// move into `next` (a diving hawk's Y there and its S in `z`); evaluates nothing.
    fn moves(&mut self, ctx: &mut Context<'_>, e1: f64) {
        let n = self.x.len();
        mean_into(&self.x, &mut self.mean);
        for i in 0..n {
            let rng = ctx.rng();
            let e = e1 * (2.0 * rng.random::<f64>() - 1.0);
            self.diving[i] = false;
            if e.abs() >= 1.0 {
                let q: f64 = rng.random();
                if q >= 0.5 {
                    let k = rng.random_range(0..n);
                    let (r1, r2): (f64, f64) = (rng.random(), rng.random());
                    perch_on_family(self.x.row(k), self.x.row(i), r1, r2, self.next.row_mut(i));
                } else {
                    let (r3, r4): (f64, f64) = (rng.random(), rng.random());
                    perch_on_tree(&self.rabbit, &self.mean, r3, r4, ctx.lower(), ctx.upper(), self.next.row_mut(i));
                }
                continue;
            }
            let r: f64 = rng.random();
            let j = 2.0 * (1.0 - rng.random::<f64>());
            if r >= 0.5 {
                if e.abs() >= 0.5 {
                    soft_besiege(&self.rabbit, self.x.row(i), e, j, self.next.row_mut(i));
                } else {
                    hard_besiege(&self.rabbit, self.x.row(i), e, self.next.row_mut(i));
                }
                continue;
            }
            // S is drawn now; the Lévy steps' normals (2 D of them, most of a dive's random
            // numbers) only for a Z that is evaluated, when Y fails (`dives`).
            fill_unit_f64_32(rng, self.z.row_mut(i));
            let base = if e.abs() >= 0.5 { self.x.row(i) } else { &self.mean[..] };
            dive_y(&self.rabbit, base, e, j, self.next.row_mut(i));
            self.diving[i] = true;
        }
    }

    /// Evaluates candidate `cand` (repaired here) against hawk `i`'s cost; true when it was
    /// evaluated and beats it.
    fn try_dive(&mut self, ctx: &mut Context<'_>, i: usize) -> bool {
        ctx.repair(&mut self.cand);
        let before = ctx.evaluations();
        let f = ctx.evaluate(&self.cand);
        ctx.evaluations() > before && beats(f, self.cost[i])
    }

    /// The dives (eq. 10), one hawk at a time: Y, then Z if Y did not beat X; the hawk keeps
    /// X when neither does, or once the budget is spent or the run stopped.
    fn dives(&mut self, ctx: &mut Context<'_>) {
        let mut since_poll = 0u32;
        let mut stopped = false;
        for i in 0..self.x.len() {
            if !self.diving[i] {
                continue;
            }
            if !stopped {
                since_poll += 1;
                stopped = ctx.exhausted() || (since_poll % POLL_DIVES == 0 && ctx.should_stop());
            }
            if !stopped {
                self.cand.copy_from_slice(self.next.row(i));
                if self.try_dive(ctx, i) {
                    self.next.row_mut(i).copy_from_slice(&self.cand);
                    continue;
                }
                stopped = ctx.exhausted();
                if !stopped {
                    // Z = Y + S ⊙ LF (eq. 10), from Y before its repair; LF's normals drawn
                    // here, in dive order (dives run one after another: deterministic).
                    fill_standard_normal(ctx.rng(), &mut self.normals);
                    self.levy.steps_from(&self.normals, &mut self.lf);
                    let (y, s) = (self.next.row(i), self.z.row(i));
                    for (((c, &y), &s), &l) in self.cand.iter_mut().zip(y).zip(s).zip(&self.lf) {
                        *c = y + s * l;
                    }
                    if self.try_dive(ctx, i) {
                        self.next.row_mut(i).copy_from_slice(&self.cand);
                        continue;
                    }
                }
            }
            self.next.copy_row_from(i, &self.x, i);
        }
    }
}

impl Optimizer for Hho {
    fn id(&self) -> &'static str {
        "hho"
    }

    fn population(&self) -> usize {
        self.params.population
    }

    fn init(&mut self, ctx: &mut Context<'_>) {
        let (n, dim) = (self.params.population, ctx.dim());
        (self.x, self.cost) = Population::initial_evaluated(n, ctx);
        self.next = Population::zeros(n, dim);
        self.z = Population::zeros(n, dim);
        self.normals = vec![0.0; 2 * dim];
        self.lf = vec![0.0; dim];
        self.diving = vec![false; n];
        self.rabbit = self.x.row(0).to_vec();
        self.rabbit_cost = f64::INFINITY;
        self.mean = vec![0.0; dim];
        self.cand = vec![0.0; dim];
        self.iteration = 0;
        self.update_rabbit();
    }

    fn step(&mut self, ctx: &mut Context<'_>) {
        if self.x.is_empty() || ctx.exhausted() || ctx.should_stop() {
            return;
        }
        // t/T before this iteration's evaluations (t: iterations completed).
        let e1 = 2.0 * (1.0 - progress(ctx, self.iteration));
        self.iteration += 1;
        self.moves(ctx, e1);
        self.dives(ctx);
        for i in 0..self.x.len() {
            if !self.diving[i] {
                ctx.repair(self.next.row_mut(i));
            }
        }
        std::mem::swap(&mut self.x, &mut self.next);
        ctx.evaluate_population(&self.x, &mut self.cost);
        self.update_rabbit();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::optim::functions::{Function, FunctionObjective};
    use crate::optim::{run, test_support};
    use crate::rng::run_rng;
    use crate::termination::Termination;

    fn hho(p: HhoParams) -> Hho {
        Hho::new(p.checked("t").unwrap())
    }

    #[test]
    fn defaults_are_the_papers() {
        let p = HhoParams::default();
        assert_eq!((p.population, p.levy_beta, p.levy_scale), (45, 1.5, 0.01));
        assert!(p.clone().checked("p").is_ok());
        let q = HhoParams::from_table(&toml::from_str("levy_scale = 1.0").unwrap(), "p").unwrap();
        assert_eq!(*q.get(), HhoParams { levy_scale: 1.0, ..HhoParams::default() });
        assert_eq!(*HhoParams::from_table(&p.to_table(), "p").unwrap().get(), p);
        assert_eq!(hho(HhoParams::default()).id(), "hho");
    }

    #[test]
    fn check_rejects_bad_values() {
        let d = HhoParams::default();
        for bad in [
            HhoParams { population: 1, ..d.clone() },
            HhoParams { levy_beta: 0.2, ..d.clone() },
            HhoParams { levy_beta: 2.0, ..d.clone() },
            HhoParams { levy_beta: f64::NAN, ..d.clone() },
            HhoParams { levy_scale: 0.0, ..d.clone() },
            HhoParams { levy_scale: 1.5, ..d.clone() },
        ] {
            let e = bad.checked("planner.params.hho").unwrap_err().to_string();
            assert!(e.starts_with("planner.params.hho."), "{e}");
        }
        assert!(HhoParams::from_table(&toml::from_str("fads = 0.2").unwrap(), "p").is_err());
    }

    /// Eq. 1, both perches, by hand.
    #[test]
    fn exploration_by_hand() {
        let mut out = [0.0; 2];
        // X_rand = (1, −2), X = (3, 0.5), r₁ = 0.5, r₂ = 0.25:
        // 1 − 0.5 |1 − 1.5| = 0.75;  −2 − 0.5 |−2 − 0.25| = −3.125.
        perch_on_family(&[1.0, -2.0], &[3.0, 0.5], 0.5, 0.25, &mut out);
        assert_eq!(out, [0.75, -3.125]);
        // X_rabbit = (1, 1), X_m = (0.5, −1), r₃ = 0.5, r₄ = 0.25, box [−4, 4] × [0, 8]:
        // (0.5) − 0.5 (−4 + 2) = 1.5;  (2) − 0.5 (0 + 2) = 1.
        perch_on_tree(&[1.0, 1.0], &[0.5, -1.0], 0.5, 0.25, &[-4.0, 0.0], &[4.0, 8.0], &mut out);
        assert_eq!(out, [1.5, 1.0]);
    }

    /// Eqs. 4–6, both besieges, by hand.
    #[test]
    fn besieges_by_hand() {
        let mut out = [0.0; 2];
        // Soft: X_rabbit = (2, −1), X = (1, 1), E = 0.75, J = 1.5:
        // (2 − 1) − 0.75 |3 − 1| = −0.5;  (−1 − 1) − 0.75 |−1.5 − 1| = −3.875.
        soft_besiege(&[2.0, -1.0], &[1.0, 1.0], 0.75, 1.5, &mut out);
        assert_eq!(out, [-0.5, -3.875]);
        // Hard: E = −0.25: 2 + 0.25 |1| = 2.25;  −1 + 0.25 |−2| = −0.5.
        hard_besiege(&[2.0, -1.0], &[1.0, 1.0], -0.25, &mut out);
        assert_eq!(out, [2.25, -0.5]);
    }

    /// Eqs. 7–8 (soft dive: base X) and 12–13 (hard dive: base X_m), and eq. 10's rule.
    #[test]
    fn dives_by_hand() {
        let (mut y, mut z) = ([0.0; 2], [0.0; 2]);
        // X_rabbit = (1, 2), base = (0, 4), E = 0.5, J = 1.0, S = (0.5, 0.25), LF = (0.1, −0.4):
        // Y = (1 − 0.5 |1|, 2 − 0.5 |−2|) = (0.5, 1); Z = (0.55, 0.9).
        dive(&[1.0, 2.0], &[0.0, 4.0], 0.5, 1.0, &[0.5, 0.25], &[0.1, -0.4], &mut y, &mut z);
        assert_eq!(y, [0.5, 1.0]);
        assert_eq!(z, [0.5 + 0.05, 1.0 - 0.1]);
        // Hard case, the flock's mean as base, E = −0.25, J = 0.5: Y = (1 + 0.25 |0.5 − 0.5|,
        // 2 + 0.25 |1 − 3|) = (1, 2.5).
        dive(&[1.0, 2.0], &[0.5, 3.0], -0.25, 0.5, &[0.0, 0.0], &[9.0, 9.0], &mut y, &mut z);
        assert_eq!((y, z), ([1.0, 2.5], [1.0, 2.5]));
        assert!(beats(1.0, 2.0) && !beats(2.0, 2.0) && !beats(3.0, 2.0));
        assert!(beats(5.0, f64::NAN) && !beats(f64::NAN, 1.0) && !beats(f64::INFINITY, 1.0));
        let mut m = [0.0; 2];
        let mut pop = Population::zeros(3, 2);
        pop.as_flat_mut().copy_from_slice(&[1.0, 2.0, 3.0, 4.0, 5.0, 9.0]);
        mean_into(&pop, &mut m);
        assert_eq!(m, [3.0, 5.0]);
    }

    /// Four iterations replayed from a twin of the stream: each hawk's move recomputed from
    /// the same random numbers; a hawk that did not dive sits at its move, clamped; a diving
    /// hawk at its clamped Y or Z or where it was; the evaluations are N for the flock plus
    /// one or two per diving hawk.
    #[test]
    fn iterations_match_a_replay_of_the_branches() {
        let (dim, n, lo, hi) = (4, 12, -3.0, 3.0);
        let obj = FunctionObjective::new(Function::Sphere, dim, lo, hi);
        // The authors' code's Lévy scale (1): Z then differs enough from Y to be kept at times.
        let levy = Levy::new(1.5, 1.0);
        let clamp = |v: &mut Vec<f64>| v.iter_mut().for_each(|w| *w = w.clamp(lo, hi));
        let mut seen = [0usize; 6];
        // Dives whose Z was evaluated: [Z failed too, Z kept].
        let mut zs = [0usize; 2];
        for seed in 21..31 {
            let mut opt = hho(HhoParams { population: n, levy_scale: 1.0, ..HhoParams::default() });
            let mut rng = run_rng(seed, 0);
            // An iteration limit of 4: t/T = 0, 1/4, 2/4, 3/4 in the four iterations.
            let t = Termination::iterations(4);
            let mut ctx = Context::new(&obj, &mut rng, None, false, &[]).with_termination(&t);
            opt.init(&mut ctx);
            assert_eq!(ctx.evaluations(), n as u64);
            for it in 0..4u64 {
                let (x0, rabbit) = (opt.x.clone(), opt.rabbit.clone());
                let mut mean = vec![0.0; dim];
                mean_into(&x0, &mut mean);
                let mut twin = ctx.rng().clone();
                let e1 = 2.0 * (1.0 - it as f64 / 4.0);
                // Per hawk: its next position; per diving hawk: (index, Y before repair, S).
                let mut want: Vec<Vec<f64>> = Vec::new();
                let mut dives: Vec<(usize, Vec<f64>, Vec<f64>)> = Vec::new();
                for i in 0..n {
                    let e = e1 * (2.0 * twin.random::<f64>() - 1.0);
                    let mut a = vec![0.0; dim];
                    if e.abs() >= 1.0 {
                        if twin.random::<f64>() >= 0.5 {
                            let k = twin.random_range(0..n);
                            let (r1, r2): (f64, f64) = (twin.random(), twin.random());
                            perch_on_family(x0.row(k), x0.row(i), r1, r2, &mut a);
                            seen[0] += 1;
                        } else {
                            let (r3, r4): (f64, f64) = (twin.random(), twin.random());
                            perch_on_tree(&rabbit, &mean, r3, r4, &[lo; 4], &[hi; 4], &mut a);
                            seen[1] += 1;
                        }
                        clamp(&mut a);
                        want.push(a);
                        continue;
                    }
                    let r: f64 = twin.random();
                    let j = 2.0 * (1.0 - twin.random::<f64>());
                    if r >= 0.5 {
                        if e.abs() >= 0.5 {
                            soft_besiege(&rabbit, x0.row(i), e, j, &mut a);
                            seen[2] += 1;
                        } else {
                            hard_besiege(&rabbit, x0.row(i), e, &mut a);
                            seen[3] += 1;
                        }
                        clamp(&mut a);
                        want.push(a);
                        continue;
                    }
                    let mut s = vec![0.0; dim];
                    fill_unit_f64_32(&mut twin, &mut s);
                    let base = if e.abs() >= 0.5 { x0.row(i).to_vec() } else { mean.clone() };
                    seen[if e.abs() >= 0.5 { 4 } else { 5 }] += 1;
                    dive_y(&rabbit, &base, e, j, &mut a);
                    dives.push((i, a.clone(), s));
                    clamp(&mut a);
                    want.push(a);
                }
                // The dives, in hawk order: Y (repaired) if it beats the hawk's cost, else Z = Y +
                // S ⊙ LF with LF's normals drawn now, else the hawk stays.
                let old_cost = opt.cost.clone();
                for (i, y, s) in &dives {
                    if Function::Sphere.value(&want[*i]) < old_cost[*i] {
                        continue;
                    }
                    let mut lf = vec![0.0; dim];
                    levy.fill(&mut twin, &mut lf);
                    let mut z: Vec<f64> = y.iter().zip(s).zip(&lf).map(|((y, s), l)| y + s * l).collect();
                    clamp(&mut z);
                    zs[usize::from(Function::Sphere.value(&z) < old_cost[*i])] += 1;
                    want[*i] = if Function::Sphere.value(&z) < old_cost[*i] { z } else { x0.row(*i).to_vec() };
                }
                let before = ctx.evaluations();
                opt.step(&mut ctx);
                let spent = ctx.evaluations() - before;
                let k = dives.len() as u64;
                assert!(spent >= n as u64 + k && spent <= n as u64 + 2 * k, "{it}: {spent} for {k} dives");
                for (i, a) in want.iter().enumerate() {
                    assert_eq!(opt.x.row(i), &a[..], "iteration {it}, hawk {i}");
                }
                for (xr, &c) in opt.x.rows().zip(&opt.cost) {
                    assert_eq!(c, Function::Sphere.value(xr));
                }
            }
        }
        // Every branch ran at least once (seeds chosen so), and Z was both kept and refused.
        assert!(seen.iter().all(|&k| k > 0), "{seen:?}");
        assert!(zs.iter().all(|&k| k > 0), "{zs:?}");
    }

    #[test]
    fn converges_on_sphere_and_stays_in_the_box() {
        let obj = FunctionObjective::new(Function::Sphere, 10, -5.12, 5.12);
        let mut opt = hho(HhoParams::default());
        let r = run(&mut opt, &obj, &Termination::evaluations(20_000), &mut run_rng(3, 0), false, &[], &mut |_| {});
        assert!(r.best_cost < 1e-8, "{}", r.best_cost);
        assert!(opt.x.rows().all(|x| x.iter().all(|v| (-5.12..=5.12).contains(v))));
        let r = run(&mut opt, &obj, &Termination::iterations(100), &mut run_rng(4, 0), false, &[], &mut |_| {});
        assert!(r.best_cost < 1e-8, "{}", r.best_cost);
    }

    #[test]
    fn stops_exactly_at_the_evaluation_budget() {
        let obj = FunctionObjective::new(Function::Rastrigin, 7, -5.12, 5.12);
        test_support::assert_exact_budgets(&obj, &[1u64, 44, 45, 46, 91, 1000, 3001], || {
            Box::new(hho(HhoParams::default()))
        });
    }

    #[test]
    fn same_seed_same_bits() {
        let obj = FunctionObjective::new(Function::Ackley, 10, -32.0, 32.0);
        test_support::assert_same_bits(&obj, || Box::new(hho(HhoParams::default())));
    }
}
