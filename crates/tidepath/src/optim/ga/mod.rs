//! Genetic algorithm with roulette-wheel selection, in two codings.
//!
//! The skeleton is Holland's / Goldberg's simple GA (Goldberg, "Genetic Algorithms in Search,
//! Optimization and Machine Learning", 1989, ch. 3): fitness-proportionate (roulette) selection
//! of parent pairs, crossover with probability `pc`, mutation, generational replacement, plus
//! elitism. The two codings reproduce the GA baselines of the papers (our readings in
//! docs/papers/wpa2017.md and docs/papers/shared.md#ga):
//!
//! * `coding = "real"` — wpa2017 (Zhang et al. 2017, Table 3: pc = 0.8, roulette, "random
//!   multi-point crossover"; the rest is our choice, docs/papers/wpa2017.md): population 50, two-point
//!   crossover with probability 0.8, each gene mutated with probability 1/D by a Gaussian step
//!   `N(0, (0.1 x range)^2)`, then clamped to the box.
//! * `coding = "binary"` — amfa2015 (Liu et al. 2015, section 5): 20 bits per variable, roulette,
//!   single-point crossover over the whole chromosome with pc = 0.6, bit-flip mutation with
//!   probability pm = 1/D applied to every bit (D = number of variables; "per bit" is our reading,
//!   docs/papers/shared.md#ga), population 40. Variable `v` decodes as
//!   `x_v = lo_v + (hi_v - lo_v) k_v / (2^bits - 1)`, `k_v` the plain (not Gray) binary integer
//!   of its bits, most significant bit first in the chromosome.
//!
//! Choices, documented again next to the code:
//! * Roulette for minimisation: `fitness_i = 1 / (1 + f_i - f_min)` with `f_min` the best cost
//!   of the current population, so the best individual has fitness 1 and the weights do not
//!   depend on the sign of the cost. A +inf (or NaN) cost has fitness 0; if every fitness is 0
//!   the parent is drawn uniformly.
//! * Elitism: the `elitism` best individuals (default 1) are copied unchanged into the next
//!   generation and are not re-evaluated; the other `population - elitism` are offspring, so a
//!   generation costs `population - elitism` evaluations.
//! * Parents are drawn with replacement (a parent may mate with itself). Each pair gives two
//!   children; the second child of the last pair is dropped when the count is odd.
//! * Two-point crossover (real): two distinct cut points among the `D - 1` gene boundaries; the
//!   genes between them are swapped. With `D = 2` it is one-point crossover; with `D = 1`
//!   crossover does nothing.
//! * Binary coding is Baldwinian: the chromosome is kept as is; the point evaluated (and
//!   reported) is its decoding after the objective's repair.
//! * Random draws per generation, in order: for each pair, parent a, parent b, the crossover
//!   test, the cut point(s) if crossing, then the mutation draws of child 1 and of child 2 (one
//!   U(0,1) per gene or bit, plus one standard normal after each real-coded hit).

use rand::Rng as _;
use rand_distr::StandardNormal;

use super::MAX_POPULATION;
use super::{Context, Optimizer, Population};
use crate::error::Result;
use crate::params::{field_error, Bound, Checked, Range, Word};
use crate::rng::{fill_unit_f64, Rng};

/// How a GA individual is coded.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum GaCoding {
    /// Real-valued genes (wpa2017).
    #[default]
    Real,
    /// `bits` bits per variable (amfa2015).
    Binary,
}

impl Word for GaCoding {
    const WORDS: &'static [(&'static str, Self)] = &[("real", GaCoding::Real), ("binary", GaCoding::Binary)];
}

crate::params::word_param!(GaCoding);

/// What the mutation probability applies to: amfa2015's "p_m = 1/n" can be read either way
/// (docs/papers/amfa2015.md A8).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum MutationScope {
    /// Each gene (real) or bit (binary) mutates with probability `mutation_rate`.
    #[default]
    Gene,
    /// Each child mutates with probability `mutation_rate`; a mutated child has one gene
    /// (real) or one bit (binary), drawn uniformly, mutated.
    Chromosome,
}

impl Word for MutationScope {
    const WORDS: &'static [(&'static str, Self)] =
        &[("gene", MutationScope::Gene), ("chromosome", MutationScope::Chromosome)];
}

crate::params::word_param!(MutationScope);

crate::params! {
    /// GA parameters. Defaults: wpa2017's real-coded GA.
    pub struct GaParams {
        /// Real-valued genes or bit strings.
        coding: GaCoding = GaCoding::Real, Range::Choice(&["real", "binary"]), "wpa2017 (real), amfa2015 (binary)";
        /// Population size.
        population: usize = 50, Range::integer(2, MAX_POPULATION as u64), "wpa2017 Table 3";
        /// Probability that a parent pair is crossed.
        crossover_rate: f64 = 0.8, Range::closed(0.0, 1.0), "wpa2017 Table 3";
        /// Mutation probability per gene (real) or per bit (binary); absent: 1/D with D the
        /// number of variables.
        mutation_rate: Option<f64> = None, Range::closed(0.0, 1.0), "docs/papers/shared.md#ga";
        /// Whether `mutation_rate` applies per gene or bit ("gene") or per child
        /// ("chromosome": one gene or bit of a mutated child changes).
        mutation_scope: MutationScope = MutationScope::Gene, Range::Choice(&["gene", "chromosome"]), "docs/papers/amfa2015.md A8";
        /// Bits per variable for the binary coding (ignored by the real coding).
        bits: u32 = 20, Range::integer(1, 52), "amfa2015 section 5";
        /// Best individuals copied unchanged; below the population.
        elitism: usize = 1, Range::integer(0, MAX_POPULATION as u64 - 1), "tidepath";
        /// Gaussian mutation step as a fraction of the box width (real coding).
        sigma_fraction: f64 = 0.1, Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded }, "tidepath";
    }
    check = check_elitism;
}

/// Elitism keeps fewer individuals than the population holds.
fn check_elitism(p: &GaParams, prefix: &str) -> Result<()> {
    if p.elitism >= p.population {
        return Err(field_error(
            prefix,
            "elitism",
            format!("must be below population ({}), got {}", p.population, p.elitism),
        ));
    }
    Ok(())
}

impl GaParams {
    /// wpa2017 (our reading, docs/papers/wpa2017.md): real coding, 50 individuals, two-point crossover with
    /// pc = 0.8, Gaussian mutation with probability 1/D and sigma = 0.1 x range, elitism 1.
    pub fn wpa2017() -> Self {
        Self {
            coding: GaCoding::Real,
            population: 50,
            crossover_rate: 0.8,
            mutation_rate: None,
            mutation_scope: MutationScope::Gene,
            bits: 20,
            elitism: 1,
            sigma_fraction: 0.1,
        }
    }

    /// amfa2015: binary coding with 20 bits per variable, 40 individuals, single-point
    /// crossover with pc = 0.6, bit-flip mutation with pm = 1/D per bit, elitism 1 (Chosen).
    pub fn amfa2015() -> Self {
        Self {
            coding: GaCoding::Binary,
            population: 40,
            crossover_rate: 0.6,
            mutation_rate: None,
            mutation_scope: MutationScope::Gene,
            bits: 20,
            elitism: 1,
            sigma_fraction: 0.1,
        }
    }
}

impl GaParams {
    /// amfa2015's GA under the second reading of "p_m = 1/n": 1/(20 D) per bit, about one
    /// flip per chromosome on average (docs/papers/amfa2015.md A8).
    pub fn amfa2015_per_bit_small(dim: usize) -> Self {
        Self { mutation_rate: Some(1.0 / (dim.max(1) as f64 * 20.0)), ..Self::amfa2015() }
    }

    /// amfa2015's GA under the third reading: each chromosome mutates with probability 1/D,
    /// one random bit flipped (docs/papers/amfa2015.md A8).
    pub fn amfa2015_per_chromosome() -> Self {
        Self { mutation_scope: MutationScope::Chromosome, ..Self::amfa2015() }
    }
}

/// Roulette weights for minimisation: `1 / (1 + f_i - f_min)` with `f_min` the lowest cost in
/// `costs`; +inf and NaN costs get 0 (as does any cost whose difference to `f_min` overflows).
/// Never produces NaN.
pub fn roulette_fitness(costs: &[f64], out: &mut [f64]) {
    let f_min = costs.iter().copied().filter(|c| !c.is_nan()).fold(f64::INFINITY, f64::min);
    for (o, &c) in out.iter_mut().zip(costs) {
        *o = if c.is_nan() || c == f64::INFINITY {
            0.0
        } else if c == f_min {
            1.0
        } else {
            // f_min is finite or -inf here; c > f_min, so the denominator is > 1 or +inf.
            1.0 / (1.0 + (c - f_min))
        };
    }
}

/// One spin of the wheel given cumulative weights `cum` (non-decreasing, last = total).
/// A zero total picks uniformly. Draws exactly one number from `rng`.
fn spin(cum: &[f64], rng: &mut Rng) -> usize {
    let n = cum.len();
    let total = cum[n - 1];
    if total > 0.0 && total.is_finite() {
        let u = rng.random::<f64>() * total;
        let i = cum.partition_point(|&c| c <= u);
        if i < n {
            i
        } else {
            // u rounded up to the total: take the last individual with positive weight.
            cum.iter().rposition(|&c| c < total).map_or(0, |k| k + 1).min(n - 1)
        }
    } else {
        rng.random_range(0..n)
    }
}

/// `x`'s place in the order of [`f64::total_cmp`], as an unsigned integer.
fn total_order_key(x: f64) -> u64 {
    let b = x.to_bits() as i64;
    ((b ^ ((((b >> 63) as u64) >> 1) as i64)) as u64) ^ (1 << 63)
}

/// Reorders `order` (a permutation of the individuals) by cost, NaN counting as +inf: the
/// result of a stable sort of `order` by `total_cmp` of the costs (so tied individuals keep
/// their relative place in `order`, which holds the previous generation's ranking). It is
/// done as an unstable sort of integer keys (cost, place) in `keys`, which is the same order
/// because no two keys are equal, without the comparison closure's cost. Places and indices
/// take 32 bits each (populations are at most `MAX_POPULATION`, far below 2^32).
fn rank(order: &mut [usize], cost: &[f64], keys: &mut Vec<u128>) {
    keys.clear();
    keys.extend(order.iter().enumerate().map(|(place, &i)| {
        let c = if cost[i].is_nan() { f64::INFINITY } else { cost[i] };
        (u128::from(total_order_key(c)) << 64) | ((place as u128) << 32) | i as u128
    }));
    keys.sort_unstable();
    for (o, &k) in order.iter_mut().zip(keys.iter()) {
        *o = (k as u32) as usize;
    }
}

/// Decodes a `bits`-bit integer to `[lo, hi]`.
pub fn decode(k: u64, bits: u32, lo: f64, hi: f64) -> f64 {
    let full = ((1u64 << bits) - 1) as f64;
    lo + (hi - lo) * (k as f64 / full)
}

/// Single-point crossover of two chromosomes of `bits`-bit words (most significant bit first)
/// at bit position `cut` (bits `< cut` come from the first parent).
fn one_point_bits(a: &mut [u64], b: &mut [u64], bits: u32, cut: usize) {
    let bits_us = bits as usize;
    let full = (1u64 << bits) - 1;
    for v in 0..a.len() {
        let start = v * bits_us;
        if start + bits_us <= cut {
            continue;
        }
        if start >= cut {
            std::mem::swap(&mut a[v], &mut b[v]);
            continue;
        }
        // The top `cut - start` bits stay, the rest are exchanged.
        let low = (1u64 << (bits_us - (cut - start))) - 1;
        let hi_mask = full & !low;
        let (na, nb) = ((a[v] & hi_mask) | (b[v] & low), (b[v] & hi_mask) | (a[v] & low));
        a[v] = na;
        b[v] = nb;
    }
}

/// The genetic algorithm. Construct with [`Ga::new`]; the parameters should pass
/// [`GaParams::check`].
#[derive(Clone, Debug)]
pub struct Ga {
    params: GaParams,
    pm: f64,
    sigma: Vec<f64>,
    /// Phenotypes (the evaluated points) and their costs.
    x: Population,
    cost: Vec<f64>,
    /// Binary chromosomes, `dim` words per individual (empty for the real coding).
    chrom: Vec<u64>,
    next_x: Population,
    next_cost: Vec<f64>,
    next_chrom: Vec<u64>,
    off_x: Population,
    off_cost: Vec<f64>,
    off_chrom: Vec<u64>,
    order: Vec<usize>,
    cum: Vec<f64>,
    /// The dropped second child of an odd offspring count.
    cb: Vec<f64>,
    ka: Vec<u64>,
    kb: Vec<u64>,
    /// Copies of the box, so mutation reads them while drawing from the run's stream.
    lower: Vec<f64>,
    upper: Vec<f64>,
    /// One binary child's mutation draws, one per bit.
    bit_draws: Vec<f64>,
    /// Sort keys for the elitism ranking (see [`rank`]).
    rank_keys: Vec<u128>,
}

impl Ga {
    pub fn new(params: Checked<GaParams>) -> Self {
        Self {
            params: params.into_inner(),
            pm: 0.0,
            sigma: Vec::new(),
            x: Population::zeros(0, 0),
            cost: Vec::new(),
            chrom: Vec::new(),
            next_x: Population::zeros(0, 0),
            next_cost: Vec::new(),
            next_chrom: Vec::new(),
            off_x: Population::zeros(0, 0),
            off_cost: Vec::new(),
            off_chrom: Vec::new(),
            order: Vec::new(),
            cum: Vec::new(),
            cb: Vec::new(),
            ka: Vec::new(),
            kb: Vec::new(),
            lower: Vec::new(),
            upper: Vec::new(),
            bit_draws: Vec::new(),
            rank_keys: Vec::new(),
        }
    }

    pub fn params(&self) -> &GaParams {
        &self.params
    }

    fn binary(&self) -> bool {
        self.params.coding == GaCoding::Binary
    }

    /// Gaussian mutation of a real-coded child, then clamp to the box (`bounds`: lower, upper).
    fn mutate_real(
        child: &mut [f64],
        pm: f64,
        scope: MutationScope,
        sigma: &[f64],
        bounds: (&[f64], &[f64]),
        rng: &mut Rng,
    ) {
        let n = child.len();
        if scope == MutationScope::Chromosome {
            // One U(0,1) for the child; when it mutates, the gene, then its normal step.
            if rng.random::<f64>() < pm && n > 0 {
                let d = rng.random_range(0..n);
                let z: f64 = rng.sample(StandardNormal);
                child[d] = (child[d] + sigma[d] * z).clamp(bounds.0[d], bounds.1[d]);
            }
            return;
        }
        let (sigma, lower, upper) = (&sigma[..n], &bounds.0[..n], &bounds.1[..n]);
        for d in 0..n {
            let u: f64 = rng.random();
            if u < pm {
                let z: f64 = rng.sample(StandardNormal);
                child[d] = (child[d] + sigma[d] * z).clamp(lower[d], upper[d]);
            }
        }
    }

    /// Bit-flip mutation: one U(0,1) per bit, most significant bit of variable 0 first. The
    /// draws go through `u` (one per bit of `child`), drawn in bulk.
    fn mutate_bits(child: &mut [u64], pm: f64, scope: MutationScope, bits: u32, u: &mut [f64], rng: &mut Rng) {
        if scope == MutationScope::Chromosome {
            // One U(0,1) for the child; when it mutates, the bit (0 = variable 0's most
            // significant bit).
            let len = child.len() * bits as usize;
            if rng.random::<f64>() < pm && len > 0 {
                let b = rng.random_range(0..len);
                child[b / bits as usize] ^= 1u64 << (bits as usize - 1 - b % bits as usize);
            }
            return;
        }
        fill_unit_f64(rng, u);
        for (word, u) in child.iter_mut().zip(u.chunks_exact(bits as usize)) {
            for (j, &u) in (0..bits).rev().zip(u) {
                *word ^= u64::from(u < pm) << j;
            }
        }
    }

    /// Writes the repaired decoding of `chrom` into `x`.
    fn decode_into(chrom: &[u64], bits: u32, x: &mut [f64], ctx: &Context<'_>) {
        for (d, (xv, &k)) in x.iter_mut().zip(chrom).enumerate() {
            *xv = decode(k, bits, ctx.lower()[d], ctx.upper()[d]);
        }
        ctx.repair(x);
    }
}

impl Optimizer for Ga {
    fn id(&self) -> &'static str {
        "ga"
    }

    fn population(&self) -> usize {
        self.params.population
    }

    fn init(&mut self, ctx: &mut Context<'_>) {
        let n = self.params.population;
        let dim = ctx.dim();
        let m = n - self.params.elitism.min(n - 1);
        self.pm = self.params.mutation_rate.unwrap_or(1.0 / dim.max(1) as f64);
        self.sigma = (0..dim).map(|d| self.params.sigma_fraction * ctx.range(d)).collect();
        if self.binary() {
            let bits = self.params.bits;
            let full = (1u64 << bits) - 1;
            self.chrom = (0..n * dim).map(|_| ctx.rng().random::<u64>() & full).collect();
            // Warm start: the nearest chromosome to each seed point, in the first rows.
            let k = ctx.seeds().len().min((n / 2).max(1));
            for i in 0..k {
                for d in 0..dim {
                    let (lo, hi) = (ctx.lower()[d], ctx.upper()[d]);
                    let u = if hi > lo { ((ctx.seeds()[i][d] - lo) / (hi - lo)).clamp(0.0, 1.0) } else { 0.0 };
                    self.chrom[i * dim + d] = (u * full as f64).round() as u64 & full;
                }
            }
            self.x = Population::zeros(n, dim);
            for i in 0..n {
                Self::decode_into(&self.chrom[i * dim..(i + 1) * dim], bits, self.x.row_mut(i), ctx);
            }
            self.next_chrom = vec![0; n * dim];
            self.off_chrom = vec![0; m * dim];
            self.ka = vec![0; dim];
            self.kb = vec![0; dim];
            self.bit_draws = vec![0.0; dim * bits as usize];
        } else {
            self.x = Population::initial(n, ctx);
            for i in 0..n {
                ctx.repair(self.x.row_mut(i));
            }
        }
        self.cost = vec![f64::INFINITY; n];
        ctx.evaluate_population(&self.x, &mut self.cost);
        self.next_x = Population::zeros(n, dim);
        self.next_cost = vec![f64::INFINITY; n];
        self.off_x = Population::zeros(m, dim);
        self.off_cost = vec![f64::INFINITY; m];
        self.order = (0..n).collect();
        self.cum = vec![0.0; n];
        self.cb = vec![0.0; dim];
        self.lower = ctx.lower().to_vec();
        self.upper = ctx.upper().to_vec();
        self.rank_keys = Vec::with_capacity(n);
    }

    fn step(&mut self, ctx: &mut Context<'_>) {
        let n = self.x.len();
        let dim = self.x.dim();
        let elites = self.params.elitism.min(n - 1);
        let m = n - elites;
        let bits = self.params.bits;
        let pc = self.params.crossover_rate;
        let pm = self.pm;
        let scope = self.params.mutation_scope;
        let binary = self.binary();

        // Rank (NaN last) for elitism.
        rank(&mut self.order, &self.cost, &mut self.rank_keys);

        // Roulette weights (see `roulette_fitness`), accumulated in place.
        roulette_fitness(&self.cost, &mut self.cum);
        let mut acc = 0.0;
        for c in &mut self.cum {
            acc += *c;
            *c = acc;
        }

        // Offspring: pairs of roulette-selected parents, crossover, mutation, repair.
        let mut k = 0;
        while k < m {
            let a = spin(&self.cum, ctx.rng());
            let b = spin(&self.cum, ctx.rng());
            let cross = ctx.rng().random::<f64>() < pc;
            let second = k + 1 < m;
            if binary {
                self.ka.copy_from_slice(&self.chrom[a * dim..(a + 1) * dim]);
                self.kb.copy_from_slice(&self.chrom[b * dim..(b + 1) * dim]);
                let len = dim * bits as usize;
                if cross && len >= 2 {
                    let cut = ctx.rng().random_range(1..len);
                    one_point_bits(&mut self.ka, &mut self.kb, bits, cut);
                }
                Self::mutate_bits(&mut self.ka, pm, scope, bits, &mut self.bit_draws, ctx.rng());
                self.off_chrom[k * dim..(k + 1) * dim].copy_from_slice(&self.ka);
                Self::decode_into(&self.ka, bits, self.off_x.row_mut(k), ctx);
                if second {
                    Self::mutate_bits(&mut self.kb, pm, scope, bits, &mut self.bit_draws, ctx.rng());
                    self.off_chrom[(k + 1) * dim..(k + 2) * dim].copy_from_slice(&self.kb);
                    Self::decode_into(&self.kb, bits, self.off_x.row_mut(k + 1), ctx);
                }
            } else {
                // The children are built in their offspring rows (the dropped second child of
                // an odd count in `cb`).
                let (ca, cb) =
                    if second { self.off_x.two_rows_mut(k, k + 1) } else { (self.off_x.row_mut(k), &mut self.cb[..]) };
                ca.copy_from_slice(self.x.row(a));
                cb.copy_from_slice(self.x.row(b));
                if cross && dim >= 2 {
                    // Two distinct cut points among the D - 1 gene boundaries 1..D.
                    let (lo, hi) = if dim == 2 {
                        (1, 2)
                    } else {
                        let p = ctx.rng().random_range(1..dim);
                        let mut q = ctx.rng().random_range(1..dim - 1);
                        if q >= p {
                            q += 1;
                        }
                        (p.min(q), p.max(q))
                    };
                    ca[lo..hi].swap_with_slice(&mut cb[lo..hi]);
                }
                let bounds = (&self.lower[..], &self.upper[..]);
                Self::mutate_real(ca, pm, scope, &self.sigma, bounds, ctx.rng());
                ctx.repair(ca);
                if second {
                    Self::mutate_real(cb, pm, scope, &self.sigma, bounds, ctx.rng());
                    ctx.repair(cb);
                }
            }
            k += 2;
        }

        ctx.evaluate_population(&self.off_x, &mut self.off_cost);

        // Next generation: the elites unchanged (not re-evaluated), then the offspring.
        for (slot, &e) in self.order[..elites].iter().enumerate() {
            self.next_x.copy_row_from(slot, &self.x, e);
            self.next_cost[slot] = self.cost[e];
            if binary {
                self.next_chrom[slot * dim..(slot + 1) * dim].copy_from_slice(&self.chrom[e * dim..(e + 1) * dim]);
            }
        }
        self.next_x.as_flat_mut()[elites * dim..].copy_from_slice(self.off_x.as_flat());
        self.next_cost[elites..].copy_from_slice(&self.off_cost);
        if binary {
            self.next_chrom[elites * dim..].copy_from_slice(&self.off_chrom);
        }
        std::mem::swap(&mut self.x, &mut self.next_x);
        std::mem::swap(&mut self.cost, &mut self.next_cost);
        std::mem::swap(&mut self.chrom, &mut self.next_chrom);
    }
}

#[cfg(test)]
mod tests;
