//! Lévy-flight steps by Mantegna's algorithm, shared by HHO ([`super::hho`]) and MPA
//! ([`super::mpa`]).
//!
//! Mantegna, "Fast, accurate algorithm for numerical simulation of Lévy stable stochastic
//! processes" (Phys. Rev. E 49, 1994), in the form both papers print (Heidari et al. 2019,
//! eq. 9; Faramarzi et al. 2020, eqs. 4–5) and both authors' MATLAB codes run:
//!
//! ```text
//! σ  = ( Γ(1+β) sin(πβ/2) / ( Γ((1+β)/2) β 2^((β−1)/2) ) )^(1/β)     (σ = 0.696575 at β = 1.5)
//! u ~ N(0, σ²),  v ~ N(0, 1)
//! step = scale · u / |v|^(1/β)
//! ```
//!
//! `scale` is 0.01 in HHO's eq. 9 and 0.05 in MPA's code (`RL = 0.05*levy(...)`). Random
//! draws, in order, per step: u's standard normal, then v's (rand_distr's `StandardNormal`),
//! from the run's stream. A v of exactly 0 (probability about 2⁻⁵³) gives a step of 0 instead
//! of an infinite one, so a position never becomes infinite or NaN.

use rand::Rng as _;
use rand_distr::StandardNormal;

use crate::rng::Rng;

/// The Lévy exponent β both papers use.
pub const BETA: f64 = 1.5;

/// Γ(x) for x > 0: Lanczos' approximation (g = 7, nine coefficients), relative error below
/// 1e-14 on (0, 10]; enough for σ, which needs Γ at 1 + β and (1 + β)/2.
pub fn gamma(x: f64) -> f64 {
    const G: f64 = 7.0;
    const C: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        // Reflection: Γ(x) Γ(1 − x) = π / sin(πx).
        return std::f64::consts::PI / ((std::f64::consts::PI * x).sin() * gamma(1.0 - x));
    }
    let x = x - 1.0;
    let mut a = C[0];
    let t = x + G + 0.5;
    for (k, &c) in C.iter().enumerate().skip(1) {
        a += c / (x + k as f64);
    }
    (2.0 * std::f64::consts::PI).sqrt() * t.powf(x + 0.5) * (-t).exp() * a
}

/// The cube root of `a` ≥ 0, within 2 ulp of `f64::cbrt`: a first guess from the exponent
/// bits (musl's, good to about 3 %), two Halley steps (cubic convergence: about 1e-5, then
/// 1e-14) and one Newton step. Only IEEE additions, multiplications and divisions, so the same bits
/// on every machine. Zero, subnormal, infinite and NaN inputs go to `f64::cbrt`.
#[inline]
pub fn cbrt(a: f64) -> f64 {
    if !cbrt_is_fast(a) {
        return a.cbrt();
    }
    cbrt_normal(a)
}

/// Whether [`cbrt`] takes its own steps for `a` (a positive normal number), not `f64::cbrt`.
#[inline(always)]
fn cbrt_is_fast(a: f64) -> bool {
    (f64::MIN_POSITIVE..f64::INFINITY).contains(&a)
}

/// [`cbrt`]'s steps for a positive normal `a`, without a branch (so a loop of it vectorizes);
/// any other `a` gives a meaningless number.
#[inline(always)]
fn cbrt_normal(a: f64) -> f64 {
    let mut y = cbrt_guess(a);
    for _ in 0..2 {
        y = cbrt_halley(y, a);
    }
    cbrt_newton(y, a)
}

/// [`cbrt`]'s first guess from the exponent bits of `a` (positive normal). `hi / 3` for the
/// high word `hi` < 2^32 is taken as `hi · 0xAAAAAAAB >> 33`, the same integer (the compiler's
/// own division by 3 in 32 bits), in a product that vector units have.
#[inline(always)]
fn cbrt_guess(a: f64) -> f64 {
    // musl's B1 = (1023 − 1023/3 − 0.03306235651) · 2^20 on the high word.
    const B1: u64 = 715_094_163;
    let hi = a.to_bits() >> 32;
    f64::from_bits((((hi * 0xAAAA_AAAB) >> 33) + B1) << 32)
}

/// One of [`cbrt`]'s Halley steps from `y` toward the cube root of `a`.
#[inline(always)]
fn cbrt_halley(y: f64, a: f64) -> f64 {
    let y3 = y * y * y;
    y * ((y3 + 2.0 * a) / (2.0 * y3 + a))
}

/// [`cbrt`]'s closing Newton step.
#[inline(always)]
fn cbrt_newton(y: f64, a: f64) -> f64 {
    y - (y * y * y - a) / (3.0 * y * y)
}

/// Mantegna's σ_u for exponent `beta`.
pub fn mantegna_sigma(beta: f64) -> f64 {
    let num = gamma(1.0 + beta) * (std::f64::consts::PI * beta / 2.0).sin();
    let den = gamma((1.0 + beta) / 2.0) * beta * 2f64.powf((beta - 1.0) / 2.0);
    (num / den).powf(1.0 / beta)
}

/// A Lévy-step generator: β, its σ and the step's scale, computed once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Levy {
    beta: f64,
    sigma: f64,
    scale: f64,
}

impl Levy {
    /// Steps of exponent `beta` (Mantegna's algorithm holds for 0.3 ≤ β ≤ 1.99) times `scale`.
    pub fn new(beta: f64, scale: f64) -> Self {
        Self { beta, sigma: mantegna_sigma(beta), scale }
    }

    pub fn sigma(&self) -> f64 {
        self.sigma
    }

    /// The step for the standard normals `z_u` (u = σ z_u) and `v`: a pure function, for tests.
    #[inline]
    pub fn step_from(&self, z_u: f64, v: f64) -> f64 {
        if v == 0.0 {
            return 0.0;
        }
        let av = v.abs();
        // |v|^(2/3) as a cube root at β = 1.5 (the library's cube root and power cost about
        // 40 ns, more than the rest of a step).
        let d = if self.beta == BETA { cbrt(av * av) } else { av.powf(1.0 / self.beta) };
        self.scale * self.sigma * z_u / d
    }

    /// `out[k]` = [`Levy::step_from`]`(z[2k], z[2k + 1])`, the same bits. At β = 1.5 every
    /// step is first computed without a branch (a loop that vectorizes: the steps' divisions
    /// overlap), then the rare ones the branches would have handled otherwise (v = 0, or |v|²
    /// not a positive normal number) are recomputed one by one.
    pub fn steps_from(&self, z: &[f64], out: &mut [f64]) {
        let z = &z[..2 * out.len()];
        if self.beta != BETA {
            for (o, p) in out.iter_mut().zip(z.chunks_exact(2)) {
                *o = self.step_from(p[0], p[1]);
            }
            return;
        }
        // step_from's `scale · σ · z_u / d` multiplies left to right: (scale σ) z_u.
        let factor = self.scale * self.sigma;
        let mut rare = false;
        // The cube roots a stage at a time over a block of steps: each stage's loop has short,
        // independent iterations, so the divisions of many steps overlap (in one loop of the
        // whole chain, each step waits on four divisions in a row).
        const BLOCK: usize = 32;
        let (mut a, mut y) = ([0.0f64; BLOCK], [0.0f64; BLOCK]);
        for (zb, ob) in z.chunks(2 * BLOCK).zip(out.chunks_mut(BLOCK)) {
            let (a, y) = (&mut a[..ob.len()], &mut y[..ob.len()]);
            for ((a, y), p) in a.iter_mut().zip(y.iter_mut()).zip(zb.chunks_exact(2)) {
                let av = p[1].abs();
                *a = av * av;
                *y = cbrt_guess(*a);
                rare |= !cbrt_is_fast(*a) | (p[1] == 0.0);
            }
            for _ in 0..2 {
                for (y, &a) in y.iter_mut().zip(a.iter()) {
                    *y = cbrt_halley(*y, a);
                }
            }
            for (y, &a) in y.iter_mut().zip(a.iter()) {
                *y = cbrt_newton(*y, a);
            }
            for ((o, p), &d) in ob.iter_mut().zip(zb.chunks_exact(2)).zip(y.iter()) {
                *o = factor * p[0] / d;
            }
        }
        if rare {
            for (o, p) in out.iter_mut().zip(z.chunks_exact(2)) {
                let av = p[1].abs();
                if !cbrt_is_fast(av * av) || p[1] == 0.0 {
                    *o = self.step_from(p[0], p[1]);
                }
            }
        }
    }

    /// One step: two standard normals from `rng` (u's, then v's).
    #[inline]
    pub fn sample(&self, rng: &mut Rng) -> f64 {
        let z_u: f64 = rng.sample(StandardNormal);
        let v: f64 = rng.sample(StandardNormal);
        self.step_from(z_u, v)
    }

    /// `out.len()` steps, in order: the same values as `out.len()` calls of
    /// [`Levy::sample`]. The normals of a chunk are drawn first and the steps computed after,
    /// so the steps' divisions overlap instead of waiting on the generator one by one.
    pub fn fill(&self, rng: &mut Rng, out: &mut [f64]) {
        const CHUNK: usize = 32;
        let mut z = [0.0f64; 2 * CHUNK];
        for chunk in out.chunks_mut(CHUNK) {
            let z = &mut z[..2 * chunk.len()];
            fill_standard_normal(rng, z);
            self.steps_from(z, chunk);
        }
    }
}

/// Fills `out` with standard normal draws (rand_distr's `StandardNormal`), in order: MPA's
/// Brownian steps R_B.
pub fn fill_standard_normal(rng: &mut Rng, out: &mut [f64]) {
    for o in out {
        *o = rng.sample(StandardNormal);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::run_rng;

    #[test]
    fn gamma_by_hand() {
        let sqrt_pi = std::f64::consts::PI.sqrt();
        for (x, want) in [
            (1.0, 1.0),
            (2.0, 1.0),
            (5.0, 24.0),
            (0.5, sqrt_pi),
            (2.5, 0.75 * sqrt_pi),
            (1.25, 0.906_402_477_055_477),
            (0.25, 3.625_609_908_221_908),
        ] {
            assert!((gamma(x) - want).abs() < 1e-13 * want, "Γ({x}) = {} not {want}", gamma(x));
        }
    }

    /// σ at β = 1.5 by hand: Γ(2.5) = 0.75 √π = 1.329340, sin(0.75π) = 0.707107, Γ(1.25) =
    /// 0.906402, 2^0.25 = 1.189207: (0.939986 / 1.616860)^(2/3) = 0.581365^(2/3) = 0.696575
    /// (Python's math.gamma: 0.696574502557697).
    #[test]
    fn mantegna_sigma_at_one_and_a_half_by_hand() {
        let s = mantegna_sigma(1.5);
        assert!((s - 0.6966).abs() < 5e-5, "{s}");
        assert!((s - 0.696_574_502_557_697).abs() < 1e-13, "{s}");
        // β = 1: Γ(2) sin(π/2) / (Γ(1) · 1 · 1) = 1.
        assert!((mantegna_sigma(1.0) - 1.0).abs() < 1e-13);
        assert_eq!(Levy::new(1.5, 0.01).sigma(), s);
    }

    #[test]
    fn cube_root_matches_the_library() {
        let mut rng = run_rng(3, 0);
        let mut worst = 0.0f64;
        for k in 0..200_000 {
            // Magnitudes from 1e-300 to 1e300, and the squares of normals a Lévy step takes.
            let a = if k % 2 == 0 {
                10f64.powf(rng.random_range(-300.0..300.0))
            } else {
                let v: f64 = rng.sample(StandardNormal);
                v * v
            };
            let (got, want) = (cbrt(a), a.cbrt());
            worst = worst.max(((got - want) / want).abs());
        }
        assert!(worst <= 2.0 * f64::EPSILON, "{worst:e}");
        assert_eq!(
            (cbrt(8.0), cbrt(27.0), cbrt(0.0), cbrt(1e-320).to_bits()),
            (2.0, 3.0, 0.0, 1e-320f64.cbrt().to_bits())
        );
        assert!(cbrt(f64::NAN).is_nan() && cbrt(f64::INFINITY) == f64::INFINITY);
    }

    /// The branch-free steps are `step_from`'s, bit for bit, the rare cases included (v = 0,
    /// |v|² subnormal, zero or infinite), at β = 1.5 and at another β; and the high word's
    /// division by 3 by multiplication is the division.
    #[test]
    fn bulk_steps_equal_single_steps() {
        for hi in (0..1u64 << 32).step_by(65_537).chain([0, 1, 2, 3, (1 << 32) - 1, (1 << 32) - 2, 0x7fef_ffff]) {
            assert_eq!((hi * 0xAAAA_AAAB) >> 33, hi / 3, "{hi}");
        }
        let mut rng = run_rng(6, 0);
        let mut z = vec![0.0; 2_000];
        fill_standard_normal(&mut rng, &mut z);
        let rare = [0.0, -0.0, 1e-160, -1e-170, 1e-320, 1e200, -1e300, f64::INFINITY, f64::NAN, 1e-154];
        for (k, &v) in rare.iter().enumerate() {
            z[2 * (37 * k + 3) + 1] = v;
        }
        for l in [Levy::new(BETA, 0.05), Levy::new(1.2, 1.0)] {
            let mut out = vec![0.0; 1_000];
            l.steps_from(&z, &mut out);
            for (k, (o, p)) in out.iter().zip(z.chunks_exact(2)).enumerate() {
                assert_eq!(o.to_bits(), l.step_from(p[0], p[1]).to_bits(), "{k}: {p:?}");
            }
        }
    }

    #[test]
    fn a_step_by_hand() {
        let l = Levy::new(1.5, 0.01);
        // u = σ · 2, v = −8: |v|^(2/3) = 4, step = 0.01 · 2σ / 4.
        assert!((l.step_from(2.0, -8.0) - 0.01 * 2.0 * l.sigma() / 4.0).abs() < 1e-16);
        assert_eq!(l.step_from(1.0, 0.0), 0.0);
        // Another β takes the general power: β = 1, σ = 1, |v|^1 = 4.
        let l2 = Levy::new(1.0, 1.0);
        assert!((l2.step_from(3.0, 4.0) - 0.75).abs() < 1e-12);
    }

    /// The steps of 200,000 draws: finite, symmetric (half positive), of a median absolute
    /// value of the order of σ, and heavy-tailed (a few percent beyond ten medians, where a
    /// normal has none); drawn in bulk or one at a time, the same bits.
    #[test]
    fn steps_are_symmetric_and_heavy_tailed() {
        let l = Levy::new(BETA, 1.0);
        let mut rng = run_rng(1, 0);
        let mut s = vec![0.0; 200_000];
        l.fill(&mut rng, &mut s);
        assert!(s.iter().all(|v| v.is_finite()));
        let positive = s.iter().filter(|&&v| v > 0.0).count() as f64 / s.len() as f64;
        assert!((positive - 0.5).abs() < 0.005, "{positive}");
        let mut a: Vec<f64> = s.iter().map(|v| v.abs()).collect();
        a.sort_by(f64::total_cmp);
        let med = a[a.len() / 2];
        // |z_u| / |v|^(2/3) has a median of 0.908 (simulated: 400,000 pairs in Python), so
        // the steps' median absolute value is about 0.908 σ = 0.633.
        assert!((med / l.sigma() - 0.908).abs() < 0.02, "median |step| {med}");
        let far = a.iter().filter(|&&v| v > 10.0 * med).count() as f64 / a.len() as f64;
        // Tail P(|L| > x) ~ x^(−1.5): 2.5 % beyond 10 medians (same simulation); a normal, none.
        assert!((far - 0.0255).abs() < 0.003, "{far}");
        // The same stream drawn one at a time gives the same steps.
        let mut rng2 = run_rng(1, 0);
        assert!((0..100).all(|k| l.sample(&mut rng2).to_bits() == s[k].to_bits()));
    }

    #[test]
    fn normals_have_unit_variance() {
        let mut rng = run_rng(2, 0);
        let mut z = vec![0.0; 100_000];
        fill_standard_normal(&mut rng, &mut z);
        let mean = z.iter().sum::<f64>() / z.len() as f64;
        let var = z.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / z.len() as f64;
        assert!(mean.abs() < 0.02 && (var - 1.0).abs() < 0.02, "{mean} {var}");
    }
}
