//! IJS, the improved jellyfish search of ijs2023 (Guo, Chen & Pang 2023, "Path Planning for
//! Autonomous Underwater Vehicles Based on an Improved Artificial Jellyfish Search Algorithm in
//! Multi-Obstacle Ocean Current Environment", section III-B, eqs. 5–13 and Algorithm 1).
//!
//! IJS keeps JS's moves ([`super::js`]) but gives each jellyfish a memory X_p,i of its best
//! position, and assigns the moves by rank instead of by JS's time control:
//!
//! ```text
//! start: uniform in the box (not the logistic map); X_p,i = x_i; X_g = the best X_p
//! each iteration, jellyfish sorted by current cost, best first; rank r = 1..Np:
//! r ≤ Np/3 (elite), hybrid passive move (eqs. 11–13):
//!     rand ≥ 0.5:  x ← x + RL (U − x),  U uniform in the box,  RL = 1 − t/T      (A2)
//!     else:        x ← x + rand(D) ⊙ ((X_g + X_p,i)/2 − x)
//! r ≤ 2Np/3 (learning), JS's active move (eqs. 5–6):
//!     j ≠ i random;  x ← x + rand(D) ⊙ (x_j − x) if f(x_j) < f(x), else x + rand(D) ⊙ (x − x_j)
//! otherwise (followers), the memory current (eqs. 8–10):
//!     x ← x + r₁ ⊙ (X_g − x) + r₂ ⊙ (X_p,i − x),  r₁, r₂ = 1.5 rand(D), independent   (A4)
//! repair (eq. 14: the objective's repair); evaluate; x_i ← the new position, always
//! X_p,i ← x_i if f(x_i) ≤ f(X_p,i);  X_g ← X_p,i if f(X_p,i) ≤ f(X_g)
//! ```
//!
//! with Np = 45 (the default, [`IjsParams::default`]).
//!
//! Readings (docs/papers/ijs2023.md):
//! * **A2, the restricted global move (eq. 11).** As printed, v_ran = RL((ub − lb) rand + lb)
//!   − X_i sends the jellyfish to RL times a random point, which collapses toward the origin as
//!   RL → 0, where the text says the range narrows around the current position; read as
//!   v_ran = RL (U − X_i), U uniform in the box (one U(0, 1) per coordinate). The local
//!   following move's rand is one per coordinate too.
//! * **A4, r₁ = r₂ = 1.5 rand (eq. 9):** two independent draws, one per coordinate each.
//! * **A12, the groups.** Algorithm 1's "i ≤ 1/3" and "i ≤ 2/3" are ranks up to Np/3 and 2Np/3
//!   (1-based, rounded down) after sorting by current cost (ties: lower index first; NaN last):
//!   15, 15 and 15 jellyfish for Np = 45; for Np = 2 no elite, one learner, one follower.
//! * **A3** does not arise: IJS has no passive/active test (the ranks choose the move).
//! * **Progress t/T** in RL = 1 − t/T (eq. 12) is [`super::fa::progress`]: evaluations used over
//!   the evaluation budget, else iterations completed over the run's iteration limit, read at
//!   the start of each iteration (RL = 1 in the first iteration of an iteration-limited run).
//! * **Bounds.** Eq. 14 (the window between consecutive planes and the box) is the objective's
//!   repair: for paths the `sliced` encoding's limits, for test functions a clamp to the box. IJS
//!   replaces JS's wrap-around by it.
//! * **One iteration (`step`) is one generation, evaluated once.** Every move uses the positions,
//!   costs and memories of the start of the iteration (x_j of the learning move included); the
//!   candidates are evaluated as one population ([`Context::evaluate_population`], parallel and
//!   deterministic); then, in rank order, each jellyfish takes its candidate (unconditionally:
//!   only the memories are greedy) and the memories are updated as in Algorithm 1. Algorithm 1
//!   moves and evaluates one jellyfish at a time; the generation-wise form lets a path's costly
//!   evaluations run in parallel and makes an improvement visible to the others one iteration
//!   later. A memory whose cost is NaN is replaced by any evaluated position.
//! * A stop (wall time, cancel) during an iteration ends it before the evaluation; a budget
//!   that runs out mid-population updates only the jellyfish that were evaluated.
//!
//! Measured on test functions (60,000 evaluations, 30 dimensions, [−5.12, 5.12]): IJS converges
//! much more slowly than JS on Sphere (about 5e-3 where JS reaches 1e-38) and is behind it on
//! Rastrigin. Its finest steps are the restricted global move's RL (U − x), whose length
//! shrinks only linearly with RL = 1 − t/T (so the error falls polynomially, about tenfold per
//! threefold budget); without that move (`global_share = 0`) Sphere stays near 1. ijs2023
//! reports IJS only on paths, where it beats JS.
//!
//! Random draws, in order: the start as [`Population::initial`] (uniform, warm starts first).
//! Per iteration, per jellyfish in rank order: an elite draws one uniform (the hybrid's choice)
//! and D uniforms (U, or the local move's rand(D)); a learner draws the other jellyfish (one
//! `random_range` over the Np − 1 others) and D uniforms; a follower draws D uniforms for r₁,
//! then D for r₂. Vectors of uniforms are drawn at 32-bit resolution ([`fill_unit_f64_32`]).

use rand::Rng as _;

use super::fa::progress;
#[cfg(doc)]
use super::js::active;
use super::js::{active_words, best_index, POLL_JELLYFISH};
use super::{Context, Optimizer, Population, MAX_POPULATION};
use crate::params::{Bound, Checked, Range};
#[cfg(any(test, doc))]
use crate::rng::fill_unit_f64_32;
use crate::rng::{fill_u32, unit_f64_32};

crate::params! {
    /// IJS parameters. Defaults: ijs2023.
    pub struct IjsParams {
        /// Number of jellyfish Np.
        population: usize = 45, Range::integer(2, MAX_POPULATION as u64), "ijs2023 section IV";
        /// The memory current's factor: r₁, r₂ = factor · rand(D) (eq. 9).
        memory_factor: f64 = 1.5, Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded }, "ijs2023 eq. 9";
        /// Probability of the hybrid passive move's restricted global motion (eq. 11's
        /// "rand ≥ 0.5"); the local following move otherwise.
        global_share: f64 = 0.5, Range::closed(0.0, 1.0), "ijs2023 eq. 11";
    }
}

/// IJS's group for rank `k` (0-based, best first) of `n` jellyfish (A12).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Group {
    /// Ranks up to n/3: the hybrid passive move.
    Elite,
    /// Ranks up to 2n/3: JS's active move.
    Learning,
    /// The rest: the memory current.
    Follower,
}

/// The group of 0-based rank `k` among `n`: 1-based rank k + 1 ≤ n/3 is elite, ≤ 2n/3 learning
/// (exactly, in integers).
#[inline]
pub fn group(k: usize, n: usize) -> Group {
    let r = 3 * (k + 1);
    if r <= n {
        Group::Elite
    } else if r <= 2 * n {
        Group::Learning
    } else {
        Group::Follower
    }
}

/// `out = x + rl (U − x)` with `U = lower + u (upper − lower)`: eq. 11's restricted global
/// motion read as in A2.
#[inline]
pub fn restricted_global(x: &[f64], rl: f64, u: &[f64], lower: &[f64], upper: &[f64], out: &mut [f64]) {
    let dim = out.len();
    let (x, u, lower, upper) = (&x[..dim], &u[..dim], &lower[..dim], &upper[..dim]);
    for (o, ((&a, &u), (&lo, &hi))) in out.iter_mut().zip(x.iter().zip(u).zip(lower.iter().zip(upper))) {
        let target = lo + u * (hi - lo);
        *o = a + rl * (target - a);
    }
}

/// `out = x + u ⊙ ((g + p)/2 − x)`: eq. 11's local following motion.
#[inline]
pub fn local_following(x: &[f64], g: &[f64], p: &[f64], u: &[f64], out: &mut [f64]) {
    let dim = out.len();
    let (x, g, p, u) = (&x[..dim], &g[..dim], &p[..dim], &u[..dim]);
    for (o, (((&a, &g), &p), &u)) in out.iter_mut().zip(x.iter().zip(g).zip(p).zip(u)) {
        *o = a + u * ((g + p) * 0.5 - a);
    }
}

/// `out = x + factor u1 ⊙ (g − x) + factor u2 ⊙ (p − x)`: the memory current (eqs. 8–10),
/// r₁ = factor · u1, r₂ = factor · u2.
#[inline]
pub fn memory_current(x: &[f64], g: &[f64], p: &[f64], factor: f64, u1: &[f64], u2: &[f64], out: &mut [f64]) {
    let dim = out.len();
    let (x, g, p, u1, u2) = (&x[..dim], &g[..dim], &p[..dim], &u1[..dim], &u2[..dim]);
    for (o, (((&a, &g), &p), (&u1, &u2))) in out.iter_mut().zip(x.iter().zip(g).zip(p).zip(u1.iter().zip(u2))) {
        *o = a + factor * u1 * (g - a) + factor * u2 * (p - a);
    }
}

/// [`restricted_global`] with `u` the 32-bit uniforms of the stream words `words`
/// ([`unit_f64_32`]): the same values as [`fill_unit_f64_32`] then [`restricted_global`].
#[inline]
fn restricted_global_words(x: &[f64], rl: f64, words: &[u32], lower: &[f64], upper: &[f64], out: &mut [f64]) {
    let dim = out.len();
    let (x, words, lower, upper) = (&x[..dim], &words[..dim], &lower[..dim], &upper[..dim]);
    for d in 0..dim {
        let (a, lo, hi) = (x[d], lower[d], upper[d]);
        let target = lo + unit_f64_32(words[d]) * (hi - lo);
        out[d] = a + rl * (target - a);
    }
}

/// [`local_following`] with `u` from the stream words `words` ([`unit_f64_32`]).
#[inline]
fn local_following_words(x: &[f64], g: &[f64], p: &[f64], words: &[u32], out: &mut [f64]) {
    let dim = out.len();
    let (x, g, p, words) = (&x[..dim], &g[..dim], &p[..dim], &words[..dim]);
    for d in 0..dim {
        let a = x[d];
        out[d] = a + unit_f64_32(words[d]) * ((g[d] + p[d]) * 0.5 - a);
    }
}

/// [`memory_current`] with `u1`, `u2` from the stream words `w1`, `w2` ([`unit_f64_32`]).
#[inline]
fn memory_current_words(x: &[f64], g: &[f64], p: &[f64], factor: f64, w1: &[u32], w2: &[u32], out: &mut [f64]) {
    let dim = out.len();
    let (x, g, p, w1, w2) = (&x[..dim], &g[..dim], &p[..dim], &w1[..dim], &w2[..dim]);
    for d in 0..dim {
        let (a, u1, u2) = (x[d], unit_f64_32(w1[d]), unit_f64_32(w2[d]));
        out[d] = a + factor * u1 * (g[d] - a) + factor * u2 * (p[d] - a);
    }
}

/// `x`'s bits as an integer in `f64::total_cmp`'s order: `order_key(a) < order_key(b)` exactly
/// when `a.total_cmp(&b)` is `Less` (the sign bit flipped for positives, every bit for
/// negatives).
#[inline]
pub(crate) fn order_key(x: f64) -> u64 {
    let b = x.to_bits();
    b ^ (((b as i64 >> 63) as u64) | 1 << 63)
}

/// ijs2023's improved jellyfish search, built from checked parameters.
#[derive(Clone, Debug)]
pub struct Ijs {
    params: IjsParams,
    x: Population,
    cost: Vec<f64>,
    /// Personal bests X_p,i and their costs.
    memory: Population,
    memory_cost: Vec<f64>,
    /// The global best X_g and its cost.
    global: Vec<f64>,
    global_cost: f64,
    /// This iteration's candidates and their costs.
    cand: Population,
    cand_cost: Vec<f64>,
    /// Jellyfish indices by cost at the start of the iteration, best first.
    order: Vec<usize>,
    /// The ranking's sort keys ([`Ijs::rank`]): 64-bit, and 128-bit when those are not enough.
    short_keys: Vec<u64>,
    keys: Vec<u128>,
    /// A move's U(0, 1) draws, as the stream's 32-bit words ([`unit_f64_32`] converts them).
    w1: Vec<u32>,
    w2: Vec<u32>,
    /// Iterations started, for the iteration-based progress.
    iteration: u64,
}

impl Ijs {
    pub fn new(params: Checked<IjsParams>) -> Self {
        Self {
            params: params.into_inner(),
            x: Population::zeros(0, 0),
            cost: Vec::new(),
            memory: Population::zeros(0, 0),
            memory_cost: Vec::new(),
            global: Vec::new(),
            global_cost: f64::INFINITY,
            cand: Population::zeros(0, 0),
            cand_cost: Vec::new(),
            order: Vec::new(),
            short_keys: Vec::new(),
            keys: Vec::new(),
            w1: Vec::new(),
            w2: Vec::new(),
            iteration: 0,
        }
    }

    pub fn params(&self) -> &IjsParams {
        &self.params
    }

    /// The global best X_g and its cost.
    pub fn global_best(&self) -> (&[f64], f64) {
        (&self.global, self.global_cost)
    }

    /// Ranks the jellyfish by cost, best first; ties by index, NaN as +inf (costs compared
    /// by `total_cmp`). Sorted as integers: each jellyfish's cost in `total_cmp`'s order
    /// ([`order_key`]) in the high 64 bits, its index in the low, so one integer comparison
    /// is the whole test (a comparator that looks the costs up is several times slower).
    ///
    /// First tried with 64-bit keys, which sort faster: the cost's key with its low bits
    /// replaced by the index (as many bits as the largest index needs). That order is the
    /// full one unless two costs differ only in those low bits; so it is kept only if every
    /// neighbour pair is in the full order (then the sequence is sorted by the full keys,
    /// which are distinct, and so is the one ranking), else the 128-bit keys are sorted.
    fn rank(&mut self) {
        let cost_key = |c: f64| order_key(if c.is_nan() { f64::INFINITY } else { c });
        let n = self.cost.len();
        let bits = usize::BITS - n.saturating_sub(1).leading_zeros();
        let mask = (1u64 << bits) - 1;
        self.short_keys.clear();
        for (k, &c) in self.cost.iter().enumerate() {
            self.short_keys.push((cost_key(c) & !mask) | k as u64);
        }
        self.short_keys.sort_unstable();
        let cost = &self.cost;
        let in_full_order = self.short_keys.windows(2).all(|w| {
            let (i, j) = ((w[0] & mask) as usize, (w[1] & mask) as usize);
            let (a, b) = (cost_key(cost[i]), cost_key(cost[j]));
            a < b || (a == b && i < j)
        });
        if in_full_order {
            for (o, &key) in self.order.iter_mut().zip(&self.short_keys) {
                *o = (key & mask) as usize;
            }
            return;
        }
        self.keys.clear();
        for (k, &c) in self.cost.iter().enumerate() {
            self.keys.push((u128::from(cost_key(c)) << 64) | k as u128);
        }
        self.keys.sort_unstable();
        for (o, &key) in self.order.iter_mut().zip(&self.keys) {
            *o = key as u64 as usize;
        }
    }

    /// Algorithm 1's memory updates for jellyfish `i`, whose position was just evaluated.
    fn remember(&mut self, i: usize) {
        let f = self.cost[i];
        let old = self.memory_cost[i];
        if f <= old || (old.is_nan() && !f.is_nan()) {
            self.memory.copy_row_from(i, &self.x, i);
            self.memory_cost[i] = f;
        }
        let (p, g) = (self.memory_cost[i], self.global_cost);
        if p <= g || (g.is_nan() && !p.is_nan()) {
            self.global.copy_from_slice(self.memory.row(i));
            self.global_cost = p;
        }
    }
}

impl Optimizer for Ijs {
    fn id(&self) -> &'static str {
        "ijs"
    }

    fn population(&self) -> usize {
        self.params.population
    }

    fn init(&mut self, ctx: &mut Context<'_>) {
        let (n, dim) = (self.params.population, ctx.dim());
        self.iteration = 0;
        self.x = Population::initial(n, ctx);
        for i in 0..n {
            if i % POLL_JELLYFISH == 0 && ctx.should_stop() {
                break;
            }
            ctx.repair(self.x.row_mut(i));
        }
        self.cost = vec![f64::INFINITY; n];
        ctx.evaluate_population(&self.x, &mut self.cost);
        self.memory = self.x.clone();
        self.memory_cost = self.cost.clone();
        let b = best_index(&self.memory_cost);
        self.global = self.memory.row(b).to_vec();
        self.global_cost = self.memory_cost[b];
        self.cand = Population::zeros(n, dim);
        self.cand_cost = vec![f64::INFINITY; n];
        self.order = (0..n).collect();
        self.w1 = vec![0; dim];
        self.w2 = vec![0; dim];
    }

    fn step(&mut self, ctx: &mut Context<'_>) {
        let n = self.x.len();
        if n < 2 || ctx.exhausted() || ctx.should_stop() {
            return;
        }
        let rl = 1.0 - progress(ctx, self.iteration);
        self.iteration += 1;
        self.rank();
        let (factor, global_share) = (self.params.memory_factor, self.params.global_share);
        for k in 0..n {
            if k % POLL_JELLYFISH == 0 && k > 0 && ctx.should_stop() {
                return;
            }
            let i = self.order[k];
            let out = self.cand.row_mut(i);
            let (xi, pi) = (self.x.row(i), self.memory.row(i));
            let (rng, lower, upper) = ctx.rng_and_bounds();
            match group(k, n) {
                Group::Elite => {
                    let s = rng.random::<f64>();
                    fill_u32(rng, &mut self.w1);
                    // eq. 11's "rand ≥ 0.5" for the default share 0.5.
                    if s >= 1.0 - global_share {
                        restricted_global_words(xi, rl, &self.w1, lower, upper, out);
                    } else {
                        local_following_words(xi, &self.global, pi, &self.w1, out);
                    }
                }
                Group::Learning => {
                    let j = rng.random_range(0..n - 1);
                    let j = if j >= i { j + 1 } else { j };
                    fill_u32(rng, &mut self.w1);
                    active_words(xi, self.x.row(j), self.cost[j] < self.cost[i], &self.w1, out);
                }
                Group::Follower => {
                    fill_u32(rng, &mut self.w1);
                    fill_u32(rng, &mut self.w2);
                    memory_current_words(xi, &self.global, pi, factor, &self.w1, &self.w2, out);
                }
            }
            ctx.repair(out);
        }
        let before = ctx.evaluations();
        ctx.evaluate_population(&self.cand, &mut self.cand_cost);
        let evaluated = (ctx.evaluations() - before) as usize;
        if evaluated < n && ctx.should_stop() {
            // Interrupted: which rows were evaluated is not known here; the run ends.
            return;
        }
        if evaluated == n {
            // Every jellyfish takes its candidate: the populations trade places instead of
            // copying rows (this iteration's positions are overwritten by the next one's
            // candidates before they are read).
            std::mem::swap(&mut self.x, &mut self.cand);
            std::mem::swap(&mut self.cost, &mut self.cand_cost);
            for k in 0..n {
                self.remember(self.order[k]);
            }
            return;
        }
        // The budget ran out: the first `evaluated` rows.
        for k in 0..n {
            let i = self.order[k];
            if i >= evaluated {
                continue;
            }
            self.x.copy_row_from(i, &self.cand, i);
            self.cost[i] = self.cand_cost[i];
            self.remember(i);
        }
    }
}

#[cfg(test)]
mod tests;
