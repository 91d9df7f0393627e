//! Quantum-behaved particle swarm optimisation (QPSO), a baseline of ijs2023.
//!
//! Sun, Feng & Xu, "Particle swarm optimization with particles having quantum behavior"
//! (CEC 2004) replaced PSO's velocity by a sample around each particle's local attractor from
//! the δ potential well, x = p ± (L/2) ln(1/u). Sun, Xu & Feng, "A global search strategy of
//! quantum-behaved particle swarm optimization" (IEEE CIS 2004) set the well's width from the
//! mean of the personal bests, which is the form later called QPSO and the one ijs2023 (Guo et
//! al.) runs as its baseline (docs/papers/shared.md, "QPSO"). Per particle i and dimension d:
//!
//! ```text
//! mbest_d = (1/M) Σ_k pbest_kd                              mean of the M personal bests
//! p_id    = φ pbest_id + (1 − φ) gbest_d                    φ ~ U(0,1), per dimension
//! x_id   <- p_id ± β |mbest_d − x_id| ln(1/u)               u ~ U(0,1], + or − with prob. 1/2
//! β       = β_start + (β_end − β_start) t/T                 1.0 -> 0.5 over the run
//! ```
//!
//! Readings (not fixed by the papers or by ijs2023, which gives QPSO no parameters):
//! * **β (the contraction–expansion coefficient) falls linearly from 1.0 to 0.5 over the run**
//!   (`beta_start`, `beta_end`): the setting Sun et al. recommend for the mbest form (Sun,
//!   Fang, Wu, Palade & Xu, Evolutionary Computation 20(3), 2012), which docs/papers/ijs2023.md
//!   (Baselines, A13) chose for ijs2023's baseline, whose paper gives none. t/T is the run's
//!   progress ([`progress`], as FA's schedule reads it): evaluations used over the evaluation
//!   budget, else iterations completed over the iteration limit, taken at the start of each
//!   iteration; so the first iteration uses β_start and β reaches β_end at the end of the budget.
//! * **One φ per dimension, p = φ pbest + (1 − φ) gbest.** Sun, Feng & Xu 2004 write the
//!   attractor as (φ₁ pbest + φ₂ gbest)/(φ₁ + φ₂) with two random weights; the single
//!   φ ~ U(0,1) is the form of the later QPSO papers and of docs/papers/shared.md.
//! * **ln(1/u) with u in (0, 1)**: u has 32-bit resolution, (w + 1/2)/2³² for a 32-bit word w
//!   ([`fill_unit_f64_32`]), so u is never 0 and ln(1/u) is at most 22.9. It is computed as
//!   −ln u by [`neg_ln`], fdlibm's logarithm without its special cases (below 1 ulp, a pure
//!   function of u on every platform, and it vectorizes).
//! * **The sign**: one random bit per dimension, + for 0 and − for 1 (probability 1/2 each; a
//!   bit rather than a third uniform, which would take a third of an iteration's random words).
//! * **Synchronous update**: every particle moves with the mbest and gbest of the previous
//!   iteration, then the swarm is evaluated as one population; the personal bests are updated
//!   afterwards, greedily (a strictly lower cost, so an evaluation past the budget, +inf, or a
//!   NaN never replaces anything), and gbest is the best personal best (ties: the lower index).
//! * **Bounds**: a coordinate outside the box is clamped to the bound (QPSO has no velocity to
//!   reset), then the objective's own repair runs.
//! * **45 particles** (`population`): ijs2023's Np = 45 for every baseline
//!   (docs/papers/ijs2023.md, Baselines); `population = 40` is the PSO baselines' usual swarm.
//!
//! Random draws, in order, all before any particle moves: per iteration, particle by particle,
//! D values of φ then D of u at 32-bit resolution ([`fill_unit_f64_32`], two per word of the
//! stream); then the signs, particle by particle, ⌈D/64⌉ 64-bit words each, bit d mod 64 of word
//! ⌊d/64⌋ for dimension d. The initial swarm is [`Population::initial`]'s. The
//! population is evaluated with [`Context::evaluate_population`], so results do not depend on
//! the thread count.

use rand::Rng as _;

use super::fa::progress;
use super::MAX_POPULATION;
use super::{clamp, Context, Optimizer, Population};
use crate::params::{Bound, Checked, Range};
use crate::rng::fill_unit_f64_32;

/// The contraction–expansion coefficient's range: above about e^γ ≈ 1.78 (γ Euler's constant)
/// a particle diverges (Sun et al. 2012), so 2 is room enough.
const BETA_RANGE: Range = Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(2.0) };

crate::params! {
    /// QPSO parameters. Defaults: ijs2023's swarm (45) and the standard β schedule 1.0 -> 0.5.
    pub struct QpsoParams {
        /// Number of particles.
        population: usize = 45, Range::integer(2, MAX_POPULATION as u64), "ijs2023 Baselines (Np = 45)";
        /// Contraction–expansion coefficient β at the start of the run.
        beta_start: f64 = 1.0, BETA_RANGE, "Sun et al. 2012; ijs2023 Baselines";
        /// β at the end of the run, reached linearly in the run's progress (equal to
        /// beta_start: a constant β).
        beta_end: f64 = 0.5, BETA_RANGE, "Sun et al. 2012; ijs2023 Baselines";
    }
}

impl QpsoParams {
    /// β at progress `t/T` = `frac` (clamped to [0, 1]): β_start + (β_end − β_start) t/T.
    pub fn beta_at(&self, frac: f64) -> f64 {
        self.beta_start + (self.beta_end - self.beta_start) * frac.clamp(0.0, 1.0)
    }
}

/// −ln x for a positive normal `x` (here x = u in (0, 1]): fdlibm's `log` (e_log.c, as in musl
/// and Rust's `libm` crate; error below 1 ulp) without the branches for zero, negative,
/// subnormal, infinite and NaN input, and with the exponent turned into a float by bit
/// operations, so a loop of it vectorizes. A pure function of `x` on every platform (the
/// platform's own `ln` may differ in the last bit).
#[inline(always)]
pub(crate) fn neg_ln(x: f64) -> f64 {
    // fdlibm's constants, by their bits: ln 2 in two parts, and Lg1..Lg7 (6.666666666666735130e-01,
    // 3.999999999940941908e-01, 2.857142874366239149e-01, 2.222219843214978396e-01,
    // 1.818357216161805012e-01, 1.531383769920937332e-01, 1.479819860511658591e-01).
    const LN2_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000);
    const LN2_LO: f64 = f64::from_bits(0x3dea_39ef_3579_3c76);
    const LG1: f64 = f64::from_bits(0x3fe5_5555_5555_5593);
    const LG2: f64 = f64::from_bits(0x3fd9_9999_9997_fa04);
    const LG3: f64 = f64::from_bits(0x3fd2_4924_9422_9359);
    const LG4: f64 = f64::from_bits(0x3fcc_71c5_1d8e_78af);
    const LG5: f64 = f64::from_bits(0x3fc7_4664_96cb_03de);
    const LG6: f64 = f64::from_bits(0x3fc3_9a09_d078_c69f);
    const LG7: f64 = f64::from_bits(0x3fc2_f112_df3e_5244);
    // 2^52 as a double.
    const TWO52_BITS: u64 = 0x4330_0000_0000_0000;
    // x = 2^k m with m in [√2/2, √2): shift the exponent field so that a mantissa at or above
    // √2 carries into the next power of two (fdlibm's reduction on the high word).
    let ix = x.to_bits().wrapping_add((0x3ff0_0000u64 - 0x3fe6_a09e) << 32);
    // k + 1023 + 2^52 as a double, minus both: k exactly, without an integer conversion.
    let dk = f64::from_bits(TWO52_BITS | (ix >> 52)) - (4_503_599_627_370_496.0 + 1023.0);
    let m = f64::from_bits((ix & 0x000f_ffff_ffff_ffff) + (0x3fe6_a09eu64 << 32));
    let f = m - 1.0;
    let hfsq = 0.5 * f * f;
    let s = f / (2.0 + f);
    let z = s * s;
    let w = z * z;
    let t1 = w * (LG2 + w * (LG4 + w * LG6));
    let t2 = z * (LG1 + w * (LG3 + w * (LG5 + w * LG7)));
    let r = t2 + t1;
    -(s * (hfsq + r) + dk * LN2_LO - hfsq + f + dk * LN2_HI)
}

/// One particle's move: for each dimension d, with p = φ_d pbest_d + (1 − φ_d) gbest_d,
/// `x_d <- clamp(p ± beta |mbest_d − x_d| ln(1/u_d))`, − where `minus[d]` is 1, + where 0.
/// `ln_inv_u` holds the draws' ln(1/u_d), taken beforehand ([`neg_ln`]) in a loop of their own:
/// the logarithm is a long chain of dependent steps, and on its own a loop of it overlaps
/// more coordinates at once than the whole move would (measured on the overhead benchmark,
/// 60,000 evaluations of Rastrigin-30: 27.3 ms a run fused, 25.9 ms split).
#[allow(clippy::too_many_arguments)]
#[inline]
pub(crate) fn move_particle(
    x: &mut [f64],
    pbest: &[f64],
    gbest: &[f64],
    mbest: &[f64],
    beta: f64,
    phi: &[f64],
    ln_inv_u: &[f64],
    minus: &[u8],
    lower: &[f64],
    upper: &[f64],
) {
    let dim = x.len();
    let (pbest, gbest, mbest) = (&pbest[..dim], &gbest[..dim], &mbest[..dim]);
    let (phi, e, minus) = (&phi[..dim], &ln_inv_u[..dim], &minus[..dim]);
    let (lower, upper) = (&lower[..dim], &upper[..dim]);
    for d in 0..dim {
        let xd = x[d];
        // φ pbest + (1 − φ) gbest, one product fewer.
        let p = gbest[d] + phi[d] * (pbest[d] - gbest[d]);
        let spread = beta * (mbest[d] - xd).abs() * e[d];
        let step = if minus[d] != 0 { -spread } else { spread };
        x[d] = clamp(p + step, lower[d], upper[d]);
    }
}

/// Particles moved between two polls of the run's stop flag and deadline (a poll reads the
/// clock, about 25 ns; a move of a test function's particle in 30 dimensions costs about
/// 150). A costly objective's repair turns into the box clamp once the run is interrupted
/// ([`Context::repair`]), so the particles left before the next poll take no time.
const POLL_PARTICLES: usize = 16;

/// Each byte value's eight bits as eight bytes of 0 or 1, bit k in byte k.
const BIT_BYTES: [u64; 256] = {
    let mut t = [0u64; 256];
    let mut b = 0;
    while b < 256 {
        let mut k = 0;
        while k < 8 {
            t[b] |= ((b as u64 >> k) & 1) << (8 * k);
            k += 1;
        }
        b += 1;
    }
    t
};

/// The 64 bits of `w` as 64 bytes of 0 or 1, bit k in `out[k]`.
#[inline]
fn unpack_bits(w: u64, out: &mut [u8]) {
    for (k, chunk) in out[..64].chunks_exact_mut(8).enumerate() {
        chunk.copy_from_slice(&BIT_BYTES[(w >> (8 * k)) as usize & 0xff].to_le_bytes());
    }
}

/// Quantum-behaved PSO, built from checked parameters.
#[derive(Clone, Debug)]
pub struct Qpso {
    params: QpsoParams,
    x: Population,
    cost: Vec<f64>,
    pbest: Population,
    /// Personal best costs, NaN held as +inf (so a finite cost can replace it).
    pbest_cost: Vec<f64>,
    /// The index of the best personal best (gbest).
    g: usize,
    /// The mean of the personal bests.
    mbest: Vec<f64>,
    /// The current iteration's uniform draws: per particle, D of φ then D of u (reused, so a
    /// step does not allocate).
    r: Vec<f64>,
    /// The current iteration's sign bits: per particle, ⌈D/64⌉ words.
    sign_words: Vec<u64>,
    /// One particle's signs, unpacked, one byte per dimension (1: −), padded to whole words.
    minus: Vec<u8>,
    /// Iterations started, for the iteration-based progress.
    iteration: u64,
}

impl Qpso {
    pub fn new(params: Checked<QpsoParams>) -> Self {
        Self {
            params: params.into_inner(),
            x: Population::zeros(0, 0),
            cost: Vec::new(),
            pbest: Population::zeros(0, 0),
            pbest_cost: Vec::new(),
            g: 0,
            mbest: Vec::new(),
            r: Vec::new(),
            sign_words: Vec::new(),
            minus: Vec::new(),
            iteration: 0,
        }
    }

    pub fn params(&self) -> &QpsoParams {
        &self.params
    }

    /// Greedy personal bests after an evaluation of `self.x`, then gbest: the first index of
    /// the lowest personal best.
    fn update_bests(&mut self) {
        for i in 0..self.x.len() {
            if self.cost[i] < self.pbest_cost[i] {
                self.pbest_cost[i] = self.cost[i];
                self.pbest.copy_row_from(i, &self.x, i);
            }
        }
        let mut g = 0;
        for (i, &c) in self.pbest_cost.iter().enumerate() {
            if c < self.pbest_cost[g] {
                g = i;
            }
        }
        self.g = g;
    }

    /// mbest: the mean of the personal bests, summed in index order.
    fn update_mbest(&mut self) {
        self.mbest.fill(0.0);
        for row in self.pbest.rows() {
            for (m, &v) in self.mbest.iter_mut().zip(row) {
                *m += v;
            }
        }
        let n = self.pbest.len() as f64;
        for m in &mut self.mbest {
            *m /= n;
        }
    }
}

impl Optimizer for Qpso {
    fn id(&self) -> &'static str {
        "qpso"
    }

    fn population(&self) -> usize {
        self.params.population
    }

    fn init(&mut self, ctx: &mut Context<'_>) {
        let n = self.params.population;
        let dim = ctx.dim();
        (self.x, self.cost) = Population::initial_evaluated(n, ctx);
        self.pbest = self.x.clone();
        self.pbest_cost = self.cost.iter().map(|&c| if c.is_nan() { f64::INFINITY } else { c }).collect();
        self.mbest = vec![0.0; dim];
        self.r = vec![0.0; 2 * n * dim];
        self.sign_words = vec![0; n * dim.div_ceil(64)];
        self.minus = vec![0; 64 * dim.div_ceil(64)];
        self.iteration = 0;
        self.update_bests();
    }

    fn step(&mut self, ctx: &mut Context<'_>) {
        if self.x.is_empty() || ctx.exhausted() || ctx.should_stop() {
            return;
        }
        // t/T before this iteration's evaluations (its iteration count: iterations completed).
        let beta = self.params.beta_at(progress(ctx, self.iteration));
        self.iteration += 1;
        self.update_mbest();
        let (n, dim) = (self.x.len(), self.x.dim());
        fill_unit_f64_32(ctx.rng(), &mut self.r);
        ctx.rng().fill(&mut self.sign_words[..]);
        // Each u becomes ln(1/u), in place.
        for block in self.r.chunks_exact_mut(2 * dim) {
            for v in &mut block[dim..] {
                *v = neg_ln(*v);
            }
        }
        let gbest = self.pbest.row(self.g);
        let words = dim.div_ceil(64);
        for i in 0..n {
            if i % POLL_PARTICLES == 0 && i > 0 && ctx.should_stop() {
                return;
            }
            let (phi, ln_inv_u) = self.r[2 * i * dim..2 * (i + 1) * dim].split_at(dim);
            let signs = &self.sign_words[i * words..(i + 1) * words];
            for (&w, bytes) in signs.iter().zip(self.minus.chunks_exact_mut(64)) {
                unpack_bits(w, bytes);
            }
            let x = self.x.row_mut(i);
            move_particle(
                x,
                self.pbest.row(i),
                gbest,
                &self.mbest,
                beta,
                phi,
                ln_inv_u,
                &self.minus,
                ctx.lower(),
                ctx.upper(),
            );
            ctx.repair(x);
        }
        ctx.evaluate_population(&self.x, &mut self.cost);
        self.update_bests();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::optim::functions::{Function, FunctionObjective};
    use crate::optim::{run, test_support};
    use crate::rng::run_rng;
    use crate::termination::Termination;

    fn qpso(p: QpsoParams) -> Qpso {
        Qpso::new(p.checked("t").unwrap())
    }

    #[test]
    fn defaults_and_checks() {
        let p = QpsoParams::default();
        assert_eq!((p.population, p.beta_start, p.beta_end), (45, 1.0, 0.5));
        assert!(p.clone().checked("p").is_ok());
        let t: toml::Table = toml::from_str("beta_end = 1.0\npopulation = 20").unwrap();
        let q = QpsoParams::from_table(&t, "p").unwrap();
        assert_eq!(*q.get(), QpsoParams { population: 20, beta_end: 1.0, ..QpsoParams::default() });
        assert_eq!(*QpsoParams::from_table(&p.to_table(), "p").unwrap().get(), p);
        for bad in [
            QpsoParams { population: 1, ..p.clone() },
            QpsoParams { beta_start: 0.0, ..p.clone() },
            QpsoParams { beta_start: 2.5, ..p.clone() },
            QpsoParams { beta_end: f64::NAN, ..p.clone() },
            QpsoParams { beta_end: -0.5, ..p.clone() },
        ] {
            let e = bad.checked("planner.params.qpso").unwrap_err().to_string();
            assert!(e.starts_with("planner.params.qpso."), "{e}");
        }
        assert!(QpsoParams::from_table(&toml::from_str("alpha = 0.7").unwrap(), "p").is_err());
    }

    #[test]
    fn beta_schedule_by_hand() {
        let p = QpsoParams::default();
        assert_eq!((p.beta_at(0.0), p.beta_at(0.5), p.beta_at(1.0)), (1.0, 0.75, 0.5));
        assert_eq!((p.beta_at(-1.0), p.beta_at(2.0)), (1.0, 0.5));
        assert!((p.beta_at(0.3) - 0.85).abs() < 1e-15);
        let constant = QpsoParams { beta_start: 0.8, beta_end: 0.8, ..p };
        assert_eq!((constant.beta_at(0.0), constant.beta_at(0.7), constant.beta_at(1.0)), (0.8, 0.8, 0.8));
    }

    /// The schedule as a run sees it: β of iteration k (1-based) is β(t/T) with t the
    /// evaluations used before it (budget) or k − 1 (iteration limit).
    #[test]
    fn beta_follows_the_runs_progress() {
        let obj = FunctionObjective::new(Function::Sphere, 2, -1.0, 1.0);
        let p = QpsoParams { population: 4, ..QpsoParams::default() };
        let (mut rng, mut opt) = (run_rng(1, 0), qpso(p.clone()));
        let mut ctx = Context::new(&obj, &mut rng, Some(40), false, &[]);
        opt.init(&mut ctx);
        assert_eq!(progress(&ctx, 0), 0.1); // 4 of 40 evaluations
        assert!((p.beta_at(progress(&ctx, 0)) - 0.95).abs() < 1e-15);
        let term = Termination::iterations(10);
        let mut rng = run_rng(1, 0);
        let mut ctx = Context::new(&obj, &mut rng, None, false, &[]).with_termination(&term);
        opt.init(&mut ctx);
        assert_eq!((progress(&ctx, 0), progress(&ctx, 5), progress(&ctx, 10)), (0.0, 0.5, 1.0));
    }

    #[test]
    fn neg_ln_is_the_logarithm() {
        assert_eq!(neg_ln(1.0), 0.0);
        assert_eq!(neg_ln(0.5), std::f64::consts::LN_2);
        assert_eq!(neg_ln(0.25), 2.0 * std::f64::consts::LN_2);
        // Within an ulp or so of the platform's ln over (0, 1], including the 32-bit draws'
        // extremes and both sides of the reduction's split near √2/2 (and 1/4 of it).
        let mut rng = run_rng(4, 0);
        let mut u = vec![0.0; 100_000];
        fill_unit_f64_32(&mut rng, &mut u);
        let split = 0x3fe6_a09e_0000_0000u64;
        let edges = [
            0.5 / 4_294_967_296.0,
            1.0 - 0.5 / 4_294_967_296.0,
            f64::from_bits(split - 1),
            f64::from_bits(split),
            f64::from_bits(split - (2 << 52) - 1),
            f64::from_bits(split - (2 << 52)),
        ];
        for &x in u.iter().chain(&edges) {
            let (got, want) = (neg_ln(x), -x.ln());
            assert!((got - want).abs() <= 2.0 * f64::EPSILON * want.abs().max(f64::MIN_POSITIVE), "{x}: {got} {want}");
        }
        assert!((neg_ln(edges[0]) - 32.0 * std::f64::consts::LN_2 - 2f64.ln()).abs() < 1e-13);
    }

    #[test]
    fn sign_bits_unpack_in_order() {
        let mut out = [9u8; 64];
        let w = 0x8000_0000_0000_0105u64;
        unpack_bits(w, &mut out);
        for (k, &b) in out.iter().enumerate() {
            assert_eq!(b as u64, (w >> k) & 1, "{k}");
        }
    }

    /// The move with given random numbers, against hand-computed values.
    #[test]
    fn the_move_by_hand() {
        let ln2 = std::f64::consts::LN_2;
        let (lo, hi) = ([-10.0; 3], [10.0; 3]);
        let mut x = [1.0, -2.0, 0.5];
        let (pbest, gbest, mbest) = ([2.0, 0.0, 0.5], [0.0, 4.0, 0.5], [3.0, -1.0, 1.5]);
        // φ = 0.25, 0.5, 1; u = 1/2, 1/4, 1 (ln(1/u) = ln 2, ln 4, 0); signs +, −, +.
        let ln_inv_u = [neg_ln(0.5), neg_ln(0.25), neg_ln(1.0)];
        assert_eq!(ln_inv_u, [ln2, 2.0 * ln2, 0.0]);
        move_particle(&mut x, &pbest, &gbest, &mbest, 0.5, &[0.25, 0.5, 1.0], &ln_inv_u, &[0, 1, 0], &lo, &hi);
        // d0: p = 0.25·2 + 0.75·0 = 0.5; spread = 0.5·|3 − 1|·ln 2 = ln 2; x = 0.5 + ln 2.
        // d1: p = 0.5·0 + 0.5·4 = 2; spread = 0.5·|−1 + 2|·ln 4 = ln 2; x = 2 − ln 2.
        // d2: p = pbest = 0.5; u = 1: no spread; x = 0.5.
        assert_eq!(x, [0.5 + ln2, 2.0 - ln2, 0.5]);
        // Clamped to the box: p = 0, ln(1/u) = 2, spread = 1·8·2 = 16, + then −.
        let mut x = [4.0, -4.0];
        move_particle(
            &mut x,
            &[0.0; 2],
            &[0.0; 2],
            &[-4.0, 4.0],
            1.0,
            &[0.5; 2],
            &[2.0; 2],
            &[0, 1],
            &[-5.0; 2],
            &[5.0; 2],
        );
        assert_eq!(x, [5.0, -5.0]);
    }

    /// One iteration of three particles recomputed from the same random numbers: mbest, gbest,
    /// β = β(3/100), the moves, the evaluations and the greedy personal bests.
    #[test]
    fn an_iteration_matches_a_hand_computation() {
        let obj = FunctionObjective::new(Function::Sphere, 2, -3.0, 3.0);
        let mut opt = qpso(QpsoParams { population: 3, ..QpsoParams::default() });
        let mut rng = run_rng(11, 0);
        let mut ctx = Context::new(&obj, &mut rng, Some(100), false, &[]);
        opt.init(&mut ctx);
        let (x0, c0) = (opt.x.clone(), opt.cost.clone());
        let g = (0..3).fold(0, |g, i| if c0[i] < c0[g] { i } else { g });
        assert_eq!(opt.g, g);
        let mut twin = ctx.rng().clone();
        let (mut r, mut signs) = ([0.0; 12], [0u64; 3]);
        fill_unit_f64_32(&mut twin, &mut r);
        twin.fill(&mut signs[..]);
        opt.step(&mut ctx);
        assert_eq!(ctx.evaluations(), 6);
        let beta = 1.0 - 0.5 * 0.03;
        for i in 0..3 {
            for d in 0..2 {
                let mbest = (x0.row(0)[d] + x0.row(1)[d] + x0.row(2)[d]) / 3.0;
                let (phi, u, minus) = (r[4 * i + d], r[4 * i + 2 + d], signs[i] >> d & 1 == 1);
                let p = phi * x0.row(i)[d] + (1.0 - phi) * x0.row(g)[d];
                let l = beta * (mbest - x0.row(i)[d]).abs() * (1.0 / u).ln();
                let want = (if minus { p - l } else { p + l }).clamp(-3.0, 3.0);
                assert!((opt.x.row(i)[d] - want).abs() < 1e-12, "{i} {d}");
            }
            assert_eq!(opt.cost[i], Function::Sphere.value(opt.x.row(i)));
            let (better, kept) = (opt.cost[i] < c0[i], opt.pbest.row(i));
            assert_eq!(kept, if better { opt.x.row(i) } else { x0.row(i) });
            assert_eq!(opt.pbest_cost[i], opt.cost[i].min(c0[i]));
        }
        let best = (0..3).fold(0, |g, i| if opt.pbest_cost[i] < opt.pbest_cost[g] { i } else { g });
        assert_eq!(opt.g, best);
    }

    #[test]
    fn converges_on_sphere_and_stays_in_the_box() {
        let obj = FunctionObjective::new(Function::Sphere, 10, -5.12, 5.12);
        let mut opt = qpso(QpsoParams::default());
        let r = run(&mut opt, &obj, &Termination::evaluations(30_000), &mut run_rng(3, 0), false, &[], &mut |_| {});
        assert!(r.best_cost < 1e-8, "{}", r.best_cost);
        assert!(opt.x.rows().all(|x| x.iter().all(|v| (-5.12..=5.12).contains(v))));
        assert_eq!(opt.pbest_cost[opt.g], r.best_cost);
        // The default iteration limit drives the schedule without a budget.
        let mut opt = qpso(QpsoParams::default());
        let r = run(&mut opt, &obj, &Termination::iterations(200), &mut run_rng(3, 0), false, &[], &mut |_| {});
        assert!(r.best_cost < 1e-4, "{}", r.best_cost);
    }

    #[test]
    fn stops_exactly_at_the_evaluation_budget() {
        let obj = FunctionObjective::new(Function::Rastrigin, 7, -5.12, 5.12);
        test_support::assert_exact_budgets(&obj, &[1u64, 44, 45, 46, 1000, 3001], || {
            Box::new(qpso(QpsoParams::default()))
        });
    }

    #[test]
    fn same_seed_same_bits() {
        let obj = FunctionObjective::new(Function::Ackley, 10, -32.0, 32.0);
        test_support::assert_same_bits(&obj, || Box::new(qpso(QpsoParams::default())));
    }
}
