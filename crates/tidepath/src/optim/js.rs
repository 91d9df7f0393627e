//! JS, the artificial jellyfish search, ijs2023's baseline and the core of its IJS
//! ([`super::ijs`]).
//!
//! Follows Chou & Truong, "A novel metaheuristic optimizer inspired by behavior of jellyfish in
//! ocean" (Applied Mathematics and Computation 389, 2021), checked against the authors' MATLAB
//! code, in the form ijs2023 (Guo, Chen & Pang 2023) restates as its eqs. 1–7
//! (docs/papers/shared.md, "JS"):
//!
//! ```text
//! x_k+1  = 4 x_k (1 − x_k),  x_0 = rand(D)                       (logistic-map start, per coordinate;
//!                                                                  jellyfish k at lb + x_k (ub − lb))
//! c(t)   = |(1 − t/T)(2 rand − 1)|                               (eq. 1, time control, one per jellyfish)
//! c ≥ C₀:  x ← x + rand(D) ⊙ (x* − β rand μ)                     (eqs. 2–4, ocean current;
//!                                                                  x* the best, μ the mean jellyfish)
//! c < C₀ and rand > 1 − c:  x ← x + γ rand (ub − lb)             (eq. 7, passive motion)
//! c < C₀ otherwise:  step = x_j − x if f(x_j) < f(x), else x − x_j
//!                    x ← x + rand(D) ⊙ step                       (eqs. 5–6, active motion, j ≠ i random)
//! bounds:  above ub re-enter at lb + (x − ub), below lb at ub + (x − lb)   (wrap-around)
//! x_i    ← the new position only if its cost is lower              (greedy, as the authors' code)
//! ```
//!
//! with β = 3, γ = 0.1, C₀ = 0.5 and 50 jellyfish (the defaults, [`JsParams::default`]; ijs2023
//! runs JS with 45).
//!
//! Readings:
//! * **Passive or active (ijs2023 A3).** A jellyfish whose c is below C₀ moves passively when
//!   rand > 1 − c and actively otherwise, as in the original paper and the authors' code, so
//!   the share of passive moves shrinks with c(t). ijs2023 prints the test the other way round
//!   ("1 − C(t) < rand → active"); the baseline follows the original. (The authors' MATLAB
//!   code tests `rand <= 1 - Ar` with the signed Ar = (1 − t/T)(2 rand − 1), so its passive
//!   moves are half as frequent; the paper's |c| is used here.)
//! * **The ocean current's scalars.** "rand(D)" is one U(0, 1) per coordinate; "β rand" is one
//!   scalar per move, as in the authors' code (`rand(1,nd).*(Best - 3*rand*Meanvl)`), and so is
//!   the passive move's rand (`0.1*(Ub-Lb)*rand`).
//! * **Progress t/T** is [`super::fa::progress`]: evaluations used over the evaluation budget,
//!   else iterations completed over the run's iteration limit, read at the start of each
//!   iteration (so the first iteration has t/T = 0, or the initial population's share of the
//!   budget).
//! * **One iteration (`step`) is one generation, evaluated once.** The best jellyfish x*, the
//!   mean μ and every x_j an active move looks at are those of the start of the iteration; every
//!   jellyfish's new position is computed from them, wrapped into the box, repaired by the
//!   objective, and the candidates are evaluated as one population
//!   ([`Context::evaluate_population`], parallel and deterministic); then each jellyfish keeps its
//!   candidate only if it is strictly better (or its own cost is NaN). The authors' code moves
//!   and evaluates one jellyfish at a time, updating x* at once; the generation-wise form is what
//!   lets a path's costly evaluations run in parallel, and differs only in that an improvement
//!   becomes visible to the others one iteration later.
//! * **Wrap-around** repeats the re-entry until the value is inside (the authors'
//!   `simplebounds` loop), computed in one step; a value exactly on a bound stays. Then the
//!   objective's repair (for paths, the encoding's limits and any repair operators) applies.
//! * **Warm starts** replace the first rows of the logistic-map population (at most half of it,
//!   as [`Population::initial`] does); the map is iterated either way, so later draws do not
//!   change.
//! * A stop (wall time, cancel) during an iteration ends it before the evaluation: the
//!   population keeps its last evaluated positions.
//!
//! Random draws, in order: at the start, D uniform numbers (53-bit, [`fill_unit_f64`]) seed the
//! map. Per iteration, per jellyfish in index order: c's uniform; then for the ocean current one
//! uniform (β rand) and D uniforms; otherwise one uniform for the passive/active test, then for
//! a passive move one uniform, for an active move the other jellyfish (one `random_range` over
//! the n − 1 others) and D uniforms. Vectors of uniforms are drawn at 32-bit resolution
//! ([`fill_unit_f64_32`]).

use rand::Rng as _;

use super::fa::progress;
use super::{Context, Optimizer, Population, MAX_POPULATION};
use crate::params::{Bound, Checked, Range};
#[cfg(any(test, doc))]
use crate::rng::fill_unit_f64_32;
use crate::rng::{fill_u32, fill_unit_f64, unit_f64_32};

crate::params! {
    /// JS parameters. Defaults: Chou & Truong 2021.
    pub struct JsParams {
        /// Number of jellyfish.
        population: usize = 50, Range::integer(2, MAX_POPULATION as u64), "Chou & Truong 2021 (authors' code; ijs2023 runs JS with 45)";
        /// Distribution coefficient β of the ocean current, x* − β rand μ.
        beta: f64 = 3.0, Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded }, "Chou & Truong 2021; ijs2023 eq. 2 (λ = 3)";
        /// Motion coefficient γ of the passive move, γ rand (ub − lb).
        gamma: f64 = 0.1, Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded }, "Chou & Truong 2021; ijs2023 eq. 7 (δ = 0.1)";
        /// Time-control threshold C₀: c ≥ C₀ follows the ocean current.
        c0: f64 = 0.5, Range::closed(0.0, 1.0), "Chou & Truong 2021; ijs2023 eq. 1";
    }
}

/// Jellyfish handled between two polls of the run's stop flag and deadline.
pub(crate) const POLL_JELLYFISH: usize = 64;

/// One step of the logistic map, 4 x (1 − x).
#[inline]
pub fn logistic(x: f64) -> f64 {
    4.0 * x * (1.0 - x)
}

/// Fills `pop` with the logistic-map start: row 0 at `lower + x0 (upper − lower)`, each next
/// row the map of the previous one's unit values, per coordinate (the authors' `initialization`).
pub fn logistic_population(x0: &[f64], lower: &[f64], upper: &[f64], pop: &mut Population) {
    let mut x = x0.to_vec();
    for i in 0..pop.len() {
        if i > 0 {
            for v in x.iter_mut() {
                *v = logistic(*v);
            }
        }
        for (((o, &v), &lo), &hi) in pop.row_mut(i).iter_mut().zip(&x).zip(lower).zip(upper) {
            *o = lo + v * (hi - lo);
        }
    }
}

/// The time control c(t) = |(1 − t/T)(2 r − 1)| for progress `frac` = t/T and a uniform `r`.
#[inline]
pub fn time_control(frac: f64, r: f64) -> f64 {
    ((1.0 - frac) * (2.0 * r - 1.0)).abs()
}

/// A jellyfish's move in one iteration of JS.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JsMove {
    OceanCurrent,
    Passive,
    Active,
}

/// The move for time control `c`: the ocean current when c ≥ C₀; otherwise passive when the
/// uniform `r` exceeds 1 − c, else active (the original's test, ijs2023 A3). `r` is drawn only
/// when c < C₀; pass anything otherwise.
#[inline]
pub fn choose_move(c: f64, c0: f64, r: f64) -> JsMove {
    if c >= c0 {
        JsMove::OceanCurrent
    } else if r > 1.0 - c {
        JsMove::Passive
    } else {
        JsMove::Active
    }
}

/// `out = x + u ⊙ (best − beta_r · mean)`: the ocean current (eqs. 2–4), `beta_r` = β rand.
#[inline]
pub fn ocean_current(x: &[f64], best: &[f64], mean: &[f64], beta_r: f64, u: &[f64], out: &mut [f64]) {
    let dim = out.len();
    let (x, best, mean, u) = (&x[..dim], &best[..dim], &mean[..dim], &u[..dim]);
    for (o, (((&a, &b), &m), &u)) in out.iter_mut().zip(x.iter().zip(best).zip(mean).zip(u)) {
        *o = a + u * (b - beta_r * m);
    }
}

/// `out = x + gamma_r (upper − lower)`: the passive move (eq. 7), `gamma_r` = γ rand.
#[inline]
pub fn passive(x: &[f64], gamma_r: f64, lower: &[f64], upper: &[f64], out: &mut [f64]) {
    let dim = out.len();
    let (x, lower, upper) = (&x[..dim], &lower[..dim], &upper[..dim]);
    for (o, ((&a, &lo), &hi)) in out.iter_mut().zip(x.iter().zip(lower).zip(upper)) {
        *o = a + gamma_r * (hi - lo);
    }
}

/// `out = x + u ⊙ (xj − x)` when `toward` (x_j is better), else `out = x + u ⊙ (x − xj)`: the
/// active move (eqs. 5–6), also IJS's learning group.
#[inline]
pub fn active(x: &[f64], xj: &[f64], toward: bool, u: &[f64], out: &mut [f64]) {
    let dim = out.len();
    let (x, xj, u) = (&x[..dim], &xj[..dim], &u[..dim]);
    let sign = if toward { 1.0 } else { -1.0 };
    for (o, ((&a, &b), &u)) in out.iter_mut().zip(x.iter().zip(xj).zip(u)) {
        *o = a + u * (sign * (b - a));
    }
}

/// `v` wrapped into `[lo, hi]`: above `hi` it re-enters at `lo + (v − hi)`, below `lo` at
/// `hi + (v − lo)`, repeated until inside (the authors' `simplebounds`), so the result is in
/// `(lo, hi]` from above and `[lo, hi)` from below. A degenerate box gives `lo`; a value that is
/// not finite is clamped.
#[inline]
pub fn wrap(v: f64, lo: f64, hi: f64) -> f64 {
    if (lo..=hi).contains(&v) {
        return v;
    }
    let w = hi - lo;
    if !v.is_finite() || w.is_nan() || w <= 0.0 {
        return super::clamp(v, lo, hi);
    }
    // The excess d > 0 beyond the bound, reduced by whole widths into (0, w].
    // Most excesses are below one width, where the remainder is d itself (f64 `%` is libm's
    // fmod, a call): the same value without it.
    let reduce = |d: f64| {
        let r = if d < w { d } else { d % w };
        if r == 0.0 {
            w
        } else {
            r
        }
    };
    let out = if v > hi { lo + reduce(v - hi) } else { hi - reduce(lo - v) };
    // Rounding of lo + r may land a hair outside.
    super::clamp(out, lo, hi)
}

/// `row` wrapped into the box coordinate by coordinate, as [`wrap`]. Most rows are already
/// inside: one branch-free pass checks that (it vectorizes; [`wrap`]'s per-coordinate test does
/// not), and only a row with a coordinate outside is wrapped, all of it, by [`wrap`] (which
/// leaves a coordinate inside as it is, so the values are the same either way).
#[inline]
pub fn wrap_row(row: &mut [f64], lower: &[f64], upper: &[f64]) {
    let dim = row.len();
    let (lower, upper) = (&lower[..dim], &upper[..dim]);
    let mut inside = true;
    for ((&v, &lo), &hi) in row.iter().zip(lower).zip(upper) {
        inside &= (lo <= v) & (v <= hi);
    }
    if !inside {
        for ((v, &lo), &hi) in row.iter_mut().zip(lower).zip(upper) {
            *v = wrap(*v, lo, hi);
        }
    }
}

/// Whether `v` is in `[lo, hi]`, without a branch (so loops over coordinates vectorize).
#[inline(always)]
fn in_box(v: f64, lo: f64, hi: f64) -> bool {
    (lo <= v) & (v <= hi)
}

/// [`wrap`] on every coordinate of `row`.
#[inline(never)]
fn wrap_each(row: &mut [f64], lower: &[f64], upper: &[f64]) {
    for ((v, &lo), &hi) in row.iter_mut().zip(lower).zip(upper) {
        *v = wrap(*v, lo, hi);
    }
}

/// [`ocean_current`] with `u` the 32-bit uniforms of the stream words `words`
/// ([`unit_f64_32`], as [`fill_unit_f64_32`] converts them), in one pass that also checks the
/// box: true when every coordinate of `out` is inside `[lower, upper]`. The same values as
/// [`fill_unit_f64_32`] then [`ocean_current`].
#[allow(clippy::too_many_arguments)]
#[inline]
pub(crate) fn ocean_current_words(
    x: &[f64],
    best: &[f64],
    mean: &[f64],
    beta_r: f64,
    words: &[u32],
    lower: &[f64],
    upper: &[f64],
    out: &mut [f64],
) -> bool {
    let dim = out.len();
    let (x, best, mean, words, lower, upper) =
        (&x[..dim], &best[..dim], &mean[..dim], &words[..dim], &lower[..dim], &upper[..dim]);
    let mut inside = true;
    for d in 0..dim {
        let v = x[d] + unit_f64_32(words[d]) * (best[d] - beta_r * mean[d]);
        out[d] = v;
        inside &= in_box(v, lower[d], upper[d]);
    }
    inside
}

/// [`passive`] and the box check of [`ocean_current_words`] in one pass.
#[inline]
pub(crate) fn passive_checked(x: &[f64], gamma_r: f64, lower: &[f64], upper: &[f64], out: &mut [f64]) -> bool {
    let dim = out.len();
    let (x, lower, upper) = (&x[..dim], &lower[..dim], &upper[..dim]);
    let mut inside = true;
    for d in 0..dim {
        let v = x[d] + gamma_r * (upper[d] - lower[d]);
        out[d] = v;
        inside &= in_box(v, lower[d], upper[d]);
    }
    inside
}

/// [`active`] with `u` from the stream words `words` ([`unit_f64_32`]), the same values as
/// [`fill_unit_f64_32`] then [`active`].
#[inline]
pub(crate) fn active_words(x: &[f64], xj: &[f64], toward: bool, words: &[u32], out: &mut [f64]) {
    let dim = out.len();
    let (x, xj, words) = (&x[..dim], &xj[..dim], &words[..dim]);
    let sign = if toward { 1.0 } else { -1.0 };
    for d in 0..dim {
        let a = x[d];
        out[d] = a + unit_f64_32(words[d]) * (sign * (xj[d] - a));
    }
}

/// Whether every coordinate of `row` is inside `[lower, upper]`.
#[inline]
fn row_in_box(row: &[f64], lower: &[f64], upper: &[f64]) -> bool {
    let dim = row.len();
    let (lower, upper) = (&lower[..dim], &upper[..dim]);
    let mut inside = true;
    for d in 0..dim {
        inside &= in_box(row[d], lower[d], upper[d]);
    }
    inside
}

/// `mean` = the mean of `pop`'s rows: each coordinate summed over the rows in row order,
/// starting from 0, then divided by the number of rows. Eight coordinates at a time are summed
/// in registers across all rows (a row at a time would load and store every partial sum once
/// per row); the additions, and so the values, are the same.
pub(crate) fn mean_rows(pop: &Population, mean: &mut [f64]) {
    const LANES: usize = 8;
    let (n, dim) = (pop.len(), pop.dim());
    if dim == 0 {
        return;
    }
    let flat = &pop.as_flat()[..n * dim];
    let mean = &mut mean[..dim];
    let mut d0 = 0;
    while d0 + LANES <= dim {
        let mut acc = [0.0f64; LANES];
        for row in flat.chunks_exact(dim) {
            let row = &row[d0..d0 + LANES];
            for k in 0..LANES {
                acc[k] += row[k];
            }
        }
        mean[d0..d0 + LANES].copy_from_slice(&acc);
        d0 += LANES;
    }
    for (d, m) in mean.iter_mut().enumerate().skip(d0) {
        let mut sum = 0.0;
        for row in flat.chunks_exact(dim) {
            sum += row[d];
        }
        *m = sum;
    }
    for m in mean.iter_mut() {
        *m /= n as f64;
    }
}

/// The index of the lowest cost; ties: the lower index; NaN counts as +inf; 0 when all are
/// NaN or +inf.
pub(crate) fn best_index(cost: &[f64]) -> usize {
    let mut b = 0;
    let mut bf = f64::INFINITY;
    for (k, &f) in cost.iter().enumerate() {
        if f < bf {
            b = k;
            bf = f;
        }
    }
    b
}

/// Whether cost `new` replaces cost `old` greedily: strictly lower, or a number where `old` is
/// NaN.
#[inline]
pub(crate) fn improves(new: f64, old: f64) -> bool {
    new < old || (old.is_nan() && !new.is_nan())
}

/// Chou & Truong's jellyfish search, built from checked parameters.
#[derive(Clone, Debug)]
pub struct Js {
    params: JsParams,
    x: Population,
    cost: Vec<f64>,
    /// This iteration's candidate for each jellyfish, and their costs.
    cand: Population,
    cand_cost: Vec<f64>,
    /// The start of the iteration's best jellyfish x* and mean μ.
    best: Vec<f64>,
    mean: Vec<f64>,
    /// A move's U(0, 1) draws, as the stream's 32-bit words ([`unit_f64_32`] converts them).
    words: Vec<u32>,
    /// Iterations started, for the iteration-based progress.
    iteration: u64,
}

impl Js {
    pub fn new(params: Checked<JsParams>) -> Self {
        Self {
            params: params.into_inner(),
            x: Population::zeros(0, 0),
            cost: Vec::new(),
            cand: Population::zeros(0, 0),
            cand_cost: Vec::new(),
            best: Vec::new(),
            mean: Vec::new(),
            words: Vec::new(),
            iteration: 0,
        }
    }

    pub fn params(&self) -> &JsParams {
        &self.params
    }

    /// The jellyfish's positions and costs.
    pub fn positions(&self) -> (&Population, &[f64]) {
        (&self.x, &self.cost)
    }
}

impl Optimizer for Js {
    fn id(&self) -> &'static str {
        "js"
    }

    fn population(&self) -> usize {
        self.params.population
    }

    fn init(&mut self, ctx: &mut Context<'_>) {
        let (n, dim) = (self.params.population, ctx.dim());
        self.iteration = 0;
        let mut x0 = vec![0.0; dim];
        fill_unit_f64(ctx.rng(), &mut x0);
        self.x = Population::zeros(n, dim);
        logistic_population(&x0, ctx.lower(), ctx.upper(), &mut self.x);
        let k = ctx.seeds().len().min((n / 2).max(1)).min(n);
        for i in 0..k {
            self.x.row_mut(i).copy_from_slice(&ctx.seeds()[i]);
        }
        for i in 0..n {
            if i % POLL_JELLYFISH == 0 && ctx.should_stop() {
                break;
            }
            ctx.repair(self.x.row_mut(i));
        }
        self.cost = vec![f64::INFINITY; n];
        ctx.evaluate_population(&self.x, &mut self.cost);
        self.cand = Population::zeros(n, dim);
        self.cand_cost = vec![f64::INFINITY; n];
        self.best = vec![0.0; dim];
        self.mean = vec![0.0; dim];
        self.words = vec![0; dim];
    }

    fn step(&mut self, ctx: &mut Context<'_>) {
        let n = self.x.len();
        if n < 2 || ctx.exhausted() || ctx.should_stop() {
            return;
        }
        let frac = progress(ctx, self.iteration);
        self.iteration += 1;
        let p = &self.params;
        self.best.copy_from_slice(self.x.row(best_index(&self.cost)));
        mean_rows(&self.x, &mut self.mean);
        for i in 0..n {
            if i % POLL_JELLYFISH == 0 && i > 0 && ctx.should_stop() {
                return;
            }
            let (rng, lower, upper) = ctx.rng_and_bounds();
            let c = time_control(frac, rng.random::<f64>());
            let r = if c >= p.c0 { 0.0 } else { rng.random::<f64>() };
            let out = self.cand.row_mut(i);
            let xi = self.x.row(i);
            // Each move checks the box as it writes the candidate; a candidate with a
            // coordinate outside is wrapped (coordinates inside stay as they are).
            let inside = match choose_move(c, p.c0, r) {
                JsMove::OceanCurrent => {
                    let beta_r = p.beta * rng.random::<f64>();
                    fill_u32(rng, &mut self.words);
                    ocean_current_words(xi, &self.best, &self.mean, beta_r, &self.words, lower, upper, out)
                }
                JsMove::Passive => {
                    let gamma_r = p.gamma * rng.random::<f64>();
                    passive_checked(xi, gamma_r, lower, upper, out)
                }
                JsMove::Active => {
                    let j = rng.random_range(0..n - 1);
                    let j = if j >= i { j + 1 } else { j };
                    fill_u32(rng, &mut self.words);
                    active_words(xi, self.x.row(j), self.cost[j] < self.cost[i], &self.words, out);
                    row_in_box(out, lower, upper)
                }
            };
            if !inside {
                wrap_each(out, lower, upper);
            }
            ctx.repair(out);
        }
        ctx.evaluate_population(&self.cand, &mut self.cand_cost);
        for i in 0..n {
            if improves(self.cand_cost[i], self.cost[i]) {
                self.x.copy_row_from(i, &self.cand, i);
                self.cost[i] = self.cand_cost[i];
            }
        }
    }
}

#[cfg(test)]
mod tests;
